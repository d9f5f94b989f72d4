# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""The filter's properties, in one table.

Each row is one property of vtkNarrowVolumeReconstruction: its Set/Get name,
the field of the core's nv::Settings it fills, its type, the range its setter
clamps to (vtkSetClampMacro in the C++ header), the named values of an
enumerated property, and what it means. From this table:

- the Python filter of the wheel (_filter.py) makes its Set/Get methods,
  with the defaults of a default-constructed nv::Settings
  (narrowvolume._core.Settings(): the C++ defaults, not a copy of them);
- reconstruct() takes the names as keyword arguments;
- the command line makes one option per row.

Adding a property to the core (a field of nv::Settings, bound in
nvBindings.cxx) and to the C++ filter is one more row here. The tests
check the table against the C++ class (test_python_api.py: PythonApi reads
the wrapped class; PipVtkOldest and PipVtkNewest compare the wheel's filter
with the C++ filter's record): the same names, defaults and clamping.
"""
from collections import namedtuple
import re

Property = namedtuple("Property", "name field kind low high choices doc")
Property.__doc__ = """One property of the filter.

name: the Set/Get name (SetOffsetDistance, GetOffsetDistance).
field: the field of nv::Settings (narrowvolume._core.Settings) it fills.
kind: float, int or bool (bool also has <name>On() and <name>Off()).
low, high: the range the setter clamps to, or None.
choices: for an enumerated property, (CONSTANT, Suffix, value) triples: the
    class constant and the setter Set<name>To<Suffix>().
doc: what it means, its unit and default."""

# Rows in the order of the C++ header.
PROPERTIES = (
    Property("OffsetDistance", "OffsetDistance", float, None, None, (),
             "Offset distance l in world units: the half-thickness of the shell, the distance of both "
             "phi = 0 sheets from the points. 0 chooses it from the cloud: l = max(1.5 m, q), m the median "
             "and q the 99.9th percentile of the distances from each point to its nearest neighbour."),
    Property("CloseGaps", "CloseGaps", bool, None, None, (),
             "Bridge the holes of the sampling: empty discs on the sampled surface wider than l (radius), "
             "where the wall is pierced, are filled with points before the distance is computed, up to "
             "ClosingRadius; wider openings (a scan's border, a cup's mouth) are left open and reported. "
             "Off: the points as given (the paper's method)."),
    Property("ClosingRadius", "ClosingRadius", float, None, None, (),
             "The widest hole CloseGaps bridges, as the radius of its empty disc, in world units; 0 "
             "chooses 3 l."),
    Property("SampleSpacing", "SampleSpacing", float, None, None, (),
             "Grid spacing h in world units. When <= 0, h comes from MaximumDimension, or, when that is 0 "
             "too, h = l / 4 (the paper's ratio) with at most 320 cells along the padded box's longest side."),
    Property("MaximumDimension", "MaximumDimension", int, 0, 100000, (),
             "Number of cells along the longest side of the padded box when SampleSpacing <= 0 (at least "
             "16); 0: h follows l, see SampleSpacing."),
    Property("XiCells", "XiCells", float, None, None, (),
             "xi = eps_m with m = XiCells (eq. 2): the width of the initial profile and of the band, "
             "2 m cells. Larger values close small holes and thin gaps. Range [1, 64], checked when the "
             "filter runs."),
    Property("EpsilonCells", "EpsilonCells", float, None, None, (),
             "eps = eps_m with m = EpsilonCells (eq. 1, 12): the interface width of the Allen-Cahn "
             "evolution. Larger values smooth more. Range [0.5, 256], checked when the filter runs."),
    Property("TimeStep", "TimeStep", float, None, None, (),
             "Time step dt. When <= 0, dt = eps^2 (the paper's)."),
    Property("MaximumNumberOfIterations", "MaximumNumberOfIterations", int, 0, 100000, (),
             "Largest number of time steps (see ConvergenceTolerance)."),
    Property("ConvergenceTolerance", "ConvergenceTolerance", float, 0.0, 1.0, (),
             "Stop when ||phi^{n+1} - phi^n||_2 / ||phi^n||_2 drops below this value (the paper's rule "
             "with 1e-5); 0 runs exactly MaximumNumberOfIterations steps."),
    Property("GaussSeidelTolerance", "GaussSeidelTolerance", float, 1e-14, 1.0, (),
             "Tolerance of the Gauss-Seidel iteration of the implicit step (10): sweeps stop when no "
             "node changes by this much or more."),
    Property("Domain", "Mode", int, 0, 1, (("NARROW_BAND", "NarrowBand", 0), ("WHOLE_DOMAIN", "WholeDomain", 1)),
             "Where the scheme runs: NARROW_BAND (0), on band nodes only; or WHOLE_DOMAIN (1), on every "
             "node of the grid, for comparison."),
    Property("EdgeStoppingFunction", "EdgeFunction", int, 3, 4,
             (("EQUATION_3", "Equation3", 3), ("EQUATION_4", "Equation4", 4)),
             "Edge-stopping function g: EQUATION_4 (4), (1 - |phi0|) |phi0|; or EQUATION_3 (3), "
             "1 - phi0^2."),
    Property("PreserveOffset", "PreserveOffset", bool, None, None, (),
             "Keep the sheets at the offset distance while they are smoothed: after each step the local "
             "mean translation of the sheets (mean-curvature drift) is cancelled. Off: the paper's scheme."),
    Property("Sheets", "KeptSheets", int, 0, 2,
             (("BOTH_SHEETS", "Both", 0), ("OUTER_SHEET", "Outer", 1), ("INNER_SHEETS", "Inner", 2)),
             "Which phi = 0 sheets the surface output holds: BOTH_SHEETS (0); OUTER_SHEET (1), the one "
             "facing the outside (for a closed input, its dilation by OffsetDistance); or INNER_SHEETS "
             "(2), those facing cavities enclosed by the shell (its erosion). phi is the same."),
    Property("OutputVolume", "OutputVolume", bool, None, None, (),
             "Whether output port 0 carries the phase field on the grid. Off: the volume keeps only its "
             "geometry, and memory follows the band."),
    Property("RemoveSmallPieces", "RemoveSmallPieces", bool, None, None, (),
             "Remove loose pieces smaller than a ball of radius 2 l and voids inside the wall smaller than "
             "a ball of radius l; field data RemovedPieces and RemovedVoids count them."),
    Property("OutputInitialPhi", "OutputInitialPhi", bool, None, None, (),
             "Adds the point array \"InitialPhi\" (phi0 of eq. 2) to output port 0."),
    Property("OutputDistance", "OutputDistance", bool, None, None, (),
             "Adds the point array \"Distance\" (the truncated distance of eq. 6) to output port 0."),
    Property("OutputNarrowBand", "OutputNarrowBand", bool, None, None, (),
             "Adds the point array \"NarrowBand\" (1 on band nodes) to output port 0."),
    Property("NumberOfThreads", "NumberOfThreads", int, 0, 1024, (),
             "Threads for the parallel loops; 0 uses all cores. phi is the same for any number."),
    Property("MemoryLimit", "MemoryLimit", float, 0.0, 1e12, (),
             "Largest memory, in MiB, one run may allocate; a grid that needs more is refused before "
             "any large allocation. 0 means half of the machine's physical memory."),
)

BY_NAME = {p.name: p for p in PROPERTIES}


def snake_case(name):
    """OffsetDistance -> offset_distance (the keyword reconstruct() also accepts)."""
    return re.sub(r"(?<!^)(?=[A-Z])", "_", name).lower()


_BY_SNAKE = {snake_case(p.name): p for p in PROPERTIES}


def find(keyword):
    """The property named by a keyword: its Set/Get name or its snake_case form. KeyError otherwise."""
    if keyword in BY_NAME:
        return BY_NAME[keyword]
    return _BY_SNAKE[keyword]


def defaults_of(filter_object):
    """{name: value} of a filter's properties, read through its Get methods."""
    return {p.name: getattr(filter_object, "Get" + p.name)() for p in PROPERTIES}
