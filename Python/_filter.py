# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""vtkNarrowVolumeReconstruction of the wheel: the C++ filter's twin in Python.

The run is the core's (narrowvolume._core, the same C++ as the C++ filter's,
its loops on std::threads): this file only converts, as
vtkNarrowVolumeReconstruction.cxx does, in the order of the core's
nvOutputs.h. The surface comes from the user's vtkFlyingEdges3D.

Not in this flavour: SetController (distributed runs under MPI need the
VTK-wrapped filter of the CMake build).
"""
import operator
import time

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.util.vtkAlgorithm import VTKPythonAlgorithmBase
from vtkmodules.vtkCommonCore import (VTK_FLOAT, vtkCommand, vtkDoubleArray, vtkFloatArray, vtkIdTypeArray,
                                      vtkInformationVector, vtkIntArray, vtkObject, vtkOutputWindow, vtkPoints,
                                      vtkTypeInt32Array, vtkTypeInt64Array, vtkUnsignedCharArray)
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkDataObject, vtkImageData, vtkPointSet, vtkPolyData
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline as sddp
from vtkmodules.vtkFiltersCore import vtkFlyingEdges3D

from . import _core
from ._properties import PROPERTIES

_CLASS_NAME = "vtkNarrowVolumeReconstruction"


class vtkNarrowVolumeReconstruction(VTKPythonAlgorithmBase):
    """Reconstructs a narrow volume (a thick shell) around an unorganized point cloud.

    The phase-field method of Li et al., "Fast and efficient narrow volume
    reconstruction from scattered data", Pattern Recognition 48 (2015): a
    uniform grid of spacing h around the points, the narrow band of nodes
    whose distance d to the nearest point is within eta/2 of the offset l,
    phi0 = tanh((l - d) / (sqrt(2) xi)) (eq. 2), and time steps of the
    Allen-Cahn equation with an edge-stopping function on the band only
    (eq. 10-12). phi is close to +1 inside the shell and -1 outside; phi = 0
    is the pair of offset surfaces at distance l on either side of the points.

    Input: any vtkPointSet (only its points are used).
    Output port 0 (vtkImageData): point array "phi" (float, in [-1, 1]), and
    on request "InitialPhi", "Distance" and "NarrowBand"; field data
    "NumberOfIterations", "NarrowBandNodes" and "RelativeChange".
    Output port 1 (vtkPolyData): the phi = 0 surfaces, by vtkFlyingEdges3D,
    with point normals.

    The properties, their defaults and the outputs are the C++ filter's
    (Filters/vtkNarrowVolumeReconstruction.h), and phi is bit-identical to
    its phi on the same input. Ctrl-C during Update() stops the run: the
    outputs are empty and an error says so.

        f = vtkNarrowVolumeReconstruction()
        f.SetInputData(points)          # any vtkPointSet
        f.SetOffsetDistance(0.1)
        f.Update()
        volume, surface = f.GetOutput(0), f.GetOutput(1)
    """

    def __init__(self):
        VTKPythonAlgorithmBase.__init__(self, nInputPorts=1, inputType="vtkPointSet", nOutputPorts=2)
        # The properties live in the core's own settings: a default-constructed
        # nv::Settings holds the C++ defaults.
        self._settings = _core.Settings()
        self._clear_results()

    def _clear_results(self):
        self._band_nodes = 0
        self._grid_nodes = 0
        self._changes = ()
        self._times = (0.0, 0.0, 0.0)

    # --- Inputs and outputs, as the C++ class has them.
    def FillOutputPortInformation(self, port, info):
        """Port 0 gives a vtkImageData (the volume), port 1 a vtkPolyData (the surface)."""
        info.Set(vtkDataObject.DATA_TYPE_NAME(), "vtkImageData" if port == 0 else "vtkPolyData")
        return 1

    def SetInputData(self, data):
        """The input point set (any vtkPointSet)."""
        self.SetInputDataObject(0, data)

    def GetOutput(self, port=0):
        """Output `port`: 0 the volume (vtkImageData), 1 the surface (vtkPolyData)."""
        return self.GetOutputDataObject(port)

    def GetVolumeOutput(self):
        """Output port 0, the volume (vtkImageData)."""
        return self.GetOutputDataObject(0)

    def GetSurfaceOutput(self):
        """Output port 1, the surface (vtkPolyData)."""
        return self.GetOutputDataObject(1)

    # --- Results of the last run.
    def GetNumberOfIterations(self):
        """Time steps the last run took."""
        return len(self._changes)

    def GetNumberOfBandNodes(self):
        """Narrow band nodes of the last run."""
        return self._band_nodes

    def GetNumberOfGridNodes(self):
        """Grid nodes of the last run."""
        return self._grid_nodes

    def GetRelativeChanges(self):
        """The relative change ||phi^{n+1} - phi^n||_2 / ||phi^n||_2 of each time step of the last run."""
        return tuple(self._changes)

    def GetSetupTime(self):
        """Wall-clock seconds of the last run's set-up (distance and band)."""
        return self._times[0]

    def GetEvolutionTime(self):
        """Wall-clock seconds of the last run's time steps."""
        return self._times[1]

    def GetOutputTime(self):
        """Wall-clock seconds of the last run's outputs (volume and surface)."""
        return self._times[2]

    # --- Messages, as vtkErrorMacro and vtkWarningMacro give them.
    def _message(self, event, text):
        if not vtkObject.GetGlobalWarningDisplay():
            return
        if self.HasObserver(event):
            self.InvokeEvent(event, text)
            return
        kind = "ERROR" if event == vtkCommand.ErrorEvent else "Warning"
        line = "%s: In %s\n%s (%s): %s\n\n" % (kind, __file__, _CLASS_NAME, hex(id(self)), text)
        window = vtkOutputWindow.GetInstance()
        if event == vtkCommand.ErrorEvent:
            window.DisplayErrorText(line)
        else:
            window.DisplayWarningText(line)

    def _error(self, text):
        self._message(vtkCommand.ErrorEvent, text)

    def _warning(self, text):
        self._message(vtkCommand.WarningEvent, text)

    # --- The pipeline passes.
    def RequestInformation(self, request, inInfoVec, outInfoVec):
        """Declares the volume's grid (whole extent, origin, spacing, float
        scalars), which follows the input's points: the input is brought up
        to date here, and the data pass finds it so."""
        volume_info = outInfoVec.GetInformationObject(0)
        bounds = (1.0, 0.0, 1.0, 0.0, 1.0, 0.0)
        if self.GetNumberOfInputConnections(0) > 0:
            connection = self.GetInputConnection(0, 0)
            producer = connection.GetProducer()
            requests = vtkInformationVector()
            requests.SetNumberOfInformationObjects(producer.GetNumberOfOutputPorts())
            piece = requests.GetInformationObject(connection.GetIndex())
            piece.Set(sddp.UPDATE_PIECE_NUMBER(), 0)
            piece.Set(sddp.UPDATE_NUMBER_OF_PIECES(), 1)
            piece.Set(sddp.UPDATE_NUMBER_OF_GHOST_LEVELS(), 0)
            producer.Update(connection.GetIndex(), requests)
            data = vtkPointSet.GetData(inInfoVec[0], 0)
            if data is not None and data.GetNumberOfPoints() > 0:
                bounds = data.GetBounds()
        plan = _core.MakePlan(self._settings, list(bounds))
        if not plan.Valid():
            volume_info.Set(sddp.WHOLE_EXTENT(), (0, -1, 0, -1, 0, -1), 6)  # RequestData says why
            return 1
        grid = plan.TheGrid
        nx, ny, nz = grid.Dims
        volume_info.Set(sddp.WHOLE_EXTENT(), (0, nx - 1, 0, ny - 1, 0, nz - 1), 6)
        volume_info.Set(vtkDataObject.ORIGIN(), tuple(grid.Origin), 3)
        volume_info.Set(vtkDataObject.SPACING(), (grid.Spacing,) * 3, 3)
        vtkDataObject.SetPointDataActiveScalarInfo(volume_info, VTK_FLOAT, 1)
        return 1

    def RequestUpdateExtent(self, request, inInfoVec, outInfoVec):
        """The shell depends on every point: asks for the whole cloud."""
        info = inInfoVec[0].GetInformationObject(0)
        info.Set(sddp.UPDATE_PIECE_NUMBER(), 0)
        info.Set(sddp.UPDATE_NUMBER_OF_PIECES(), 1)
        info.Set(sddp.UPDATE_NUMBER_OF_GHOST_LEVELS(), 0)
        return 1

    def RequestData(self, request, inInfoVec, outInfoVec):
        """Runs the core on the input's points and makes the two outputs."""
        volume = vtkImageData.GetData(outInfoVec, 0)
        surface = vtkPolyData.GetData(outInfoVec, 1)
        volume.Initialize()
        surface.Initialize()
        self._clear_results()
        # One process computes everything: a request for another piece is left empty.
        piece_info = outInfoVec.GetInformationObject(1)
        if piece_info.Has(sddp.UPDATE_PIECE_NUMBER()) and piece_info.Get(sddp.UPDATE_PIECE_NUMBER()) > 0:
            return 1
        try:
            ok = self._run(vtkPointSet.GetData(inInfoVec[0], 0), volume, surface)
        except KeyboardInterrupt:
            self._error("Interrupted (Ctrl-C): the outputs are empty.")
            ok = False
        if not ok:
            volume.Initialize()
            surface.Initialize()
            return 1
        self._add_run_summary(volume)
        self.UpdateProgress(1.0)
        return 1

    def _run(self, data, volume, surface):
        monitor = _core.Monitor(report=self.UpdateProgress, poll=lambda: bool(self.GetAbortExecute()))
        run = _core.Reconstruction(self._settings, monitor)
        if not run.Run(_points_of(data)):
            if run.Error():
                self._error(run.Error())
            return False
        self._grid_nodes = run.GetGrid().NumberOfNodes()
        self._band_nodes = run.NumberOfBandNodes()
        self._changes = tuple(run.RelativeChanges())
        start = time.perf_counter()
        ok, explained = self._produce_outputs(run, monitor, volume, surface)
        self._times = (run.SetupSeconds(), run.EvolutionSeconds(), time.perf_counter() - start)
        if ok and surface.GetNumberOfPoints() == 0 and not explained:
            self._warning(_core.EmptySurfaceWarning(run.GetSettings(), run.GetGrid().Spacing))
        return ok

    def _produce_outputs(self, run, monitor, volume, surface):
        """The volume and the surface of a finished run (nvOutputs.h): (ok, whether a warning explained an empty surface)."""
        settings = run.GetSettings()
        grid = run.GetGrid()
        nx, ny, nz = grid.Dims
        volume.SetOrigin(tuple(grid.Origin))
        volume.SetSpacing((grid.Spacing,) * 3)
        volume.SetExtent(0, nx - 1, 0, ny - 1, 0, nz - 1)
        if _core.SurfaceBySlabs(settings):
            # The surface without a dense volume: slab by slab.
            monitor.Stage(*_core.SlabStage)
            surface.ShallowCopy(surface_by_slabs(run, monitor))
            return not monitor.Aborted(), False

        nodes = nx * ny * nz
        phi = _new_array(vtkFloatArray, "phi", nodes)
        arrays = {"phi": vtk_to_numpy(phi)}
        if settings.OutputVolume:
            volume.GetPointData().SetScalars(phi)
            for wanted, name, key, kind in ((settings.OutputInitialPhi, "InitialPhi", "initial_phi", vtkFloatArray),
                                            (settings.OutputDistance, "Distance", "distance", vtkFloatArray),
                                            (settings.OutputNarrowBand, "NarrowBand", "band", vtkUnsignedCharArray)):
                if wanted:
                    array = _new_array(kind, name, nodes)
                    volume.GetPointData().AddArray(array)
                    arrays[key] = vtk_to_numpy(array)
        else:
            self._warning(_core.OneSheetNeedsGridWarning())
        monitor.Stage(*_core.VolumeStage)
        run.FillVolume(k_begin=0, k_end=nz, **arrays)
        if monitor.Aborted():
            return False, False

        # The surface, of all sheets or some: choosing sheets works on a copy, phi stays phi.
        monitor.Stage(*_core.SurfaceStage)
        contoured, explained = phi, False
        if settings.KeptSheets != _core.Sheets.Both:
            copy = np.array(arrays["phi"])
            cavities = _core.KeepSheets(grid, copy, settings.KeptSheets)
            contoured = numpy_to_vtk(copy, deep=0)
            contoured._kept = copy  # the array borrows copy's memory
            explained = _core.NoInnerSheet(settings, cavities)
            if explained:
                self._warning(_core.NoInnerSheetWarning())
        surface.ShallowCopy(extract_surface(grid, contoured, 0, nz, monitor))
        return not monitor.Aborted(), explained

    def _add_run_summary(self, volume):
        """NumberOfIterations, NarrowBandNodes and RelativeChange in the volume's field data."""
        iterations = vtkIntArray()
        iterations.SetName("NumberOfIterations")
        iterations.InsertNextValue(self.GetNumberOfIterations())
        band = vtkIdTypeArray()
        band.SetName("NarrowBandNodes")
        band.InsertNextValue(self._band_nodes)
        changes = vtkDoubleArray()
        changes.SetName("RelativeChange")
        for change in self._changes:
            changes.InsertNextValue(change)
        for array in (iterations, band, changes):
            volume.GetFieldData().AddArray(array)


def _points_of(data):
    """The points of a point set as an (n, 3) float64 array in C order."""
    if data is None or data.GetPoints() is None:
        return np.zeros((0, 3))
    return np.ascontiguousarray(vtk_to_numpy(data.GetPoints().GetData()), dtype=np.float64).reshape(-1, 3)


def _new_array(kind, name, tuples):
    array = kind()
    array.SetName(name)
    array.SetNumberOfTuples(tuples)
    return array


# --- The surface, as Filters/vtkNarrowVolumeSurface.cxx makes it: contoured
# in the grid's own frame (origin 0), then moved to world coordinates in
# double precision, so that a cloud far from the origin keeps its precision.
def _contour_local(grid, scalars, k_begin, k_end, monitor=None):
    nx, ny, _ = grid.Dims
    image = vtkImageData()
    image.SetOrigin(0.0, 0.0, 0.0)
    image.SetSpacing((grid.Spacing,) * 3)
    image.SetExtent(0, nx - 1, 0, ny - 1, k_begin, k_end - 1)
    image.GetPointData().SetScalars(scalars)
    contour = vtkFlyingEdges3D()
    contour.SetInputData(image)
    contour.SetValue(0, 0.0)
    contour.ComputeNormalsOn()
    contour.ComputeGradientsOff()
    contour.ComputeScalarsOff()
    failure = []
    if monitor is not None:
        def forward(caller, event):
            # The isosurfacer's progress to the monitor, the monitor's abort to it.
            try:
                monitor.Progress(caller.GetProgress())
                stop = monitor.Aborted()
            except BaseException as error:  # Ctrl-C: raised again below
                failure.append(error)
                stop = True
            if stop:
                caller.SetAbortExecute(1)
        contour.AddObserver(vtkCommand.ProgressEvent, forward)
    contour.Update()
    if failure:
        raise failure[0]
    return contour.GetOutput()


def _world_points(local, grid):
    """Grid-frame float points as double world points."""
    xyz = vtk_to_numpy(local.GetData()).astype(np.float64) + np.asarray(grid.Origin)
    points = vtkPoints()
    points.SetDataTypeToDouble()
    points.SetData(numpy_to_vtk(np.ascontiguousarray(xyz), deep=1))
    return points


def extract_surface(grid, phi, k_begin, k_end, monitor=None):
    """The phi = 0 surface of a dense phi (a vtkDataArray, the node layers [k_begin, k_end))."""
    surface = _contour_local(grid, phi, k_begin, k_end, monitor)
    if surface.GetPoints() is not None:
        surface.SetPoints(_world_points(surface.GetPoints(), grid))
    return surface


class _Growing:
    """Rows appended to a numpy array that grows in place, handed to VTK
    without a copy at the end. It starts at 64 MiB of address space, which
    the system maps on demand (untouched pages take no memory) and which
    malloc serves by mmap: growing and the final trim are then mremap calls,
    without copies or freed pieces left behind in the heap."""

    START = 1 << 26  # bytes

    def __init__(self, dtype, columns):
        rows = self.START // (np.dtype(dtype).itemsize * columns)
        self.data = np.empty((rows, columns), dtype=dtype)
        self.size = 0

    def append(self, rows):
        needed = self.size + len(rows)
        if needed > len(self.data):
            self.data.resize((max(needed, 2 * len(self.data)), self.data.shape[1]), refcheck=False)
        self.data[self.size:needed] = rows
        self.size = needed

    def to_vtk(self, kind, name):
        """The rows as a VTK array of class kind that uses the same memory (which it keeps alive)."""
        self.data.resize((self.size, self.data.shape[1]), refcheck=False)
        array = kind()
        array.SetName(name)
        array.SetNumberOfComponents(self.data.shape[1])
        array.SetVoidArray(self.data, self.data.size, 1)
        array._numpy_reference = self.data  # as numpy_to_vtk does
        return array


def surface_by_slabs(run, monitor):
    """The same surface without the dense volume: the slabs that hold band
    nodes (the core's SurfaceSlabs) filled and contoured one at a time, the
    vertices on the plane two slabs share merged. Each slab's part goes
    straight into the output's arrays, which grow in place: memory holds the
    surface about once, as the C++ filter's does."""
    grid = run.GetGrid()
    nx, ny, nz = grid.Dims
    origin = np.asarray(grid.Origin)
    points, normals = _Growing(np.float64, 3), _Growing(np.float32, 3)
    # 32-bit cells (vtkCellArray's own storage option) while ids and offsets
    # fit: half the memory of vtkIdType's, the largest part of a surface.
    connectivity = _Growing(np.int32, 1)
    count = 0
    below = {}  # (x, y) of the vertices the previous slab made on this slab's first plane -> id
    previous_end = -1
    for k_begin, k_end in run.SurfaceSlabs(0, nz):
        if k_begin != previous_end - 1:
            below = {}  # the slab below was skipped
        previous_end = k_end
        monitor.Progress(k_begin / nz)
        if monitor.Aborted():
            break
        slab = np.empty(nx * ny * (k_end - k_begin), dtype=np.float32)
        run.FillVolume(phi=slab, k_begin=k_begin, k_end=k_end, monitored=False)
        scalars = numpy_to_vtk(slab, deep=0)
        scalars.SetName("phi")
        piece = _contour_local(grid, scalars, k_begin, k_end)
        if piece.GetNumberOfPoints() == 0:
            below = {}
            continue
        xyz = vtk_to_numpy(piece.GetPoints().GetData())
        z_below = np.float32(k_begin * grid.Spacing)
        z_above = np.float32((k_end - 1) * grid.Spacing)
        ids = np.full(len(xyz), -1, dtype=np.int64)
        if below:
            for p in np.nonzero(xyz[:, 2] == z_below)[0]:
                ids[p] = below.get((xyz[p, 0].item(), xyz[p, 1].item()), -1)
        new = ids < 0
        added = int(new.sum())
        ids[new] = count + np.arange(added)
        count += added
        above = np.nonzero(new & (xyz[:, 2] == z_above))[0]
        below = {(xyz[p, 0].item(), xyz[p, 1].item()): int(ids[p]) for p in above}
        points.append(xyz[new] + origin)  # world coordinates, in double precision
        normals.append(vtk_to_numpy(piece.GetPointData().GetNormals())[new])
        cells = ids[vtk_to_numpy(piece.GetPolys().GetConnectivityArray())]
        if max(count, connectivity.size + len(cells)) >= 2 ** 31 and connectivity.data.dtype == np.int32:
            wide = _Growing(np.int64, 1)
            wide.append(connectivity.data[:connectivity.size])
            connectivity = wide
        connectivity.append(cells.reshape(-1, 1))

    surface = vtkPolyData()
    if count == 0:
        return surface
    kind = vtkTypeInt32Array if connectivity.data.dtype == np.int32 else vtkTypeInt64Array
    offsets = _Growing(connectivity.data.dtype, 1)
    offsets.append(np.arange(0, connectivity.size + 1, 3).reshape(-1, 1))
    polys = vtkCellArray()
    polys.SetData(offsets.to_vtk(kind, "Offsets"), connectivity.to_vtk(kind, "Connectivity"))
    world = vtkPoints()
    world.SetData(points.to_vtk(vtkDoubleArray, "Points"))
    surface.SetPoints(world)
    surface.GetPointData().SetNormals(normals.to_vtk(vtkFloatArray, "Normals"))
    surface.SetPolys(polys)
    return surface


# --- The properties, made from the table (_properties.py).
def _convert(prop, value):
    """A value as the C++ setter takes it: clamped like vtkSetClampMacro."""
    if prop.kind is float:
        value = float(value)
    else:
        value = operator.index(value)
        if prop.kind is bool:
            return bool(value)
    if prop.low is not None and value < prop.low:
        value = prop.low
    elif prop.high is not None and value > prop.high:
        value = prop.high
    return prop.kind(value)


def _install_properties(cls):
    defaults = _core.Settings()
    for prop in PROPERTIES:
        field_type = type(getattr(defaults, prop.field))
        default = prop.kind(getattr(defaults, prop.field))
        clamp = "" if prop.low is None else " Clamped to [%g, %g]." % (prop.low, prop.high)
        doc = "%s Default %r.%s" % (prop.doc, default, clamp)

        def getter(self, prop=prop):
            return prop.kind(getattr(self._settings, prop.field))

        def setter(self, value, prop=prop, field_type=field_type):
            value = _convert(prop, value)
            if getattr(self, "Get" + prop.name)() != value:
                setattr(self._settings, prop.field, field_type(value))
                self.Modified()

        getter.__doc__ = "%s\n\n%s" % (prop.name, doc)
        setter.__doc__ = "Sets %s.\n\n%s" % (prop.name, doc)
        getter.__name__, setter.__name__ = "Get" + prop.name, "Set" + prop.name
        setattr(cls, getter.__name__, getter)
        setattr(cls, setter.__name__, setter)
        if prop.kind is bool:
            def on(self, prop=prop):
                getattr(self, "Set" + prop.name)(True)

            def off(self, prop=prop):
                getattr(self, "Set" + prop.name)(False)
            on.__doc__, off.__doc__ = "Sets %s on." % prop.name, "Sets %s off." % prop.name
            setattr(cls, prop.name + "On", on)
            setattr(cls, prop.name + "Off", off)
        if prop.low is not None:
            def low(self, prop=prop):
                return prop.low

            def high(self, prop=prop):
                return prop.high
            low.__doc__ = "The smallest value Set%s takes (%r)." % (prop.name, prop.low)
            high.__doc__ = "The largest value Set%s takes (%r)." % (prop.name, prop.high)
            setattr(cls, "Get%sMinValue" % prop.name, low)
            setattr(cls, "Get%sMaxValue" % prop.name, high)
        if prop.choices:
            # As VTK wraps a C++ enum: an int type, whose values are the class's constants.
            kind = type(prop.name + "Type", (int,), {"__doc__": "The values of %s." % prop.name,
                                                     "__module__": cls.__module__})
            setattr(cls, kind.__name__, kind)
        for constant, suffix, value in prop.choices:
            def choose(self, prop=prop, value=value):
                getattr(self, "Set" + prop.name)(value)
            choose.__doc__ = "Sets %s to %s (%d)." % (prop.name, constant, value)
            setattr(cls, constant, kind(value))
            setattr(cls, "Set%sTo%s" % (prop.name, suffix), choose)


_install_properties(vtkNarrowVolumeReconstruction)
