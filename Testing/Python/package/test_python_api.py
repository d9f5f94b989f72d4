# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""The Python API of the package narrowvolume, for both of its flavours.

    pvpython -m pytest test_python_api.py        (the CMake build's package)
    python -m pytest test_python_api.py          (in a venv with the wheel)

The same tests run against the C++ filter wrapped by VTK and against the
wheel's Python filter: the property table against the class, reconstruct()
with every kind of input, progress, errors, warnings and Ctrl-C, the command
line (every format, progress on a terminal, bad input, Ctrl-C) and pyvista's
accessor. Tests that only one flavour can run say why they skip.

Environment: NV_EXPECT_FLAVOUR ("vtk-module" or "wheel") guards against
testing the wrong package; NV_PIP_REFERENCE, a folder written by
pip_reference.py (the C++ filter's record), turns on the comparisons of the
wheel with the C++ filter: the same public names, defaults and clamping, and
bit-identical outputs on the same points; NV_PYTHON runs the command line
(default: this Python, or pvpython for the CMake build's package).
"""
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time
import warnings

import numpy as np
import pytest
from vtkmodules.util.misc import calldata_type
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.util.vtkConstants import VTK_STRING
from vtkmodules.vtkCommonCore import vtkCommand
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPolyData, vtkUnstructuredGrid

import narrowvolume
from narrowvolume import _properties
import nvclouds
import nvflavours
import nvtesting

HERE = os.path.dirname(os.path.abspath(__file__))
TESTS = os.path.dirname(HERE)  # Testing/Python, the areas' folders
SOURCE = os.path.normpath(os.path.join(TESTS, "..", ".."))
TREFOIL = nvclouds.data_file("trefoil.vtp")
REFERENCE = os.environ.get("NV_PIP_REFERENCE")
WHEEL = narrowvolume.FLAVOUR == "wheel"
only_wheel = pytest.mark.pip  # conftest.py skips these with the CMake build's package
needs_reference = pytest.mark.skipif(not (WHEEL and REFERENCE),
                                     reason="compares the wheel with the C++ filter's record (NV_PIP_REFERENCE)")
# The wheel's core has no VTK: what it computes is the same whatever the vtk
# beside it, so those checks run in one of the wheel's environments, the
# newest vtk's; the oldest vtk's (NV_PIP_VTK_ONLY=1) runs what meets vtk.
not_again_per_vtk = pytest.mark.skipif(
    WHEEL and os.environ.get("NV_PIP_VTK_ONLY") == "1",
    reason="the wheel's core alone, the same with any vtk: run in the newest vtk's environment")
SPHERE = nvclouds.sphere_points(5000, 0.5, (1.0, 2.0, -3.0))
SETTINGS = dict(OffsetDistance=0.1, SampleSpacing=0.025)


@pytest.fixture(autouse=True, scope="module")
def python_sigint():
    """Python's own Ctrl-C handler, as in a plain Python (pvpython leaves
    SIGINT to ParaView's logger, which ends the process)."""
    previous = signal.getsignal(signal.SIGINT)
    signal.signal(signal.SIGINT, signal.default_int_handler)
    yield
    if previous is not None:
        signal.signal(signal.SIGINT, previous)


def phi_of(volume):
    return vtk_to_numpy(volume.GetPointData().GetArray("phi"))


def test_flavour(flavour):
    """The package under test is the one the test run asked for ($NV_EXPECT_FLAVOUR: the fixture checks it)."""
    print("narrowvolume %s from %s" % (narrowvolume.FLAVOUR, narrowvolume.__file__))
    assert flavour in ("vtk-module", "wheel")
    assert (narrowvolume.vtkPointCloudTextReader is None) == WHEEL


def test_version():
    """__version__ is the project's version (CMakeLists.txt's project(), which the wheel's metadata reads too)."""
    with open(os.path.join(SOURCE, "CMakeLists.txt")) as f:
        project = re.search(r"project\(NarrowVolume VERSION ([0-9.]+)", f.read()).group(1)
    assert narrowvolume.__version__ == project
    if WHEEL:
        from importlib.metadata import version
        assert version("narrowvolume") == project


def test_type_hints():
    """The public functions carry type hints that resolve."""
    import typing
    from narrowvolume import _cli, _properties as table
    hints = typing.get_type_hints(narrowvolume.reconstruct)
    assert set(hints) >= {"points", "progress", "return"}
    assert typing.get_type_hints(_cli.main)["return"] is int
    assert typing.get_type_hints(table.describe)["return"] is str


@only_wheel
def test_stub_lists_every_property():
    """The wheel carries py.typed and _filter.pyi, whose class declares each
    property's methods (made from the table), with the table's documentation,
    and exactly the class's own public methods and types (less VTK's pipeline
    passes, which VTK calls)."""
    import ast
    folder = os.path.dirname(narrowvolume.__file__)
    assert os.path.exists(os.path.join(folder, "py.typed"))
    with open(os.path.join(folder, "_filter.pyi")) as f:
        tree = ast.parse(f.read())
    cls = next(n for n in tree.body if isinstance(n, ast.ClassDef) and n.name == "vtkNarrowVolumeReconstruction")
    methods = {n.name: n for n in cls.body if isinstance(n, ast.FunctionDef)}
    for prop in _properties.PROPERTIES:
        assert "Get" + prop.name in methods and "Set" + prop.name in methods, prop.name
        words = " ".join(ast.get_docstring(methods["Set" + prop.name]).split())
        expected = " ".join(_properties.describe(prop).replace('"', "'").split())  # the stub's quotes
        assert words == expected, prop.name
    for result in _properties.RESULTS:
        words = " ".join(ast.get_docstring(methods["Get" + result.name]).split())
        assert words == " ".join(_properties.describe(result).replace('"', "'").split()), result.name
    passes = {"FillInputPortInformation", "FillOutputPortInformation", "RequestInformation", "RequestUpdateExtent",
              "RequestData"}
    own = {name for name, value in vars(narrowvolume.vtkNarrowVolumeReconstruction).items()
           if callable(value) and not name.startswith("_")} - passes
    stubbed = {n.name for n in cls.body if isinstance(n, (ast.FunctionDef, ast.ClassDef))}
    assert stubbed == own, "stub only: %s; class only: %s" % (sorted(stubbed - own), sorted(own - stubbed))


# --- The property table against the filter.
@pytest.mark.parametrize("prop", _properties.PROPERTIES, ids=lambda p: p.name)
def test_property_methods(prop):
    """Every row of the table is a property with the filter's Set/Get methods,
    clamps as the table says, and has its boolean and enumerated helpers."""
    f = narrowvolume.vtkNarrowVolumeReconstruction()
    default = getattr(f, "Get" + prop.name)()
    assert isinstance(default, prop.kind) or (prop.kind is float and isinstance(default, int))
    assert default == prop.default, "the filter's default is the table's"
    if prop.low is not None:
        getattr(f, "Set" + prop.name)(prop.low - 1)
        assert getattr(f, "Get" + prop.name)() == prop.low
        getattr(f, "Set" + prop.name)(prop.high * 10)
        assert getattr(f, "Get" + prop.name)() == prop.high
        assert getattr(f, "Get%sMinValue" % prop.name)() == prop.low
        assert getattr(f, "Get%sMaxValue" % prop.name)() == prop.high
    if prop.kind is bool:
        getattr(f, prop.name + "On")()
        assert getattr(f, "Get" + prop.name)() is True
        getattr(f, prop.name + "Off")()
        assert getattr(f, "Get" + prop.name)() is False
    for constant, suffix, value, _ in prop.choices:
        assert getattr(narrowvolume.vtkNarrowVolumeReconstruction, constant) == value
        getattr(f, "Set%sTo%s" % (prop.name, suffix))()
        assert getattr(f, "Get" + prop.name)() == value


def test_results_from_the_table():
    """Each row of RESULTS is a Get method of the filter: zero (or "")
    before a run, what the run chose after it, and zero again after a run
    that failed."""
    f = narrowvolume.vtkNarrowVolumeReconstruction()
    zero = {float: 0.0, int: 0, str: ""}

    def results():
        return {r.name: getattr(f, "Get" + r.name)() for r in _properties.RESULTS}

    for result in _properties.RESULTS:
        value = getattr(f, "Get" + result.name)()
        assert value == (tuple([zero[result.kind]] * result.size) if result.size > 1 else zero[result.kind])
    f.SetInputData(nvclouds.cloud(SPHERE))
    f.SetOffsetDistance(0.1)
    f.SetSampleSpacing(0.025)
    f.Update()
    chosen = results()
    print(chosen)
    assert chosen["OffsetDistanceUsed"] == 0.1 and chosen["SampleSpacingUsed"] == 0.025
    assert chosen["ClosingRadiusUsed"] == pytest.approx(0.3)
    assert tuple(chosen["GridDimensionsUsed"]) == f.GetVolumeOutput().GetDimensions()
    assert chosen["GridUsed"] == " x ".join(str(n) for n in chosen["GridDimensionsUsed"])
    f.SetXiCells(0.5)  # refused: the run fails
    f.AddObserver("ErrorEvent", lambda *args: None)
    f.Update()
    assert results()["GridUsed"] == "" and results()["OffsetDistanceUsed"] == 0.0


def test_setter_marks_modified():
    """A setter that changes a value marks the filter modified, one that does not leaves it."""
    f = narrowvolume.vtkNarrowVolumeReconstruction()
    before = f.GetMTime()
    f.SetOffsetDistance(f.GetOffsetDistance())
    assert f.GetMTime() == before
    f.SetOffsetDistance(f.GetOffsetDistance() + 1.0)
    assert f.GetMTime() > before


def test_list_property_methods():
    """DrainHolePositions, as vtkContourFilter's values: SetNumberOf grows
    with zeros and shrinks, Set at an index past the end grows, Add appends,
    RemoveAll empties; a change marks the filter modified, the same points
    do not. The same in both flavours."""
    f = narrowvolume.vtkNarrowVolumeReconstruction()
    assert f.GetNumberOfDrainHolePositions() == 0
    f.SetNumberOfDrainHolePositions(2)
    assert f.GetNumberOfDrainHolePositions() == 2 and f.GetDrainHolePosition(1) == (0.0, 0.0, 0.0)
    assert f.GetDrainHolePosition(2) is None
    f.SetDrainHolePosition(3, 1.0, 2.0, 3.0)
    f.AddDrainHolePosition(4.0, 5.0, 6.0)
    assert f.GetNumberOfDrainHolePositions() == 5
    before = f.GetMTime()
    f.SetDrainHolePosition(3, 1.0, 2.0, 3.0)
    assert f.GetMTime() == before
    assert f.GetDrainHolePosition(3) == (1.0, 2.0, 3.0) and f.GetDrainHolePosition(4) == (4.0, 5.0, 6.0)
    f.RemoveAllDrainHolePositions()
    assert f.GetNumberOfDrainHolePositions() == 0 and f.GetMTime() > before


@pytest.mark.skipif(WHEEL, reason="reads the C++ class itself (the wheel is compared with its record instead)")
def test_table_covers_the_cpp_class():
    """Every Set/Get pair of the C++ filter is a row of the table (but
    SetController and SetPanelLabelsInMessages, which are not settings of
    the method) or a list property's (SetNumberOf<Name>, Set<Name less s>),
    and every list property has its six methods."""
    api = set(nvflavours.public_api(narrowvolume.vtkNarrowVolumeReconstruction))
    pairs = {n[3:] for n in api if n.startswith("Set") and "Get" + n[3:] in api}
    lists = set()
    for listed in _properties.LIST_PROPERTIES:
        one = _properties.singular(listed.name)
        lists |= {"NumberOf" + listed.name, one}
        assert {"Add" + one, "RemoveAll" + listed.name} <= api, listed.name
    assert pairs - {"Controller", "PanelLabelsInMessages"} == {p.name for p in _properties.PROPERTIES} | lists


# A helix of points 1 high: a cloud whose grid reaches the automatic cap of
# 320 cells with a band of few nodes (the trefoil's took 3 s a run).
HELIX_TURNS = np.linspace(0.0, 6.0 * np.pi, 3000)
HELIX = np.c_[0.3 * np.cos(HELIX_TURNS), 0.3 * np.sin(HELIX_TURNS), HELIX_TURNS / (6.0 * np.pi)]


def test_messages_in_the_panels_words():
    """With PanelLabelsInMessages (as the ParaView plugins set it) the
    warnings name the panel's labels, otherwise the properties' names."""
    cloud = nvclouds.cloud(HELIX)
    extent = 1.0  # the helix's height, its longest side
    texts = {}
    for labels in (False, True):
        f = narrowvolume.vtkNarrowVolumeReconstruction()
        f.SetInputData(cloud)
        f.SetOffsetDistance(2.5 * extent / 320)  # a coarse grid: a warning naming SampleSpacing
        f.SetPanelLabelsInMessages(labels)
        assert f.GetPanelLabelsInMessages() is labels
        caught = []

        @calldata_type(VTK_STRING)
        def on_warning(caller, event, text, caught=caught):
            caught.append(text)
        f.AddObserver("WarningEvent", on_warning)
        f.Update()
        texts[labels] = "\n".join(str(t) for t in caught)
    print(texts[True])
    assert "SampleSpacing" in texts[False] and "Sample Spacing" not in texts[False], texts[False]
    assert "Sample Spacing" in texts[True] and "SampleSpacing" not in texts[True], texts[True]
    assert "Offset Distance" in texts[True] and "Maximum Dimension" in texts[True], texts[True]


@needs_reference
def test_same_names_defaults_and_clamping_as_cpp():
    """The wheel's filter has the C++ filter's public names (but SetController),
    defaults and clamping."""
    with open(os.path.join(REFERENCE, "reference.json")) as f:
        record = json.load(f)
    api = set(nvflavours.public_api(narrowvolume.vtkNarrowVolumeReconstruction))
    assert set(record["api"]) - nvflavours.CPP_ONLY == api
    assert nvflavours.property_report(narrowvolume.vtkNarrowVolumeReconstruction,
                                      _properties.PROPERTIES) == record["properties"]


@needs_reference
@pytest.mark.parametrize("case", sorted(nvflavours.CASES))
def test_outputs_bit_identical_to_cpp(case):
    """The same points give the C++ filter's outputs bit for bit: the grid,
    phi and the optional arrays, every field data array (with its class),
    and the surface's points, normals and triangles."""
    with open(os.path.join(REFERENCE, "reference.json")) as f:
        expected = json.load(f)["cases"][case]
    cloud = nvclouds.cloud(np.load(os.path.join(REFERENCE, "points.npy")))
    got = nvflavours.summary(nvflavours.run_case(narrowvolume.vtkNarrowVolumeReconstruction, cloud,
                                                 nvflavours.CASES[case]))
    assert sorted(got) == sorted(expected)
    for key in expected:
        # dtype, shape and digest: the bytes. (The sums only help to read a
        # failure: numpy's summation order differs between its versions.)
        assert got[key][:3] == expected[key][:3], (key, got[key], expected[key])


# --- reconstruct()
def test_reconstruct_inputs():
    """An (n, 3) array, a vtkPolyData and a vtkUnstructuredGrid of the same
    points give the same phi, the filter's."""
    volume, surface = narrowvolume.reconstruct(SPHERE, **SETTINGS)
    assert isinstance(volume, vtkImageData) and isinstance(surface, vtkPolyData)
    grid = vtkUnstructuredGrid()
    grid.SetPoints(nvclouds.cloud(SPHERE).GetPoints())
    for data in (nvclouds.cloud(SPHERE), grid, SPHERE.tolist()):
        other, _ = narrowvolume.reconstruct(data, **SETTINGS)
        assert np.array_equal(phi_of(other), phi_of(volume))
    f = narrowvolume.vtkNarrowVolumeReconstruction()
    f.SetInputData(nvclouds.cloud(SPHERE))
    f.SetOffsetDistance(0.1)
    f.SetSampleSpacing(0.025)
    f.Update()
    assert np.array_equal(phi_of(f.GetOutput(0)), phi_of(volume))
    assert surface.GetNumberOfPolys() == f.GetOutput(1).GetNumberOfPolys() > 0
    assert nvtesting.regions(surface) == 2 and nvtesting.boundary_edges(surface) == 0
    assert volume.GetFieldData().GetArray("NumberOfIterations").GetValue(0) == 3


def test_reconstruct_keywords():
    """Properties by name or in snake_case; an unknown one is a TypeError naming the valid ones."""
    a, _ = narrowvolume.reconstruct(SPHERE, OffsetDistance=0.1, SampleSpacing=0.025, OutputDistance=True)
    b, _ = narrowvolume.reconstruct(SPHERE, offset_distance=0.1, sample_spacing=0.025, output_distance=True)
    assert np.array_equal(phi_of(a), phi_of(b))
    assert b.GetPointData().GetArray("Distance") is not None
    with pytest.raises(TypeError, match="OffsetDistance"):
        narrowvolume.reconstruct(SPHERE, Offset=0.1)


def test_reconstruct_errors():
    """Refused input raises ReconstructionError with the filter's message."""
    with pytest.raises(narrowvolume.ReconstructionError, match="no points"):
        narrowvolume.reconstruct(np.zeros((0, 3)))
    with pytest.raises(narrowvolume.ReconstructionError, match="OffsetDistance"):
        narrowvolume.reconstruct(SPHERE, OffsetDistance=-1.0)
    bad = SPHERE.copy()
    bad[17, 1] = np.nan
    with pytest.raises(narrowvolume.ReconstructionError, match="point 17"):
        narrowvolume.reconstruct(bad, **SETTINGS)
    with pytest.raises(ValueError):
        narrowvolume.reconstruct(np.zeros((10, 2)))
    with pytest.raises(TypeError, match="point set"):
        narrowvolume.reconstruct(vtkImageData())
    # The message alone, without VTK's header (source file and line, class and address).
    with pytest.raises(narrowvolume.ReconstructionError) as refused:
        narrowvolume.reconstruct(np.zeros((0, 3)))
    assert str(refused.value).startswith("The input has no points"), str(refused.value)


def test_a_table_is_refused_with_table_to_points():
    """A table (a CSV file read as columns) as input: one error that names
    Table To Points, both outputs empty (issue 37: it gave six identical
    errors of the pipeline and an empty surface)."""
    from vtkmodules.util.numpy_support import numpy_to_vtk
    from vtkmodules.vtkCommonDataModel import vtkTable
    table = vtkTable()
    for axis, name in enumerate("xyz"):
        column = numpy_to_vtk(np.ascontiguousarray(SPHERE[:, axis]), deep=1)
        column.SetName(name)
        table.AddColumn(column)
    f = narrowvolume.vtkNarrowVolumeReconstruction()
    errors = []

    @calldata_type(VTK_STRING)
    def on_error(caller, event, text):
        errors.append(text)

    f.AddObserver("ErrorEvent", on_error)
    f.SetInputData(table)
    f.Update()
    assert len(errors) == 1 and "Table To Points" in errors[0], errors
    assert f.GetOutputDataObject(1).GetNumberOfPoints() == 0 and f.GetOutputDataObject(0).GetNumberOfPoints() == 0


def test_truth_values_for_switches():
    """Switches take any truth value, as VTK's wrapping does (numpy bools too)."""
    f = narrowvolume.vtkNarrowVolumeReconstruction()
    f.SetOutputVolume(np.bool_(False))
    assert f.GetOutputVolume() == 0
    f.SetPreserveOffset(1.0)
    assert f.GetPreserveOffset() == 1
    volume, surface = narrowvolume.reconstruct(SPHERE, output_volume=np.bool_(False), **SETTINGS)
    assert volume.GetPointData().GetArray("phi") is None and surface.GetNumberOfPolys() > 0


def test_sampling_time():
    """The points' spacing is measured once per cloud: GetSamplingTime is the
    measurement's seconds in the update that made it, and 0 in an update that
    only changed a property."""
    f = narrowvolume.vtkNarrowVolumeReconstruction()
    f.SetInputData(nvclouds.cloud(SPHERE))
    f.SetOutputVolume(0)
    f.Update()
    assert f.GetSamplingTime() > 0.0
    f.SetMaximumNumberOfIterations(2)
    f.Update()
    assert f.GetSamplingTime() == 0.0 and f.GetSetupTime() > 0.0


def test_reconstruct_with_vtk_output_off():
    """With VTK's messages turned off (vtkObject.GlobalWarningDisplayOff()),
    reconstruct() still raises its errors and gives its warnings, and leaves
    the setting as it found it."""
    from vtkmodules.vtkCommonCore import vtkObject
    vtkObject.GlobalWarningDisplayOff()
    try:
        with pytest.raises(narrowvolume.ReconstructionError, match="no points"):
            narrowvolume.reconstruct(np.zeros((0, 3)))
        assert not vtkObject.GetGlobalWarningDisplay()
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            narrowvolume.reconstruct(SPHERE[SPHERE[:, 2] > -2.8], OffsetDistance=0.1, SampleSpacing=0.025, Sheets=2)
        assert any(issubclass(w.category, narrowvolume.ReconstructionWarning) for w in caught), caught
        assert not vtkObject.GetGlobalWarningDisplay()
    finally:
        vtkObject.GlobalWarningDisplayOn()


def test_reconstruct_warning():
    """The filter's warnings come as ReconstructionWarning."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        _, surface = narrowvolume.reconstruct(SPHERE[SPHERE[:, 2] > -2.8], OffsetDistance=0.1,
                                              SampleSpacing=0.025, Sheets=2)
    assert surface.GetNumberOfCells() == 0
    messages = [str(w.message) for w in caught if issubclass(w.category, narrowvolume.ReconstructionWarning)]
    assert any("open" in m for m in messages), messages


def test_progress_callback():
    """The callback sees at least 20 fractions, never going back, ending at 1;
    an exception it raises stops the run and comes out of reconstruct()."""
    seen = []
    narrowvolume.reconstruct(SPHERE, progress=seen.append, **SETTINGS)
    print("%d progress calls" % len(seen))
    assert len(seen) >= 20 and seen[-1] == 1.0
    assert all(b >= a for a, b in zip(seen, seen[1:]))

    class Stop(Exception):
        pass

    def stop_at_half(fraction):
        if fraction >= 0.5:
            raise Stop()
    with pytest.raises(Stop):
        narrowvolume.reconstruct(SPHERE, progress=stop_at_half, **SETTINGS)


def test_spacing_progress_in_the_information_pass():
    """The measurement of the points' spacing runs in the information pass
    (seconds on a large cloud, before the data pass): its progress shows
    there as the run's first tenth, never going back."""
    f = narrowvolume.vtkNarrowVolumeReconstruction()
    f.SetInputData(nvclouds.cloud(nvclouds.sphere_points(100000)))
    seen = []
    f.AddObserver(vtkCommand.ProgressEvent, lambda caller, event: seen.append(caller.GetProgress()))
    f.UpdateInformation()
    print("%d progress events in the information pass" % len(seen))
    assert len(seen) >= 8 and seen[-1] == pytest.approx(0.1)
    assert all(b >= a for a, b in zip(seen, seen[1:]))


@only_wheel
def test_spacing_stops_when_asked():
    """The binding's measurement stops when the monitor asks (None), and on
    Ctrl-C (KeyboardInterrupt), as a run does."""
    from narrowvolume import _core
    points = np.ascontiguousarray(nvclouds.sphere_points(100000))
    assert _core.Sampling.Measure(points, 0, None).Statistics().Valid()
    assert _core.Sampling.Measure(points, 0, _core.Monitor(None, lambda: True)) is None

    def interrupt(fraction):
        if fraction > 0.2:
            os.kill(os.getpid(), signal.SIGINT)
    with pytest.raises(KeyboardInterrupt):
        _core.Sampling.Measure(points, 0, _core.Monitor(interrupt, None))


def _timed(**settings):
    start = time.perf_counter()
    narrowvolume.reconstruct(SPHERE, **settings)
    return time.perf_counter() - start


def test_ctrl_c_from_progress():
    """Ctrl-C (a SIGINT the progress callback sends itself at 20 %) stops the
    run soon and raises KeyboardInterrupt."""
    settings = dict(OffsetDistance=0.1, SampleSpacing=0.01)
    full = _timed(**settings)
    sent = []

    def interrupt(fraction):
        if fraction >= 0.2 and not sent:
            sent.append(time.perf_counter())
            os.kill(os.getpid(), signal.SIGINT)
    with pytest.raises(KeyboardInterrupt):
        narrowvolume.reconstruct(SPHERE, progress=interrupt, **settings)
    after = time.perf_counter() - sent[0]
    print("interrupted %.3f s after Ctrl-C (a full run: %.2f s)" % (after, full))
    assert after < 0.3 * full
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler  # restored


def test_abort_while_the_spacing_is_measured():
    """An abort at the first report of a large cloud's measurement (the
    points' spacing, in the information pass, before the data pass; its
    sorts of millions report nothing): the run stops inside it, its progress
    never past that stage's share, the outputs empty; the next Update runs
    whole. The measurement could not be stopped before (seconds for millions
    of points), and the data pass, which clears the flag, then ran whole."""
    sampling_stage = 0.1  # the measurement's share of the progress (nv::SamplingStage)
    rng = np.random.default_rng(7)
    directions = rng.normal(size=(1000000, 3))
    f = narrowvolume.vtkNarrowVolumeReconstruction()
    f.SetInputData(nvclouds.cloud(0.5 * directions / np.linalg.norm(directions, axis=1)[:, None]))
    f.SetSampleSpacing(0.05)
    seen = []

    def abort(caller, event):
        seen.append(caller.GetProgress())
        if len(seen) == 1:
            caller.SetAbortExecute(1)  # as ParaView's abort button and reconstruct()'s Ctrl-C do
    observer = f.AddObserver(vtkCommand.ProgressEvent, abort)
    f.Update()
    print("progress seen: %s" % seen)
    assert max(v for v in seen if v < 1.0) < sampling_stage  # (the pipeline's own 1.0 as it ends)
    assert f.GetOutput(1).GetNumberOfPoints() == 0 and f.GetOutput(0).GetNumberOfPoints() == 0
    f.RemoveObserver(observer)
    f.Modified()
    f.Update()
    assert f.GetOutput(1).GetNumberOfPoints() > 0


@only_wheel
def test_ctrl_c_while_the_core_runs():
    """Ctrl-C from outside while the core computes (the GIL released), with
    no Python callback at all: the binding's monitor polls Python's signals
    between the core's steps, the run stops, Reconstruct raises KeyboardInterrupt."""
    from narrowvolume import _core
    settings = _core.Settings()
    settings.OffsetDistance, settings.SampleSpacing = 0.1, 0.01
    settings.MaximumNumberOfIterations = 5000  # minutes: the signal comes long before the end
    settings.ConvergenceTolerance = 0.0  # (no convergence test to end it early)
    run = _core.Reconstruction(settings, _core.Monitor())
    sent = []

    def interrupt():
        sent.append(time.perf_counter())
        os.kill(os.getpid(), signal.SIGINT)
    timer = threading.Timer(0.5, interrupt)
    start = time.perf_counter()
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        run.Reconstruct(np.ascontiguousarray(SPHERE), None, _core.MeshSink())
    end = time.perf_counter()
    timer.join()
    print("interrupted %.3f s after Ctrl-C, %.2f s into the run" % (end - sent[0], end - start))
    # Stopped by the signal, not by its end (no wall-clock bound, which a
    # loaded machine would break: the time is printed).
    assert run.Aborted()


@only_wheel
@not_again_per_vtk
def test_gpu_back_end_through_the_host_launcher_on_scans():
    """Device GPU's back end (the points' sort, the distance, the band, the
    evolution, the surface: the GPU's kernels) through its host launcher,
    against the CPU core on three scans with their defaults, as
    benchmarks/gpu_check.py checks a GPU: the same band, every vertex within
    0.05 h of the CPU's (here the same bits), both surfaces closed with the
    same Euler characteristic, the surface made by the kernels."""
    if not nvclouds.have_scans():
        pytest.skip("the scans are not in %s (../shared/data/scans)" % nvclouds.SCANS_DIR)
    sys.path.insert(0, os.path.join(SOURCE, "benchmarks"))
    try:
        import gpu_check
    finally:
        sys.path.pop(0)
    from narrowvolume import _core
    assert gpu_check.check_scans(_core, "gpu-host")


@only_wheel
def test_ctrl_c_during_update():
    """Ctrl-C during the filter's Update(): the run stops, the outputs are
    empty, an error says so, and Update() returns."""
    f = narrowvolume.vtkNarrowVolumeReconstruction()
    f.SetInputData(nvclouds.cloud(SPHERE))
    f.SetOffsetDistance(0.1)
    f.SetSampleSpacing(0.01)
    f.SetMaximumNumberOfIterations(5000)
    f.SetConvergenceTolerance(0.0)
    errors = []
    f.AddObserver(vtkCommand.ErrorEvent, calldata_type(VTK_STRING)(lambda c, e, text: errors.append(text)))
    timer = threading.Timer(0.5, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    f.Update()
    timer.join()
    assert f.GetOutput(1).GetNumberOfPoints() == 0 and f.GetOutput(0).GetNumberOfPoints() == 0
    assert any("Interrupted" in e for e in errors), errors


@only_wheel
def test_gil_released():
    """Another Python thread runs while the core computes: the GIL is released."""
    def rate(seconds, busy=None):
        count = [0]
        stop = threading.Event()

        def counter():
            while not stop.is_set():
                count[0] += 1
        thread = threading.Thread(target=counter)
        start = time.perf_counter()
        thread.start()
        if busy:
            busy()
        else:
            time.sleep(seconds)
        stop.set()
        thread.join()
        return count[0] / (time.perf_counter() - start)
    free = rate(0.5)
    during = rate(None, lambda: narrowvolume.reconstruct(SPHERE, OffsetDistance=0.1, SampleSpacing=0.008,
                                                          NumberOfThreads=1))
    print("another thread counts %.3g/s alone, %.3g/s while the core runs" % (free, during))
    assert during > 0.3 * free


# --- pyvista
def _pyvista():
    return pytest.importorskip("pyvista")


def test_pyvista_input():
    """A pyvista point set in, pyvista objects out."""
    pv = _pyvista()
    volume, surface = narrowvolume.reconstruct(pv.PolyData(SPHERE), **SETTINGS)
    assert isinstance(volume, pv.ImageData) and isinstance(surface, pv.PolyData)
    assert surface.n_cells > 0 and "phi" in volume.point_data


def test_pyvista_accessor():
    """cloud.narrowvolume.reconstruct() on pyvista's point sets (pyvista 0.48 and later)."""
    pv = _pyvista()
    if not hasattr(pv, "register_dataset_accessor"):
        pytest.skip("pyvista %s has no dataset accessors (0.48 and later)" % pv.__version__)
    from narrowvolume import _pyvista as accessor
    assert accessor.REGISTERED
    cloud = pv.PolyData(SPHERE)
    volume, surface = cloud.narrowvolume.reconstruct(**SETTINGS)
    expected, _ = narrowvolume.reconstruct(SPHERE, **SETTINGS)
    assert np.array_equal(volume.point_data["phi"], phi_of(expected))
    for kind in (pv.PointSet, pv.UnstructuredGrid):
        assert hasattr(kind, "narrowvolume")


@only_wheel
def test_pyvista_entry_point():
    """With the wheel installed, pyvista finds the accessor by itself: no import of narrowvolume."""
    pv = _pyvista()
    if not hasattr(pv, "register_dataset_accessor"):
        pytest.skip("pyvista %s has no dataset accessors" % pv.__version__)
    code = ("import sys, numpy as np, pyvista as pv\n"
            "assert 'narrowvolume' not in sys.modules\n"
            "v, s = pv.PolyData(np.load(sys.argv[1])).narrowvolume.reconstruct(OffsetDistance=0.1, SampleSpacing=0.025)\n"
            "print(type(v).__name__, type(s).__name__, s.n_cells)\n")
    with tempfile.TemporaryDirectory() as folder:
        np.save(os.path.join(folder, "p.npy"), SPHERE)
        result = subprocess.run([sys.executable, "-c", code, os.path.join(folder, "p.npy")],
                                capture_output=True, text=True)
    assert result.returncode == 0, nvtesting.explain(result)
    assert result.stdout.startswith("ImageData PolyData ")


# --- The command line
def cli(*args, **kwargs):
    return subprocess.run(nvtesting.python_command() + ["-m", "narrowvolume"] + [str(a) for a in args],
                          capture_output=True, text=True, **kwargs)


def _read(path):
    from vtkmodules.vtkIOGeometry import vtkSTLReader
    from vtkmodules.vtkIOPLY import vtkPLYReader
    from vtkmodules.vtkIOXML import vtkXMLImageDataReader, vtkXMLPolyDataReader
    reader = {".stl": vtkSTLReader, ".ply": vtkPLYReader, ".vtp": vtkXMLPolyDataReader,
              ".vti": vtkXMLImageDataReader}[os.path.splitext(path)[1]]()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def test_cli_writes_every_format(tmp_path):
    """STL, PLY and VTP hold the surface, VTI the volume; the XML files are Binary."""
    outputs = [tmp_path / ("shell" + e) for e in (".stl", ".ply", ".vtp")] + [tmp_path / "phi.vti"]
    args = [TREFOIL, "--maximum-dimension", 60]
    for path in outputs:
        args += ["-o", path]
    result = cli(*args)
    assert result.returncode == 0, nvtesting.explain(result)
    print(result.stdout)
    expected, surface = narrowvolume.reconstruct(_read(TREFOIL), MaximumDimension=60)
    for path in outputs[:3]:
        assert _read(str(path)).GetNumberOfPolys() == surface.GetNumberOfPolys() > 0, path
    assert _read(str(outputs[2])).GetPointData().GetArray("Normals") is not None
    volume = _read(str(outputs[3]))
    assert volume.GetDimensions() == expected.GetDimensions()
    assert np.array_equal(phi_of(volume), phi_of(expected))
    for path in outputs[2:]:
        header = path.read_bytes()[:4000]
        assert b'format="binary"' in header and b'format="appended"' not in header


def test_cli_text_cloud(tmp_path):
    """A plain-text cloud (x y z, a header line) gives the shell of the same points."""
    points = vtk_to_numpy(_read(TREFOIL).GetPoints().GetData()).astype(np.float64)
    text = tmp_path / "cloud.xyz"
    np.savetxt(str(text), points, header="x y z", comments="", fmt="%.9g")
    result = cli(text, "-o", tmp_path / "a.vtp", "--maximum-dimension", 50, "-q")
    assert result.returncode == 0, nvtesting.explain(result)
    _, surface = narrowvolume.reconstruct(np.loadtxt(str(text), skiprows=1), MaximumDimension=50)
    assert _read(str(tmp_path / "a.vtp")).GetNumberOfPolys() == surface.GetNumberOfPolys() > 0


@only_wheel
def test_cli_text_layouts(tmp_path):
    """The wheel's plain-text reading (narrowvolume._core.read_text_cloud):
    a header line, a point count, commas, tabs and CRLF, comments, blank
    lines, rows of different lengths and text after x y z give the same
    points; a line that is not a point is named, in the words the command
    line has always used."""
    from narrowvolume import _cli
    texts = ["1 2 3\n4 5 6\n", "x y z\n1,2,3\n4,5,6", "2\n1 2 3 0.5\n4 5 6 0.5\n",
             "1\t2\t3\r\n4\t5\t6\r\n\n", "1 2 3\n# a comment\n4 5 6\n", "1 2 3\n\n4 5 6 7\n",
             "1 2 3 red\n4 5 6 blue\n", "x;y;z;name\n1;2;3;a\n4;5;6;b\n", "1;2;3\n4;5;6\n"]
    for number, text in enumerate(texts):
        path = tmp_path / ("cloud%d.xyz" % number)
        path.write_text(text)
        xyz = vtk_to_numpy(_cli._read_text(str(path)).GetPoints().GetData())
        assert np.array_equal(xyz, [[1, 2, 3], [4, 5, 6]]), text
    refused = {"1 2 3\n4 5 six\n": "%s, line 2: not a point (x y z): '4 5 six'",
               "x y z\nno numbers\n": "%s: no line of x y z numbers in its 2 lines: not a text point cloud",
               "x y z\n\0\1\n": "%s: no line of x y z numbers in its 2 lines: not a text point cloud "
                                  "(it holds binary data)"}
    for number, (text, message) in enumerate(refused.items()):
        path = str(tmp_path / ("bad%d.xyz" % number))
        with open(path, "w") as f:
            f.write(text)
        with pytest.raises(_cli.Failure) as failure:
            _cli._read_text(path)
        assert str(failure.value) == message % path


def test_cli_options_and_defaults():
    """--help names every property, with the filter's default."""
    result = cli("--help")
    assert result.returncode == 0, nvtesting.explain(result)
    text = " ".join(result.stdout.split()).replace("- ", "-")  # argparse may wrap a line after a hyphen
    defaults = _properties.defaults_of(narrowvolume.vtkNarrowVolumeReconstruction())
    for prop in _properties.PROPERTIES:
        option = "--" + _properties.snake_case(prop.name).replace("_", "-")
        assert option in text
        default = defaults[prop.name]
        names = {value: _properties.snake_case(suffix).replace("_", "-") for _, suffix, value, _ in prop.choices}
        assert "(default: %s)" % names.get(default, default) in text, prop.name  # an enumeration's by name
    assert "(default: both)" in text and "(default: narrow-band)" in text and "(default: equation4)" in text


def test_coarse_grid_warns():
    """An explicit offset that the grid's cap (320 cells) leaves under 3
    cells warns, with what to set; at 4 cells (the automatic ratio) not."""
    cloud = nvclouds.cloud(HELIX)
    extent = 1.0
    for factor, coarse in ((2.5, True), (5.0, False)):
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always", narrowvolume.ReconstructionWarning)
            volume, _ = narrowvolume.reconstruct(cloud, OffsetDistance=factor * extent / 320)
        field = volume.GetFieldData()
        ratio = field.GetArray("OffsetDistance").GetValue(0) / field.GetArray("SampleSpacing").GetValue(0)
        texts = [str(w.message) for w in caught if "grid is coarse" in str(w.message)]
        assert (ratio < 3.0) == coarse and bool(texts) == coarse, (factor, ratio, texts)
        if coarse:
            assert "Set SampleSpacing to" in texts[0] and "MaximumDimension" in texts[0], texts[0]


def test_cli_version():
    """--version prints the package's version and nothing else."""
    result = cli("--version")
    assert result.returncode == 0 and result.stdout == "narrowvolume %s\n" % narrowvolume.__version__


def test_cli_prints_what_it_chose(tmp_path):
    """The command line says the offset, spacing, their ratio, the grid and the band it used."""
    result = cli(TREFOIL, "--maximum-dimension", 60, "-o", tmp_path / "a.vtp")
    assert result.returncode == 0, nvtesting.explain(result)
    volume, _ = narrowvolume.reconstruct(_read(TREFOIL), MaximumDimension=60)
    field = volume.GetFieldData()
    offset, spacing = field.GetArray("OffsetDistance").GetValue(0), field.GetArray("SampleSpacing").GetValue(0)
    line = "offset distance %.6g, spacing %.6g (offset / spacing %.2f), grid %d x %d x %d, %d band nodes" % (
        (offset, spacing, offset / spacing) + volume.GetDimensions()
        + (field.GetArray("NarrowBandNodes").GetValue(0),))
    assert "narrowvolume: " + line in result.stdout, result.stdout


def test_cli_empty_result(tmp_path):
    """No surface (the inner sheet of an open, one-sided cloud): exit 1, the
    reason, the options' names in the warning, and no file written."""
    rng = np.random.default_rng(4)
    disc = rng.random((3000, 2)) * 2.0 - 1.0
    disc = disc[(disc ** 2).sum(axis=1) < 1.0]
    cloud = tmp_path / "disc.xyz"
    np.savetxt(str(cloud), np.c_[disc, np.zeros(len(disc))], fmt="%.9g")
    result = cli(cloud, "--sheets", "inner", "-o", tmp_path / "inner.stl", "-o", tmp_path / "phi.vti")
    assert result.returncode == 1, nvtesting.explain(result)
    assert "the surface is empty" in result.stderr and "no inner sheet" in result.stderr.lower(), result.stderr
    assert not (tmp_path / "inner.stl").exists() and not (tmp_path / "phi.vti").exists()


def test_cli_scan_surface(tmp_path):
    """--sheets scan: one closed surface on a closed cloud (the sphere); on
    points along a curve (a helix) none, exit 1, and the warning's reason and
    advice in the options' names."""
    cloud = tmp_path / "sphere.xyz"
    np.savetxt(str(cloud), SPHERE, fmt="%.9g")
    result = cli(cloud, "--sheets", "scan", "--offset-distance", 0.1, "--sample-spacing", 0.025,
                 "-o", tmp_path / "scan.stl")
    assert result.returncode == 0, nvtesting.explain(result)
    surface = _read(str(tmp_path / "scan.stl"))
    assert nvtesting.regions(surface) == 1 and nvtesting.boundary_edges(surface) == 0
    r = np.linalg.norm(nvtesting.points_of(surface) - SPHERE.mean(axis=0), axis=1)
    assert abs(r.mean() - np.linalg.norm(SPHERE - SPHERE.mean(axis=0), axis=1).mean()) < 0.25 * 0.025
    assert "narrowvolume: scan surface: 1 closed piece (volume " in result.stdout, result.stdout
    assert ", 0 open pieces; the points " in result.stdout
    t = np.random.default_rng(5).uniform(0, 6 * np.pi, 3000)
    helix = tmp_path / "helix.xyz"
    np.savetxt(str(helix), np.c_[np.cos(t), np.sin(t), 0.15 * t], fmt="%.9g")
    result = cli(helix, "--sheets", "scan", "-o", tmp_path / "none.stl")
    assert result.returncode == 1, nvtesting.explain(result)
    assert "the scan surface is empty" in result.stderr.lower() and "--sheets both" in result.stderr.lower(), \
        result.stderr
    assert not (tmp_path / "none.stl").exists()


def test_cli_bad_input(tmp_path):
    """Bad input: a non-zero exit and the error's message."""
    missing = cli(tmp_path / "none.ply", "-o", tmp_path / "a.stl")
    assert missing.returncode == 1 and "no such file" in missing.stderr
    refused = cli(TREFOIL, "--offset-distance", -1, "-o", tmp_path / "a.stl")
    assert refused.returncode == 1 and "--offset-distance must be" in refused.stderr, refused.stderr  # its words
    assert not (tmp_path / "a.stl").exists()
    (tmp_path / "bad.xyz").write_text("1 2 3\n4 5 six\n")
    malformed = cli(tmp_path / "bad.xyz", "-o", tmp_path / "a.stl")
    assert malformed.returncode == 1 and "line 2" in malformed.stderr, malformed.stderr
    unknown = cli(TREFOIL, "-o", tmp_path / "a.doc")
    assert unknown.returncode == 2 and "unknown output format" in unknown.stderr
    wrong = cli(TREFOIL, "--sheets", "sideways")
    assert wrong.returncode == 2
    (tmp_path / "bad.ply").write_text("not a PLY file\n")
    unreadable = cli(tmp_path / "bad.ply", "-o", tmp_path / "a.stl")
    assert unreadable.returncode == 1 and "bad.ply: not a PLY file" in unreadable.stderr, unreadable.stderr


def test_cli_project_formats(tmp_path):
    """PCD through the project's readers: the CMake build's C++ reader, the
    wheel's binding of its parser (narrowvolume._core.read_pcd)."""
    (tmp_path / "c.pcd").write_text(
        "VERSION .7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH %d\nHEIGHT 1\n"
        "VIEWPOINT 0 0 0 1 0 0 0\nPOINTS %d\nDATA ascii\n" % (len(SPHERE), len(SPHERE))
        + "".join("%.9g %.9g %.9g\n" % tuple(p) for p in SPHERE))
    result = cli(tmp_path / "c.pcd", "-o", tmp_path / "c.stl", "--offset-distance", 0.1, "--sample-spacing", 0.025)
    assert result.returncode == 0, result.stderr
    assert _read(str(tmp_path / "c.stl")).GetNumberOfPolys() > 0


# The LAS reader's arrays and their types (vtkLASPointCloudReader's; test_las_reader.py's TYPES).
LAS_TYPES = {"Intensity": "unsigned short", "Classification": "unsigned char", "ReturnNumber": "unsigned char",
             "NumberOfReturns": "unsigned char", "ClassificationFlags": "unsigned char",
             "ScanDirectionFlag": "unsigned char", "EdgeOfFlightLine": "unsigned char", "UserData": "unsigned char",
             "ScanAngle": "float", "PointSourceId": "unsigned short", "ScannerChannel": "unsigned char",
             "GpsTime": "double", "Colors": "unsigned char", "NearInfrared": "unsigned short"}


@pytest.mark.parametrize("point_format", range(11), ids=["format%d" % f for f in range(11)])
def test_read_cloud_las(tmp_path, point_format):
    """LAS 1.4 in every point format through the project's readers, without
    laspy: the CMake build's C++ reader, the wheel's binding of its parser
    (narrowvolume._core.read_las, nv::las::ReadFile). The coordinates in
    double precision, every array of the C++ reader with its type and the
    values written (nvpointfiles.py), the colours as the scalars."""
    import nvpointfiles
    from narrowvolume import _cli
    path = str(tmp_path / ("format%d.las" % point_format))
    expected = nvpointfiles.write_las(path, 4, point_format, SPHERE[:300], seed=point_format, extra_bytes=3,
                                      with_vlr=True)
    cloud = _cli.read_cloud(path)
    n = len(expected["xyz"])
    assert cloud.GetNumberOfPoints() == n and cloud.GetNumberOfVerts() == n
    assert cloud.GetPoints().GetData().GetDataTypeAsString() == "double"
    error = float(np.abs(vtk_to_numpy(cloud.GetPoints().GetData()) - expected["xyz"]).max())
    assert error <= 1e-9, "coordinates = X * scale + offset in double (max error %g)" % error
    data = cloud.GetPointData()
    names = {data.GetArrayName(i) for i in range(data.GetNumberOfArrays())}
    assert names == set(expected) - {"xyz"}
    for name in names:
        assert data.GetArray(name).GetDataTypeAsString() == LAS_TYPES[name], name
        assert np.array_equal(vtk_to_numpy(data.GetArray(name)), expected[name]), name
    assert ("Colors" in names) == (data.GetScalars() is not None and data.GetScalars().GetName() == "Colors")


def test_read_cloud_las_damaged(tmp_path):
    """A LAS file cut short: the parser's sentence, naming the file, on both routes."""
    import nvpointfiles
    path = tmp_path / "short.las"
    nvpointfiles.write_las(str(path), 2, 1, SPHERE[:100])
    path.write_bytes(path.read_bytes()[:-50])
    result = cli(path, "-o", tmp_path / "a.stl")
    assert result.returncode == 1 and "short.las" in result.stderr and "point" in result.stderr, result.stderr


def test_cli_progress_on_a_terminal(tmp_path):
    """A progress bar on a terminal, none when standard error is a file."""
    import pty
    main, secondary = pty.openpty()
    # Both streams on the terminal: pvpython's stderr says it is one only then.
    process = subprocess.Popen(nvtesting.python_command() + [
        "-m", "narrowvolume", TREFOIL, "-o", str(tmp_path / "a.stl"), "--maximum-dimension", "60"],
        stdout=secondary, stderr=secondary)
    os.close(secondary)
    shown = b""
    while True:
        try:
            chunk = os.read(main, 65536)
        except OSError:  # the terminal's other side closed
            break
        if not chunk:
            break
        shown += chunk
    os.close(main)
    assert process.wait() == 0
    bars = [part for part in shown.decode(errors="replace").split("\r") if "narrowvolume: [" in part]
    print("%d updates of the bar, the last %r" % (len(bars), bars[-1].strip() if bars else None))
    assert len(bars) >= 20 and "100 %" in bars[-1]
    quiet = cli(TREFOIL, "-o", tmp_path / "b.stl", "--maximum-dimension", 60)
    assert quiet.returncode == 0 and "%" not in quiet.stderr


def test_cli_ctrl_c(tmp_path):
    """Ctrl-C stops the command: exit status 130, a message, no file. The run
    asked for (4,000 steps at 200 cells, no convergence test to end it early)
    takes minutes; the command must stop well before (the time it took is
    printed; no wall-clock bound, which a loaded machine would break). Its
    first line comes as the run starts, through a pipe, without
    PYTHONUNBUFFERED (pvpython's own sys.stdout would hold it to the end)."""
    environment = {k: v for k, v in os.environ.items() if k != "PYTHONUNBUFFERED"}
    process = subprocess.Popen(nvtesting.python_command() + [
        "-m", "narrowvolume", TREFOIL, "-o", str(tmp_path / "a.stl"), "--maximum-dimension", "200",
        "--maximum-number-of-iterations", "4000", "--convergence-tolerance", "0"],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=environment)
    first = process.stdout.readline()  # "... points from ...": the run starts
    assert "points from" in first, first
    time.sleep(0.5)
    sent = time.perf_counter()
    process.send_signal(signal.SIGINT)
    try:
        out, err = process.communicate(timeout=60)
    except subprocess.TimeoutExpired:
        process.kill()
        raise AssertionError("the command did not stop within 60 s of Ctrl-C")
    print("exit %d %.2f s after Ctrl-C: %s" % (process.returncode, time.perf_counter() - sent, err.strip()))
    assert process.returncode == 130 and "interrupted" in err
    assert not (tmp_path / "a.stl").exists()


@only_wheel
def test_console_script():
    """pip installs the command narrowvolume beside the interpreter."""
    script = shutil.which("narrowvolume", path=os.path.dirname(sys.executable))
    assert script, "no narrowvolume script beside %s" % sys.executable
    result = subprocess.run([script, "--help"], capture_output=True, text=True)
    assert result.returncode == 0 and "--offset-distance" in result.stdout


# --- The pip page of the documentation (doc/getting-started/python.md)
PIP_PAGE = os.path.join(SOURCE, "doc", "getting-started", "python.md")


def readme_pip_snippets():
    """The ```python blocks of the pip page, but the one that works on a
    `points` of its reader's (DocSnippets and ReadmeSnippets run that one)."""
    import re
    blocks = re.findall(r"```python\n(.*?)```", open(PIP_PAGE).read(), re.S)
    return [block for block in blocks if "SetInputData(points)" not in block]


def test_readme_pip_snippets(tmp_path):
    """Each Python snippet of the pip page runs as written, in
    a folder where scan.xyz and scan.ply hold a sphere of radius 15 sampled
    about 1.2 apart (so that the snippets' offset of 2 closes it), and the
    files it writes hold a closed shell."""
    from vtkmodules.vtkIOPLY import vtkPLYWriter
    snippets = readme_pip_snippets()
    assert len(snippets) >= 4, "the pip page's snippets"
    points = nvclouds.sphere_points(2000, 15.0)
    np.savetxt(str(tmp_path / "scan.xyz"), points)
    writer = vtkPLYWriter()
    writer.SetInputData(nvclouds.cloud(points))
    writer.SetFileName(str(tmp_path / "scan.ply"))
    writer.Write()
    try:
        import pyvista  # noqa: F401
        has_pyvista = True
    except ImportError:
        has_pyvista = False
    ran = 0
    for number, code in enumerate(snippets):
        if "import pyvista" in code and not (has_pyvista and WHEEL):
            # pyvista finds the accessor through the wheel's entry point.
            print("snippet %d skipped: %s" % (number, "not the wheel" if has_pyvista else "no pyvista"))
            continue
        stl = tmp_path / "shell.stl"
        if stl.exists():
            stl.unlink()
        result = subprocess.run(nvtesting.python_command() + ["-c", code], cwd=str(tmp_path),
                                capture_output=True, text=True)
        assert result.returncode == 0, "snippet %d:\n%s\n%s" % (number, code, nvtesting.explain(result))
        assert "Traceback" not in result.stderr and "refused" not in result.stdout, result.stdout + result.stderr
        print("snippet %d: %s" % (number, result.stdout.strip().replace("\n", " | ")[-200:]))
        if '"shell.stl"' in code:
            surface = _read(str(stl))
            triangles, open_edges, _ = nvtesting.merged_surface(surface)
            assert triangles > 1000 and open_edges == 0, (number, triangles, open_edges)
        ran += 1
    assert ran >= 3


# --- The project's other Python tests, against the wheel (ctest runs them
# against the CMake build's package, each on its own), each module with
# pytest in a child process, as ctest runs it. Paths in Testing/Python; the
# numerical ones (the core's results, whatever the vtk) in one environment.
SHARED_MODULES = {
    "package/test_python_package.py": [],
    "filter/test_robustness.py": [],
    "fidelity/test_reference_scheme.py": [],
    "filter/test_volume_off.py": [],
    "filter/test_pipeline_vtk.py": ["--trefoil", TREFOIL],
}
NUMERICAL_MODULES = {"filter/test_robustness.py", "fidelity/test_reference_scheme.py"}


@only_wheel
@pytest.mark.parametrize("module", [pytest.param(m, marks=not_again_per_vtk) if m in NUMERICAL_MODULES else m
                                    for m in sorted(SHARED_MODULES)])
def test_shared_module(module):
    """A test module of the CMake build's package passes with the wheel."""
    start = time.perf_counter()
    result = subprocess.run([sys.executable, "-m", "pytest", "-p", "no:cacheprovider", "-v", "-r", "s", "-s",
                             os.path.join(TESTS, module)] + SHARED_MODULES[module],
                            capture_output=True, text=True, cwd=TESTS)
    print(result.stdout[-3000:])
    print("%s: %.1f s" % (module, time.perf_counter() - start))
    assert result.returncode == 0 and "FAILED" not in result.stdout, nvtesting.explain(result)
