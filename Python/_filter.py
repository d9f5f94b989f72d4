# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""vtkNarrowVolumeReconstruction of the wheel: the C++ filter's twin in Python.

The run is the core's (narrowvolume._core, the same C++ as the C++ filter's,
its loops on std::threads), and so are the surface (marching cubes in the
band's bricks, as in the C++ filter), the small pieces' removal, the
warnings and the field data: one call of the core's nv::Reconstruct
(nvReconstruct.h) makes them, and this file only converts, as
vtkNarrowVolumeReconstruction.cxx does. The arrays the core fills reach VTK
without a copy.

Not in this flavour: SetController (distributed runs under MPI need the
VTK-wrapped filter of the CMake build).
"""
import operator

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.util.vtkAlgorithm import VTKPythonAlgorithmBase
from vtkmodules.vtkCommonCore import (VTK_FLOAT, vtkCommand, vtkDoubleArray, vtkFloatArray, vtkIdTypeArray,
                                      vtkInformationVector, vtkIntArray, vtkObject, vtkOutputWindow, vtkPoints,
                                      vtkTypeInt64Array, vtkUnsignedCharArray)
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkDataObject, vtkImageData, vtkPointSet, vtkPolyData, vtkTable
from vtkmodules.vtkCommonExecutionModel import vtkAlgorithm, vtkStreamingDemandDrivenPipeline as sddp

from . import _core
from . import _properties
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
    "NumberOfIterations", "NarrowBandNodes", "RelativeChange" (one value per
    step), "OffsetDistance" and "SampleSpacing" (l and h used),
    "MedianPointSpacing", "ClosingRadius", "AddedPoints", "NumberOfGaps",
    "LargestGap" (a radius), "LargestGapCenter", "PiercedGaps",
    "RemovedPieces" and "RemovedVoids".
    Output port 1 (vtkPolyData): the phi = 0 surfaces with point normals
    ("Normals") and double-precision points, made by the core (marching cubes
    on the signed distance phi implies, in the band's bricks), as the C++
    filter makes them: the same triangles, vertices and normals.

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
        self._samplings = _core.SamplingCache()  # the input's sampling, measured once per points
        self._stopped_before_data = False  # the information pass's measurement was stopped (abort)
        self._panel_labels = False  # SetPanelLabelsInMessages
        self._clear_results()

    def _clear_results(self):
        self._band_nodes = 0
        self._grid_nodes = 0
        self._changes = ()
        self._chosen = _core.Results()  # the results (RESULTS): zero before a run
        self._times = (0.0, 0.0, 0.0)
        self._sampling_time = 0.0

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

    # --- Figures of the last run (the results of the table's RESULTS are made below).
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

    def GetSamplingTime(self):
        """Wall-clock seconds spent measuring the points' spacing (nearest
        neighbours, for the automatic offset and MedianPointSpacing) in the
        last update; 0 when the points had not changed and the last
        measurement served."""
        return self._sampling_time

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
    def SetPanelLabelsInMessages(self, on):
        """Whether the warnings and errors name the properties by the labels of
        ParaView's panel ("Offset Distance") instead of their names
        (OffsetDistance, the default). The ParaView plugins turn it on; it is
        not a setting of the method."""
        self._panel_labels = bool(on)

    def GetPanelLabelsInMessages(self):
        """See SetPanelLabelsInMessages."""
        return self._panel_labels

    def _message(self, event, text):
        if self.GetPanelLabelsInMessages():
            text = _core.InPanelWords(text)  # the C++ filter's words (nv::InPanelWords)
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
    def FillInputPortInformation(self, port, info):
        info.Set(vtkAlgorithm.INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet")
        info.Append(vtkAlgorithm.INPUT_REQUIRED_DATA_TYPE(), "vtkTable")  # refused with a message (RequestData)
        return 1

    def RequestInformation(self, request, inInfoVec, outInfoVec):
        """Declares the volume's grid (whole extent, origin, spacing, float
        scalars), which follows the input's points and their sampling: the
        input is brought up to date here, and the data pass finds it so."""
        volume_info = outInfoVec.GetInformationObject(0)
        if self.GetNumberOfInputConnections(0) > 0:
            _update_input_piece(self.GetInputConnection(0, 0))
        data = vtkPointSet.GetData(inInfoVec[0], 0)
        bounds = (1.0, 0.0, 1.0, 0.0, 1.0, 0.0)
        if data is not None and data.GetNumberOfPoints() > 0:
            bounds = data.GetBounds()
        try:
            # The measurement shows its progress (seconds on a large cloud,
            # before the data pass) as the run's first stage; the data pass's
            # progress, which the pipeline starts again from 0, then fills
            # the rest. It stops when asked (AbortExecute, cleared first as
            # the data pass does, since it may hold the last run's): the data
            # pass then leaves the outputs empty.
            self.SetProgressShiftScale(0.0, 1.0)
            self.SetAbortExecute(0)
            monitor = _core.Monitor(report=self.UpdateProgress, poll=lambda: bool(self.GetAbortExecute()))
            sampling, measured = self._measure_sampling(data, monitor)
            self._stopped_before_data = sampling is None
            if sampling is None:
                return 1
            if measured:
                self.SetProgressShiftScale(_core.SamplingStage, 1.0 - _core.SamplingStage)
        except (KeyboardInterrupt, Exception) as error:  # RequestData reports the run's own errors
            volume_info.Set(sddp.WHOLE_EXTENT(), (0, -1, 0, -1, 0, -1), 6)
            self._error("%s while measuring the points' spacing: %s" % (type(error).__name__, error))
            return 0
        _declare_grid(volume_info, _core.MakePlan(self._settings, list(bounds), sampling.Statistics()))
        return 1

    def _measure_sampling(self, data, monitor):
        """The core's sampling of the input's points, measured once per
        points (object, modification time, count) by the core's
        SamplingCache, as the C++ filter's (None if the monitor stopped the
        measurement), and whether this call measured."""
        points = data.GetPoints() if data is not None else None
        # The C++ object's address (__this__): a Python wrapper's id() changes
        # whenever VTK hands out a new wrapper for the same points.
        key = (points.__this__, points.GetMTime(), points.GetNumberOfPoints()) if points else ("", 0, 0)
        return self._samplings.Get(key, lambda: _points_of(data), self._settings.NumberOfThreads, monitor)

    def RequestUpdateExtent(self, request, inInfoVec, outInfoVec):
        """The shell depends on every point: asks for the whole cloud."""
        info = inInfoVec[0].GetInformationObject(0)
        info.Set(sddp.UPDATE_PIECE_NUMBER(), 0)
        info.Set(sddp.UPDATE_NUMBER_OF_PIECES(), 1)
        info.Set(sddp.UPDATE_NUMBER_OF_GHOST_LEVELS(), 0)
        return 1

    def RequestData(self, request, inInfoVec, outInfoVec):
        """Runs the core on the input's points and makes the two outputs."""
        try:
            return self._request_data(inInfoVec, outInfoVec)
        finally:
            self.SetProgressShiftScale(0.0, 1.0)  # the information pass's measurement's share ends here

    def _request_data(self, inInfoVec, outInfoVec):
        volume = vtkImageData.GetData(outInfoVec, 0)
        surface = vtkPolyData.GetData(outInfoVec, 1)
        volume.Initialize()
        surface.Initialize()
        self._clear_results()
        if self._stopped_before_data:  # stopped in the information pass: no run, empty outputs
            self._stopped_before_data = False
            return 1
        # One process computes everything: a request for another piece is left empty.
        piece_info = outInfoVec.GetInformationObject(1)
        if piece_info.Has(sddp.UPDATE_PIECE_NUMBER()) and piece_info.Get(sddp.UPDATE_PIECE_NUMBER()) > 0:
            return 1
        if vtkTable.GetData(inInfoVec[0], 0) is not None:
            self._error(_core.TableInputError())
            return 1
        try:
            summary = self._run(vtkPointSet.GetData(inInfoVec[0], 0), volume, surface)
        except KeyboardInterrupt:
            self._error("Interrupted (Ctrl-C): the outputs are empty.")
            summary = None
        except Exception as error:  # e.g. MemoryError: reported as the C++ filter reports its errors
            self._error("%s: %s; the outputs are empty." % (type(error).__name__, error))
            summary = None
        if summary is None:
            volume.Initialize()
            surface.Initialize()
            return 1
        _add_field_data(volume, summary)
        self.UpdateProgress(1.0)
        return 1

    def _run(self, data, volume, surface):
        """The run and its outputs, as vtkNarrowVolumeReconstruction::RequestData:
        the core's nv::Reconstruct makes them; this converts. The run's
        summary, or None when it failed or stopped."""
        monitor = _core.Monitor(report=self.UpdateProgress, poll=lambda: bool(self.GetAbortExecute()))
        run = _core.Reconstruction(self._settings, monitor)
        sampling, _ = self._measure_sampling(data, monitor)
        # The measurement's seconds go to the first run that uses it (it may
        # have been made for this run's information pass).
        self._sampling_time = self._samplings.TakeSeconds()
        if sampling is None:  # stopped (AbortExecute)
            return None
        sink = _core.MeshSink()
        outcome = run.Reconstruct(_points_of(data), sampling, sink)
        if outcome.Ran:
            self._grid_nodes = run.GetGrid().NumberOfNodes()
            self._band_nodes = run.NumberOfBandNodes()
            self._changes = tuple(run.RelativeChanges())
            self._chosen = outcome.Chosen
            self._times = (run.SetupSeconds(), run.EvolutionSeconds(), outcome.OutputSeconds)
        if outcome.Error:
            self._error(outcome.Error)
        for warning in outcome.Warnings:
            self._warning(warning)
        if not outcome.Done:
            return None
        _make_volume(volume, run, outcome)
        surface.ShallowCopy(_polydata(*sink.Take()))
        return outcome.Summary


def _update_input_piece(connection):
    """Brings the output of `connection` up to date as one piece, without
    ghost levels (as the C++ filter's UpdateInputPiece)."""
    producer = connection.GetProducer()
    requests = vtkInformationVector()
    requests.SetNumberOfInformationObjects(producer.GetNumberOfOutputPorts())
    piece = requests.GetInformationObject(connection.GetIndex())
    piece.Set(sddp.UPDATE_PIECE_NUMBER(), 0)
    piece.Set(sddp.UPDATE_NUMBER_OF_PIECES(), 1)
    piece.Set(sddp.UPDATE_NUMBER_OF_GHOST_LEVELS(), 0)
    producer.Update(connection.GetIndex(), requests)


def _declare_grid(info, plan):
    """The volume's grid as the pipeline information of output 0 (as the C++
    filter's DeclareGrid): an empty extent for an invalid plan (RequestData
    then says why)."""
    if not plan.Valid():
        info.Set(sddp.WHOLE_EXTENT(), (0, -1, 0, -1, 0, -1), 6)
        return
    grid = plan.TheGrid
    nx, ny, nz = grid.Dims
    info.Set(sddp.WHOLE_EXTENT(), (0, nx - 1, 0, ny - 1, 0, nz - 1), 6)
    info.Set(vtkDataObject.ORIGIN(), tuple(grid.Origin), 3)
    info.Set(vtkDataObject.SPACING(), (grid.Spacing,) * 3, 3)
    vtkDataObject.SetPointDataActiveScalarInfo(info, VTK_FLOAT, 1)


def _make_volume(volume, run, outcome):
    """Output 0 of a finished run: the grid's geometry and the dense arrays
    (as vtkNarrowVolumeReconstruction::MakeVolume), without copies."""
    grid = run.GetGrid()
    nx, ny, _ = grid.Dims
    dense = run.TakeVolume()  # {name: numpy array} of the layers VolumeBegin to VolumeEnd
    if outcome.VolumeEnd <= outcome.VolumeBegin:
        return
    volume.SetOrigin(tuple(grid.Origin))
    volume.SetSpacing((grid.Spacing,) * 3)
    volume.SetExtent(0, nx - 1, 0, ny - 1, outcome.VolumeBegin, outcome.VolumeEnd - 1)
    if not run.GetSettings().OutputVolume:
        return
    for name, values in dense.items():
        kind = vtkUnsignedCharArray if name == "NarrowBand" else vtkFloatArray
        array = _vtk_array(kind, name, values)
        if name == "phi":
            volume.GetPointData().SetScalars(array)
        else:
            volume.GetPointData().AddArray(array)


def _points_of(data):
    """The points of a point set as an (n, 3) float64 array in C order."""
    if data is None or data.GetPoints() is None:
        return np.zeros((0, 3))
    return np.ascontiguousarray(vtk_to_numpy(data.GetPoints().GetData()), dtype=np.float64).reshape(-1, 3)


def _vtk_array(kind, name, values):
    """A VTK array of class kind that uses the memory of the numpy array
    values (one tuple per row), which it keeps alive, as numpy_to_vtk does."""
    array = kind()
    array.SetName(name)
    array.SetNumberOfComponents(values.shape[1] if values.ndim == 2 else 1)
    array.SetVoidArray(values, values.size, 1)
    array._numpy_reference = values
    return array


def _polydata(points, normals, triangles):
    """The core's surface arrays as a vtkPolyData, without copies: double
    world coordinates, float "Normals", triangles in 64-bit cells.

    The cells are vtkTypeInt64Array, the cell array's own storage type, and
    the numpy memory is tied to the arrays the cell array holds afterwards:
    VTK 9.3 takes a vtkIdTypeArray by a shallow copy into a new array, and
    VTK 9.2 (ParaView 5.11's) any array, which would drop the Python array
    that keeps the numpy memory alive (the cells would then point to freed
    memory)."""
    surface = vtkPolyData()
    if len(triangles) == 0:
        return surface
    world = vtkPoints()
    world.SetData(_vtk_array(vtkDoubleArray, "Points", points))
    surface.SetPoints(world)
    surface.GetPointData().SetNormals(_vtk_array(vtkFloatArray, "Normals", normals))
    offsets = np.arange(0, 3 * len(triangles) + 1, 3, dtype=np.int64)
    connectivity = triangles.reshape(-1)
    polys = vtkCellArray()
    polys.SetData(_vtk_array(vtkTypeInt64Array, "Offsets", offsets),
                  _vtk_array(vtkTypeInt64Array, "Connectivity", connectivity))
    polys.GetOffsetsArray()._numpy_reference = offsets
    polys.GetConnectivityArray()._numpy_reference = connectivity
    surface.SetPolys(polys)
    return surface


def _add_field_data(volume, summary):
    """The run's figures (the core's RunSummary) as the volume's field data."""
    kinds = {"int": vtkIntArray, "id": vtkIdTypeArray, "double": vtkDoubleArray}
    for name, kind, components, values, component_names in summary:
        array = kinds[kind]()
        array.SetName(name)
        array.SetNumberOfComponents(max(1, components))
        for c, component_name in enumerate(component_names):
            array.SetComponentName(c, component_name)
        array.SetNumberOfTuples(len(values) // max(1, components))
        for v, value in enumerate(values):
            array.SetValue(v, int(value) if kind != "double" else value)
        volume.GetFieldData().AddArray(array)


# --- The properties, made from the table (_properties.py).
def _convert(prop, value):
    """A value as the C++ setter takes it: clamped like vtkSetClampMacro."""
    if prop.kind is bool:
        return bool(value)  # as VTK's wrapping takes any truth value (numpy bools too)
    if prop.kind is float:
        value = float(value)
    else:
        value = operator.index(value)
    if prop.low is not None and value < prop.low:
        value = prop.low
    elif prop.high is not None and value > prop.high:
        value = prop.high
    return prop.kind(value)


def _install_properties(cls):
    defaults = _core.Settings()
    for prop in PROPERTIES:
        field_type = type(getattr(defaults, prop.name))
        default = prop.kind(getattr(defaults, prop.name))
        clamp = "" if prop.low is None else " Clamped to [%g, %g]." % (prop.low, prop.high)
        doc = "%s Default %r.%s" % (_properties.describe(prop), default, clamp)

        def getter(self, prop=prop):
            return prop.kind(getattr(self._settings, prop.name))

        def setter(self, value, prop=prop, field_type=field_type):
            value = _convert(prop, value)
            if getattr(self, "Get" + prop.name)() != value:
                setattr(self._settings, prop.name, field_type(value))
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
        for constant, suffix, value, _ in prop.choices:
            def choose(self, prop=prop, value=value):
                getattr(self, "Set" + prop.name)(value)
            choose.__doc__ = "Sets %s to %s (%d)." % (prop.name, constant, value)
            setattr(cls, constant, kind(value))
            setattr(cls, "Set%sTo%s" % (prop.name, suffix), choose)


def _install_lists(cls):
    """The list properties (LIST_PROPERTIES), as the VTK filter has them:
    SetNumberOf<Name>, Set<Name less s>(i, x, y, z), Add..., Get...(i),
    GetNumberOf<Name>, RemoveAll<Name>, over the field of nv::Settings."""
    for listed in _properties.LIST_PROPERTIES:
        one = _properties.singular(listed.name)

        def values(self, listed=listed):
            return list(getattr(self._settings, listed.name))

        def store(self, new, listed=listed):
            if values(self) != new:
                setattr(self._settings, listed.name, new)
                self.Modified()

        def set_number(self, number, store=store, values=values):
            old = values(self)
            number = max(0, operator.index(number))
            store(self, (old + [0.0] * (3 * number))[:3 * number])

        def get_number(self, values=values):
            return len(values(self)) // 3

        def set_one(self, i, x, y, z, store=store, values=values, set_number=set_number):
            i = operator.index(i)
            if i < 0:
                return
            new = values(self)
            if 3 * i >= len(new):
                new += [0.0] * (3 * (i + 1) - len(new))
            new[3 * i:3 * i + 3] = [float(x), float(y), float(z)]
            store(self, new)

        def add_one(self, x, y, z, one=one, get_number=get_number):
            getattr(self, "Set" + one)(get_number(self), x, y, z)

        def get_one(self, i, values=values):
            i = operator.index(i)
            point = tuple(values(self)[3 * i:3 * i + 3]) if i >= 0 else ()
            return point if len(point) == 3 else None

        def remove_all(self, set_number=set_number):
            set_number(self, 0)

        doc = _properties.describe(listed)
        for name, method in (("SetNumberOf" + listed.name, set_number), ("GetNumberOf" + listed.name, get_number),
                             ("Set" + one, set_one), ("Add" + one, add_one), ("Get" + one, get_one),
                             ("RemoveAll" + listed.name, remove_all)):
            method.__name__ = name
            method.__doc__ = "%s (%s).\n\n%s" % (name, listed.name, doc)
            setattr(cls, name, method)


def _install_results(cls):
    """Get<Name> for each result of the table (RESULTS), over the run's nv::Results."""
    for result in _properties.RESULTS:
        def getter(self, result=result):
            value = getattr(self._chosen, result.name)
            return tuple(result.kind(v) for v in value) if result.size > 1 else result.kind(value)

        getter.__doc__ = "%s\n\n%s" % (result.name, _properties.describe(result))
        getter.__name__ = "Get" + result.name
        setattr(cls, getter.__name__, getter)


_install_properties(vtkNarrowVolumeReconstruction)
_install_lists(vtkNarrowVolumeReconstruction)
_install_results(vtkNarrowVolumeReconstruction)
