# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""Helpers shared by the Python tests: surface checks, child processes and
scratch folders. (The point clouds are in nvclouds.py.)"""
import atexit
import os
import re
import shlex
import shutil
import sys
import tempfile

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkFiltersCore import (vtkCleanPolyData, vtkFeatureEdges, vtkMassProperties,
                                      vtkPolyDataConnectivityFilter)


def python_command():
    """The command that runs a Python with the same narrowvolume package as
    this one: $NV_PYTHON if set, else pvpython for the CMake build's package,
    else this interpreter (the wheel's)."""
    if os.environ.get("NV_PYTHON"):
        return shlex.split(os.environ["NV_PYTHON"])
    import narrowvolume
    return [sys.executable] if narrowvolume.FLAVOUR == "wheel" else ["pvpython"]


def run_filter(cloud, **settings):
    """The filter on a point set with the given properties, updated: returns
    (the filter, {field data array: its values as a list}, [its warnings])."""
    from vtkmodules.vtkCommonCore import vtkCommand
    from narrowvolume import vtkNarrowVolumeReconstruction
    f = vtkNarrowVolumeReconstruction()
    warnings = []

    def on_warning(caller, event, text):
        warnings.append(str(text))

    on_warning.CallDataType = "string0"
    f.AddObserver(vtkCommand.WarningEvent, on_warning)
    f.SetInputData(cloud)
    for key, value in settings.items():
        getattr(f, "Set" + key)(value)
    f.Update()
    field = f.GetOutput(0).GetFieldData()
    figures = {field.GetArrayName(a): vtk_to_numpy(field.GetArray(a)).ravel().tolist()
               for a in range(field.GetNumberOfArrays())}
    return f, figures, warnings


def boundary_edges(surface):
    edges = vtkFeatureEdges()
    edges.SetInputData(surface)
    edges.BoundaryEdgesOn()
    edges.NonManifoldEdgesOn()
    edges.FeatureEdgesOff()
    edges.ManifoldEdgesOff()
    edges.Update()
    return edges.GetOutput().GetNumberOfCells()


def volume_of(surface):
    """The signed volume a closed surface encloses (divergence theorem; normals point out of the shell)."""
    if surface.GetNumberOfPolys() == 0:
        return 0.0
    xyz = vtk_to_numpy(surface.GetPoints().GetData()).astype(float)
    triangles = vtk_to_numpy(surface.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    a, b, c = xyz[triangles[:, 0]], xyz[triangles[:, 1]], xyz[triangles[:, 2]]
    return float(np.einsum("ij,ij->i", a, np.cross(b, c)).sum() / 6.0)


def merged_surface(surface):
    """Merges the coincident points of surface pieces (exactly); returns
    (triangles, open edges, area)."""
    clean = vtkCleanPolyData()
    clean.SetInputData(surface)
    clean.SetTolerance(0.0)
    clean.Update()
    mass = vtkMassProperties()
    mass.SetInputData(clean.GetOutput())
    mass.Update()
    return clean.GetOutput().GetNumberOfPolys(), boundary_edges(clean.GetOutput()), mass.GetSurfaceArea()


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


def regions(surface):
    connectivity = vtkPolyDataConnectivityFilter()
    connectivity.SetInputData(surface)
    connectivity.SetExtractionModeToAllRegions()
    connectivity.Update()
    return connectivity.GetNumberOfExtractedRegions()


def points_of(dataset):
    return vtk_to_numpy(dataset.GetPoints().GetData())


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


def _vertices_by_edge(surface, origin, h):
    """{(i, j, k, axis) of the grid edge: fraction of h along it} for the
    surface's vertices, and the number within 1e-4 h of a node (which cannot
    tell their edge)."""
    u = (points_of(surface).astype(float) - np.asarray(origin)) / h
    off = np.abs(u - np.round(u))
    axis = off.argmax(axis=1)
    at_node = off.max(axis=1) <= 1e-4
    rows = np.arange(len(u))[~at_node]
    edges = {}
    for r in rows:
        a = axis[r]
        key = tuple(int(np.floor(u[r, b])) if b == a else int(round(u[r, b])) for b in range(3)) + (int(a),)
        edges[key] = u[r, a] - np.floor(u[r, a])
    return edges, int(at_node.sum())


def cut_edge_shift(surface, reference, origin, h, margin=1e-3):
    """Whether the surface's vertices lie on the reference's cut edges of the
    grid, one each; then the largest move along an edge (in h) from the
    reference's vertex, itself first moved `margin` h off the nodes (the
    filter keeps its vertices that far from them). -1 if the edges differ."""
    ours, ours_at_nodes = _vertices_by_edge(surface, origin, h)
    theirs, theirs_at_nodes = _vertices_by_edge(reference, origin, h)
    shift, unmatched = 0.0, 0
    for key, t in ours.items():
        if key in theirs:
            shift = max(shift, abs(t - min(1.0 - margin, max(margin, theirs[key]))))
        elif abs(t - margin) < 1e-6 or abs(t - 1.0 + margin) < 1e-6:
            unmatched += 1  # the reference's vertex sits on the node
        else:
            return -1.0
    same = ours_at_nodes == 0 and unmatched == theirs_at_nodes and len(ours) - unmatched == len(theirs)
    return shift if same else -1.0


def face_normal_roughness(surface):
    """Mean angle (degrees) between the normals of triangles that share an
    edge: 0 for a plane, small for a smooth surface, larger for a wrinkled one."""
    from vtkmodules.vtkFiltersCore import vtkTriangleFilter

    triangles = vtkTriangleFilter()
    triangles.SetInputData(surface)
    triangles.Update()
    mesh = triangles.GetOutput()
    x = points_of(mesh)
    cells = vtk_to_numpy(mesh.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    n = np.cross(x[cells[:, 1]] - x[cells[:, 0]], x[cells[:, 2]] - x[cells[:, 0]])
    length = np.linalg.norm(n, axis=1)
    # Slivers of zero area (flying edges makes a few where phi = 0 at a node) have no normal.
    cells, n = cells[length > 0], n[length > 0] / length[length > 0][:, None]
    # Each edge, as a sorted vertex pair, with the triangle it belongs to.
    edges = np.vstack([cells[:, [0, 1]], cells[:, [1, 2]], cells[:, [2, 0]]])
    edges.sort(axis=1)
    owner = np.tile(np.arange(len(cells)), 3)
    order = np.lexsort((edges[:, 1], edges[:, 0]))
    edges, owner = edges[order], owner[order]
    same = np.all(edges[1:] == edges[:-1], axis=1)
    a, b = owner[:-1][same], owner[1:][same]
    cosine = np.clip((n[a] * n[b]).sum(axis=1), -1.0, 1.0)
    return float(np.degrees(np.arccos(cosine)).mean())


def euler_characteristic(surface):
    """V - E + F of a triangle mesh: 2 per closed sphere-like sheet, 2 less for
    every tunnel (a hole through the shell's wall, or a handle)."""
    cells = vtk_to_numpy(surface.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    edges = np.vstack([cells[:, [0, 1]], cells[:, [1, 2]], cells[:, [2, 0]]])
    edges.sort(axis=1)
    unique_edges = np.unique(edges, axis=0)
    used = np.unique(cells)
    return int(len(used) - len(unique_edges) + len(cells))
