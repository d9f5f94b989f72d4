# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""The filter's properties, in one table: the home of every property.

Each row is one property of vtkNarrowVolumeReconstruction: its name (Set/Get
name, the field of the core's nv::Settings, the ParaView property, the
keyword of reconstruct()), the label of the ParaView panel, its type, its
default, the range its setter clamps to, the named values of an enumerated
property, the panel's group, whether the panel shows it only in advanced
mode, and what it means.

Everything else is made from this table (cmake/generate-properties.py, run
when CMake configures, writes the generated files into the build; the core's
header is committed, and the PropertyTable test checks it):

- the core's nv::Settings: its fields and their defaults
  (Filters/Core/Run/nvSettingsTable.h, read by nvSettings.h), which the VTK
  filter holds (its Set/Get are defined over the fields, clamped to the
  table's ranges) and the binding binds (Python/nvBindings.cxx), field by
  field through one macro;
- the ParaView server-manager XML of the filter (_servermanager.py makes
  the whole proxy, for the compiled plugin and for the Python plugin);
- the parameter reference (Markdown: the site's doc/reference/parameters.md),
  and the summary table of the parameters in doc/how-to/choose-parameters.md,
  which the ctest PropertyTable checks;
- at run time: the wheel's Python filter (its Set/Get methods and their
  docstrings, _filter.py), reconstruct()'s keywords and the command line's
  options (_cli.py).

Adding a property: a row here, the core code that uses it, and its line
(vtkNarrowVolumeSettingMacro and the like) in Filters/vtkNarrowVolumeReconstruction.h,
as VTK's wrapping needs real declarations; then rewrite the summary table
with `python3 cmake/generate-properties.py --readme doc/how-to/choose-parameters.md`. The tests
check the table against the wrapped C++ class (PythonApi: names, defaults,
clamping) and the wheel's filter against the C++ filter (PipVtkOldest,
PipVtkNewest).

In `doc`, {OtherProperty} names another property: each place writes it in
its own words (the panel's label in ParaView, the option on the command
line, the property's name in Python).
"""
from __future__ import annotations

from collections import namedtuple
import re
from typing import Any, Callable, Dict

Property = namedtuple("Property", "name label kind default low high choices enum group advanced widget doc valid",
                      defaults=(None,))
Property.__doc__ = """One property of the filter.

name: the Set/Get name (SetOffsetDistance), the field of nv::Settings and
    the ParaView property's name.
label: the ParaView panel's label.
kind: float, int or bool (bool also has <name>On() and <name>Off()).
default: the default value (for an enumerated property, one of its values).
low, high: the range the setter clamps to (vtkSetClampMacro), or None.
choices: for an enumerated property, its Choice values, in the panel's order.
enum: for an enumerated property, the core's C++ enum (nv::<enum>) its field has.
group: the panel's group of properties.
advanced: whether the panel shows it only in advanced mode (the gear).
widget: None, or how the panel edits it beyond its type: ("bounds", f), a
    slider from 0 to f times the input's longest side (ParaView's
    BoundsDomain, scaled_extent), whose reset button gives 0, the default; ("slider", low, high), a slider over that range (any value can
    still be typed).
doc: what it means, its unit and its default, with {OtherProperty} for the
    names of other properties.
valid: (low, high), the values a run accepts, where the setter does not
    clamp: the run refuses others with an error that gives the range
    (nv::MakePlan, from NV_SETTINGS_VALID); None: no such range."""

Choice = namedtuple("Choice", "constant suffix value label")
Choice.__doc__ = """One value of an enumerated property: the class constant
(NARROW_BAND), the setter's suffix (SetDomainToNarrowBand), the value, and
the panel's text for it."""

# Rows in the panel's order.
PROPERTIES = (
    # --- Offset distance
    Property(
        "OffsetDistance", "Offset Distance", float, 0.0, None, None, (), None, "Offset Distance", False,
        ("bounds", 0.25),
        "Half-thickness l of the shell in world units: both phi = 0 sheets lie at this distance from the "
        "points. 0 (the default) chooses it from the cloud: l = max(1.5 m, q), m the median and q the 99.9th "
        "percentile of the distances from each point to its nearest neighbour, so that the shell closes where "
        "the sampling allows and keeps detail near its scale. The value used is in the Volume output's field "
        "data \"OffsetDistance\"."),
    Property(
        "CloseGaps", "Close Gaps", bool, True, None, None, (), None, "Offset Distance", False, None,
        "Bridge the holes of the sampling (on by default). A hole is an empty disc on the sampled surface "
        "wider than the offset distance (as a radius): the shell's wall is pierced there, and one such tunnel "
        "joins its outer and inner sheets, so a closed scan gives no cavity. Holes up to {ClosingRadius} are "
        "filled with points before the distance is computed, so that the wall over them stays at least 0.66 "
        "of the offset thick on each side; wider openings (a scan's border, the mouth of a cup, an open base) "
        "are left open. After the evolution each hole left open is probed, and a warning names those that "
        "pierce the shell's wall. Concavities and thin parts are not filled. Off: the points "
        "as given (the paper's method). Field data \"AddedPoints\" counts the points added; \"NumberOfGaps\", "
        "\"LargestGap\" (a radius) and \"LargestGapCenter\" describe the holes left open, \"PiercedGaps\" "
        "counts those that pierce the shell."),
    Property(
        "ClosingRadius", "Closing Radius", float, 0.0, None, None, (), None, "Offset Distance", True, None,
        "The widest hole {CloseGaps} bridges, as the radius of its empty disc, in world units. 0 (the "
        "default): 3 times the offset distance. Raise it to bridge a wider hole that the warning names (if it "
        "is a hole, not an opening of the surface). Field data \"ClosingRadius\" shows the value used (0 with "
        "{CloseGaps} off)."),
    # --- Grid
    Property(
        "SampleSpacing", "Sample Spacing", float, 0.0, None, None, (), None, "Grid", True, None,
        "Grid spacing h in world units. 0 (the default) takes h from {MaximumDimension}, or when that is 0 "
        "too, h = l / 4 (the paper's ratio) with at most 320 cells along the longest side of the padded box "
        "(then an automatic l is at least 4 h). Finer spacing gives more detail and costs time and memory as "
        "1/h^2 to 1/h^3. The value used is in field data \"SampleSpacing\"."),
    Property(
        "MaximumDimension", "Maximum Dimension", int, 0, 0, 100000, (), None, "Grid", True, None,
        "Number of grid cells along the longest side of the padded box, used when {SampleSpacing} is 0 (at "
        "least 16). 0 (the default): the spacing follows the offset, h = l / 4."),
    # --- Phase field
    Property(
        "XiCells", "Xi Cells", float, 2.0, None, None, (), None, "Phase field", True, None,
        "Width m of the initial profile, xi = eps_m (eq. 2), in cells; the band is 2 m cells wide. From 1 to "
        "64 (other values are refused when the filter runs). Small values leave holes where the points are "
        "sparse; large ones close thin gaps. Default 2 (the paper's).", (1.0, 64.0)),
    Property(
        "EpsilonCells", "Epsilon Cells", float, 6.0, None, None, (), None, "Phase field", True, None,
        "Interface width m of the Allen-Cahn evolution, eps = eps_m (eq. 1, 12), in cells. From 0.5 to 256 "
        "(other values are refused when the filter runs). Larger values smooth the wrinkles of sparse or "
        "noisy points more. Default 6 (the paper's).", (0.5, 256.0)),
    Property(
        "EdgeStoppingFunction", "Edge Stopping Function", int, 4, 3, 4,
        (Choice("EQUATION_4", "Equation4", 4, "Eq. (4): (1-|phi0|)|phi0|"),
         Choice("EQUATION_3", "Equation3", 3, "Eq. (3): 1-phi0^2")),
        "EdgeStopping", "Phase field", True, None,
        "The edge-stopping function g that confines the evolution to the band: EQUATION_4 (4, the default), "
        "g = (1 - |phi0|) |phi0|, the paper's; or EQUATION_3 (3), g = 1 - phi0^2, the earlier paper's."),
    # --- Solver
    Property(
        "Domain", "Domain", int, 0, 0, 1,
        (Choice("NARROW_BAND", "NarrowBand", 0, "Narrow Band"),
         Choice("WHOLE_DOMAIN", "WholeDomain", 1, "Whole Domain")),
        "Domain", "Solver", True, None,
        "Where the scheme runs: NARROW_BAND (0, the default) updates only the band around the shell's "
        "boundary; WHOLE_DOMAIN (1) updates every grid node, for comparison (slower, more memory)."),
    Property(
        "MaximumNumberOfIterations", "Maximum Number Of Iterations", int, 3, 0, 100000, (), None, "Solver",
        False, ("slider", 0, 20),
        "Largest number of time steps. Each step smooths the sheets a little more, and moves them inward a "
        "little on curved parts (motion by mean curvature): the default 3 keeps the paper's Table 1 accuracy. "
        "See {ConvergenceTolerance} and {PreserveOffset}."),
    Property(
        "PreserveOffset", "Preserve Offset", bool, False, None, None, (), None, "Solver", False, None,
        "Keep the sheets at the offset distance while more steps smooth them: after each step, the local mean "
        "translation of the sheets (their drift by mean-curvature motion, which shrinks curved parts) is "
        "cancelled, while wrinkles and noise are still smoothed. With it, 10 to 20 steps keep the Table 1 "
        "accuracy. Off (the default): exactly the paper's scheme. Costs about a third of a step more."),
    Property(
        "ConvergenceTolerance", "Convergence Tolerance", float, 0.0, 0.0, 1.0, (), None, "Solver", True, None,
        "Stop when the relative change ||phi^{n+1} - phi^n||_2 / ||phi^n||_2 drops below this value (the "
        "paper's rule uses 1e-5). 0 (the default) runs exactly {MaximumNumberOfIterations} steps."),
    Property(
        "TimeStep", "Time Step", float, 0.0, None, None, (), None, "Solver", True, None,
        "Time step dt. 0 (the default): dt = eps^2 (the paper's)."),
    Property(
        "GaussSeidelTolerance", "Gauss-Seidel Tolerance", float, 1e-06, 1e-14, 1.0, (), None, "Solver", True,
        None,
        "Tolerance of the Gauss-Seidel iteration of the implicit step (10): its red-black sweeps stop when no "
        "node changes by this much or more. Default 1e-6 (the paper's)."),
    # --- Threads and memory
    Property(
        "NumberOfThreads", "Number Of Threads", int, 0, 0, 1024, (), None, "Threads and Memory", True, None,
        "Threads for the parallel loops; 0 (the default) uses all cores. phi is the same for any number."),
    Property(
        "MemoryLimit", "Memory Limit", float, 0.0, 0.0, 1e12, (), None, "Threads and Memory", True, None,
        "Largest memory one run may allocate, in MiB; a grid that needs more is refused with a message before "
        "any large allocation. 0 (the default): half of the machine's physical memory."),
    Property(
        "Device", "Device", int, 0, 0, 2,
        (Choice("DEVICE_AUTOMATIC", "Automatic", 0, "Automatic"),
         Choice("DEVICE_CPU", "CPU", 1, "CPU"),
         Choice("DEVICE_GPU", "GPU", 2, "GPU")),
        "ComputeDevice", "Threads and Memory", True, None,
        "Where the truncated distance, the evolution (phi0, g and the time steps), the surface and the "
        "dense volume run: DEVICE_AUTOMATIC "
        "(0, the default), for now the CPU; DEVICE_CPU (1), the CPU's threads; DEVICE_GPU (2), an NVIDIA GPU "
        "through CUDA, with the CPU's distances and the same scheme and stopping rule (the sheets within 0.05 "
        "of a cell of the CPU's). The GPU needs a build "
        "with CUDA and a CUDA device, one process, and {PreserveOffset} off. DEVICE_GPU never falls back to "
        "the CPU: where one of these is missing, or the GPU fails during the run, the run stops with an "
        "error that says which and to choose DEVICE_CPU or DEVICE_AUTOMATIC. Automatic stays on the CPU until the "
        "GPU back end has passed its tests on a GPU (where it stands: the documentation's performance page). Field data \"DeviceUsed\" holds the device that ran: "
        "1 (CPU) or 2 (GPU)."),
    # --- Output
    Property(
        "Sheets", "Sheets", int, 0, 0, 3,
        (Choice("BOTH_SHEETS", "Both", 0, "Both"),
         Choice("OUTER_SHEET", "Outer", 1, "Outer"),
         Choice("INNER_SHEETS", "Inner", 2, "Inner"),
         Choice("SCAN_SURFACE", "Scan", 3, "Scan")),
        "Sheets", "Output", False, None,
        "Which surface the Surface output holds: BOTH_SHEETS (0, the default), the phi = 0 sheets; "
        "OUTER_SHEET (1), the one facing the outside (for a closed input, its dilation by the offset "
        "distance); INNER_SHEETS (2), those facing cavities enclosed by the shell (its erosion); or "
        "SCAN_SURFACE (3), no sheet but one surface on the scan, through the middle of the points (where "
        "noise thickens the shell, not on its outer envelope), made from the shell without normals: closed "
        "around a closed scan, open on an open one (its boundary at the scan's rim). An open scan has only "
        "an outer sheet. Field data \"ScanSurface\" says what was made (1 closed, 2 open, 3 both), "
        "\"ScanDistanceMean\" and \"ScanDistance95\" how far the points lie from it (mean and 95th "
        "percentile, in cells). "
        "phi is the same; all but BOTH_SHEETS need the dense grid even when {OutputVolume} is off. With "
        "{WallThickness} above 0 the output is the part to print, whatever Sheets says (a warning says so)."),
    Property(
        "RemoveSmallPieces", "Remove Small Pieces", bool, True, None, None, (), None, "Output", False, None,
        "Remove loose pieces smaller than a ball of radius 2 l (the balls around lone points) and voids "
        "inside the wall smaller than a ball of radius l (on by default). Field data \"RemovedPieces\" and "
        "\"RemovedVoids\" count them. Not applied in a distributed (MPI) run."),
    Property(
        "OutputVolume", "Output Volume", bool, True, None, None, (), None, "Output", False, None,
        "Produce the phase field phi on the grid, the Volume output (on by default). Off: the Volume output "
        "keeps only the grid's geometry and the surface is extracted slab by slab, so memory follows the band "
        "instead of the whole box: use it for very fine grids. The extra arrays below need it."),
    Property(
        "OutputInitialPhi", "Output Initial Phi", bool, False, None, None, (), None, "Output", True, None,
        "Add the initial profile phi0 (eq. 2) to the Volume output as the point array \"InitialPhi\"."),
    Property(
        "OutputDistance", "Output Distance", bool, False, None, None, (), None, "Output", True, None,
        "Add the truncated distance to the points (eq. 6) to the Volume output as the point array "
        "\"Distance\"."),
    Property(
        "OutputNarrowBand", "Output Narrow Band", bool, False, None, None, (), None, "Output", True, None,
        "Add the point array \"NarrowBand\" (1 on the nodes the scheme updates) to the Volume output."),
    # --- Printing
    Property(
        "WallThickness", "Wall Thickness", float, 0.0, None, None, (), None, "Printing", False, ("bounds", 0.05),
        "Make a part to print instead of the shell: above 0, the Surface output is a hollow solid whose outer "
        "surface is the cloud's closing (the solid the shell's outer sheet encloses, eroded back by the "
        "offset distance: it lies on the scan where the surface is smooth on the scale of the offset, and "
        "spans concavities narrower than it and bridged holes) and whose inner surface lies this far inside "
        "it, in world units: a wall of this thickness. Normals point out of the material (outward on the "
        "outer surface, into the cavity on the inner). Where the model is thinner than twice the wall, the "
        "part is solid there. With {SampleSpacing} 0 the grid follows the wall (three cells across it at "
        "least), within {MemoryLimit}; scale the model to its print size first. The part is checked against "
        "the scan: material is put back around points it lost (a limb thinner than the closing holds) and a "
        "warning says where. 0 (the default): the shell. Field data \"MaterialVolume\", \"CavityVolume\", "
        "\"MinimumWallThickness\" (measured between the two surfaces, at \"ThinnestWallAt\"), "
        "\"KeptCavities\", \"RemovedCavities\", \"PartPieces\", \"PartBounds\", \"RestoredPoints\" and "
        "\"LostPoints\" describe the part. Needs the whole grid on one process."),
    Property(
        "MinimumCavityVolume", "Minimum Cavity Volume", float, 0.0, None, None, (), None, "Printing", True, None,
        "With {WallThickness} above 0: cavities of the part smaller than this volume (world units cubed) are "
        "merged into the wall, so that no small sealed pocket traps resin or powder. 0 (the default): those "
        "smaller than 1 % of the largest cavity. The value used is in field data \"MinimumCavityVolume\"."),
    Property(
        "CavityClosingDistance", "Cavity Closing Distance", float, 0.0, None, None, (), None, "Printing", True, None,
        "With {WallThickness} above 0: the cavity is first made this much deeper, then grown back by as much "
        "(world units), so that its inside corners and creases are rounded with this radius, where resin "
        "would pool, and cavities narrower than twice this vanish into the wall (a slicer's hollowing "
        "closing distance; 2 mm is PrusaSlicer's default). 0 (the default): the cavity is the exact inward "
        "offset of the outer surface, sharp creases and all."),
    Property(
        "NumberOfDrainHoles", "Number Of Drain Holes", int, 0, 0, 64, (), None, "Printing", False, None,
        "With {WallThickness} above 0: drill this many holes through the wall from each cavity, at its lowest "
        "points along {DrainHoleAxis} (at least three diameters apart), so that resin or powder drains out. "
        "The holes are made on the field, so the surface stays closed and manifold. 0 (the default): none. "
        "Points given as the filter's DrainHoles input (the second input; drain_holes in Python, "
        "--drain-hole on the command line) place the holes instead: one from the cavity's point nearest to "
        "each. Field data \"DrainHoles\" counts those made."),
    Property(
        "DrainHoleAxis", "Drain Hole Axis", int, 4, 0, 5,
        (Choice("DRAIN_MINUS_X", "MinusX", 0, "-X"),
         Choice("DRAIN_PLUS_X", "PlusX", 1, "+X"),
         Choice("DRAIN_MINUS_Y", "MinusY", 2, "-Y"),
         Choice("DRAIN_PLUS_Y", "PlusY", 3, "+Y"),
         Choice("DRAIN_MINUS_Z", "MinusZ", 4, "-Z"),
         Choice("DRAIN_PLUS_Z", "PlusZ", 5, "+Z")),
        "DrainAxis", "Printing", True, None,
        "The way down for the drain holes: each cavity's holes start at its lowest points along this "
        "direction and run along it out through the wall. DRAIN_MINUS_Z (4, the default): down is -z, as a "
        "part stands on its base; DRAIN_PLUS_Z (5) for a part that hangs from a resin printer's build plate; "
        "DRAIN_MINUS_X (0), DRAIN_PLUS_X (1), DRAIN_MINUS_Y (2) and DRAIN_PLUS_Y (3) for a cloud whose up "
        "is another axis."),
    Property(
        "DrainHoleAngle", "Drain Hole Angle", float, 30.0, 0.0, 90.0, (), None, "Printing", True, None,
        "The most, in degrees, a drain hole may lean from {DrainHoleAxis}: each hole leaves its cavity by the "
        "shortest way out through the wall within this angle, and is not made where that way runs longer than "
        "twice the offset and the wall (down the inside of a limb); a warning says so. 30 (the default); 0: "
        "straight along {DrainHoleAxis}."),
    Property(
        "DrainHoleDiameter", "Drain Hole Diameter", float, 0.0, None, None, (), None, "Printing", True, None,
        "The drain holes' diameter in world units. 0 (the default): twice {WallThickness}, at least four grid "
        "cells."),
)

BY_NAME = {p.name: p for p in PROPERTIES}

ListProperty = namedtuple("ListProperty", "name label after advanced doc")
ListProperty.__doc__ = """A property that holds a list of points (x y z after
one another, world units), not one value: a field std::vector<double> of
nv::Settings beside the table's (nvSettings.h); on the VTK filter
SetNumberOf<Name>(n), Set<Name-s>(i, x, y, z), Add<Name-s>(x, y, z),
RemoveAll<Name>(), GetNumberOf<Name>() and Get<Name-s>(i) (the name less
its plural s), as vtkContourFilter's values; in ParaView a list the panel
edits as rows of x y z; reconstruct()'s keyword takes an (n, 3) array; the
command line's option takes x y z, repeated. Empty by default.

after: the property the panel shows it after (its group's)."""

# The list properties, each shown after the table's row it names.
LIST_PROPERTIES = (
    ListProperty(
        "DrainHolePositions", "Drain Hole Positions", "NumberOfDrainHoles", False,
        "With {WallThickness} above 0: where the drain holes go, as points (x y z in world units, such as "
        "points of the scan where a hole may show): one hole from the point of a kept cavity nearest to each, "
        "by the shortest way out through the wall within {DrainHoleAngle} of {DrainHoleAxis}. A position "
        "farther than twice the offset and the wall from every cavity makes no hole, and a warning says "
        "which. Empty (the default): {NumberOfDrainHoles} holes at each cavity's lowest points."),
)

# Every property by name: the table's rows and the list properties.
NAMED = dict(BY_NAME, **{p.name: p for p in LIST_PROPERTIES})


def singular(name: str) -> str:
    """DrainHolePositions -> DrainHolePosition: the name of one of a list's points."""
    return name[:-1] if name.endswith("s") else name

# The panel's group titles that say more than the group's name, where 0
# does not mean "automatic" (Wall Thickness 0 is the shell, no part).
GROUP_TITLES = {"Printing": "Printing (a part when Wall Thickness > 0)"}

# The properties whose 0 means "chosen by the filter": the panel's other
# groups that hold one say "(0 = automatic)" in their title.
AUTOMATIC_WHEN_ZERO = frozenset(("OffsetDistance", "ClosingRadius", "SampleSpacing", "MaximumDimension",
                                 "NumberOfThreads", "MemoryLimit", "MinimumCavityVolume", "DrainHoleDiameter"))

Result = namedtuple("Result", "name label kind size beside panel doc")
Result.__doc__ = """A value the last run chose, which the ParaView panel shows
read-only (an information property) beside the property it resolves.

name: the Get name (GetOffsetDistanceUsed), of the VTK filter and the
    wheel's filter alike, and the ParaView property's name.
label: the panel's label. kind: float, int or str. size: number of values.
beside: the property it follows on the panel (and in its group).
panel: "default" (the panel shows it), "advanced" (only in advanced mode)
    or "hidden": a property for scripts (pvpython's shell.<name>) that the
    panel shows in another form. Hidden by the proxy's hint
    <Property name=... show="0"/>, not panel_visibility="never", which
    would also take it from pvpython's attributes.
doc: what it is, with {OtherProperty} for the names of other properties.

A row here and the line of ResultsOf (Filters/Core/Run/nvReconstruct.cxx) that
computes it are all a new result needs: the header's NV_RESULTS (rewrite it
with --header, as for a property) gives nv::Results its field, the VTK
filter and the binding their Get method and field, and _filter.py and the
stub make theirs from this table."""

# What the last run chose, in the panel's order.
RESULTS = (
    Result("OffsetDistanceUsed", "Offset Distance Used", float, 1, "OffsetDistance", "default",
           "The offset distance of the last Apply: the one set, or the automatic one when {OffsetDistance} "
           "is 0. Read-only."),
    Result("ClosingRadiusUsed", "Closing Radius Used", float, 1, "ClosingRadius", "advanced",
           "The closing radius of the last Apply: the one set, or 3 times the offset distance when "
           "{ClosingRadius} is 0; 0 with {CloseGaps} off. Read-only."),
    Result("SampleSpacingUsed", "Sample Spacing Used", float, 1, "SampleSpacing", "default",
           "The grid spacing of the last Apply: the one set, or the automatic one when {SampleSpacing} is 0. "
           "Read-only."),
    # The panel shows the grid as one text (three fields of their own do
    # not fit the panel's default width); scripts read the three integers.
    Result("GridUsed", "Grid Used", str, 1, "MaximumDimension", "default",
           "Grid nodes along x, y and z in the last Apply, as one text: \"221 x 260 x 200\" (empty before "
           "the first). Read-only."),
    Result("GridDimensionsUsed", "Grid Dimensions Used", int, 3, "MaximumDimension", "hidden",
           "Grid nodes along x, y and z in the last Apply: three integers, for scripts (the panel shows them "
           "as Grid Used). Read-only."),
    Result("PartSizeUsed", "Part Size Used", str, 1, "WallThickness", "default",
           "The size along x, y and z of the part to print of the last Apply, beside the cloud's, as one "
           "text: \"0.836 x 0.996 x 0.749 (the cloud 0.838 x 0.998 x 0.753)\"; empty when {WallThickness} "
           "is 0. Read-only."),
)


def snake_case(name: str) -> str:
    """OffsetDistance -> offset_distance (the keyword reconstruct() also accepts); an acronym is one
    word: CPU -> cpu."""
    return re.sub(r"(?<=[a-z0-9])(?=[A-Z])|(?<=[A-Z])(?=[A-Z][a-z])", "_", name).lower()


def option(name: str) -> str:
    """OffsetDistance -> --offset-distance (the command line's option)."""
    return "--" + snake_case(name).replace("_", "-")


_BY_SNAKE = {snake_case(p.name): p for p in PROPERTIES + LIST_PROPERTIES}


def find(keyword: str) -> Any:
    """The property (a Property or a ListProperty) named by a keyword: its
    Set/Get name or its snake_case form. KeyError otherwise."""
    if keyword in NAMED:
        return NAMED[keyword]
    return _BY_SNAKE[keyword]


def describe(prop: Property, name_of: Callable[[str], str] = lambda name: name) -> str:
    """The property's documentation with the names of other properties as
    name_of(name) gives them: BY_NAME[name].label in the panel, option(name)
    on the command line, the name itself in Python (the default)."""
    return re.sub(r"\{([A-Za-z]+)\}", lambda m: name_of(m.group(1)) if m.group(1) in NAMED else m.group(0),
                  prop.doc)


def in_words(text: str, name_of: Callable[[str], str]) -> str:
    """A message of the filter, which names properties by their names
    (OffsetDistance), with each name as name_of(name) gives it: the panel's
    label, the command line's option. Whole names only: no ASCII letter,
    digit or underscore on either side, the core's rule (nv::InPanelWords;
    the WordRules test feeds both the same texts)."""
    for prop in PROPERTIES + LIST_PROPERTIES:
        words = name_of(prop.name)
        text = re.sub(r"(?<![A-Za-z0-9_])%s(?![A-Za-z0-9_])" % prop.name, lambda _: words, text)
    return text


def results_beside(name: str) -> tuple:
    """The results the panel shows right after property `name`."""
    return tuple(r for r in RESULTS if r.beside == name)


def defaults_of(filter_object: Any) -> Dict[str, Any]:
    """{name: value} of a filter's properties, read through its Get methods."""
    return {p.name: getattr(filter_object, "Get" + p.name)() for p in PROPERTIES}
