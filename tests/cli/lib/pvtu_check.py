#!/usr/bin/env python3
"""tests/cli/lib/pvtu_check.py DIR RANKS WHOLE.vtu: the VTU pieces of an MPI run's result
set (DIR/result.pvtu and the pieces it names; docs/format.md, "ParaView") against the
whole model's result.vtu of the same run (DIR/result.vtu, written by rank 0; the run
itself is compared with the serial one by mpi_compare.py). Checked: both files are well-formed XML of
ParaView's types (PUnstructuredGrid, UnstructuredGrid); the .pvtu names RANKS pieces,
result_r0.vtu .. result_rN.vtu, each present; each piece declares exactly the arrays the
.pvtu declares (names, types, components); the pieces' cells, in piece order, are the
serial file's cells in model order with the same values; each piece cell's points have the
coordinates and point values of the whole file's nodes (the same bits: every rank holds the
same solution); every node is in some piece. Prints the first differences; exit 1 on any."""
import sys
import xml.etree.ElementTree as ET


def arrays(piece, tag):
    out = {}
    for a in piece.find(tag).findall("DataArray"):
        vals = [float(x) for x in (a.text or "").split()]
        out[a.get("Name")] = (a.get("type"), int(a.get("NumberOfComponents", "1")), vals)
    return out


def grid(path):
    root = ET.parse(path).getroot()
    if root.get("type") != "UnstructuredGrid":
        raise ValueError("%s: VTKFile type %r" % (path, root.get("type")))
    piece = root.find("UnstructuredGrid").find("Piece")
    npts, ncells = int(piece.get("NumberOfPoints")), int(piece.get("NumberOfCells"))
    cells = arrays(piece, "Cells")
    conn, offs = cells["connectivity"][2], cells["offsets"][2]
    start, cl = 0, []
    for o in offs:
        cl.append([int(x) for x in conn[start:int(o)]])
        start = int(o)
    xyz = arrays(piece, "Points")["coordinates"][2]
    pts = [tuple(xyz[3 * i:3 * i + 3]) for i in range(npts)]
    return {"points": pts, "cells": cl, "pd": arrays(piece, "PointData"), "cd": arrays(piece, "CellData"),
            "npts": npts, "ncells": ncells}


def tuples(arr, i):
    t, nc, v = arr
    return v[nc * i:nc * i + nc]


def main():
    d, ranks, serial = sys.argv[1], int(sys.argv[2]), sys.argv[3]
    errs = []
    root = ET.parse(d + "/result.pvtu").getroot()
    if root.get("type") != "PUnstructuredGrid":
        errs.append("result.pvtu: VTKFile type %r" % root.get("type"))
    pg = root.find("PUnstructuredGrid")
    decl = {}
    for tag in ("PPointData", "PCellData"):
        decl[tag] = [(a.get("Name"), a.get("type"), int(a.get("NumberOfComponents"))) for a in pg.find(tag)]
    sources = [p.get("Source") for p in pg.findall("Piece")]
    want = ["result_r%d.vtu" % r for r in range(ranks)]
    if sources != want:
        errs.append("result.pvtu names %s, expected %s" % (sources, want))
    s = grid(serial)
    node_of = {p: i for i, p in enumerate(s["points"])}
    seen, cell = set(), 0
    for src in sources:
        g = grid(d + "/" + src)
        for tag, key in (("PPointData", "pd"), ("PCellData", "cd")):
            have = [(n, a[0], a[1]) for n, a in g[key].items()]
            if have != decl[tag]:
                errs.append("%s: %s arrays %s, the .pvtu declares %s" % (src, key, have, decl[tag]))
        for i, c in enumerate(g["cells"]):
            if cell >= s["ncells"]:
                errs.append("%s: more cells than the serial file's %d" % (src, s["ncells"]))
                break
            if [g["points"][p] for p in c] != [s["points"][p] for p in s["cells"][cell]]:
                errs.append("%s: cell %d is not serial cell %d" % (src, i, cell))
            for name, arr in g["cd"].items():
                if tuples(arr, i) != tuples(s["cd"][name], cell):
                    errs.append("%s: cell %d %s differs" % (src, i, name))
            cell += 1
        for i, p in enumerate(g["points"]):
            j = node_of.get(p)
            if j is None:
                errs.append("%s: point %d not a serial node" % (src, i))
                continue
            seen.add(j)
            for name, arr in g["pd"].items():
                if tuples(arr, i) != tuples(s["pd"][name], j):
                    errs.append("%s: point %d %s differs" % (src, i, name))
    if cell != s["ncells"]:
        errs.append("the pieces hold %d cells, the serial file %d" % (cell, s["ncells"]))
    if len(seen) != s["npts"]:
        errs.append("the pieces hold %d of the %d nodes" % (len(seen), s["npts"]))
    for e in errs[:12]:
        print(e)
    return 1 if errs else 0


if __name__ == "__main__":
    sys.exit(main())
