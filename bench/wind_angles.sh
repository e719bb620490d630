#!/usr/bin/env bash
# bench/wind_angles.sh CATENA [OLD_CATENA] - iterations of the default method on a slack
# span under a wind at angles to its chord (issue 27): 100 m span, L0 = 130 m (weightless,
# 30 kPa on d = 1 m) or L0 = 103 m (w = 0.3 kN/m along -z, 1 kPa), 400 cable elements,
# tol=1e-12. Prints "angle weightless-iterations [old] weighted-iterations [old]"; a run
# that did not converge shows its iterations with '!'.
set -u
new=$1
old=${2:-}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
model() {   # model DEGREES WEIGHTED
    python3 - "$1" "$2" <<'PY'
import math, sys
th, weighted = float(sys.argv[1]) * math.pi / 180, sys.argv[2] == "1"
sec, grav, L, p = ("w=0.3", "0 0 -1", 103, 1) if weighted else ("", "0 1 0", 130, 30)
print("units kN m\nmaterial steel E=2.0e8 strain=engineering\nsection s material=steel A=1e-3 %s\n"
      "gravity %s\nnode 1 0 0 0 fix=xyz\nnode 2 100 0 0 fix=xyz\ncable 1 2 section=s n=400 length=%g\n"
      "wind all dir=%.17g,%.17g,0 pressure=%g d=1m cd=1\nsolve tol=1e-12" % (sec, grav, L, math.cos(th), math.sin(th), p))
PY
}
its() {   # its BIN MODEL
    "$1" solve "$2" --json 2>/dev/null | python3 -c "import json,sys; d=json.load(sys.stdin); print('%d%s' % (d['iterations'], '' if d['converged'] else '!'))" 2>/dev/null || echo "-"
}
echo "# $(nproc) cores, load $(cut -d ' ' -f 1-3 /proc/loadavg); columns: degrees, weightless new [old], weighted new [old]"
for deg in 0.5 1 2 5 10 15 20 30 45 60 80 89; do
    line="$deg"
    for w in 0 1; do
        model "$deg" "$w" >"$dir/m.cable"
        line="$line  $(its "$new" "$dir/m.cable")"
        [ -n "$old" ] && line="$line [$(its "$old" "$dir/m.cable")]"
    done
    echo "$line"
done
