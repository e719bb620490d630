"""Closed forms of a single cable (catena/analytic.h, docs/analytic.md): supports at
(0, 0) and (l, h), x horizontal, y up, gravity along -y.

Each function returns a Closed: H, reactions, sag (largest, signed, and at mid-span),
length (stretched) and length0 (unstressed), T_max, T_min and where, and, at the
abscissae x (a number or an array, default 101 points over the span), the cable's height
y and tension T as arrays. Errors: CatenaError (arguments out of range; no solution, e.g.
an inextensible cable not longer than its chord)."""
from . import _catena, errors
from ._np import np


class Closed:
    """A closed-form solution: the fields of ctn_analytic_summary, plus x, y, T."""

    def __init__(self, kind, x, d):
        self.kind = kind
        self.x = x
        for k, v in d.items():
            setattr(self, k, np.asarray(v) if k in ("y", "T") else v)

    def __repr__(self):
        return f"<catena.analytic {self.kind}: H={self.H:.6g}, sag={self.sag:.6g}, T_max={self.T_max:.6g}>"


def _x(l, x):
    return np.ascontiguousarray(np.linspace(0.0, l, 101) if x is None else np.atleast_1d(np.asarray(x, dtype=float)))


def catenary(l, h, w, S, x=None):
    """The inextensible catenary of length S and weight w per length."""
    xs = _x(l, x)
    return Closed("catenary", xs, errors.call(_catena.catenary, l, h, w, S, xs))


def elastic_catenary(l, h, w, EA, L0, x=None):
    """Irvine's elastic catenary: unstressed length L0, weight w per unstressed length,
    axial stiffness EA (engineering strain; EA=inf: inextensible)."""
    xs = _x(l, x)
    return Closed("elastic catenary", xs, errors.call(_catena.ecatenary, l, h, w, EA, L0, xs))


def parabola(l, h, q, L0, EA=float("inf"), x=None):
    """The parabolic cable under q per horizontal length: length (EA=inf) or unstressed
    length L0."""
    xs = _x(l, x)
    return Closed("parabola", xs, errors.call(_catena.parabola, l, h, q, L0, EA, xs))
