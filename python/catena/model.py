"""catena models in Python: read from a .cable file, or built from arrays and keywords
(each directive of docs/format.md has its method, or the generic Model.add) and written
back as a .cable file that `catena solve` reads unchanged."""
from __future__ import annotations

import os
import tempfile
import threading

from . import _catena, _rows, errors
from ._rows import _num
from ._np import np
from .solution import Solution


def _value(key, v):
    if isinstance(v, str):
        if not v or any(c.isspace() or c in "#" for c in v) or (key != "argument" and "=" in v):
            raise ValueError(f"{key}={v!r}: a value of a .cable file is one word")
        return v
    if isinstance(v, (tuple, list, np.ndarray)):
        raise TypeError(f"{key}=: one value was expected, got {type(v).__name__}")
    return _num(v)


def _keys(kw):
    """' key=value ...' of keyword arguments; True is a flag (tension_only -> tension-only),
    None and False are left out."""
    out = []
    for k, v in kw.items():
        if v is None or v is False:
            continue
        name = k.replace("_", "-") if v is True else k
        out.append(name if v is True else f"{name}={_value(k, v)}")
    return (" " + " ".join(out)) if out else ""


def _positional(args):
    return "".join(" " + (_value("argument", a) if isinstance(a, str) else _num(a)) for a in args)


class Model:
    """A catena model.

    Read one:            m = catena.read("bridge.cable")
    Build one:           m = catena.Model(units=("kN", "m"), gravity=(0, -1, 0))
                         m.material("steel", E=2.0e8)
                         m.section("strand", material="steel", A=3.14e-4, w=0.1)
                         m.nodes([1, 2], [[0, 0, 0], [200, 0, 0]], fix="xyz")
                         m.cable(1, 2, section="strand", n=20, length=250.8777)
    Solve it:            sol = m.solve()                 # the file's `solve` options
                         sol = m.solve(method="newton", tol=1e-12, modes=4)
    Write it:            m.write("bridge.cable")         # read back by `catena solve`

    Every directive of the .cable format (docs/format.md) has a method: units, gravity,
    material, section, node / nodes, element / elements (any family: "element" (a
    cable element), "spring", "rspring", "catenary", "pulley"), cable, load / loads,
    moment, hload, displace, step, group, temperature, modes, options (the `solve`
    line); add(directive, *args, **keys) writes any line. Arguments are numbers, words
    and keyword values as in the file; array arguments (nodes, elements, loads) take
    numpy arrays and stand for one line per row in to_cable(). The model is compiled
    when it is first used: its text lines by the C reader, its array blocks in bulk by
    the C API (ctn_model_add_nodes, ctn_model_add_elements: no text made for them), each
    checked as the reader checks a line; a ModelError then names the line of
    to_cable()'s text (and .path the model's name).

    Solve options (solve(**options)): tol, dtol, maxit, method ("auto", "newton",
    "arclength"), ordering ("auto", "natural", "amd", "metis"), linesearch, reuse,
    threads, steps, cutbacks, arclength, arcsteps, lambda (also lambda_max),
    linear_solver ("cholmod", "cholmod-ldl"); modes (a count), mass ("consistent",
    "lumped"), shift [Hz], eigen_solver ("auto", "block", "arpack"); and check=True to
    raise NotConvergedError instead of returning a solution that did not converge.
    The GIL is released during the solve; Ctrl-C (on the main thread) stops it with
    KeyboardInterrupt and leaves the model usable. Two Python threads may solve two
    models at once; one model is solved by one thread at a time (a lock).
    """

    def __init__(self, units=None, gravity=None, name="<model>"):
        self.path = None
        self.name = name
        self._lines = []
        self._c = None
        self._tables = None
        if units is not None:
            self.units(*units)
        if gravity is not None:
            self.gravity(*gravity)

    # ---- reading ----------------------------------------------------------------------
    @classmethod
    def read(cls, path: str | os.PathLike) -> "Model":
        """Read a .cable file (the C reader); ModelError (with .path, .line) on a bad model,
        CatenaIOError when it cannot be read."""
        path = os.fspath(path)
        m = cls(name=path)
        m.path = path
        m._lines = None
        m._c = errors.call(_catena.read, path, _main_thread(), path=path)
        return m

    @classmethod
    def from_string(cls, text: str, name: str = "<string>") -> "Model":
        """A model from .cable text; name stands for the file in messages."""
        m = cls(name=name)
        m._lines = text.splitlines()
        m._compile()
        return m

    # ---- building ----------------------------------------------------------------------
    def add(self, directive, *args, **keys):
        """Append a line `directive args... key=value...` (any directive of docs/format.md)."""
        if self._lines is None:
            self._lines = self.to_cable().splitlines()
            self.path = None
        self._lines.append(directive + _positional(args) + _keys(keys))
        self._c = None
        self._tables = None
        return self

    def _rows(self, block):
        """Append a block of rows from arrays (_rows.Nodes, Elements, Loads): one line per
        row in to_cable(), added to the library in bulk when the model is compiled."""
        self.add("#")
        self._lines[-1] = block
        return self

    def units(self, force, length):
        return self.add("units", force, length)

    def gravity(self, gx, gy, gz):
        return self.add("gravity", gx, gy, gz)

    def material(self, name, E, strain=None, tension_only=False, alpha=None, G=None):
        return self.add("material", name, E=E, strain=strain, tension_only=tension_only, alpha=alpha, G=G)

    def section(self, name, material, A, **keys):
        """section NAME material= A= [w= mass= mbl= safety= Iy= Iz= J= Asy= Asz=]"""
        return self.add("section", name, material=material, A=A, **keys)

    def node(self, id, x, y, z, fix=None, mass=None):
        return self.add("node", id, x, y, z, fix=fix or None, mass=mass)

    def nodes(self, ids, X, fix=None, mass=None) -> "Model":
        """Nodes from arrays: ids (n,), X (n, 3); fix one word for all ("xyz"), a word per
        node, or a bool array (n, 3); mass None, a number or an array (n,)."""
        return self._rows(_rows.Nodes(ids, X, fix, mass))

    def element(self, id, n1, n2, family="element", **keys):
        return self.add(family, id, n1, n2, **keys)

    def elements(self, ids, conn, family: str = "element", **keys) -> "Model":
        """Elements from arrays: ids (ne,), conn (ne, 2) node ids ((ne, k) for a pulley: the
        ends and k - 2 pulleys); family "element" (a cable element), "spring", "rspring",
        "catenary", "pulley", "beam"; keys each one value for all (section=, k=, group=,
        release=) or an array with a value per element (l0=, length=, N0=, s0=, eps0=, k=,
        H=, sag=, tension=, a beam's n=; a beam's orient= is a "VX,VY,VZ" word, three
        numbers or an (ne, 3) array). Every family reaches the library in bulk."""
        return self._rows(_rows.Elements(family, ids, conn, keys, _value))

    def cable(self, n1, n2, section, n, **keys):
        """cable NODE1 NODE2 section= n= length=|H=|sag=|tension= [shape= start= guess= N0=
        s0= eps0= group=]: a generated cable of n elements."""
        return self.add("cable", n1, n2, section=section, n=n, **keys)

    def load(self, node, fx, fy, fz):
        return self.add("load", node, fx, fy, fz)

    def loads(self, nodes, F):
        """Loads from arrays: nodes (k,) ids, F (k, 3)."""
        return self._rows(_rows.Loads(nodes, F))

    def moment(self, node, mx, my, mz):
        return self.add("moment", node, mx, my, mz)

    def hload(self, q, elements=None, projection=None):
        return self.add("hload", q=q, elements=elements, projection=projection)

    def displace(self, node, **dofs):
        """displace NODE [x= y= z= rx= ry= rz=]"""
        return self.add("displace", node, **dofs)

    def step(self, name, substeps=None):
        return self.add("step", name, substeps=substeps)

    def group(self, name, *members):
        """group NAME ID|FIRST-LAST ...; members may be ids, "a-b" ranges or an array of ids."""
        words = []
        for mbr in members:
            if isinstance(mbr, str):
                words.append(mbr)
            else:
                words.extend(str(int(i)) for i in np.asarray(mbr).reshape(-1).tolist())
        return self.add("group", name, *words)

    def temperature(self, target, dT):
        return self.add("temperature", target, dT=dT)

    def modes(self, count, mass=None, shift=None, solver=None):
        return self.add("modes", count=count, mass=mass, shift=shift, solver=solver)

    def options(self, **keys):
        """The `solve` line: the options a solve of the file (or solve()) starts from."""
        keys = {k: ("on" if v else "off") if isinstance(v, bool) else v for k, v in keys.items()}
        if "lambda_max" in keys:
            keys["lambda"] = keys.pop("lambda_max")
        return self.add("solve", **keys)

    # ---- text ---------------------------------------------------------------------------
    def to_cable(self) -> str:
        """The model as .cable text (a file read: its text as it is on disk)."""
        if self._lines is None:
            with open(self.path, encoding="utf-8", errors="surrogateescape") as f:
                return f.read()
        out = []
        for part in self._lines:
            if isinstance(part, str):
                out.append(part)
            else:
                out.extend(part.lines())
        return "\n".join(out) + "\n"

    def write(self, path: str | os.PathLike) -> None:
        """Write the model as a .cable file (temporary beside it, then renamed)."""
        path = os.fspath(path)
        text = self.to_cable()
        d = os.path.dirname(os.path.abspath(path))
        fd, tmp = tempfile.mkstemp(prefix=os.path.basename(path) + ".", suffix=".tmp", dir=d)
        try:
            with os.fdopen(fd, "w", encoding="utf-8", errors="surrogateescape") as f:
                f.write(text)
            os.replace(tmp, path)
        except BaseException:
            if os.path.exists(tmp):
                os.unlink(tmp)
            raise

    def _compile(self):
        """The C model: the text's lines through the reader, the blocks of rows from arrays
        in bulk (their text only where the bulk route would not give the reader's
        answer), each numbered by its first line in to_cable()."""
        if self._c is not None:
            return self._c
        name, irq = self.name, _main_thread()
        c = errors.call(_catena.new_model, name, path=name)
        line, text, self._bulk = 1, [], 0

        def flush(text, line):
            if text:
                errors.call(c.read_more, name, line, "\n".join(text) + "\n", irq, path=name)
            return line + len(text)

        for part in self._lines:
            if isinstance(part, str):
                text.append(part)
                continue
            line = flush(text, line)
            text = []
            if errors.call(part.add_to, c, name, line, path=name):
                self._bulk += 1                          # blocks that went in bulk (tests)
            else:
                flush(part.lines(), line)
            line += len(part)
        flush(text, line)
        self._c = c
        return c

    # ---- solving ------------------------------------------------------------------------
    def solve(self, check: bool = False, **options) -> Solution:
        """Solve (as `catena solve` does: validate, resolve targets, solve) -> Solution."""
        if "lambda_max" in options:
            options["lambda"] = options.pop("lambda_max")
        c = self._compile()
        sol = Solution(self, errors.call(c.solve, options, _main_thread(), path=self.path or self.name))
        return sol.check() if check else sol

    @property
    def solve_options(self):
        """The options of the file's `solve` and `modes` lines (with the defaults)."""
        return self._compile().options()

    # ---- tables -------------------------------------------------------------------------
    def _table(self):
        if self._tables is None:
            c = self._compile()
            ids, X, fix = (np.asarray(b) for b in c.nodes())
            eid, ends, l0, A, E, w, fam, names = c.elements()
            self._tables = dict(node_ids=ids, coordinates=X, fix=fix, element_ids=np.asarray(eid),
                                element_ends=np.asarray(ends), l0=np.asarray(l0), A=np.asarray(A),
                                E=np.asarray(E), w=np.asarray(w),
                                families=np.array(names, dtype=object)[np.asarray(fam)] if len(names) else
                                np.array([], dtype=object))
        return self._tables

    node_ids = property(lambda self: self._table()["node_ids"], doc="Node ids, model order (n,).")
    coordinates = property(lambda self: self._table()["coordinates"], doc="Reference positions (n, 3).")
    fix = property(lambda self: self._table()["fix"], doc="Fix flags per node (1 x, 2 y, 4 z, 8.. rotations).")
    element_ids = property(lambda self: self._table()["element_ids"], doc="Element ids, model order (ne,).")
    element_ends = property(lambda self: self._table()["element_ends"], doc="First and last node index per element (ne, 2).")
    l0 = property(lambda self: self._table()["l0"], doc="Unstressed lengths (after targets were resolved by a solve).")
    families = property(lambda self: self._table()["families"], doc="Family name per element.")

    def __len__(self):
        return self._compile().counts()[1]

    def __repr__(self):
        nn, ne = self._compile().counts()
        return f"<catena.Model {self.name!r}: {nn} nodes, {ne} elements>"


def _main_thread():
    """Ctrl-C can be polled only on the main thread (Python runs its handlers there)."""
    return threading.current_thread() is threading.main_thread()


def read(path: str | os.PathLike) -> Model:
    """Read a .cable model file: catena.read("m.cable") -> Model."""
    return Model.read(path)
