"""Blocks of rows from arrays (nodes, elements, loads) in a Model's text: each is one
.cable line per row in Model.to_cable(), and reaches the library in bulk (one C call
over the arrays: ctn_model_add_nodes, ctn_model_add_elements, the loads in one C loop)
when the arrays hold what the reader would accept; anything else (a value out of
range, not finite, a key the bulk calls do not take) goes through the reader as the
block's text, so that its error is the reader's, on the row's line."""
from __future__ import annotations

import re

from ._np import np

INT_MAX = 2**31 - 1
_FIX = {"x": 1, "y": 2, "z": 4, "rx": 8, "ry": 16, "rz": 32}


def _num(x):
    """A number as the .cable reader reads it back to the same double (shortest repr)."""
    if isinstance(x, (bool, np.bool_)):
        raise TypeError("a number was expected, not a bool")
    if isinstance(x, (int, np.integer)):
        return str(int(x))
    return repr(float(x))


def _ids(a):
    """int32 ids when every one is an integer from 1 to INT_MAX (the reader's ids); else None."""
    a = np.asarray(a)
    if a.dtype.kind not in "iu" or (a.size and (a.min() < 1 or a.max() > INT_MAX)):
        return None
    return np.ascontiguousarray(a, dtype=np.intc)


def _reals(a, shape):
    """float64 values of shape when a is numeric (not bool) and finite; else None."""
    a = np.asarray(a)
    if a.dtype.kind not in "iuf":
        return None
    a = np.ascontiguousarray(np.broadcast_to(a, shape), dtype=np.float64)
    return a if np.isfinite(a).all() else None


def fix_bits(word):
    """The fix flags of a fix= word (x, y, z, rx, ry, rz, each once), or None."""
    bits, i = 0, 0
    while i < len(word):
        key = word[i:i + 2] if word[i] == "r" else word[i]
        bit = _FIX.get(key, 0)
        if not bit or bits & bit:
            return None
        bits |= bit
        i += len(key)
    return bits


def _fix_words(fix, n):
    """A fix= word per node: one string for all, a sequence of strings, or a bool array
    (n, 3) of fixed translations."""
    if fix is None:
        return [""] * n
    if isinstance(fix, str):
        return [f" fix={fix}" if fix else ""] * n
    arr = np.asarray(fix)
    if arr.dtype == bool and arr.shape == (n, 3):
        letters = np.array(["x", "y", "z"])
        return [(" fix=" + "".join(letters[row])) if row.any() else "" for row in arr]
    if len(arr) != n:
        raise ValueError(f"fix: {len(arr)} entries for {n} nodes")
    return [f" fix={f}" if f else "" for f in arr.tolist()]


def _fix_array(fix, n):
    """The fix flags per node as int32 (n,), None for no fix at all, False when a word is
    not one the reader takes."""
    if fix is None:
        return None
    if isinstance(fix, str):
        b = fix_bits(fix)
        return False if b is None else np.full(n, b, dtype=np.intc)
    arr = np.asarray(fix)
    if arr.dtype == bool and arr.shape == (n, 3):
        return np.ascontiguousarray(arr @ np.array([1, 2, 4]), dtype=np.intc)
    if arr.dtype.kind not in "U" or arr.shape != (n,):
        return False
    words, inv = np.unique(arr, return_inverse=True)
    bits = [fix_bits(str(w)) for w in words.tolist()]
    if any(b is None for b in bits):
        return False
    return np.ascontiguousarray(np.array(bits, dtype=np.intc)[inv.reshape(-1)])


class Nodes:
    """node ID X Y Z [fix=] [mass=] rows."""

    def __init__(self, ids, X, fix, mass):
        self.X = np.asarray(X, dtype=float).reshape(-1, 3)
        self.ids = np.asarray(ids).reshape(-1)
        if len(self.ids) != len(self.X):
            raise ValueError(f"nodes: {len(self.ids)} ids for {len(self.X)} positions")
        self.fix, self.mass = fix, mass
        if fix is not None and not isinstance(fix, str) and np.ndim(fix) != 2 and len(fix) != len(self.ids):
            raise ValueError(f"fix: {len(fix)} entries for {len(self.ids)} nodes")

    def __len__(self):
        return len(self.ids)

    def lines(self):
        ms = [""] * len(self.ids) if self.mass is None else \
            [f" mass={_num(v)}" for v in np.broadcast_to(self.mass, self.ids.shape).tolist()]
        return [f"node {i} {x!r} {y!r} {z!r}{f}{s}" for i, (x, y, z), f, s in
                zip(self.ids.tolist(), self.X.tolist(), _fix_words(self.fix, len(self.ids)), ms)]

    def add_to(self, c, name, line):
        ids, X = _ids(self.ids), _reals(self.X, self.X.shape)
        fix = _fix_array(self.fix, len(self.ids))
        mass = None if self.mass is None else _reals(self.mass, self.ids.shape)
        if ids is None or X is None or fix is False or (self.mass is not None and (mass is None or (mass < 0).any())):
            return False
        c.add_nodes(name, line, ids, X, fix, mass)
        return True


class Loads:
    """load NODE FX FY FZ rows."""

    def __init__(self, nodes, F):
        self.nodes = np.asarray(nodes).reshape(-1)
        self.F = np.broadcast_to(np.asarray(F, dtype=float), (len(self.nodes), 3))

    def __len__(self):
        return len(self.nodes)

    def lines(self):
        return [f"load {i} {a!r} {b!r} {c!r}" for i, (a, b, c) in zip(self.nodes.tolist(), self.F.tolist())]

    def add_to(self, c, name, line):
        ids, F = _ids(self.nodes), _reals(self.F, self.F.shape)
        if ids is None or F is None:
            return False
        c.add_loads(name, line, ids, F)
        return True


_FAMILIES = {"element": "cable", "spring": "spring", "rspring": "rspring", "catenary": "catenary",
             "pulley": "pulley", "beam": "beam"}                # the library's family names
_PRESTRESS = {"N0": 1, "s0": 2, "eps0": 3}
_TARGETS = {"H": 1, "sag": 2, "tension": 3}
_NUMERIC = ("l0", "N0", "s0", "eps0", "k", "q", "force", "length", "H", "sag", "tension")
_POSITIVE = ("l0", "k", "q", "force", "length", "H", "sag", "tension")
_LENGTHS = ("l0", "length", "N0", "s0", "eps0", "H", "sag", "tension")
# The keys each family's line takes (besides group=) and the one it needs, as the reader.
_KEYS = {"element": {"section", "l0", "N0", "s0", "eps0", "q", "force"},
         "spring": {"k", "l0", "N0", "s0", "eps0", "q", "force"},
         "rspring": {"k"},
         "catenary": {"section", "length", "H", "sag", "tension", "N0", "s0", "eps0"},
         "pulley": {"section", "length", "N0", "s0", "eps0"},
         "beam": {"section", "orient", "n", "release"}}
_REQUIRED = {"element": "section", "spring": "k", "rspring": "k", "catenary": "section", "pulley": "section",
             "beam": "section"}
_DECIMAL = re.compile(r"^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$")
_BEAM_MAX_N = 100000
_PULLEY_MAX_NODES = 64


def release_bits(word):
    """The release flags of a beam's release= word (END:DOFS items, END 1 or 2, DOFS among
    rx ry rz, each once), or None when the reader would refuse it."""
    bits = 0
    for item in word.split(","):
        if len(item) < 3 or item[0] not in "12" or item[1] != ":":
            return None
        end, rest = int(item[0]) - 1, item[2:]
        if len(rest) % 2:
            return None
        for j in range(0, len(rest), 2):
            k = ("rx", "ry", "rz").index(rest[j:j + 2]) if rest[j:j + 2] in ("rx", "ry", "rz") else -1
            if k < 0 or bits & (1 << (3 * end + k)):
                return None
            bits |= 1 << (3 * end + k)
    return bits


def _orient(v, n):
    """A beam's orient per row as float64 (n, 3): from a "VX,VY,VZ" word, three numbers or
    an (n, 3) array; None when the reader would refuse one (not three finite numbers,
    the zero vector)."""
    if isinstance(v, str):
        parts = v.split(",")
        if len(parts) != 3 or not all(_DECIMAL.match(p) for p in parts):
            return None
        v = [float(p) for p in parts]
    a = _reals(v, (n, 3)) if np.ndim(v) in (1, 2) else None
    if a is None or (n and not (np.abs(a).max(axis=1) > 0).all()):
        return None
    return a


def _counts(v, n):
    """A beam's n= per row as int32 (n,), None when one is not an integer 1..100000."""
    a = np.asarray(v)
    if a.dtype.kind not in "iu" or a.ndim > 1:
        return None
    a = np.ascontiguousarray(np.broadcast_to(a, (n,)), dtype=np.int64)
    if n and (a.min() < 1 or a.max() > _BEAM_MAX_N):
        return None
    return np.ascontiguousarray(a, dtype=np.intc)


class Elements:
    """FAMILY ID NODE1 NODE2 key=value... rows (a pulley: ID NODE1 PULLEY... NODE2)."""

    def __init__(self, family, ids, conn, keys, word):
        self.family = family
        self.ids = np.asarray(ids).reshape(-1)
        self.conn = np.asarray(conn).reshape(len(self.ids), -1)
        self.keys = {k: v for k, v in keys.items() if v is not None}
        self.words = {}                                  # the one-value keys, checked now
        for k, v in self.keys.items():
            if k == "orient" and not isinstance(v, str):
                a = np.asarray(v)
                if a.dtype.kind not in "iuf" or a.shape not in ((3,), (len(self.ids), 3)):
                    raise TypeError("orient=: a 'VX,VY,VZ' word, three numbers or an (n, 3) array was expected")
                if a.shape == (3,):
                    self.words[k] = ",".join(_num(x) for x in a.tolist())
            elif isinstance(v, (str, int, float, np.number)):
                self.words[k] = word(k, v)
            elif np.asarray(v).dtype.kind not in "iuf" or np.asarray(v).ndim > 1:
                raise TypeError(f"{k}=: a number or an array of numbers (one per element) was expected")

    def __len__(self):
        return len(self.ids)

    def lines(self):
        cols = []
        for k, v in self.keys.items():
            if k in self.words:
                cols.append([f" {k}={self.words[k]}"] * len(self.ids))
            elif k == "orient":
                cols.append([" orient=" + ",".join(_num(x) for x in row) for row in np.asarray(v).tolist()])
            else:
                cols.append([f" {k}={_num(x)}" for x in np.broadcast_to(np.asarray(v), self.ids.shape).tolist()])
        rest = ["".join(t) for t in zip(*cols)] if cols else [""] * len(self.ids)
        return [f"{self.family} {i} " + " ".join(map(str, c)) + r
                for i, c, r in zip(self.ids.tolist(), self.conn.tolist(), rest)]

    def _columns(self):
        """{key: float or float64 array} of the numeric keys, or None when one is not
        what the reader takes (not a number, not finite, a key of the wrong sign)."""
        out = {}
        for k in _NUMERIC:
            if k not in self.keys:
                continue
            v = self.keys[k]
            if isinstance(v, (str, bool, np.bool_)):
                return None
            a = _reals(v, self.ids.shape)
            if a is None or (k in _POSITIVE and not (a > 0).all()):
                return None
            out[k] = float(np.asarray(v)) if np.ndim(v) == 0 else a
        return out

    def add_to(self, c, name, line):
        keys, fam = self.keys, self.family
        if fam not in _FAMILIES:
            return False
        cols = self._columns()
        ids, conn = _ids(self.ids), _ids(self.conn)
        width = self.conn.shape[1]
        if cols is None or ids is None or conn is None or \
                not (3 <= width <= _PULLEY_MAX_NODES if fam == "pulley" else width == 2):
            return False
        if set(keys) - _KEYS[fam] - {"group"} or _REQUIRED[fam] not in keys:
            return False                                   # a key the reader will name
        lengths = [k for k in _LENGTHS if k in keys]
        dens = [k for k in ("q", "force") if k in keys]
        if len(lengths) > 1 or len(dens) > 1 or (dens and lengths) or \
                not all(isinstance(keys.get(k, ""), str) for k in ("section", "group")):
            return False
        kind = next((_PRESTRESS[k] for k in lengths if k in _PRESTRESS), 0)
        value = cols.get(lengths[0]) if kind else None
        target = next((_TARGETS[k] for k in lengths if k in _TARGETS), 0)
        tvalue = cols.get(lengths[0]) if target else None
        l0 = cols.get("l0", cols.get("length"))
        orient = release = segments = None
        if fam == "beam":
            n = len(self.ids)
            if "orient" in keys and (orient := _orient(keys["orient"], n)) is None:
                return False
            if "n" in keys and (segments := _counts(keys["n"], n)) is None:
                return False
            if "release" in keys:
                bits = release_bits(keys["release"]) if isinstance(keys["release"], str) else None
                if bits is None:
                    return False
                release = np.full(n, bits, dtype=np.intc)
        c.add_elements(name, line, _FAMILIES[fam], ids, conn, width, keys.get("section"), keys.get("group"), kind,
                       l0, value, cols.get("k"), cols.get("q"), cols.get("force"), target, tvalue, orient, release,
                       segments)
        return True
