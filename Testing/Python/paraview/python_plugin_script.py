# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""Run by test_python_plugin.py in pvpython (or under mpiexec in pvbatch):
loads one plugin, the compiled one or the Python one, and records what a
user meets in ParaView: the proxy (label, group, menu, outputs, property
groups) and each property (label, default, domains, panel visibility,
documentation), the outputs on a cloud with the defaults, the progress
events, an abort, and the error of a cloud with a NaN coordinate.

    python_plugin_script.py compiled|python PLUGIN CLOUD.vtp OUT [mpi]

OUT.json holds the result, OUT.npz the outputs' arrays. With `mpi` (under
mpiexec) only the outputs, written by the first rank.
"""
import builtins
import json
import sys

import numpy as np

mode, plugin, cloud, out = sys.argv[1:5]
distributed = len(sys.argv) > 5 and sys.argv[5] == "mpi"
if mode == "python":
    # What the README says for ParaView 5.11 with Python 3.11 (Debian 12's):
    # ParaView's Python plugin loader needs inspect.getargspec.
    import inspect
    if not hasattr(inspect, "getargspec"):
        inspect.getargspec = inspect.getfullargspec

import paraview.simple as pvs  # noqa: E402
from paraview import servermanager  # noqa: E402
from vtkmodules.util.misc import calldata_type  # noqa: E402
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402
from vtkmodules.util.vtkConstants import VTK_STRING  # noqa: E402
from vtkmodules.vtkParallelCore import vtkMultiProcessController  # noqa: E402

pvs.LoadPlugin(plugin)
if not cloud.endswith(".json"):
    reader = pvs.XMLPolyDataReader(FileName=[cloud])
    shell = pvs.NarrowVolumeReconstruction(Input=reader)


def outputs(proxy):
    """The volume's phi and the surface's points and triangles, gathered on the first rank."""
    volume, surface = servermanager.Fetch(proxy, idx=0), servermanager.Fetch(proxy, idx=1)
    arrays = {"phi": np.zeros(0, np.float32), "points": np.zeros((0, 3)), "triangles": np.zeros(0, np.int64)}
    if volume is not None and volume.GetPointData().GetArray("phi") is not None:
        arrays["phi"] = vtk_to_numpy(volume.GetPointData().GetArray("phi")).copy()
        arrays["dimensions"] = np.array(volume.GetDimensions())
    if surface is not None and surface.GetNumberOfPoints() > 0:
        arrays["points"] = vtk_to_numpy(surface.GetPoints().GetData()).astype(np.float64)
        arrays["triangles"] = vtk_to_numpy(surface.GetPolys().GetConnectivityArray()).astype(np.int64)
    return arrays


if mode == "python" and cloud.endswith(".json"):
    # The readers: each file of the list opened as File > Open does, by its extension.
    with open(cloud) as f:
        files = json.load(f)
    opened = {}
    # The plugin's readers and the extensions their ReaderFactory hints give
    # File > Open (some of ParaView's own readers crash when probed with a LAS
    # file's bytes, so the file picks its reader by its extension only).
    proxies = servermanager.vtkSMProxyManager.GetProxyManager().GetActiveSessionProxyManager()
    extensions = {}
    for name in ("PointCloudTextReader", "PCDPointCloudReader", "LASPointCloudReader", "LAZPointCloudReader",
                 "E57PointCloudReader"):
        hints = proxies.GetPrototypeProxy("sources", name).GetHints()
        factory = hints.FindNestedElementByName("ReaderFactory") if hints else None
        for extension in (factory.GetAttribute("extensions") or "").split() if factory else ():
            extensions[extension] = name
    for path in files:
        name = extensions.get(path.rsplit(".", 1)[-1])
        reader = getattr(pvs, name)(FileName=path) if name else None
        data = servermanager.Fetch(reader) if reader is not None else None
        opened[path] = None if data is None else {
            "reader": reader.SMProxy.GetXMLName(), "points": data.GetNumberOfPoints(),
            "vertices": data.GetNumberOfVerts(),
            "xyz": vtk_to_numpy(data.GetPoints().GetData()).tolist() if data.GetNumberOfPoints() else [],
            "arrays": sorted(data.GetPointData().GetArrayName(i)
                             for i in range(data.GetPointData().GetNumberOfArrays()))}
    with open(out + ".json", "w") as f:
        json.dump(opened, f)
    print("python_plugin_script: %d files opened" % len(opened))
elif distributed:
    # Run with `pvbatch --symmetric` (every rank runs this script, and so
    # mends ParaView 5.11's loader where it needs it). The cloud as a reader
    # gives it: each rank asks for the whole of it.
    shell.UpdatePipeline()
    arrays = outputs(shell)
    # A source that gives each rank a share of its own, whatever it is asked:
    # the Python plugin refuses (one rank would compute on a part).
    errors = []
    shell.GetClientSideObject().AddObserver(
        "ErrorEvent", calldata_type(VTK_STRING)(lambda caller, event, text: errors.append(text)))
    shares = pvs.ProgrammableSource(OutputDataSetType="vtkPolyData", Script="""
import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkParallelCore import vtkMultiProcessController
rank = vtkMultiProcessController.GetGlobalController().GetLocalProcessId()
xyz = np.random.default_rng(5).random((300 + 100 * rank, 3))
points = vtkPoints()
points.SetData(numpy_to_vtk(xyz, deep=1))
self.GetOutput().SetPoints(points)
""")
    shell.Input = shares
    shell.UpdatePipeline()
    arrays["shares_surface_points"] = np.array([len(outputs(shell)["points"])])
    arrays["shares_errors"] = np.array([len(errors)])
    if vtkMultiProcessController.GetGlobalController().GetLocalProcessId() == 0:
        np.savez(out + ".npz", **arrays)
        with open(out + ".txt", "w") as f:
            f.write("\n".join(errors))



def plain(value):
    """A recorded value as plain Python: numpy's and VTK's own bool, integer
    and float types become Python's, and tuples lists, recursively; the
    values themselves are unchanged. Python's types are named through
    builtins: the first Programmable Source that runs imports numpy's names
    into __main__, this script's namespace, and numpy 2 (ParaView 5.13 and
    6.1 on Debian) has a `bool` of its own, which then replaces Python's
    here, and which json cannot write."""
    if isinstance(value, dict):
        return {plain(k): plain(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [plain(v) for v in value]
    if value is None or type(value) in (builtins.bool, builtins.int, builtins.float, builtins.str):
        return value
    if isinstance(value, np.generic):
        return value.item()
    if isinstance(value, np.ndarray):
        return value.tolist()
    for kind in (builtins.bool, builtins.int, builtins.float, builtins.str):
        if isinstance(value, kind):
            return kind(value)
    raise TypeError("python_plugin_script: cannot record a %s (%r)" % (type(value).__name__, value))


def record_all():
    """The whole record of one serial pvpython."""
    def describe_property(proxy, name):
        smp = proxy.GetProperty(name).SMProperty
        domains = []
        iterator = smp.NewDomainIterator()
        iterator.Begin()
        while not iterator.IsAtEnd():
            domain = iterator.GetDomain()
            entries = []
            if domain.IsA("vtkSMEnumerationDomain"):
                entries = [[domain.GetEntryText(i), domain.GetEntryValue(i)] for i in range(domain.GetNumberOfEntries())]
            domains.append([domain.GetClassName(), entries])
            iterator.Next()
        defaults = []
        if hasattr(smp, "GetDefaultValue"):
            defaults = [smp.GetDefaultValue(i) for i in range(smp.GetNumberOfElements())]
        documentation = smp.GetDocumentation()
        return plain({"label": smp.GetXMLLabel(), "class": smp.GetClassName(), "command": smp.GetCommand(),
                      "defaults": defaults,
                      "value": [smp.GetElement(i) for i in range(smp.GetNumberOfElements())]
                      if hasattr(smp, "GetElement") else None,
                      "visibility": smp.GetPanelVisibility(), "domains": domains,
                      "documentation": " ".join(documentation.GetDescription().split()) if documentation else ""})


    def hints(element):
        """The proxy's hints: each element's name and the attributes the filter's hints have."""
        if element is None:
            return []
        nested = [element.GetNestedElement(i) for i in range(element.GetNumberOfNestedElements())]
        return [[e.GetName(), e.GetAttribute("category"), e.GetAttribute("replace_input")] for e in nested]


    sm = shell.SMProxy
    result = {
        "proxy": {"name": sm.GetXMLName(), "label": sm.GetXMLLabel(), "group": sm.GetXMLGroup(),
                  "outputs": [sm.GetOutputPortName(i) for i in range(sm.GetNumberOfOutputPorts())],
                  "hints": hints(sm.GetHints()),
                  "groups": [[sm.GetPropertyGroup(g).GetXMLLabel(),
                              [sm.GetPropertyGroup(g).GetProperty(p).GetXMLName()
                               for p in range(sm.GetPropertyGroup(g).GetNumberOfProperties())]]
                             for g in range(sm.GetNumberOfPropertyGroups())]},
        "properties": {name: describe_property(shell, name) for name in shell.ListProperties()},
    }

    # The outputs with the defaults, and the progress the run reports.
    algorithm = shell.GetClientSideObject()
    progress = []
    watch = algorithm.AddObserver("ProgressEvent", lambda caller, event: progress.append(caller.GetProgress()))
    shell.UpdatePipeline()
    algorithm.RemoveObserver(watch)
    np.savez(out + ".npz", **outputs(shell))
    result["progress"] = plain(progress)
    # The grid of the run: the panel's text (Grid Used) and pvpython's three integers.
    shell.UpdatePropertyInformation()
    result["grid_used"] = plain([shell.GridUsed, list(shell.GridDimensionsUsed)])
    result["field_data"] = sorted(
        servermanager.Fetch(shell, idx=0).GetFieldData().GetAbstractArray(i).GetName()
        for i in range(servermanager.Fetch(shell, idx=0).GetFieldData().GetNumberOfArrays()))

    # An abort part way: empty outputs; the next update without it is whole again.
    def abort(caller, event):
        if caller.GetProgress() > 0.3:
            caller.SetAbortExecute(1)


    shell.MaximumNumberOfIterations = 4  # a change, so that the update runs again
    watch = algorithm.AddObserver("ProgressEvent", abort)
    shell.UpdatePipeline()
    algorithm.RemoveObserver(watch)
    aborted = outputs(shell)
    algorithm.SetAbortExecute(0)  # VTK 9.2's pipeline leaves it set (both plugins alike)
    shell.MaximumNumberOfIterations = 3
    shell.UpdatePipeline()
    result["abort"] = {"volume points": int(aborted["phi"].size), "surface points": len(aborted["points"]),
                       "after": len(outputs(shell)["points"])}

    # A part with a drain hole placed (a list property: SetNumberOf... and
    # Set...(i, x, y, z) on the algorithm, the Python one's too).
    ball = pvs.Sphere(Radius=0.5, ThetaResolution=60, PhiResolution=60)
    part = pvs.NarrowVolumeReconstruction(Input=ball, OffsetDistance=0.08, SampleSpacing=0.02, WallThickness=0.05,
                                          DrainHolePositions=[0.5, 0.0, 0.0])
    part.UpdatePipeline()
    field = servermanager.Fetch(part, idx=0).GetFieldData()
    result["part"] = {name: field.GetArray(name).GetValue(0) for name in ("DrainHoles", "KeptCavities")}
    result["part"]["positions"] = list(part.DrainHolePositions)
    pvs.Delete(part)

    # A cloud with a NaN coordinate: the filter's error, and empty outputs.
    errors = []


    @calldata_type(VTK_STRING)
    def on_error(caller, event, text):
        errors.append(text)


    algorithm.AddObserver("ErrorEvent", on_error)
    bad = pvs.ProgrammableSource(OutputDataSetType="vtkPolyData", Script="""
    import numpy as np
    from vtkmodules.util.numpy_support import numpy_to_vtk
    from vtkmodules.vtkCommonCore import vtkPoints
    xyz = np.random.default_rng(3).random((200, 3))
    xyz[17, 1] = np.nan
    points = vtkPoints()
    points.SetData(numpy_to_vtk(xyz, deep=1))
    self.GetOutput().SetPoints(points)
    """)
    shell.Input = bad
    shell.UpdatePipeline()
    result["bad input"] = {"surface points": len(outputs(shell)["points"]), "errors": errors}
    result["framing"] = plain(framing())

    with open(out + ".json", "w") as f:
        json.dump(plain(result), f, indent=1, sort_keys=True)
    print("python_plugin_script: %s plugin recorded into %s" % (mode, out))


def framing():
    """The client's second behaviour (NarrowVolumeClientBehaviors.cxx,
    _paraview_client.py): a cloud of points without cells far from the
    origin draws nothing in its view; once the filter's outputs are shown
    as Apply shows them, the camera is on the shell and the cloud shows as
    Point Gaussian discs."""
    from paraview.modules.vtkRemotingServerManager import vtkSMPropertyHelper
    view = pvs.CreateRenderView()
    controller = servermanager.vtkSMParaViewPipelineControllerWithRendering()

    def show_as_apply_does(source):
        for port in range(source.SMProxy.GetNumberOfOutputPorts()):
            controller.ShowInPreferredView(source.SMProxy, port, view.SMProxy)
            if len([r for r in view.Representations if r.Visibility]) == 1:
                view.ResetCamera()
        view.Update()  # no Render: pvpython runs here without a display

    far = pvs.ProgrammableSource(OutputDataSetType="vtkPolyData", Script="""
import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonCore import vtkPoints
xyz = np.random.default_rng(7).normal(size=(2000, 3))
xyz = 0.5 * xyz / np.linalg.norm(xyz, axis=1)[:, None] + [1000.0, -2000.0, 500.0]
points = vtkPoints()
points.SetData(numpy_to_vtk(xyz, deep=1))
self.GetOutput().SetPoints(points)
""")
    show_as_apply_does(far)
    filtered = pvs.NarrowVolumeReconstruction(Input=far)
    show_as_apply_does(filtered)
    view.SMProxy.SynchronizeCameraProperties()  # the camera as the view holds it, in its properties
    focal = list(view.CameraFocalPoint)
    representation = vtkSMPropertyHelper(pvs.GetDisplayProperties(far, view).SMProxy, "Representation")
    return {"cloud representation": representation.GetAsString(),
            "focal point near the shell": builtins.bool(np.linalg.norm(np.subtract(focal, [1000.0, -2000.0, 500.0])) < 2.0)}


if not distributed and not cloud.endswith(".json"):
    record_all()
