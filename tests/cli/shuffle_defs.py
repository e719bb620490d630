#!/usr/bin/env python3
"""Move a model's definitions below their uses (tests/cli/any_order.sh): the lines of
units, gravity, material, section, function, group and set, and the node lines above the
first element-family line, go to the end of the file, in the reverse order of their
kinds (sets and groups, sections, then the materials they use, nodes, gravity, units),
each kind keeping its own order. Usage: shuffle_defs.py IN OUT."""
import sys

MESH = {"element", "cable", "catenary", "pulley", "beam", "spring", "rspring", "net"}
ORDER = ["set", "group", "section", "function", "material", "node", "gravity", "units"]


def shuffle(lines):
    kept, moved = [], {k: [] for k in ORDER}
    mesh_seen = False
    for line in lines:
        words = line.split("#")[0].split()
        word = words[0] if words else ""
        if word in MESH:
            mesh_seen = True
        if word == "node" and mesh_seen:
            kept.append(line)
        elif word in moved:
            moved[word].append(line)
        else:
            kept.append(line)
    out = kept[:]
    for k in ORDER:
        out += moved[k]
    return out, sum(len(v) for v in moved.values())


def main():
    src, dst = sys.argv[1], sys.argv[2]
    lines = open(src, encoding="utf-8", errors="surrogateescape").read().splitlines()
    out, n = shuffle(lines)
    with open(dst, "w", encoding="utf-8", errors="surrogateescape") as f:
        f.write("\n".join(out) + "\n")
    print(n)


if __name__ == "__main__":
    main()
