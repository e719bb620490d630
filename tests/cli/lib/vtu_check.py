#!/usr/bin/env python3
"""tests/cli/lib/vtu_check.py DIR: the ParaView files of a result directory read back
and compared with result.json, value for value, and result.vtu with nodes.csv and
elements.csv. The .vtu and .csv files print "%.17g", which round-trips: that comparison
is exact. result.json prints as cJSON does, 15 digits when they come back within
DBL_EPSILON (relative) of the value: that comparison allows exactly that.

  result.vtu        the final state: points = result.json's nodes (x, y, z) in order;
                    point data displacement = (ux, uy, uz), reaction = the node's entry
                    of "reactions" (0 for a node without supports); line cells = the
                    elements in order through their two nodes; cell data force, stress
                    (0 for a spring), strain, slack (0 unless the element says true)
  result_K.vtu      with "steps" (several steps): step K of "steps", the same way, and
  result.pvd        lists them in order.

Read twice: by a plain XML reader (the standard library), and, when Debian's
python3-vtk9 is installed, by VTK's own vtkXMLUnstructuredGridReader. Prints what
differs; exit 1 if anything does, 0 otherwise."""
import csv, json, os, sys
import xml.etree.ElementTree as ET

EPS = sys.float_info.epsilon
problems = []


def same(a, b, exact):
    a, b = float(a), float(b)
    return a == b if exact else abs(a - b) <= max(abs(a), abs(b)) * EPS


def same_list(a, b, exact):
    return len(a) == len(b) and all(same(x, y, exact) for x, y in zip(a, b))


def fail(msg):
    problems.append(msg)


def plain_read(path):
    """{'points': [...], 'conn': [...], 'offsets', 'types', 'point': {name: [[...]]},
    'cell': {...}, 'load_factor'} from the XML text."""
    root = ET.parse(path).getroot()
    if root.get("type") != "UnstructuredGrid":
        fail("%s: not an UnstructuredGrid" % path)
    grid = root.find("UnstructuredGrid")
    piece = grid.find("Piece")
    npts, ncells = int(piece.get("NumberOfPoints")), int(piece.get("NumberOfCells"))

    def values(a):
        if a.get("format") != "ascii":
            fail("%s: array %s is not ascii" % (path, a.get("Name")))
        conv = float if a.get("type").startswith("Float") else int
        return [conv(t) for t in (a.text or "").split()]

    def tuples(a, count):
        v, k = values(a), int(a.get("NumberOfComponents", "1"))
        if len(v) != k * count:
            fail("%s: array %s has %d values, expected %d" % (path, a.get("Name"), len(v), k * count))
        return [v[i * k:(i + 1) * k] for i in range(count)]

    out = {"npts": npts, "ncells": ncells, "point": {}, "cell": {}}
    for a in piece.find("PointData"):
        out["point"][a.get("Name")] = tuples(a, npts)
    for a in piece.find("CellData"):
        out["cell"][a.get("Name")] = tuples(a, ncells)
    out["points"] = tuples(piece.find("Points").find("DataArray"), npts)
    cells = {a.get("Name"): values(a) for a in piece.find("Cells")}
    out["conn"], out["offsets"], out["types"] = cells["connectivity"], cells["offsets"], cells["types"]
    lf = [a for a in grid.find("FieldData") if a.get("Name") == "load_factor"]
    out["load_factor"] = values(lf[0])[0] if lf else None
    return out


def vtk_read(path):
    """The same dictionary from VTK's reader, or None without VTK."""
    try:
        import vtk
        from vtk.util.numpy_support import vtk_to_numpy
    except ImportError:
        return None
    r = vtk.vtkXMLUnstructuredGridReader()
    r.SetFileName(path)
    r.Update()
    g = r.GetOutput()
    if r.GetErrorCode() or g is None:
        fail("%s: VTK could not read it" % path)
        return None

    def arrays(data, count):
        res = {}
        for i in range(data.GetNumberOfArrays()):
            a = data.GetArray(i)
            v = vtk_to_numpy(a).reshape(count, -1).tolist()
            res[a.GetName()] = v
        return res

    npts, ncells = g.GetNumberOfPoints(), g.GetNumberOfCells()
    out = {"npts": npts, "ncells": ncells,
           "point": arrays(g.GetPointData(), npts), "cell": arrays(g.GetCellData(), ncells),
           "points": vtk_to_numpy(g.GetPoints().GetData()).reshape(npts, 3).tolist()}
    conn, offsets, types = [], [], []
    for c in range(ncells):
        ids = g.GetCell(c).GetPointIds()
        conn += [ids.GetId(k) for k in range(ids.GetNumberOfIds())]
        offsets.append(len(conn))
        types.append(g.GetCellType(c))
    out["conn"], out["offsets"], out["types"] = conn, offsets, types
    fd = g.GetFieldData().GetArray("load_factor")
    out["load_factor"] = fd.GetValue(0) if fd else None
    return out


def compare(path, got, state, nodes_ref, reader, exact=False):
    """got (a read file) against state: a dict with "nodes", "reactions", "elements"
    (result.json's, or the CSV files' with exact)."""
    where = "%s (%s)" % (path, reader)
    nodes, elements = state["nodes"], state["elements"]
    if got["npts"] != len(nodes) or got["ncells"] != len(elements):
        fail("%s: %d points, %d cells; result.json has %d nodes, %d elements"
             % (where, got["npts"], got["ncells"], len(nodes), len(elements)))
        return
    index = {n["id"]: i for i, n in enumerate(nodes_ref)}
    react = {r["node"]: [r["fx"], r["fy"], r["fz"]] for r in state["reactions"]}
    for i, n in enumerate(nodes):
        want = {"points": [n["x"], n["y"], n["z"]], "displacement": [n["ux"], n["uy"], n["uz"]],
                "reaction": react.get(n["id"], [0.0, 0.0, 0.0])}
        have = {"points": got["points"][i], "displacement": got["point"]["displacement"][i],
                "reaction": got["point"]["reaction"][i]}
        for k in want:
            if not same_list(have[k], want[k], exact):
                fail("%s: node %d %s %s, result.json %s" % (where, n["id"], k, have[k], want[k]))
    for i, e in enumerate(elements):
        ends = got["conn"][got["offsets"][i] - 2:got["offsets"][i]] if got["offsets"][i] >= 2 else []
        if [index.get(e["nodes"][0]), index.get(e["nodes"][1])] != ends or got["types"][i] != 3:
            fail("%s: element %d: cell %s type %s, result.json nodes %s" % (where, e["id"], ends, got["types"][i], e["nodes"]))
        want = {"force": e["force"], "stress": e.get("stress", 0.0), "strain": e["strain"],
                "slack": 1 if e.get("slack") else 0}
        for k, v in want.items():
            have = got["cell"][k][i][0]
            if not same(have, v, exact):
                fail("%s: element %d %s %r, result.json %r" % (where, e["id"], k, have, v))
    if got["offsets"] != [2 * (i + 1) for i in range(len(elements))]:
        fail("%s: offsets are not those of two-node lines" % where)


def csv_state(d):
    """nodes.csv and elements.csv as a state like result.json's."""
    with open(os.path.join(d, "nodes.csv")) as f:
        rows = list(csv.DictReader(f))
    nodes = [{"id": int(r["id"]), **{k: float(r[k]) for k in ("x", "y", "z", "ux", "uy", "uz")}} for r in rows]
    reactions = [{"node": int(r["id"]), "fx": float(r["rx"]), "fy": float(r["ry"]), "fz": float(r["rz"])}
                 for r in rows if r["fix"]]
    with open(os.path.join(d, "elements.csv")) as f:
        elements = [{"id": int(r["id"]), "nodes": [int(r["node1"]), int(r["node2"])], "force": float(r["force"]),
                     "stress": float(r["stress"]), "strain": float(r["strain"]), "slack": r["slack"] == "1"}
                    for r in csv.DictReader(f)]
    return {"nodes": nodes, "reactions": reactions, "elements": elements}


def check(path, state, nodes_ref, load_factor, exact=None):
    for reader, read in (("plain XML", plain_read), ("VTK", vtk_read)):
        got = read(path)
        if got is None:
            continue
        compare(path, got, state, nodes_ref, reader)
        if exact:
            compare(path, got, exact, exact["nodes"], reader + ", against the CSV files", True)
        if load_factor is not None and got["load_factor"] != load_factor:
            fail("%s (%s): load_factor %r, result.json %r" % (path, reader, got["load_factor"], load_factor))


def main():
    d = sys.argv[1]
    with open(os.path.join(d, "result.json")) as f:
        res = json.load(f)
    check(os.path.join(d, "result.vtu"), res, res["nodes"], None, csv_state(d))
    steps = res.get("steps", [])
    pvd = os.path.join(d, "result.pvd")
    if steps:
        listed = [ds.get("file") for ds in ET.parse(pvd).getroot().find("Collection")]
        width = len(str(len(steps)))
        want = ["result_%0*d.vtu" % (width, k + 1) for k in range(len(steps))]
        if listed != want:
            fail("result.pvd lists %s, expected %s" % (listed, want))
        for k, st in enumerate(steps):
            check(os.path.join(d, want[k]), st, res["nodes"], st["load_factor"])
        last = steps[-1]["load_factor"]
        check(os.path.join(d, "result.vtu"), steps[-1], res["nodes"], last)
    elif os.path.exists(pvd):
        fail("result.pvd written for a one-step run")
    for p in problems[:20]:
        print(p)
    try:
        import vtk  # noqa: F401
        print("vtu_check: read by the plain XML reader and by VTK %s" % vtk.vtkVersion.GetVTKVersion())
    except ImportError:
        print("vtu_check: read by the plain XML reader (python3-vtk9 not installed)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
