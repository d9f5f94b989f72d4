# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""Helpers shared by the Python tests: the filter run once, child processes
and scratch folders. The point clouds are in Data/nvclouds.py and the
surface measures in Data/nvmeasures.py (the benchmarks use them too); the
measures are given here as well, as the tests have always called them
(nvtesting.merged_surface, ...)."""
import atexit
import os
import re
import shlex
import shutil
import sys
import tempfile

from vtkmodules.util.numpy_support import vtk_to_numpy

from nvmeasures import (boundary_edges, boundary_of, cut_edge_shift, euler_characteristic,  # noqa: F401
                        face_normal_roughness, merged_surface, points_of, regions, regions_of, sheet_volumes,
                        volume_of)


def python_command():
    """The command that runs a Python with the same narrowvolume package as
    this one: $NV_PYTHON if set, else pvpython for the CMake build's package,
    else this interpreter (the wheel's)."""
    if os.environ.get("NV_PYTHON"):
        return shlex.split(os.environ["NV_PYTHON"])
    import narrowvolume
    return [sys.executable] if narrowvolume.FLAVOUR == "wheel" else ["pvpython"]


def _run_filter(cloud, kinds, settings):
    """The filter updated, and what it said of each kind ("warnings",
    "errors"; an observer takes each kind asked for, so VTK does not print it)."""
    from vtkmodules.vtkCommonCore import vtkCommand
    from narrowvolume import vtkNarrowVolumeReconstruction
    f = vtkNarrowVolumeReconstruction()
    said = {kind: [] for kind in kinds}

    def listener(kind):
        def on_event(caller, event, text):
            said[kind].append(str(text))
        on_event.CallDataType = "string0"
        return on_event

    events = {"warnings": vtkCommand.WarningEvent, "errors": vtkCommand.ErrorEvent}
    for kind in kinds:
        f.AddObserver(events[kind], listener(kind))
    f.SetInputData(cloud)
    for key, value in settings.items():
        if hasattr(f, "RemoveAll" + key):  # a list property (DrainHolePositions): its points
            getattr(f, "RemoveAll" + key)()
            for point in value:
                getattr(f, "Add" + key[:-1])(*point)
        else:
            getattr(f, "Set" + key)(value)
    f.Update()
    field = f.GetOutput(0).GetFieldData()
    figures = {field.GetArrayName(a): vtk_to_numpy(field.GetArray(a)).ravel().tolist()
               for a in range(field.GetNumberOfArrays())}
    return f, figures, said


def run_filter(cloud, **settings):
    """The filter on a point set with the given properties, updated: returns
    (the filter, {field data array: its values as a list}, [its warnings])."""
    f, figures, said = _run_filter(cloud, ("warnings",), settings)
    return f, figures, said["warnings"]


def run_filter_said(cloud, **settings):
    """The same, with its errors too: (the filter, figures, [warnings], [errors])."""
    f, figures, said = _run_filter(cloud, ("warnings", "errors"), settings)
    return f, figures, said["warnings"], said["errors"]


def split_cloud_script(cloud):
    """A ParaView ProgrammableSource script that gives piece p of n an uneven
    share of the points of the .vtp file `cloud`, in shuffled order (so every
    piece spreads over the whole shape): shares 3:0 for 2 pieces and 5:1:0:2
    for 4 (one piece empty), equal shares otherwise."""
    return """
import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline as sddp
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
info = self.GetOutputInformation(0)
piece, pieces = info.Get(sddp.UPDATE_PIECE_NUMBER()), info.Get(sddp.UPDATE_NUMBER_OF_PIECES())
reader = vtkXMLPolyDataReader()
reader.SetFileName(%r)
reader.Update()
xyz = vtk_to_numpy(reader.GetOutput().GetPoints().GetData()).astype(float)
xyz = xyz[np.random.default_rng(7).permutation(len(xyz))]
weights = np.array({2: [3.0, 0.0], 4: [5.0, 1.0, 0.0, 2.0]}.get(pieces, [1.0] * pieces))
ends = np.round(np.cumsum(weights) / weights.sum() * len(xyz)).astype(int)
begin = 0 if piece == 0 else ends[piece - 1]
points = vtkPoints()
points.SetData(numpy_to_vtk(np.ascontiguousarray(xyz[begin:ends[piece]]), deep=1))
self.GetOutput().SetPoints(points)
""" % cloud


# Lines that say why a child process failed: VTK's and ParaView's errors, X
# and MPI failures, Python exceptions, crashes.
_EXPLAINING = re.compile(r"ERROR|Error|error:|ERR\||FAILED|Traceback|Exception|X connection|X server|XIO|"
                         r"Segmentation|Aborted|abort|core dumped|Killed|signal|mpiexec|MPI_ABORT|"
                         r"cannot|not found|No such")


def build_of(plugin_path):
    """The build folder of a compiled plugin,
    BUILD/lib/paraview-X.Y/plugins/NarrowVolume/NarrowVolume.so: what
    scripts/build.sh takes as BUILD_DIR."""
    folder = os.path.abspath(plugin_path)
    for _ in range(5):
        folder = os.path.dirname(folder)
    return folder


def explain(run, tail=8):
    """A failed subprocess.run(..., capture_output=True, text=True) in a few
    lines: its exit code, every line of its output that names an error (however
    early it came), and the last lines of stderr."""
    lines = [line for line in (run.stdout or "").splitlines() + (run.stderr or "").splitlines()
             if _EXPLAINING.search(line)]
    last = (run.stderr or run.stdout or "").splitlines()[-tail:]
    picked = lines[:20] + (["..."] if len(lines) > 20 else [])
    return "exit code %s\n    %s\n  last lines:\n    %s" % (
        run.returncode, "\n    ".join(picked) or "(no line names an error)", "\n    ".join(last))


_scratch = []
_keep_scratch = [bool(os.environ.get("NV_KEEP_SCRATCH"))]


def scratch_folder(prefix="nv-test-"):
    """A new temporary folder, removed when the process ends unless a test
    failed (a failed assert or check, or an uncaught exception, keeps it, and
    says where) or NV_KEEP_SCRATCH is set."""
    folder = tempfile.mkdtemp(prefix=prefix)
    _scratch.append(folder)
    return folder


def keep_scratch():
    """Keeps the scratch folders (conftest.py calls it when a test fails)."""
    _keep_scratch[0] = True


def _remove_scratch():
    for folder in _scratch:
        if _keep_scratch[0]:
            print("scratch folder kept: %s" % folder)
        else:
            shutil.rmtree(folder, ignore_errors=True)


def _keep_on_exception(kind, value, traceback):
    _keep_scratch[0] = True
    _previous_excepthook(kind, value, traceback)


_previous_excepthook = sys.excepthook
sys.excepthook = _keep_on_exception
atexit.register(_remove_scratch)


class Checker:
    """Counts failed checks and prints each one; exit code via finish(). For
    the scripts that run inside other processes (mpi_vtk_script.py, one per
    MPI rank); the tests themselves are pytest modules with plain asserts."""

    def __init__(self, name):
        self.name = name
        self.failures = 0

    def check(self, condition, message):
        if not condition:
            self.failures += 1
            _keep_scratch[0] = True
            print("FAILED:", message)
        return condition

    def finish(self):
        print("%s: %s (%d failed checks)" % (self.name, "FAILED" if self.failures else "passed", self.failures))
        sys.exit(1 if self.failures else 0)


