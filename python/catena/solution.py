"""The result of a solve, as numpy arrays."""
from __future__ import annotations

import json as _json

from . import errors
from ._np import np


def _arr(buf):
    """A numpy view of an extension buffer (no copy); None stays None."""
    return None if buf is None else np.asarray(buf)


class Step:
    """The state at the end of one load step.

    name, converged, reason, load_factor, iterations; displacements and reactions (n, 3)
    in model node order; rotations and moments (n, 3) for a model with rotations, else
    None; forces, stresses, strains, lengths, slack, utilisation per element in model
    element order (read on first use, one C loop each)."""

    def __init__(self, sol, k):
        self._sol = sol
        self.index = k
        (self.name, code, self.load_factor, self.iterations, d, r, rot, mom) = sol._c.step(k)
        self.reason_code = code
        self.converged = code > 0
        self.displacements = _arr(d)
        self.reactions = _arr(r)
        self.rotations = _arr(rot)
        self.moments = _arr(mom)
        self._el = None

    def _elements(self):
        if self._el is None:
            self._el = [np.asarray(b) for b in errors.call(self._sol._c.elements, self.index)]
        return self._el

    @property
    def coordinates(self):
        """Deformed node positions X + d, (n, 3)."""
        return self._sol.model.coordinates + self.displacements

    forces = property(lambda self: self._elements()[0], doc="Axial tension N per element [force].")
    stresses = property(lambda self: self._elements()[1], doc="N / A per element (0 for springs) [force/length^2].")
    strains = property(lambda self: self._elements()[2], doc="Strain of each element's measure.")
    lengths = property(lambda self: self._elements()[3], doc="Current length per element [length].")
    slack = property(lambda self: self._elements()[4], doc="True for a slack tension-only element.")
    utilisation = property(lambda self: self._elements()[5], doc="N / (mbl / safety), 0 without mbl.")

    def __repr__(self):
        return f"<catena.Step {self.index} {self.name!r}: {'converged' if self.converged else 'not converged'}>"


class Solution:
    """The result of Model.solve().

    converged (bool), reason (str), iterations; the state at the end of the last step:
    displacements, reactions, coordinates ((n, 3), model node order: the order of the
    JSON's `nodes`), forces, stresses, strains, lengths, slack, utilisation (per element,
    the order of the JSON's `elements`); steps (a list of Step, one per load step);
    residual_history, increment_history; groups(step) and cables (dicts: few, not per
    element); summary (a dict of the solve's summary:
    iterations, residual, factorizations, timings ...); stability (a dict, None when not
    checked); modes (a Modes, None without a modal analysis). Arrays are numpy arrays
    read in place from the C solution where it holds them (displacements, reactions,
    histories), or filled by one C loop (element results, mode shapes): no per-element
    Python objects. They are read-only.

    to_vtu(path, step=-1) writes a ParaView file by the C writer; write(dir) the result
    set of `catena solve -o DIR`; to_json() the text of `catena solve --json`;
    to_dataframe() the elements as a pandas DataFrame (pandas optional); plot() the
    deformed shape coloured by force (matplotlib optional).
    """

    def __init__(self, model, c):
        self.model = model
        self._c = c
        self.summary = c.summary()
        self.reason = self.summary["reason_name"]
        self.converged = self.summary["reason"] > 0
        self.iterations = self.summary["iterations"]
        self._steps = None
        self._modes = False
        self._last = Step(self, -1)
        self.displacements = self._last.displacements
        self.reactions = self._last.reactions
        self.rotations = self._last.rotations
        self.moments = self._last.moments

    @property
    def steps(self):
        if self._steps is None:
            n = self._c.step_count()
            self._steps = [Step(self, k) for k in range(n - 1)] + [self._last]
            self._last.index = n - 1
        return self._steps

    coordinates = property(lambda self: self._last.coordinates, doc=Step.coordinates.__doc__)
    forces = property(lambda self: self._last.forces, doc=Step.forces.__doc__)
    stresses = property(lambda self: self._last.stresses, doc=Step.stresses.__doc__)
    strains = property(lambda self: self._last.strains, doc=Step.strains.__doc__)
    lengths = property(lambda self: self._last.lengths, doc=Step.lengths.__doc__)
    slack = property(lambda self: self._last.slack, doc=Step.slack.__doc__)
    utilisation = property(lambda self: self._last.utilisation, doc=Step.utilisation.__doc__)

    @property
    def residual_history(self):
        return np.asarray(self._c.histories()[0])

    @property
    def increment_history(self):
        return np.asarray(self._c.histories()[1])

    @property
    def stability(self):
        return self._c.stability()

    def groups(self, step=-1):
        """The groups at the end of a step: {name: dict of max_force, min_force, max_stress,
        max_strain, max_utilisation, worst_element, slack, length, stressed_length, weight}."""
        return {g["name"]: g for g in errors.call(self._c.groups, step)}

    def catenary(self, element, step=-1):
        """A catenary element's forces (element: its index in model order): H, tension at
        both ends, end_forces, V, sag, stretched_length."""
        return errors.call(self._c.catenary, step, element)

    def element_shape(self, element, n=21, step=-1):
        """The deformed shape of an element (index) as n points (n, 3): on the elastic
        catenary for a catenary element, on its straight segments otherwise."""
        return np.asarray(errors.call(self._c.element_shape, step, element, n))

    @property
    def cables(self):
        """The generated cables (a `cable` line each): nodes, first_element, count, length
        (for a target: the length found), sag (mid-span, nan when the cable does not cross
        mid-span), max_sag_from_chord, target ("", "H", "sag", "tension"), target_value,
        target_achieved, target_iterations."""
        return self._c.cables()

    @property
    def modes(self):
        """The modal analysis (Modes), None when none was asked (modes= or a `modes` line)."""
        if self._modes is False:
            d = errors.call(self._c.modes)
            self._modes = None if d is None else Modes(d)
        return self._modes

    def check(self) -> "Solution":
        """Raise NotConvergedError (carrying this solution) unless it converged; self."""
        if not self.converged:
            raise errors.NotConvergedError(f"not converged: {self.reason}", self)
        return self

    def to_json(self, pretty: bool = True) -> str:
        """The text of `catena solve --json` (ctn_result_json)."""
        return errors.call(self._c.json, pretty)

    def to_dict(self):
        return _json.loads(self.to_json(False))

    def to_vtu(self, path, step: int = -1) -> None:
        """Write step `step` (default the last) as a ParaView .vtu file (the C writer)."""
        errors.call(self._c.write_vtu, str(path), step, path=str(path))

    def write(self, directory):
        """result.json, nodes.csv, elements.csv, result.vtu (and per step) into directory."""
        errors.call(self._c.write_results, str(directory), path=str(directory))

    def to_dataframe(self, step=-1):
        """The elements at the end of a step as a pandas DataFrame (needs pandas)."""
        import pandas as pd
        st = self.steps[step]
        return pd.DataFrame({"id": self.model.element_ids, "force": st.forces, "stress": st.stresses,
                             "strain": st.strains, "length": st.lengths, "slack": st.slack,
                             "utilisation": st.utilisation}).set_index("id")

    def plot(self, ax=None, step=-1, scale=1.0):
        """The deformed shape, elements coloured by force (needs matplotlib); the axes."""
        import matplotlib.pyplot as plt
        from matplotlib.collections import LineCollection
        st = self.steps[step]
        xyz = self.model.coordinates + scale * st.displacements
        ends = self.model.element_ends
        # the plane of the two coordinates that vary most
        a, b = np.argsort(np.ptp(xyz, axis=0))[::-1][:2]
        seg = np.stack([xyz[ends[:, 0]][:, [a, b]], xyz[ends[:, 1]][:, [a, b]]], axis=1)
        if ax is None:
            ax = plt.figure().add_subplot()
        lc = LineCollection(seg, array=st.forces, cmap="viridis")
        ax.add_collection(lc)
        ax.autoscale()
        ax.set_aspect("equal")
        ax.figure.colorbar(lc, ax=ax, label="force")
        return ax

    def __repr__(self):
        return f"<catena.Solution {self.reason}, {self.iterations} iterations>"


class Modes:
    """A modal analysis: frequencies [Hz], angular_frequencies, periods, eigenvalues,
    kinds ("vibration", "zero", "unstable"), nodes (the node moving most), participation
    and effective_mass ((nmodes, 3)), shapes ((nmodes, n, 3), mass-normalized),
    total_mass (3), mass ("consistent" or "lumped")."""

    _KINDS = np.array(["vibration", "zero", "unstable"])

    def __init__(self, d):
        for key in ("eigenvalues", "angular_frequencies", "frequencies", "periods", "participation",
                    "effective_mass", "shapes", "nodes"):
            setattr(self, key, np.asarray(d[key]))
        self.kinds = self._KINDS[np.asarray(d["kinds"])]
        self.total_mass = np.array(d["total_mass"])
        self.mass = d["mass"]
        self.max_residual = d["max_residual"]

    def __len__(self):
        return len(self.frequencies)

    def __repr__(self):
        return f"<catena.Modes {len(self)}: {np.array2string(self.frequencies, precision=4)} Hz>"
