# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""reconstruct(): the filter in one call, for arrays, VTK and pyvista point sets."""
from __future__ import annotations

import ctypes
import re
import signal
import threading
import warnings
from typing import Any, Callable, Optional, Tuple

import numpy as np
from vtkmodules.util.misc import calldata_type
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.util.vtkConstants import VTK_STRING
from vtkmodules.vtkCommonCore import vtkCommand, vtkObject, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkDataObject, vtkImageData, vtkPointSet, vtkPolyData

from . import _properties


def _run_signal_handlers():
    """Runs the Python handlers of the signals received so far, as the
    interpreter does between bytecodes (raises what a handler raises). Python
    3.11 records a signal that the kernel hands to another thread (one of the
    run's workers) without telling its main loop, which then runs the handler
    only after the run: asking in each progress event stops the run there."""
    ctypes.pythonapi.PyErr_CheckSignals()


class ReconstructionError(RuntimeError):
    """The filter refused the input or the properties; the message says what to change."""


class ReconstructionWarning(UserWarning):
    """A warning of the filter about its result (an empty surface, an open input's missing inner sheet, ...)."""


def point_cloud(xyz: Any) -> vtkPolyData:
    """A vtkPolyData holding the points of an (n, 3) array (copied, as float64), no cells."""
    xyz = np.ascontiguousarray(xyz, dtype=np.float64)
    if xyz.ndim != 2 or xyz.shape[1] != 3:
        raise ValueError("points must be an (n, 3) array, not of shape %s" % (xyz.shape,))
    points = vtkPoints()
    points.SetData(numpy_to_vtk(xyz, deep=1))
    cloud = vtkPolyData()
    cloud.SetPoints(points)
    return cloud


def _as_point_set(points: Any) -> Tuple[vtkPointSet, bool]:
    """(a vtkPointSet, whether to return pyvista objects)."""
    if isinstance(points, vtkPointSet):
        return points, type(points).__module__.split(".")[0] == "pyvista"
    if isinstance(points, vtkDataObject):
        raise TypeError("reconstruct() needs a point set (vtkPointSet, e.g. vtkPolyData), not a %s; "
                        "a pyvista dataset converts with cast_to_pointset()" % points.GetClassName())
    return point_cloud(points), False


def reconstruct(points: Any, progress: Optional[Callable[[float], None]] = None,
                **properties: Any) -> Tuple[vtkImageData, vtkPolyData]:
    """The narrow volume (a thick shell) around a point cloud, in one call.

    points: an (n, 3) array of coordinates (anything numpy.asarray takes), a
        vtkPointSet (vtkPolyData, vtkUnstructuredGrid, ...; only its points
        are used) or a pyvista point set (PolyData, PointSet, ...).
    progress: optional callable, progress(fraction) with fraction in [0, 1],
        called on the calling thread while the run proceeds (a few dozen times,
        never going back, ending at 1).
        An exception it raises stops the run and propagates.
    properties: the filter's properties by their names, OffsetDistance=0.05,
        or in snake_case, offset_distance=0.05 (see vtkNarrowVolumeReconstruction;
        the defaults are the filter's).

    Returns (volume, surface): the phase field on the grid (vtkImageData with
    the point array "phi" and, on request, "InitialPhi", "Distance" and
    "NarrowBand"; the run's summary in its field data) and the phi = 0
    surface (vtkPolyData, triangles with point normals). For a pyvista input
    they are pyvista objects (ImageData, PolyData).

    Raises ReconstructionError when the filter refuses the input or the
    properties (no points, a NaN coordinate, an offset < 0, a grid too large
    for the memory limit), with the filter's message; TypeError for an
    unknown property. Ctrl-C stops the run within a progress step and raises
    KeyboardInterrupt. The filter's warnings (holes that pierce the shell, an
    empty surface, no cavity, a coarsened grid) come as ReconstructionWarning.

        volume, surface = narrowvolume.reconstruct(xyz, OffsetDistance=0.05)
    """
    from . import vtkNarrowVolumeReconstruction

    data, to_pyvista = _as_point_set(points)
    f = vtkNarrowVolumeReconstruction()
    for keyword, value in properties.items():
        try:
            prop = _properties.find(keyword)
        except KeyError:
            raise TypeError("reconstruct() got an unknown property %r; the properties are %s" % (
                keyword, ", ".join(p.name for p in _properties.PROPERTIES + _properties.LIST_PROPERTIES))) from None
        if isinstance(prop, _properties.ListProperty):  # points: an (n, 3) array, or x y z after one another
            xyz = np.asarray(value if value is not None else [], dtype=float).reshape(-1)
            if xyz.size % 3:
                raise ValueError("%s takes points (x, y, z), not %d values" % (keyword, xyz.size))
            getattr(f, "RemoveAll" + prop.name)()
            for x, y, z in xyz.reshape(-1, 3):
                getattr(f, "Add" + _properties.singular(prop.name))(x, y, z)
        else:
            getattr(f, "Set" + prop.name)(value)
    f.SetInputData(data)

    errors, notes = [], []
    f.AddObserver(vtkCommand.ErrorEvent, calldata_type(VTK_STRING)(lambda caller, event, text: errors.append(text)))
    f.AddObserver(vtkCommand.WarningEvent, calldata_type(VTK_STRING)(lambda caller, event, text: notes.append(text)))
    state = {"interrupted": False, "failure": None}

    def on_progress(caller, event):
        try:
            if replace:
                _run_signal_handlers()  # on_interrupt below, for Ctrl-C
            if progress is not None and not state["interrupted"] and state["failure"] is None:
                progress(caller.GetProgress())
        except BaseException as failure:  # raised again after the run
            state["failure"] = failure
        if state["interrupted"] or state["failure"] is not None:
            caller.SetAbortExecute(1)
    f.AddObserver(vtkCommand.ProgressEvent, on_progress)

    def on_interrupt(signum, frame):
        # Python runs this on the calling thread between the run's steps
        # (in a progress event, or when the core polls): the run stops there.
        state["interrupted"] = True
        f.SetAbortExecute(1)

    # Ctrl-C stops the run instead of ending the program mid-way: only where
    # Python's own handler is in place (the main thread, no handler of the user's).
    replace = threading.current_thread() is threading.main_thread() and \
        signal.getsignal(signal.SIGINT) is signal.default_int_handler
    if replace:
        signal.signal(signal.SIGINT, on_interrupt)
    # The filter's errors and warnings come out as exceptions and Python
    # warnings even where VTK's output is turned off (GlobalWarningDisplayOff
    # also stops VTK's error events, which would lose the error); the
    # observers above take them, so VTK prints nothing either way.
    display = vtkObject.GetGlobalWarningDisplay()
    vtkObject.GlobalWarningDisplayOn()
    try:
        f.Update()
    finally:
        vtkObject.SetGlobalWarningDisplay(display)
        if replace:
            signal.signal(signal.SIGINT, signal.default_int_handler)
    if state["interrupted"]:
        raise KeyboardInterrupt
    if state["failure"] is not None:
        raise state["failure"]
    if errors:
        raise ReconstructionError(_message_of(errors[-1]))
    for note in notes:
        warnings.warn(_message_of(note), ReconstructionWarning, stacklevel=2)

    volume, surface = vtkImageData(), vtkPolyData()
    volume.ShallowCopy(f.GetOutputDataObject(0))
    surface.ShallowCopy(f.GetOutputDataObject(1))
    if to_pyvista:
        import pyvista
        return pyvista.wrap(volume), pyvista.wrap(surface)
    return volume, surface


_HEADER = re.compile(r"^\s*(ERROR|Warning|Generic Warning): In .*, line \d+\s*$", re.MULTILINE)
_SENDER = re.compile(r"^\w+ \(0x[0-9a-fA-F]+\): ", re.MULTILINE)


def _message_of(text):
    """The message of a VTK error or warning text, without VTK's header (the
    source file and line, the sender's class and address)."""
    return _SENDER.sub("", _HEADER.sub("", text)).strip()
