#!/usr/bin/env bash
# The form-finding example of docs/validation.md ("A hypar net found by force density"):
#   - examples/formfind/hypar_net.cable found by `catena formfind`, the found model
#     solved by `catena solve` (it must stay put), a figure of the net;
#   - the iteration q <- force / l on targets: the net's own forces (found with q=)
#     given back as force= targets, with and without self-weight, and the grid net of
#     tests/test_formfind.c; the force mismatch against the iteration, a figure.
# Output (data, gnuplot scripts, SVG) in out/formfind/; DOCS=1 copies the SVGs to
# docs/figures/. Needs python3 and gnuplot.
#     bash scripts/formfind.sh [build/catena]
set -eu
cli=${1:-build/catena}
case $cli in /*) ;; *) cli=$PWD/$cli ;; esac
cd "$(dirname "$0")/.."
out=out/formfind
mkdir -p "$out"
ex=examples/formfind/hypar_net.cable

echo "== form finding: $ex =="
"$cli" formfind "$ex" -o "$out/hypar_net.found.cable" | tee "$out/found.log" | tail -4
echo "== catena solve of the found model =="
"$cli" solve "$out/hypar_net.found.cable" --json >"$out/found.json"
python3 - "$ex" "$out" <<'PY'
import json, math, re, sys
src, out = sys.argv[1], sys.argv[2]
def nodes(path):
    return {int(m.group(1)): tuple(map(float, m.group(2, 3, 4)))
            for m in re.finditer(r"^node (\d+) (\S+) (\S+) (\S+)", open(path).read(), re.M)}
members = [(int(m.group(1)), int(m.group(2)), int(m.group(3)), m.group(4), float(m.group(5)))
           for m in re.finditer(r"^element (\d+) (\d+) (\d+) section=(\S+) q=(\S+)", open(src).read(), re.M)]
start, found = nodes(src), nodes(out + "/hypar_net.found.cable")
d = json.load(open(out + "/found.json"))
u = max(abs(n[k]) for n in d["nodes"] for k in ("ux", "uy", "uz"))
force = {e["id"]: e["force"] for e in d["elements"]}
mis = max(abs(force[i] - q * math.dist(found[a], found[b])) / force[i] for i, a, b, s, q in members)
print("solve of the found model: converged %s in %d iteration(s), largest displacement %.2e m, "
      "largest |N - q l| / N %.2e" % (d["converged"], d["iterations"], u, mis))
for sec in ("net", "edge"):
    f = [force[i] for i, a, b, s, q in members if s == sec]
    print("  %-4s %3d members, forces %.3f to %.3f kN" % (sec, len(f), min(f), max(f)))
edge_mid = [found[a] for i, a, b, s, q in members if s == "edge"]
inward = max(abs(p[0]) + abs(p[1]) for p in edge_mid) - min(abs(p[0]) + abs(p[1]) for p in edge_mid)
print("  edge cables curve inward by up to %.3f m in plan (|x| + |y| from %.3f to %.3f)" % (
      inward / math.sqrt(2), min(abs(p[0]) + abs(p[1]) for p in edge_mid), max(abs(p[0]) + abs(p[1]) for p in edge_mid)))
print("  centre node: z = %.4f m (the saddle start: 0)" % [p for p in found.values() if abs(p[0]) < 1e-9 and abs(p[1]) < 1e-9][0][2])
for name, pos in (("start", start), ("found", found)):
    for sec in ("net", "edge"):
        with open("%s/%s_%s.dat" % (out, name, sec), "w") as fh:
            fh.write("# x y z of the %s members, one segment per data block (%s shape)\n" % (sec, name))
            for i, a, b, s, q in members:
                if s == sec:
                    fh.write("%.17g %.17g %.17g\n%.17g %.17g %.17g\n\n\n" % (pos[a] + pos[b]))
PY
cat >"$out/hypar_net.gp" <<'GP'
if (!exists("fmt")) fmt = 'svg'
if (fmt eq 'png') set terminal pngcairo size 900,640; else if (fmt eq 'pdf') set terminal pdfcairo size 9in,6.4in; else set terminal svg size 900,640 dynamic font "Helvetica,13"
set output 'hypar_net.'.fmt
set title "hypar net found by force density (strands q = 5 kN/m, edge cables q = 60 kN/m, self-weight)"
set view 62, 32, 1, 1.6
set xlabel "x [m]"; set ylabel "y [m]"; set zlabel "z [m]" rotate
set ticslevel 0
set key at screen 0.98, 0.95 right
splot 'start_net.dat' with lines lc rgb '#c8c8c8' dt 2 title 'start: the saddle z = H (x^2 - y^2) / A^2', \
      'found_net.dat' with lines lc rgb '#1f5fa8' lw 1.2 title 'strands, found', \
      'found_edge.dat' with lines lc rgb '#c0392b' lw 2.5 title 'edge cables, found'
GP
(cd "$out" && gnuplot hypar_net.gp)

echo
echo "== the iteration q <- force / l on targets =="
python3 - "$cli" "$ex" "$out" <<'PY'
import json, re, subprocess, sys
cli, src, out = sys.argv[1:4]
def run(model, log, extra=()):
    r = subprocess.run([cli, "formfind", model] + list(extra), capture_output=True, text=True)
    rows = [l.split() for l in r.stdout.splitlines() if re.match(r"^\s+\d+\s+\S+\s+\S+$", l)]
    with open(log, "w") as fh:
        fh.write("# iteration, largest |q l - force| / force, load change\n")
        fh.writelines(" ".join(r) + "\n" for r in rows)
    last = (r.stderr.strip() or r.stdout.strip().splitlines()[-3]).replace(out + "/", "")
    print("  %-30s %5d iterations, exit %d: %s" % (model.split("/")[-1], len(rows), r.returncode, last[:150]))
def targets(qmodel, name):
    subprocess.run([cli, "formfind", qmodel, "-q", "-o", out + "/tmp.found.cable"], check=True)
    d = json.loads(subprocess.run([cli, "solve", out + "/tmp.found.cable", "--json"], capture_output=True, text=True).stdout)
    F = {e["id"]: e["force"] for e in d["elements"]}
    text = re.sub(r"^(element (\d+) \d+ \d+ section=\S+) q=\S+", lambda m: "%s force=%.17g" % (m.group(1), F[int(m.group(2))]),
                  open(qmodel).read(), flags=re.M)
    open(out + "/" + name, "w").write(text)
    return out + "/" + name
# the grid net of tests/test_formfind.c: 8 x 8 m, border on a saddle, uneven q, loads
n, lines, e = 8, ["material s E=1e7", "section c material=s A=1e-3"], 0
for i in range(n + 1):
    for j in range(n + 1):
        edge = i in (0, n) or j in (0, n)
        x, y = i - n / 2, j - n / 2
        lines.append("node %d %g %g %.17g%s" % (i * (n + 1) + j + 1, x, y, (x * x - y * y) / n if edge else 0, " fix=xyz" if edge else ""))
        if not edge: lines.append("load %d 0 0 -0.3" % (i * (n + 1) + j + 1))
for i in range(n + 1):
    for j in range(n + 1):
        for d in (0, 1):
            i2, j2 = i + (d == 0), j + (d == 1)
            if i2 > n or j2 > n or (d == 0 and j in (0, n)) or (d == 1 and i in (0, n)): continue
            lines.append("element %d %d %d section=c q=%.17g" % (e + 1, i * (n + 1) + j + 1, i2 * (n + 1) + j2 + 1, 1 + 0.25 * (e % 5)))
            e += 1
open(out + "/grid_q.cable", "w").write("\n".join(lines) + "\n")
run(targets(out + "/grid_q.cable", "grid_targets.cable"), out + "/iter_grid.dat")
nw = re.sub(r" w=\S+", "", open(src).read())
open(out + "/hypar_noweight.cable", "w").write(nw)
run(targets(out + "/hypar_noweight.cable", "hypar_noweight_targets.cable"), out + "/iter_hypar_noweight.dat", ["--maxit", "3000"])
run(targets(src, "hypar_targets.cable"), out + "/iter_hypar.dat")
PY
cat >"$out/formfind_targets.gp" <<'GP'
if (!exists("fmt")) fmt = 'svg'
if (fmt eq 'png') set terminal pngcairo size 900,560; else if (fmt eq 'pdf') set terminal pdfcairo size 9in,5.6in; else set terminal svg size 900,560 dynamic font "Helvetica,13"
set output 'formfind_targets.'.fmt
set title "force targets: the iteration q <- force / l (targets = the forces of a q= form)"
set xlabel "iteration"; set ylabel "largest |q l - force| / force"
set logscale y; set format y "10^{%L}"; set grid
set key top right
set arrow from graph 0, first 1e-10 to graph 1, first 1e-10 nohead dt 2 lc rgb '#555555'
set label "tol 1e-10" at graph 0.02, first 3e-10
plot 'iter_grid.dat' using 1:2 with lines lw 2 lc rgb '#1f5fa8' title 'grid net 8 x 8, point loads: converged', \
     'iter_hypar_noweight.dat' using 1:2 with lines lw 2 lc rgb '#e67e22' title 'hypar net, no self-weight: 3000 iterations, not converged', \
     'iter_hypar.dat' using 1:2 with lines lw 2 lc rgb '#c0392b' title 'hypar net with self-weight: stalled'
GP
(cd "$out" && gnuplot formfind_targets.gp)
rm -f "$out/tmp.found.cable"
echo "figures: $out/hypar_net.svg $out/formfind_targets.svg"
if [ "${DOCS:-0}" = 1 ]; then
    cp "$out/hypar_net.svg" "$out/formfind_targets.svg" docs/figures/
    echo "copied the SVGs to docs/figures/"
fi
