#!/usr/bin/env bash
# tests/cli/architecture.sh CATENA: docs/architecture.md against the code.
#   - its "Files" table: every directory of src/, app/ and include/ that holds C sources
#     or headers has a row, and the row's count is the directory's;
#   - the layers go one way (docs/architecture.md, "Layers"): io/ includes nothing of the
#     problem, the analyses, their start and design, post-processing, the assembly or
#     the linear algebra; the model, the element families, the core, the distributed
#     data and the assembly include nothing of the problem, the analyses or io/; the CLI
#     (app/) includes only its own header and the public ones; linalg/ does not include
#     the public solve header.
# Prints "N passed, N failed"; exit 1 on any failure.
set -u

. "$(dirname "$0")/lib/common.sh"
cli_init architecture "${1:-}"

doc=docs/architecture.md
table=$(sed -n '/^## Files/,/^## /p' "$doc" | sed -n 's/^| `\([^`]*\)\/` | \([0-9][0-9]*\) |$/\1 \2/p')
[ -n "$table" ] || WHY+=("$doc: no Files table")
while read -r dir n; do
    [ -n "$dir" ] || continue
    if [ ! -d "$dir" ]; then WHY+=("$doc: $dir/ is in the table but not in the tree"); continue; fi
    have=$(find "$dir" -maxdepth 1 -type f \( -name '*.c' -o -name '*.h' \) | wc -l)
    [ "$have" -eq "$n" ] || WHY+=("$doc: $dir/ has $have C files, the table says $n")
done <<< "$table"
for dir in $(find src app include -type d | sort); do
    have=$(find "$dir" -maxdepth 1 -type f \( -name '*.c' -o -name '*.h' \) | wc -l)
    [ "$have" -eq 0 ] && continue
    grep -q "^$dir " <<< "$table" || WHY+=("$doc: $dir/ ($have C files) has no row in the Files table")
done
finish files_table

# includes "DIR/..." found in the files of the given directories
reach() {
    local pattern=$1; shift
    grep -rn --include='*.c' --include='*.h' -E "^#include \"($pattern)/" "$@" 2>/dev/null
}
bad=$(reach 'problem|analysis|start|design|post|assemble|linalg' src/io)
[ -z "$bad" ] || WHY+=("io/ reaches into the solver: $bad")
finish io_knows_no_solver

bad=$(reach 'problem|analysis|start|design|post|io' src/model src/element src/core src/dist src/assemble)
[ -z "$bad" ] || WHY+=("a lower layer reaches up: $bad")
finish lower_layers

bad=$(grep -rn -E '^#include "' app | grep -v -E '#include "(app\.h|catena\.h|catena/[a-z_]+\.h)"')
[ -z "$bad" ] || WHY+=("the CLI includes the library's internals: $bad")
finish app_public_only

bad=$(grep -rn '#include "catena/solve.h"' src/linalg)
[ -z "$bad" ] || WHY+=("linalg/ includes the public solve header: $bad")
finish linalg_own_options

cli_summary
