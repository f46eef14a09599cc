# SPDX-License-Identifier: BSD-3-Clause
"""kinestat: how free and how constrained is a mechanism, a compliant mechanism or a structure?

Python interface to the C++ library (docs/python.md). Three model kinds, as in model files:

- ``network``: Davies' coupling networks (seed 000) -> :class:`NetworkResult`
- ``framework``: exact-constraint analysis of frameworks and flexures (seed 002) -> :class:`FrameworkResult`
- ``structure``: structural groups (Assur groups, seed 004) -> :class:`StructureResult`

>>> import kinestat
>>> result = kinestat.analyze("examples/davies-2-circuit.yaml")
>>> result.FN, result.CN
(3, 2)

Models can also be built from numpy arrays (:class:`Framework`, :class:`Network`); they are
checked by the same reader as model files, so the same errors, with the same positions, apply.
Bad input raises :class:`InputError` (a ``ValueError``) with ``file``, ``line``, ``column`` and
``problem``; a missing file :class:`MissingFileError` (also a ``FileNotFoundError``), an index
out of range in a model built in code :class:`ModelIndexError` (also an ``IndexError``).
"""

import collections.abc as _abc
import errno as _errno
import html as _html
import json as _json
import math as _math
import numbers as _numbers
import os as _os

import numpy as _np

try:
    from . import _core
except ImportError as error:  # Python's own message would blame a circular import
    raise ImportError(f"kinestat's compiled part, kinestat._core, is missing or does not load beside {__file__} "
                      f"(is its build finished? `cmake --build` makes it): {error}") from error
from ._core import InputError

#: The version of kinestat this module was built from (the CMake project's version).
__version__ = _core.__version__

__all__ = [
    "InputError", "MissingFileError", "ModelIndexError", "analyze", "analyse", "structural_groups", "trace", "solve_positions", "Framework", "Network",
    "NetworkResult", "FrameworkResult", "StructureResult", "html_built_in", "sweep", "formats",
]


class MissingFileError(FileNotFoundError, InputError):
    """A model or sweep file that does not exist: a ``FileNotFoundError`` (``errno``,
    ``filename``) and an :class:`InputError` (``file``, ``line`` 0, ``column`` 0, ``problem``)."""

    def __init__(self, path):
        super().__init__(_errno.ENOENT, _os.strerror(_errno.ENOENT), str(path))
        self.file, self.line, self.column = str(path), 0, 0
        self.problem = "no such file"


class ModelIndexError(IndexError, InputError):
    """An index out of range in a model built in code (a bar's node, a support's node): an
    ``IndexError`` and an :class:`InputError` whose ``file`` is the model's name for errors."""

    def __init__(self, where, problem):
        super().__init__(f"{where}: {problem}")
        self.file, self.line, self.column, self.problem = where, 0, 0, problem


def _argument_error(problem):
    error = InputError(problem)
    error.file, error.line, error.column, error.problem = "<arguments>", 0, 0, problem
    return error


def _import_pyrigi(caller):
    # PyRigi is optional: only the conversions need it, and they say so when it is missing.
    try:
        import pyrigi
    except ImportError as error:
        raise ImportError(f"{caller} needs PyRigi (the Python package pyrigi, https://pyrigi.github.io/PyRigi/), "
                          f"which could not be imported: {error}") from error
    return pyrigi


def _tolerance(value):
    # As the command's --tolerance: a positive finite number (or None for the default rule).
    if value is None:
        return None
    if isinstance(value, bool) or not isinstance(value, _numbers.Real):
        raise _argument_error(f"tolerance: {value!r} is not a number: expected a positive number such as 1e-9")
    number = float(value)
    if not _math.isfinite(number):
        raise _argument_error(f"tolerance: {value!r} is not finite: expected a positive number such as 1e-9")
    if number <= 0:
        raise _argument_error(f"tolerance: {value!r} is not positive: expected a positive number such as 1e-9")
    return number


def _misfit_argument(value):
    # As the command's --misfit VALUE (every element) or --misfit ELEMENT=VALUE (repeated): a
    # length, or a dict {element name: length}. The module checks the lengths (zero or more,
    # finite) and the element names against the model (ValueError).
    if isinstance(value, _abc.Mapping):
        if not value:
            raise _argument_error("misfit: the dict names no element: expected {element name: length}, e.g. {'d1': 0.01}")
        misfits = {}
        for element, length in value.items():
            if not isinstance(element, str):
                raise _argument_error(f"misfit: {element!r} is not an element name (a string)")
            misfits[element] = _misfit_length(length, f"misfit of element '{element}'")
        return misfits
    return _misfit_length(value, "misfit")


def _misfit_length(value, what):
    if isinstance(value, bool) or not isinstance(value, _numbers.Real):
        raise _argument_error(f"{what}: {value!r} is not a number: expected a length zero or more such as 0.01, "
                              "or a dict {element name: length}")
    return float(value)


def _existing(path):
    # A missing file is a FileNotFoundError, as Python's own readers raise.
    path = _os.fspath(path)
    if not _os.path.exists(path):
        raise MissingFileError(path)
    return str(path)


def formats():
    """The model file formats this build reads, by name: "kinestat" and "SPACAR" always,
    "URDF", "SDFormat" and "MJCF" when kinestat was built with their libraries."""
    return list(_core.formats())


def html_built_in():
    """True when the HTML report viewer (three.js) was embedded at build time."""
    return _core.html_built_in()


class _Result:
    """What every result has: the kind, the JSON report as a dict, the HTML report, SVG drawings."""

    def __init__(self, analysed):
        self._analysed = analysed
        self._dict = None

    @property
    def kind(self):
        """The model's kind: "network", "framework" or "structure"."""
        return self._analysed.kind

    @property
    def path(self):
        """The model file (or the name given to a model built in code)."""
        return self._analysed.path

    @property
    def notices(self):
        """What the reader of a SPACAR, URDF, SDFormat or MJCF file ignored or assumed, one
        line each (``kinestat analyze`` prints them to standard error); empty for kinestat's
        own files."""
        return list(self._analysed.notices)

    def to_dict(self, full_vectors=False):
        """The command's JSON report (``kinestat analyze --json``, ``kinestat structure --json``)
        as Python data, key for key. A framework's modes and stress states list their non-zero
        entries; ``full_vectors=True`` lists every entry (``--full-vectors``, docs/report.md)."""
        if full_vectors:
            return _json.loads(self._analysed.json(True))
        if self._dict is None:
            self._dict = _json.loads(self._analysed.json())
        return _json.loads(_json.dumps(self._dict))  # a copy the caller may change

    @property
    def verdict(self):
        """The verdict every report leads with (exactly constrained or not, where, one change
        that fixes it), as in the JSON report's "verdict"."""
        return self.to_dict().get("verdict")

    @property
    def summary(self):
        """The verdict in one sentence, e.g. "Not exactly constrained: 1 redundant constraint
        (a structure, no intended motion)." (the JSON report's ``verdict.summary``)."""
        return self._analysed.verdict_summary

    @property
    def exactly_constrained(self):
        """True when the verdict is "exactly constrained": no motion beyond the intended ones and
        no redundant constraint (the JSON report's ``verdict.exactly_constrained``)."""
        return self._analysed.exactly_constrained

    def to_json(self, full_vectors=False):
        """The JSON report text, byte for byte as the command writes it (``full_vectors=True``:
        as ``--full-vectors`` writes it)."""
        return self._analysed.json(full_vectors)

    def html(self):
        """The self-contained interactive HTML report (``kinestat report``). Raises RuntimeError
        when this kinestat was built without the viewer (npm was not reachable)."""
        text = self._analysed.html()
        if not text:
            raise RuntimeError("HTML output is not built in: kinestat was built without npm")
        return text

    def iframe(self, height=640):
        """The interactive report as one ``<iframe>`` element whose whole document is in its
        ``srcdoc`` (HTML-escaped), sandboxed with scripts only: its styles, ids and globals cannot
        reach the page around it nor another report's, so any number share a notebook. ``height``
        in CSS pixels. Raises RuntimeError without the viewer, as :meth:`html`."""
        title = _html.escape(f"kinestat report: {self.path}", quote=True)
        return (f'<iframe srcdoc="{_html.escape(self.html(), quote=True)}" title="{title}" '
                f'sandbox="allow-scripts allow-downloads" loading="lazy" '
                f'style="box-sizing: border-box; width: 100%; height: {int(height)}px; border: 1px solid #ccc;"></iframe>')

    def _repr_html_(self):
        # Jupyter shows the interactive report inline, isolated in its iframe; without the
        # viewer, the text repr.
        return self.iframe() if _core.html_built_in() else None

    def svg(self, what=None, mode=1, stress=1):
        """An SVG drawing as ``kinestat draw`` makes it: ``what`` is "graph" (coupling, motion and
        action graphs), "mechanism" (the model with kinematic mode ``mode`` and self-stress
        ``stress``, 1-based, 0 for none) or "structure" (the structural diagram). Default: the
        mechanism for frameworks, the graph otherwise."""
        if what is None:
            what = "mechanism" if self.kind == "framework" else "graph"
        return self._analysed.svg(what, mode, stress)

    def _counts_text(self):
        return ""

    def __repr__(self):
        return f"<kinestat.{type(self).__name__} of {self.path!r}: {self._counts_text()}\n {self.summary}>"


class NetworkResult(_Result):
    """Nett freedom and constraint of a coupling network (seed 000). Matrices are numpy arrays;
    screws are in the user's frame, d coordinates per coupling."""

    def __init__(self, analysed):
        super().__init__(analysed)
        counts = analysed.network_counts()
        #: dimension of the screw space (6 spatial, 3 planar), bodies, couplings, circuits, cutsets
        self.d, self.n, self.e, self.l, self.k = (counts[key] for key in ("d", "n", "e", "l", "k"))
        #: gross and nett degrees of freedom and of constraint, ranks of the unit matrices
        self.F, self.C, self.m, self.a = (counts[key] for key in ("F", "C", "m", "a"))
        self.FN, self.CN = counts["FN"], counts["CN"]
        #: the names every kind answers to: FN motions (mechanisms), CN self-stresses
        self.mechanisms, self.self_stresses = self.FN, self.CN
        #: whether exact rational arithmetic was used
        self.exact = counts["exact"]
        #: "dense" (Davies' matrices: every method below) or "sparse" (above 300 couplings: the
        #: counts, ``rank_evidence()`` and the report's stressed and moving couplings; the
        #: matrices and bases raise ValueError, ``analyze(..., method="dense")`` gives them)
        self.method = counts["method"]

    def inf_flexes(self):
        """Basis of the network's motions: F x FN, column j the magnitudes of all F coupling
        freedoms (``motion_names``) when primary motion j is 1 and the others 0."""
        return self._analysed.motion_basis()

    def stresses(self):
        """Basis of the internal actions (self-stress): C x CN, column j the magnitudes of all C
        coupling constraints (``action_names``) when primary action j is 1."""
        return self._analysed.action_basis()

    def unit_motion_matrix(self):
        """The network unit motion matrix [M̂N] (d l x F, eq. 5a); its rank is m."""
        return self._analysed.unit_motion_matrix()

    def unit_action_matrix(self):
        """The network unit action matrix [ÂN] (d k x C, eq. 5b); its rank is a."""
        return self._analysed.unit_action_matrix()

    def circuit_matrix(self):
        """The circuit matrix [B] (l x e, eq. 3a)."""
        return self._analysed.circuit_matrix()

    def cutset_matrix(self):
        """The cutset matrix [Q] (k x e, eq. 3b)."""
        return self._analysed.cutset_matrix()

    @property
    def motion_names(self):
        """Names of the F motion magnitudes, e.g. "sa" (rows of ``inf_flexes()``)."""
        return self._analysed.motion_names()

    @property
    def action_names(self):
        """Names of the C action magnitudes, e.g. "Ub" (rows of ``stresses()``)."""
        return self._analysed.action_names()

    @property
    def primary_motions(self):
        """The FN primary motion variables (columns of ``inf_flexes()``)."""
        return self._analysed.primary_motions()

    @property
    def primary_actions(self):
        """The CN primary action variables (columns of ``stresses()``)."""
        return self._analysed.primary_actions()

    def rank_evidence(self):
        """The evidence of the two rank decisions: {"motion": {...}, "action": {...}}, each with its
        ``status`` ("exact", "certain", "close") and ``distance`` (smallest kept / largest singular
        value, None when the rank is 0)."""
        return {"motion": self._analysed.motion_rank(), "action": self._analysed.action_rank()}

    def structural_groups(self):
        """The network's structural groups (seed 004), as ``kinestat structure``."""
        return structural_groups(self.path)

    def _counts_text(self):
        return f"FN = {self.FN}, CN = {self.CN} (F = {self.F}, C = {self.C}, {self.method})"


class FrameworkResult(_Result):
    """Exact-constraint analysis of a framework or flexure mechanism (seed 002). Vectors are
    non-dimensional: translations divided by the characteristic length ``length``, rotations
    in rad, deformations as in D(c)."""

    def __init__(self, analysed):
        super().__init__(analysed)
        counts = analysed.framework_counts()
        #: rank of D(c), its rows (fixed and independent deformations) and columns (dependent coordinates)
        self.rank, self.rows, self.columns = counts["rank"], counts["rows"], counts["columns"]
        #: kinematically indeterminate modes and statically indeterminate stress states
        self.mechanisms, self.self_stresses = counts["mechanisms"], counts["self_stresses"]
        #: characteristic length used to non-dimensionalise D(c)
        self.length = counts["length"]
        #: 2 (planar) or 3 (spatial), as PyRigi's ``dim``
        self.dimension = counts["dimension"]
        #: the names every kind answers to: FN motions (mechanisms), CN self-stresses
        self.FN, self.CN = self.mechanisms, self.self_stresses
        self._vectors = counts["vectors"]
        self._trivial = None

    def _counts_text(self):
        return (f"mechanisms = {self.mechanisms}, self_stresses = {self.self_stresses} "
                f"(D(c) {self.rows} x {self.columns}, rank {self.rank})")

    def rigidity_matrix(self, sparse=False):
        """D(c): rows deformations (``row_labels``), columns dependent coordinates
        (``column_labels``), non-dimensional. Its null space holds ``inf_flexes()``, the null
        space of its transpose ``stresses()``. ``sparse=True``: a ``scipy.sparse`` matrix (needs
        SciPy, Debian's python3-scipy). Unlike PyRigi's rigidity matrix it has no columns for the
        supported (fixed) and independent coordinates, and its translations are divided by the
        characteristic length ``length``."""
        if sparse:
            try:
                import scipy.sparse  # noqa: F401 (pybind11 converts to it)
            except ImportError:
                raise ImportError("rigidity_matrix(sparse=True) needs SciPy (Debian: python3-scipy); "
                                  "rigidity_matrix() gives the dense numpy array") from None
            return self._analysed.jacobian_sparse()
        return self._analysed.jacobian()

    def trivial_inf_flexes(self):
        """The rigid motions of the whole framework that its supports and independent
        coordinates allow, as a basis of columns of D(c) (orthonormal, D̂'s units): 3 for an
        unsupported planar framework, 6 for a spatial one (fewer for degenerate placements such
        as collinear nodes in space), none for a framework held in place."""
        if self._trivial is None:
            self._trivial = _rigid_motions(self._analysed, self.dimension, self.length)
        return self._trivial.copy()

    def nontrivial_inf_flexes(self):
        """A basis of the infinitesimal flexes that are not rigid motions: the modes with their
        trivial part projected out (orthonormal; the modes themselves when there is no trivial
        flex). Its size is ``mechanisms - trivial_inf_flexes().shape[1]``."""
        modes = self._modes()
        trivial = self.trivial_inf_flexes()
        if trivial.shape[1] == 0:
            return modes
        rest = modes - trivial @ (trivial.T @ modes)
        return _orthonormal_columns(rest, self.mechanisms - trivial.shape[1])

    def is_inf_rigid(self):
        """True when every infinitesimal flex is a rigid motion of the whole framework (PyRigi's
        ``is_inf_rigid``): no mechanism beyond the trivial flexes the supports allow."""
        return self.mechanisms == self.trivial_inf_flexes().shape[1]

    def rigid_components(self):
        """The generic rigid components (PyRigi's ``rigid_components``): lists of node names, from
        the pebble game on the bar graph (planar frameworks of bars only, as the report's
        ``generic.laman.rigid_components``, which also says which one holds the ground)."""
        laman = (self.to_dict().get("generic") or {}).get("laman")
        if not laman or "rigid_components" not in laman:
            raise ValueError("rigid components come from the pebble game: planar frameworks of bars only")
        return [list(component["nodes"]) for component in laman["rigid_components"]]

    def _modes(self):
        if not self._vectors:
            raise ValueError("this framework took the sparse path (above 1,500 rows or columns of D(c)): counts only, "
                             "no modes or stress states")
        return self._analysed.modes()

    def singular_values(self):
        """Singular values of the (element-length scaled) D(c), decreasing; the rank decision's evidence."""
        return self._analysed.singular_values()

    def inf_flexes(self, include_trivial=False):
        """A basis of the infinitesimal flexes (coordinate rates of the columns of D(c)), one
        column each. ``include_trivial=True``: every kinematically indeterminate mode, as the
        report numbers them (columns x mechanisms, unit 2-norm); ``False`` (PyRigi's default):
        without the rigid motions of the whole framework (:meth:`nontrivial_inf_flexes`) — the
        same modes for a framework held in place, which has none."""
        return self._modes() if include_trivial else self.nontrivial_inf_flexes()

    def stresses(self):
        """Statically indeterminate stress states: rows x self_stresses, unit 2-norm."""
        return self._analysed.stress_states()

    def rank_evidence(self):
        """The rank decision: rank, threshold, smallest kept and largest dropped singular values,
        ``status`` ("certain", "close"; "unproven" for a sparse QR) and ``distance``."""
        return self._analysed.rank_evidence()

    def trace(self, mode=1, amplitude=0.1, steps=20):
        """Finite motion (issue 13): kinematic mode ``mode`` (1-based, as ``inf_flexes()``
        columns) followed by the predictor-corrector over ``amplitude`` times the characteristic
        length in ``steps`` steps. The JSON of ``kinestat move --mode N --amplitude A
        --steps S --json`` as a dict (see :func:`trace`)."""
        return _json.loads(self._analysed.trace(int(mode), float(amplitude), int(steps)))

    def stiffness_matrix(self):
        """The linear stiffness K = Dᵀ K_ε D over the free coordinates (``stiffness_labels``), a
        symmetric numpy array in the model's units (docs/stiffness.md): force per length for
        translation pairs, force·length per rad for rotation pairs, force per rad where they
        couple. Coordinates are global: x, y, z and small rotations rx, ry, rz about the global
        axes through the node. Needs elastic data (materials and sections); ValueError otherwise."""
        return self._analysed.stiffness_matrix()[0]

    @property
    def stiffness_labels(self):
        """The free coordinates of :meth:`stiffness_matrix` and :meth:`eigenpairs`, in order, as
        "NODE.slot" (slot x, y, z, rx, ry, rz; planar x, y, rz)."""
        return list(self._analysed.stiffness_matrix()[1])

    def eigenpairs(self, misfit=0.0):
        """The eigenfrequencies (Hz, ascending, a numpy vector) and mode shapes (a numpy array,
        one mass-normalised column per frequency over ``stiffness_labels``; massless coordinates
        condensed out) of the framework with its masses. ``misfit`` (a length in the model's
        unit, or a dict ``{element name: length}`` as in ``over_constraint``): under the
        prestress of the worst misfit (``kinestat stiffness --misfit``); a negative frequency is
        a mode the prestress buckled, −√|ω²| / 2π. ValueError without elastic data or masses."""
        frequencies, shapes, _ = self._analysed.eigenpairs(_misfit_argument(misfit))
        return frequencies, shapes

    def over_constraint(self, at, misfit):
        """What over-constraint costs (``kinestat stiffness MODEL --at AT --misfit MISFIT
        --json``): the ``misfit`` block (``value``, ``worst``: ``element``, ``force`` in N,
        tension positive, ``stress`` peak in N/length², …; ``worst`` None for an exactly
        constrained design) and ``frequencies`` (Hz, ascending; with ``frequencies_with_misfit``)
        as a dict. ``misfit`` is a length in the model's unit for every element, or a dict
        ``{element name: length}`` (``--misfit ELEMENT=VALUE``: the elements not named get none;
        the block then has ``per_element`` and ``value`` None). ValueError for a negative or
        non-finite length or an element the model does not have."""
        return _json.loads(self._analysed.over_constraint(str(at), _misfit_argument(misfit)))

    @property
    def row_labels(self):
        return self._analysed.row_labels()

    @property
    def column_labels(self):
        return self._analysed.column_labels()


class StructureResult(_Result):
    """Structural groups (Assur groups) of a mechanism, in order of formation (seed 004)."""

    def _counts_text(self):
        groups = self.groups
        return f"{len(groups)} structural group{'s' if len(groups) != 1 else ''}, " + \
            ("complete" if self.complete else "incomplete")

    @property
    def groups(self):
        """One dict per group: number, bodies (names), Nm, nc, P, Sc, stage, after."""
        return self._analysed.groups()

    @property
    def complete(self):
        """True when every movable body belongs to a group."""
        return self._analysed.complete()

    def svg(self, what="structure", mode=1, stress=1):
        return super().svg(what, mode, stress)


_RESULTS = {"network": NetworkResult, "framework": FrameworkResult, "structure": StructureResult}


def _source(model):
    if isinstance(model, (Framework, Network)):
        return model.name_for_errors, model.to_json()
    return _existing(model), None


def analyze(model, *, tolerance=None, arithmetic="auto", primary=None, method="auto"):
    """Analyses a model file (path) or a :class:`Framework` / :class:`Network` built in code.
    Files are read in their format, as ``kinestat analyze`` reads them (docs/formats.md):
    kinestat YAML / JSON, SPACAR ``.dat`` (a framework), URDF ``.urdf``, SDFormat ``.sdf`` /
    ``.world`` and MJCF (networks; ``.xml`` by its root element); ``notices`` says what a
    reader of another program's format ignored.

    ``tolerance``: relative rank tolerance (as ``--tolerance``); ``arithmetic`` for networks:
    "auto", "exact" or "float"; ``primary``: the networks' primary variables; ``method`` for
    networks: "auto" (as ``kinestat analyze``: the sparse body-twist path above 300 couplings,
    unless exact arithmetic or primary variables are asked for), "dense" (Davies' matrices at
    any size: time and memory grow as the cube of the network) or "sparse". A model of kind
    structure gives its structural groups."""
    path, text = _source(model)
    analysed = _core.analyse(path, text, _tolerance(tolerance), arithmetic, list(primary or []), method)
    if analysed.kind == "structure":
        return structural_groups(model)
    return _RESULTS[analysed.kind](analysed)


analyse = analyze


def structural_groups(model):
    """Structural groups of a network or structure model (path or :class:`Network`), as
    ``kinestat structure``: ``to_dict()`` equals its ``--json``."""
    path, text = _source(model)
    return StructureResult(_core.decompose(path, text))


def sweep(spec, *, shard=(0, 1), tolerance=None, full=False):
    """A design sweep (docs/sweep.md): one dict per variant of the sweep spec file ``spec``, as
    the lines of ``kinestat sweep SPEC --shard I/N`` (``shard=(I, N)``). A variant that could not
    be analysed has ``error``; a bad spec or model raises :class:`InputError`."""
    index, count = shard
    lines, _failed = _core.sweep_lines(_existing(spec), index, count, _tolerance(tolerance), full)
    return [_json.loads(line) for line in lines]


def trace(model, mode=1, amplitude=0.1, steps=20, *, tolerance=None):
    """Finite motion of a framework (issue 13), as ``kinestat move MODEL --mode N
    --amplitude A --steps S --json``, key for key: kinematic mode ``mode`` (1-based, numbered as
    ``kinestat analyze`` numbers them) followed from the model's configuration over ``amplitude``
    times the characteristic length in ``steps`` steps, on the full bar-length equations.

    Returns a dict with ``order``, ``closed`` (every point reached with closure), ``failed_step``,
    ``amplitude`` (arc length reached, length units), ``max_residual`` (largest closure residual
    over the characteristic length), ``rank_drops`` and ``path``: one dict per point with
    ``step``, ``parameter`` (arc length over the characteristic length), ``arc_length``,
    ``residual``, ``rank`` (of D(c) there) and ``positions`` (node name -> coordinates, length
    units, ten significant digits)."""
    path, text = _source(model)
    analysed = _core.analyse(path, text, _tolerance(tolerance), "auto", [])
    if analysed.kind != "framework":
        raise ValueError("trace follows a kinematic mode of a framework (kind: framework); "
                         "a network's positions are solved by solve_positions")
    return _json.loads(analysed.trace(int(mode), float(amplitude), int(steps)))


def solve_positions(model, inputs=None, *, sweep=None):
    """Positions of a planar mechanism (network model), solved group by group in the order of
    formation of its structural groups, as ``kinestat move MODEL --input NAME=VALUE ...
    [--sweep NAME=FROM:TO:STEPS] --json``, key for key.

    ``inputs``: driving coupling name -> value relative to the file's configuration (rad for a
    revolute, length units for a prismatic), in the order given; ``sweep``: one more driving
    coupling swept as ``(name, from, to, steps)``. Returns a dict with ``groups`` (order of
    formation, type, method, branch), ``steps`` (per input set: ``inputs``, ``assembled``,
    ``max_residual``, per-body poses and per-coupling points) and ``not_assembled``."""
    path, text = _source(model)
    pairs = [(str(name), float(value)) for name, value in (inputs or {}).items()]
    if sweep is not None:
        name, start, stop, steps = sweep
        sweep = (str(name), float(start), float(stop), int(steps))
    return _json.loads(_core.read(path, text).positions(pairs, sweep))


def _rigid_motions(analysed, dimension, length):
    # Translations along the axes and rotations about axes through the centroid (planar: x, y
    # and the rotation about z) at every coordinate, D̂'s units (translations over the
    # characteristic length, rotations in rad); the combinations that leave every held
    # coordinate at rest, on the columns of D(c), orthonormalised.
    positions = analysed.node_positions()
    arms = (positions - positions.mean(axis=0)) / length if len(positions) else positions
    translations = (0, 1) if dimension == 2 else (0, 1, 2)
    rotations = (2,) if dimension == 2 else (0, 1, 2)

    def generators(slots):
        node, slot = slots[:, 0], slots[:, 1]
        g = _np.zeros((len(slots), len(translations) + len(rotations)))
        for k, axis in enumerate(translations):
            g[:, k] = slot == axis
        for k, axis in enumerate(rotations, start=len(translations)):
            velocity = _np.cross(_np.eye(3)[axis], arms[node]) if len(slots) else _np.zeros((0, 3))
            along = velocity[_np.arange(len(slots)), _np.minimum(slot, 2)]
            g[:, k] = _np.where(slot < 3, along, slot - 3 == axis)
        return g

    dependent = generators(analysed.coordinate_slots("dependent"))
    held = generators(analysed.coordinate_slots("held"))
    combinations = _np.eye(dependent.shape[1])
    if len(held):
        _u, values, vt = _np.linalg.svd(held)
        kept = int(_np.sum(values > _RIGID_MOTION_CUT * max(1.0, values.max(initial=0.0))))
        combinations = vt[kept:].T
    return _orthonormal_columns(dependent @ combinations)


# Relative size below which a combination of rigid motions counts as none (rounding of O(1) entries).
_RIGID_MOTION_CUT = 1e-9


def _orthonormal_columns(matrix, count=None):
    # An orthonormal basis of the column space (its `count` leading directions, or those above the
    # cut), each column signed so that its largest-magnitude entry is positive.
    if matrix.size == 0:
        return _np.zeros((matrix.shape[0], 0))
    u, values, _vt = _np.linalg.svd(matrix, full_matrices=False)
    if count is None:
        count = int(_np.sum(values > _RIGID_MOTION_CUT * max(1.0, values.max(initial=0.0))))
    basis = u[:, :count]
    for j in range(basis.shape[1]):
        if basis[_np.argmax(_np.abs(basis[:, j])), j] < 0:
            basis[:, j] = -basis[:, j]
    return basis


def _check_finite(array, what, model, name):
    # NaN and infinite coordinates are refused where they are given, naming the row.
    rows = _np.flatnonzero(~_np.isfinite(array).all(axis=1))
    if rows.size:
        i = int(rows[0])
        problem = f"{what}: {name(i)} has a coordinate that is not a finite number: {array[i].tolist()}"
        error = InputError(f"{model}: {problem}")
        error.file, error.line, error.column, error.problem = model, 0, 0, problem
        raise error


def _rows(array, what):
    # Each row of a float array as a list of numbers: integral values as integers, others as
    # floats, whose repr is the shortest decimal that reads back as the same double, so a model
    # built in code and its file give the same exact numbers. No Python call per value: the
    # finiteness check runs once on the whole array.
    array = _np.asarray(array, dtype=float)
    if not _np.all(_np.isfinite(array)):
        raise ValueError(f"{what}: not a finite number: {array[~_np.isfinite(array)][0]}")
    integral = (array == _np.round(array)) & (_np.abs(array) < 2**53)
    values = array.astype(object)
    values[integral] = array[integral].astype(_np.int64).astype(object)
    return values.tolist()


class _Encoded(list):
    """The items of a large list (or the entries of a mapping, ``mapping=True``) already encoded
    as JSON text, one per line of the document: no Python dict per item, no encoder call."""

    def __init__(self, items, mapping=False):
        super().__init__(items)
        self.mapping = mapping


_quote = _json.encoder.encode_basestring_ascii  # as json.dumps quotes strings (C, ASCII-escaped)


def _json_lines(document):
    # JSON with one top-level key per line and one item per line of each list or mapping value,
    # so that a reader's error line names the item. Items go through the C encoder one by one
    # (json.dumps with `indent` falls back to the pure-Python encoder, ten times slower on large
    # models), or come encoded (_Encoded).
    lines = ["{"]
    keys = list(document)
    for position, key in enumerate(keys):
        value = document[key]
        comma = "," if position + 1 < len(keys) else ""
        if isinstance(value, _Encoded) and not value:
            lines.append(f" {_quote(key)}: {'{}' if value.mapping else '[]'}{comma}")
        elif isinstance(value, (list, dict)) and value:
            mapping = value.mapping if isinstance(value, _Encoded) else isinstance(value, dict)
            if isinstance(value, _Encoded):
                items = value
            elif mapping:
                items = [f"{_quote(str(name))}: {_json.dumps(item)}" for name, item in value.items()]
            else:
                items = [_json.dumps(item) for item in value]
            lines.append(f" {_quote(key)}: {'{' if mapping else '['}")
            lines.append("  " + ",\n  ".join(items))
            lines.append(f" {'}' if mapping else ']'}{comma}")
        else:
            lines.append(f" {_quote(key)}: {_json.dumps(value)}{comma}")
    lines.append("}")
    return "\n".join(lines) + "\n"


class _Model:
    """A model document built in code; analysed by the same reader as model files."""

    name_for_errors = "<model>"

    def _document(self):
        raise NotImplementedError

    def to_json(self):
        """The model as a JSON model file (a valid ``kinestat: 1`` document): one item (node,
        element, coupling, ...) per line."""
        return _json_lines(self._document())

    def to_dict(self):
        """The model file's document as Python data (``json.loads`` of :meth:`to_json`)."""
        return _json.loads(self.to_json())

    def analyze(self, **options):
        return analyze(self, **options)

    analyse = analyze


class Framework(_Model):
    """A framework (``kind: framework``) from numpy arrays.

    nodes: (n, 2) or (n, 3) positions (planar or spatial); node_names: n names (default
    "0", "1", ...); bars: (b, 2) node indices of trusses; beams: (k, 2) node indices of beams,
    beam_z: (k, 3) the z axis of each spatial beam's cross-section; rigid_bodies: lists of
    node indices (reference node first); supports: {node index or name: "fixed" | "pinned" |
    list of coordinates such as ["x", "rz"]}; independent: the same for independent
    coordinates; released: {element index: list of deformation names}.
    Elements are numbered bars first, then beams, then rigid bodies."""

    name_for_errors = "<framework>"

    def __init__(self, nodes, bars=None, beams=None, beam_z=None, rigid_bodies=None, supports=None,
                 independent=None, released=None, node_names=None, name=None):
        self.nodes = _np.atleast_2d(_np.asarray(nodes, dtype=float))
        if self.nodes.ndim != 2 or self.nodes.shape[1] not in (2, 3):
            raise ValueError("nodes: an (n, 2) or (n, 3) array of positions")
        self.node_names = [str(x) for x in (node_names if node_names is not None else range(len(self.nodes)))]
        if len(self.node_names) != len(self.nodes):
            raise ValueError("node_names: one name per node")
        _check_finite(self.nodes, "nodes", self.name_for_errors, lambda i: f"node {self.node_names[i]!r}")
        self.bars = self._node_pairs(bars, "bars")
        self.beams = self._node_pairs(beams, "beams")
        self.beam_z = None if beam_z is None else _np.asarray(beam_z, dtype=float).reshape(-1, 3)
        if self.beam_z is not None:
            _check_finite(self.beam_z, "beam_z", self.name_for_errors, lambda i: f"beam {i}")
        self.rigid_bodies = [list(map(int, body)) for body in (rigid_bodies or [])]
        for k, body in enumerate(self.rigid_bodies):
            for i in body:
                self._node_index(i, f"rigid_bodies[{k}]")
        self.supports = dict(supports or {})
        self.independent = dict(independent or {})
        for what, table in (("supports", self.supports), ("independent", self.independent)):
            for key in table:
                self._node(key, what)
        self.released = dict(released or {})
        self.name = name

    @classmethod
    def from_pyrigi(cls, framework, *, supports=None, name=None):
        """A kinestat framework of bars from a PyRigi ``pyrigi.Framework``: one node per vertex,
        in the order of ``framework.graph.vertex_list()``, named ``str(vertex)``; one bar per
        edge; positions are the realization as floats (PyRigi's exact or symbolic coordinates,
        such as ``sqrt(3)/2``, rounded to the nearest double). PyRigi frameworks have no
        supports: ``supports`` (as in the constructor) and ``name`` are kinestat's own.
        Raises ImportError when PyRigi cannot be imported, TypeError for anything but a
        ``pyrigi.Framework``, ValueError for a dimension other than 2 or 3, a coordinate with a
        free symbol, or two vertices with the same ``str``."""
        pyrigi = _import_pyrigi("Framework.from_pyrigi")
        if not isinstance(framework, pyrigi.Framework):
            raise TypeError(f"from_pyrigi: expected a pyrigi.Framework, got {type(framework).__name__}")
        if framework.dim not in (2, 3):
            raise ValueError(f"from_pyrigi: a {framework.dim}-dimensional PyRigi framework: kinestat analyses "
                             "planar (2) and spatial (3) frameworks")
        graph = framework.graph
        vertices = list(graph.vertex_list())
        names = [str(vertex) for vertex in vertices]
        if len(set(names)) != len(names):
            twins = sorted({text for text in names if names.count(text) > 1})
            raise ValueError(f"from_pyrigi: distinct vertices with the same name {twins[0]!r}: node names are str(vertex)")
        realization = framework.realization(as_points=True)
        positions = _np.zeros((len(vertices), framework.dim))
        for i, vertex in enumerate(vertices):
            for j, coordinate in enumerate(realization[vertex]):
                try:
                    positions[i, j] = float(coordinate)
                except (TypeError, ValueError):
                    raise ValueError(f"from_pyrigi: vertex {vertex!r}: coordinate {coordinate} is not a number "
                                     "(a symbolic coordinate needs values for its symbols)") from None
        index = {vertex: i for i, vertex in enumerate(vertices)}
        bars = [[index[u], index[v]] for u, v in graph.edge_list()]
        return cls(positions, bars=_np.array(bars, dtype=int).reshape(-1, 2), supports=supports,
                   node_names=names, name=name)

    def to_pyrigi(self, *, drop_supports=False):
        """This framework as a PyRigi ``pyrigi.Framework``: its graph has a vertex per node and an
        edge per bar, its realization the node positions (integral values as Python ints, so
        PyRigi computes with them exactly; others as floats, on which PyRigi's symbolic methods
        warn and ``numerical=True`` applies). Vertices are the node names, except that nodes named
        "0", "1", ... in order (the default names) become the vertices 0, 1, ... as PyRigi numbers
        them, so that ``Framework.from_pyrigi`` and ``to_pyrigi`` give each other's frameworks back.

        PyRigi frameworks are bars and joints without supports: a framework with supports or
        independent coordinates raises ValueError unless ``drop_supports=True``, which leaves
        them out (the PyRigi framework is then the free one, whose trivial flexes are all the rigid
        motions). Beams, rigid bodies and released deformations have no PyRigi counterpart and
        always raise ValueError. Raises ImportError when PyRigi cannot be imported."""
        pyrigi = _import_pyrigi("Framework.to_pyrigi")
        others = [what for what, present in (("beams", len(self.beams)), ("rigid_bodies", self.rigid_bodies),
                                             ("released", self.released)) if present]
        if others:
            raise ValueError(f"to_pyrigi: PyRigi frameworks are bars and joints: this framework has {others[0]}")
        held = [what for what, table in (("supports", self.supports), ("independent", self.independent)) if table]
        if held and not drop_supports:
            raise ValueError(f"to_pyrigi: PyRigi frameworks have no supports: this framework has {held[0]}; "
                             "to_pyrigi(drop_supports=True) leaves them out")
        seen = {}
        for k, (p, q) in enumerate(self.bars.tolist()):
            pair = (min(p, q), max(p, q))
            if pair in seen:
                raise ValueError(f"to_pyrigi: bars {seen[pair]} and {k} join the same nodes: a PyRigi graph has one edge "
                                 "between two vertices")
            seen[pair] = k
        if self.node_names == [str(i) for i in range(len(self.nodes))]:
            vertices = list(range(len(self.nodes)))
        else:
            vertices = list(self.node_names)
        graph = pyrigi.Graph()
        graph.add_nodes_from(vertices)
        graph.add_edges_from((vertices[p], vertices[q]) for p, q in self.bars.tolist())
        realization = {vertex: row for vertex, row in zip(vertices, _rows(self.nodes, "nodes"))}
        return pyrigi.Framework(graph, realization)

    def _node_index(self, index, where):
        # Node indices as Python counts them from 0, never from the end: -1 is a mistake here.
        count = len(self.nodes)
        if not 0 <= int(index) < count:
            raise ModelIndexError(self.name_for_errors, f"{where}: node index {int(index)} is out of range: "
                                  f"there are {count} nodes, 0 to {count - 1}")
        return int(index)

    def _node_pairs(self, pairs, what):
        if pairs is None:
            return _np.zeros((0, 2), dtype=int)
        pairs = _np.asarray(pairs, dtype=int).reshape(-1, 2)
        outside = _np.flatnonzero(((pairs < 0) | (pairs >= len(self.nodes))).any(axis=1))
        if outside.size:
            k = int(outside[0])
            p, q = pairs[k].tolist()
            bad = p if not 0 <= p < len(self.nodes) else q
            self._node_index(bad, f"{what}[{k}] = [{p}, {q}]")
        return pairs

    def _node(self, key, where="supports"):
        if isinstance(key, (int, _np.integer)):
            return self.node_names[self._node_index(key, where)]
        return str(key)

    @staticmethod
    def _coordinates(value):
        return value if isinstance(value, str) else [str(x) for x in value]

    def _document(self):
        dimension = self.nodes.shape[1]
        document = {"kinestat": 1, "kind": "framework"}
        if self.name is not None:
            document["name"] = self.name
        document["dimension"] = "planar" if dimension == 2 else "spatial"
        # Nodes and bars are what large models are made of: encoded here directly (repr of an
        # int or a float is its JSON text, as json.dumps writes it).
        quoted = [_quote(name) for name in self.node_names]
        document["nodes"] = _Encoded([f"{name}: [{', '.join(map(repr, row))}]"
                                      for name, row in zip(quoted, _rows(self.nodes, "nodes"))], mapping=True)
        if self.supports:
            document["supports"] = {self._node(k): self._coordinates(v) for k, v in self.supports.items()}
        if self.independent:
            document["independent"] = {self._node(k): self._coordinates(v) for k, v in self.independent.items()}
        count = len(self.bars) + len(self.beams) + len(self.rigid_bodies)
        released = {}
        for index, deformations in self.released.items():
            k = int(index) + (count if int(index) < 0 else 0)
            if not 0 <= k < count:
                raise ModelIndexError(self.name_for_errors, f"released: no element {index} (there are {count})")
            released[k] = [str(x) for x in deformations]
        names = self.node_names
        elements = []
        for k, (p, q) in enumerate(self.bars.tolist()):
            if k in released:
                elements.append(_json.dumps({"type": "truss", "nodes": [names[p], names[q]], "released": released[k]}))
            else:
                elements.append(f'{{"type": "truss", "nodes": [{quoted[p]}, {quoted[q]}]}}')
        beam_z = None if self.beam_z is None else _rows(self.beam_z, "beam_z")
        bodies = [{"type": "beam", "nodes": [names[p], names[q]]} for p, q in self.beams.tolist()]
        for index, beam in enumerate(bodies):
            if beam_z is not None:
                beam["orientation"] = {"z": beam_z[index]}
        bodies += [{"type": "rigid_body", "nodes": [self._node(i) for i in body]} for body in self.rigid_bodies]
        for k, element in enumerate(bodies, start=len(elements)):
            if k in released:
                element["released"] = released[k]
            elements.append(_json.dumps(element))
        document["elements"] = _Encoded(elements)
        return document


class Network(_Model):
    """A coupling network (``kind: network``) from numpy arrays.

    types: e coupling type names ("revolute", "spherical", ...); between: (e, 2) body indices
    into ``bodies`` (or names); points, axes, normals: (e, d') arrays, d' = 3 spatial or 2
    planar, a row of NaN where the coupling type has no such key; pitches: e values (NaN where
    unused); bodies: body names (default "1", "2", ...); coupling_names (default "A", "B", ...);
    dimension: "spatial" (or 6) or "planar" (or 3); ground, chords, primary, inputs as in model files."""

    name_for_errors = "<network>"

    def __init__(self, types, between, points=None, axes=None, normals=None, pitches=None, bodies=None,
                 coupling_names=None, dimension="spatial", ground=None, chords=None, primary=None, inputs=None, name=None):
        self.types = [str(t) for t in types]
        e = len(self.types)
        self.between = _np.asarray(between).reshape(e, 2)
        if bodies is None:
            count = int(_np.max(self.between)) + 1 if e and _np.issubdtype(self.between.dtype, _np.integer) else 0
            bodies = [str(i + 1) for i in range(count)]
        self.bodies = [str(b) for b in bodies]
        self.coupling_names = [str(c) for c in coupling_names] if coupling_names is not None else \
            [_letters(i) for i in range(e)]
        self.geometry = {}
        for key, array in (("point", points), ("axis", axes), ("normal", normals)):
            if array is not None:
                self.geometry[key] = _np.asarray(array, dtype=float).reshape(e, -1)
        self.pitches = None if pitches is None else _np.asarray(pitches, dtype=float).reshape(e)
        self.dimension, self.ground, self.name = dimension, ground, name
        self.chords, self.primary, self.inputs = chords, primary, inputs

    def _body(self, key, where="ground"):
        if isinstance(key, (int, _np.integer)):
            if not 0 <= int(key) < len(self.bodies):
                raise ModelIndexError(self.name_for_errors, f"{where}: body index {int(key)} is out of range: there are "
                                      f"{len(self.bodies)} bodies, 0 to {len(self.bodies) - 1}")
            return self.bodies[int(key)]
        return str(key)

    def _document(self):
        document = {"kinestat": 1, "kind": "network"}
        if self.name is not None:
            document["name"] = self.name
        document["dimension"] = "planar" if self.dimension in (3, "planar") else "spatial"
        if self.ground is not None:
            document["ground"] = self._body(self.ground)
        if self.bodies:
            document["bodies"] = list(self.bodies)
        # Each coupling written straight to its line, as the framework's nodes and bars: a row of
        # NaN leaves its key out, any other row must be finite.
        e = len(self.types)
        between = [_quote(self._body(b, f"between[{i // 2}] (coupling {self.coupling_names[i // 2]!r})"))
                   for i, b in enumerate(self.between.ravel().tolist())]
        columns = []
        arrays = list(self.geometry.items())
        if self.pitches is not None:
            arrays.append(("pitch", self.pitches.reshape(e, 1)))
        for key, array in arrays:
            texts = [None] * e
            present = _np.flatnonzero(~_np.isnan(array).all(axis=1))
            for i, row in zip(present.tolist(), _rows(array[present], key)):
                texts[i] = f'"{key}": {repr(row[0]) if key == "pitch" else "[" + ", ".join(map(repr, row)) + "]"}'
            columns.append(texts)
        couplings = []
        for i, coupling_type in enumerate(self.types):
            parts = [f'"name": {_quote(self.coupling_names[i])}', f'"type": {_quote(coupling_type)}',
                     f'"between": [{between[2 * i]}, {between[2 * i + 1]}]']
            parts += [texts[i] for texts in columns if texts[i] is not None]
            couplings.append("{" + ", ".join(parts) + "}")
        document["couplings"] = _Encoded(couplings)
        for key in ("chords", "primary", "inputs"):
            value = getattr(self, key)
            if value:
                document[key] = [str(x) for x in value]
        return document


def _letters(index):
    # Coupling names as in the seed's figures: A, B, ..., Z, AA, AB, ...
    name = ""
    index += 1
    while index:
        index, remainder = divmod(index - 1, 26)
        name = chr(ord("A") + remainder) + name
    return name
