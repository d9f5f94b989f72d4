# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""What the Python plugin does in the ParaView client beyond running the
filter, as the compiled plugin does (Plugin/NarrowVolumeClientBehaviors.cxx):

1. After each run of a NarrowVolumeReconstruction proxy, its read-only
   properties (OffsetDistanceUsed, SampleSpacingUsed, ...: what the run
   chose) are fetched, so the panel shows them after Apply.
2. When a render view first shows an output of the filter and none of its
   other visible representations draws anything (a point cloud without
   cells, such as a PLY of points, draws nothing, and ParaView then keeps
   an empty framing), the camera is reset on the output's bounds, and the
   filter's input, if it is one of those, is shown as Point Gaussian discs
   (a fifth of the offset used).

Both watch the server manager, so the GUI, pvpython and pvbatch behave
alike. start() runs once per process.
"""
from paraview.modules.vtkRemotingServerManager import vtkSMProxyIterator, vtkSMProxyManager, vtkSMPropertyHelper
from paraview.modules.vtkRemotingViews import vtkSMRenderViewProxy, vtkSMRepresentationProxy
from vtkmodules.util.misc import calldata_type
from vtkmodules.util.vtkConstants import VTK_STRING
from vtkmodules.vtkCommonCore import vtkCommand

PROXY_NAME = "NarrowVolumeReconstruction"
_watched = set()  # global ids of the proxies observed
_framed = set()  # global ids of the filter's representations already seen
_managers = []


def start():
    """Starts watching this process's sessions (nothing without one)."""
    if _managers or not vtkSMProxyManager.IsInitialized():
        return
    manager = vtkSMProxyManager.GetProxyManager()
    _managers.append(manager)
    manager.AddObserver(vtkSMProxyManager.ActiveSessionChanged,
                        lambda *_: _watch(manager.GetActiveSessionProxyManager()))
    _watch(manager.GetActiveSessionProxyManager())


def _watch(proxies):
    if proxies is None or proxies in _managers:
        return
    _managers.append(proxies)
    proxies.AddObserver(vtkCommand.RegisterEvent, lambda *_: _scan(proxies))
    _scan(proxies)


def _group(proxies, name):
    proxies_of_group = vtkSMProxyIterator()
    proxies_of_group.SetSessionProxyManager(proxies)
    proxies_of_group.SetModeToOneGroup()
    proxies_of_group.Begin(name)
    while not proxies_of_group.IsAtEnd():
        yield proxies_of_group.GetProxy()
        proxies_of_group.Next()


def _scan(proxies):
    """Observes the filters and render views not observed yet."""
    for proxy in _group(proxies, "sources"):
        if proxy.GetXMLName() == PROXY_NAME and proxy.GetGlobalID() not in _watched:
            _watched.add(proxy.GetGlobalID())
            proxy.AddObserver(vtkCommand.UpdateDataEvent, lambda caller, _: caller.UpdatePropertyInformation())
    for view in _group(proxies, "views"):
        if isinstance(view, vtkSMRenderViewProxy) and view.GetGlobalID() not in _watched:
            _watched.add(view.GetGlobalID())
            view.AddObserver(vtkCommand.PropertyModifiedEvent, _property_modified)


@calldata_type(VTK_STRING)
def _property_modified(view, _, name):
    if name == "Representations":
        _representations_changed(view)


def _producer(representation):
    if representation is None or representation.GetProperty("Input") is None:
        return None
    return vtkSMPropertyHelper(representation, "Input", True).GetAsProxy()


def _draws(representation):
    """Visible, and its data has cells (Point Gaussian draws points without cells)."""
    if not isinstance(representation, vtkSMRepresentationProxy) or \
            not vtkSMPropertyHelper(representation, "Visibility", True).GetAsInt():
        return False
    if representation.GetProperty("Representation") is not None and \
            vtkSMPropertyHelper(representation, "Representation", True).GetAsString() == "Point Gaussian":
        return True
    data = representation.GetRepresentedDataInformation()
    return data is not None and data.GetNumberOfCells() > 0


def _show_input_as_points(view, shell):
    """The filter's input, where the view shows it and it draws nothing
    (points without cells), as Point Gaussian discs of a fifth of the offset used."""
    source = vtkSMPropertyHelper(shell, "Input", True).GetAsProxy()
    offset = vtkSMPropertyHelper(shell, "OffsetDistanceUsed", True).GetAsDouble()
    if source is None or not offset > 0.0:
        return
    representations = vtkSMPropertyHelper(view, "Representations")
    for i in range(representations.GetNumberOfElements()):
        representation = representations.GetAsProxy(i)
        if not isinstance(representation, vtkSMRepresentationProxy) or _producer(representation) != source or \
                representation.GetProperty("GaussianRadius") is None or \
                not vtkSMPropertyHelper(representation, "Visibility", True).GetAsInt() or _draws(representation):
            continue
        data = representation.GetRepresentedDataInformation()
        if data is not None and data.GetNumberOfPoints() > 0:
            vtkSMPropertyHelper(representation, "Representation").Set("Point Gaussian")
            vtkSMPropertyHelper(representation, "GaussianRadius").Set(0.2 * offset)
            vtkSMPropertyHelper(representation, "ShaderPreset", True).Set("Plain circle")
            representation.UpdateVTKObjects()


def _representations_changed(view):
    """Frames the camera on the filter's output the view shows first, when nothing else draws."""
    representations = vtkSMPropertyHelper(view, "Representations")
    shown, something_else_draws = None, False
    for i in range(representations.GetNumberOfElements()):
        representation = representations.GetAsProxy(i)
        producer = _producer(representation)
        if producer is None or producer.GetXMLName() != PROXY_NAME:
            something_else_draws = something_else_draws or _draws(representation)
        elif representation.GetGlobalID() not in _framed:
            _framed.add(representation.GetGlobalID())
            shown = shown or producer
    if shown is None or something_else_draws:
        return
    _show_input_as_points(view, shown)
    bounds = shown.GetDataInformation(0).GetBounds()
    if bounds[0] <= bounds[1] and bounds[2] <= bounds[3] and bounds[4] <= bounds[5]:
        view.ResetCamera(bounds)
