#!/usr/bin/env bash
# The net of three catenary elements (examples/catenary/net.cable) against the same net
# of cable elements, n = 10 ... 320 per 110 m: the distance of the free node's position
# from the catenary net's, written to out/catenary/net_convergence.dat with a gnuplot
# script and, when gnuplot is installed, net_convergence.svg; and `catena compare` of
# examples/catenary/span.cable, one catenary element (docs/validation.md §10).
# With DOCS=1 the SVG is also copied to docs/figures/.
#     bash scripts/catenary.sh [build/catena]
set -eu
cli=${1:-build/catena}
case $cli in /*) ;; *) cli=$PWD/$cli ;; esac
cd "$(dirname "$0")/.."
out=out/catenary
mkdir -p "$out"
net=examples/catenary/net.cable

# Displacement "ux uy uz" of node 4 in the result directory $1.
node4() { awk -F, '$1 == 4 { print $5, $6, $7 }' "$1/nodes.csv"; }

"$cli" solve "$net" -q -o "$out/cat"
read -r cx cy cz <<< "$(node4 "$out/cat")"
{
    echo "# n (elements per 110 m)  |u_FE - u_catenary| [m]  (node 4)"
    for n in 10 20 40 80 160 320; do
        sed -e "s/^catenary 1 1 4 section=strand length=110/cable 1 4 section=strand n=$n length=110/" \
            -e "s/^catenary 2 4 2 section=strand length=112/cable 4 2 section=strand n=$n length=112/" \
            -e "s/^catenary 3 4 3 section=strand length=230/cable 4 3 section=strand n=$((2 * n)) length=230/" \
            "$net" > "$out/fe$n.cable"
        echo "solve maxit=1000" >> "$out/fe$n.cable"
        "$cli" solve "$out/fe$n.cable" -q -o "$out/fe$n"
        read -r x y z <<< "$(node4 "$out/fe$n")"
        awk -v n="$n" -v x="$x" -v y="$y" -v z="$z" -v a="$cx" -v b="$cy" -v c="$cz" \
            'BEGIN { printf "%d %.17g\n", n, sqrt((x - a)^2 + (y - b)^2 + (z - c)^2) }'
    done
} > "$out/net_convergence.dat"
cat "$out/net_convergence.dat"
cat > "$out/net_convergence.gp" <<'GP'
if (!exists("fmt")) fmt = 'svg'
if (fmt eq 'svg') set terminal svg size 640,440 dynamic font 'sans,11'
if (fmt eq 'png') set terminal pngcairo size 800,550
if (fmt eq 'pdf') set terminal pdfcairo
set output 'net_convergence.'.fmt
set title "Net of three spans: cable elements against one catenary element per span"
set xlabel "elements per 110 m span (n)"
set ylabel "|position of the free node - catenary net's| [m]"
set logscale xy
set grid
set key top right
plot 'net_convergence.dat' using 1:2 with linespoints pt 7 title 'cable elements (engineering strain)', \
     'net_convergence.dat' using 1:(column(2) > 0 ? 0.2 / $1**2 : NaN) with lines dt 2 title 'slope -2'
GP
# One inclined span as one catenary element beside the closed forms (its figures too).
"$cli" compare examples/catenary/span.cable -o "$out/span"
if command -v gnuplot >/dev/null; then
    (cd "$out" && gnuplot net_convergence.gp)
    if [ "${DOCS:-0}" = 1 ]; then
        cp "$out/net_convergence.svg" docs/figures/net_convergence.svg
        cp "$out/span/compare_shape.svg" docs/figures/catenary_span_shape.svg
    fi
else
    echo "gnuplot not installed: data and script written, no figure" >&2
fi
