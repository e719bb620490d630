#!/usr/bin/env bash
# Rewrite the "Files" table of docs/architecture.md from the tree (the count of C sources
# and headers of each directory of src/, app/ and include/); tests/cli/architecture.sh
# checks it. Run from the project root after adding or removing files.
set -eu
doc=docs/architecture.md
rows=$(for d in $(find src app include -type d | sort); do
    n=$(find "$d" -maxdepth 1 -type f \( -name '*.c' -o -name '*.h' \) | wc -l)
    [ "$n" -gt 0 ] && echo "| \`$d/\` | $n |"
done)
python3 - "$doc" "$rows" <<'PY'
import re, sys
path, rows = sys.argv[1], sys.argv[2]
s = open(path).read()
head = "| directory | files |\n|---|---|\n"
i = s.index(head, s.index("## Files")) + len(head)
j = s.index("\n\n", i)
open(path, "w").write(s[:i] + rows + s[j:])
PY
