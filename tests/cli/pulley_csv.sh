#!/usr/bin/env bash
# tests/cli/pulley_csv.sh CATENA: elements.csv lists every node of a pulley (issue 28,
# item 14): a column `nodes`, last, in a model with an element of more than two nodes;
# the same columns as before in a model without.
#   - examples/catenary/pulleys.cable: the rope 9 over nodes 1 2 3 4 and the carriage
#     cable 10 over 11 13 12 (read from the model's own lines);
#   - the paper's cable: the header without `nodes`.
# Prints "N passed, N failed"; exit 1 on any failure.
set -u

. "$(dirname "$0")/lib/common.sh"
cli_init pulley_csv "${1:-}"

"$BIN" solve examples/catenary/pulleys.cable -o "$T/p" >/dev/null 2>"$T/err" || WHY+=("pulleys: exit $?: $(cat "$T/err")")
if [ -f "$T/p/elements.csv" ]; then
    head -1 "$T/p/elements.csv" | grep -q ',nodes$' || WHY+=("header: $(head -1 "$T/p/elements.csv")")
    while read -r kw id rest; do
        want=$(echo "$rest" | tr ' ' '\n' | grep -v = | tr '\n' ' ' | sed 's/ $//')
        got=$(awk -F, -v id="$id" '$1 == id { print $NF }' "$T/p/elements.csv")
        [ "$got" = "$want" ] || WHY+=("pulley $id: nodes '$got', the model's '$want'")
    done < <(grep '^pulley ' examples/catenary/pulleys.cable)
    n=$(awk -F, 'NR > 1 && $2 != "" { n++ } END { print n + 0 }' "$T/p/elements.csv")
    [ "$n" -ge 2 ] || WHY+=("$n element rows")
fi
finish pulley_rows_list_every_node

"$BIN" solve examples/paper/s250.8777.cable -o "$T/c" >/dev/null 2>"$T/err" || WHY+=("paper: exit $?")
[ "$(head -1 "$T/c/elements.csv")" = "id,node1,node2,l0,length,strain,force,stress,slack,utilisation,group" ] ||
    WHY+=("paper header: $(head -1 "$T/c/elements.csv")")
finish no_nodes_column_without_pulleys

cli_summary
