# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""Runs inside the real ParaView client (paraview --script=gui_script.py):
loads the plugin (NV_PLUGIN: the compiled one, or the Python plugin's file
with NV_MEND_GETARGSPEC=1), opens a point cloud, applies the filter with the panel's
defaults, shows both outputs beside the points, saves a screenshot, applies
ParaView's Slice, Clip, Threshold, Contour, Resample To Image and Plot Over
Line to the Volume output of a run at twice its spacing, writes what it saw to NV_GUI_RESULT (JSON) and
closes the client. With NV_POINTS_PLY it only shows that cloud (no cells)
and a shell of it, as Apply does, and records what the view shows."""
import json
import os
import traceback

result = {"ok": False}


def drawn_pixels(view, png):
    """Pixels of a screenshot of the view that differ from its background."""
    from paraview.simple import SaveScreenshot
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOImage import vtkPNGReader
    SaveScreenshot(png, view, ImageResolution=[400, 300])
    reader = vtkPNGReader()
    reader.SetFileName(png)
    reader.Update()
    pixels = vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars())[:, :3].astype(int)
    return int((abs(pixels - pixels[0]).sum(axis=1) > 30).sum())


def frame_in_a_view_that_drew_nothing(ply, view, result):
    """A cloud that draws nothing (a PLY of points has no cells) far from the
    origin, in the client's first view (`view`), shown as Apply shows data
    (pqApplyBehavior: each output port through the pipeline controller, and
    the camera reset only when the new representation is the view's one
    visible dataset); then the filter's outputs, the same way. What the view
    shows after."""
    import paraview.simple as pvs
    from paraview import servermanager
    controller = servermanager.vtkSMParaViewPipelineControllerWithRendering()

    def show_as_apply_does(source):
        for port in range(source.SMProxy.GetNumberOfOutputPorts()):
            controller.ShowInPreferredView(source.SMProxy, port, view.SMProxy)
            if sum(1 for r in view.Representations if r.Visibility) == 1:
                view.ResetCamera()
        pvs.Render(view)

    cloud = pvs.OpenDataFile(ply)
    show_as_apply_does(cloud)
    png = os.environ["NV_SCREENSHOT"].replace(".png", "_ply.png")
    result["ply_cloud_cells"] = cloud.GetDataInformation().GetNumberOfCells()
    result["ply_cloud_pixels"] = drawn_pixels(view, png)
    shell = NarrowVolumeReconstruction(Input=cloud)  # noqa: F821 (from LoadPlugin)
    show_as_apply_does(shell)
    result["ply_shell_cells"] = shell.GetDataInformation(1).GetNumberOfCells()
    result["ply_shell_pixels"] = drawn_pixels(view, png)
    result["ply_offset_used"] = shell.OffsetDistanceUsed
    result["ply_grid_used"] = list(shell.GridDimensionsUsed)
    # The cloud alone, as it shows now.
    cloud_display = pvs.GetDisplayProperties(cloud, view)
    from paraview.modules.vtkRemotingServerManager import vtkSMPropertyHelper
    result["ply_cloud_representation"] = vtkSMPropertyHelper(cloud_display.SMProxy, "Representation").GetAsString()
    pvs.Hide(pvs.OutputPort(shell, 0), view)
    pvs.Hide(pvs.OutputPort(shell, 1), view)
    result["ply_cloud_pixels_after"] = drawn_pixels(view, png)


try:
    if os.environ.get("NV_MEND_GETARGSPEC") == "1":
        # The Python plugin in ParaView 5.11 with Python 3.11, as the README
        # says: the line a user runs in the Python Shell before loading it.
        import inspect
        if not hasattr(inspect, "getargspec"):
            inspect.getargspec = inspect.getfullargspec
    from paraview.simple import (GetActiveViewOrCreate, LoadPlugin, OpenDataFile, OutputPort, Render,
                                 ResetCamera, SaveScreenshot, Show)
    import paraview.simple as pvs

    LoadPlugin(os.environ["NV_PLUGIN"], ns=globals())
    view = GetActiveViewOrCreate("RenderView")
    if os.environ.get("NV_NO_LOD") == "1":  # ParaView 6.1's LOD aborts on flat data: see test_gui.py
        view.LODThreshold = 1.0e6  # MB
        result["lod_threshold"] = view.LODThreshold
    if os.environ.get("NV_POINTS_PLY"):
        # A run of its own: after another view showed a Slice, ParaView 6.1
        # aborts in its LOD when the client renders again (see test_gui.py).
        frame_in_a_view_that_drew_nothing(os.environ["NV_POINTS_PLY"], view, result)
        result["ok"] = True
        raise SystemExit
    cloud = OpenDataFile(os.environ["NV_CLOUD"])
    Show(cloud, view)
    cloud.UpdatePipeline()
    shell = NarrowVolumeReconstruction(Input=cloud)  # noqa: F821 (from LoadPlugin)
    result["offset_default"] = shell.OffsetDistance
    result["label"] = shell.GetXMLLabel()
    # The information pass, before the run: the Volume's grid is already
    # declared in its pipeline information (the client is a builtin session,
    # so the proxy's VTK object is here).
    from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline as sddp
    shell.UpdatePipelineInformation()
    algorithm = shell.GetClientSideObject()
    info = algorithm.GetOutputInformation(0)
    result["info_whole_extent"] = list(info.Get(sddp.WHOLE_EXTENT())) if info.Has(sddp.WHOLE_EXTENT()) else None
    result["points_before_run"] = algorithm.GetOutputDataObject(0).GetNumberOfPoints()
    surface = Show(OutputPort(shell, 1), view)
    volume = Show(OutputPort(shell, 0), view)  # an image shows as its outline
    surface.DiffuseColor = [0.9, 0.5, 0.2]
    Render(view)
    ResetCamera(view)
    Render(view)
    result["surface_cells"] = shell.GetDataInformation(1).GetNumberOfCells()
    result["volume_points"] = shell.GetDataInformation(0).GetNumberOfPoints()
    result["cloud_visible"] = bool(pvs.GetDisplayProperties(cloud, view).Visibility)
    result["volume_extent"] = list(shell.GetDataInformation(0).GetExtent())
    SaveScreenshot(os.environ["NV_SCREENSHOT"], view, ImageResolution=[800, 600])
    # The offset the run chose, and the slider's range (the offset property's bounds domain).
    field = algorithm.GetOutputDataObject(0).GetFieldData()
    result["offset_used"] = float(field.GetArray("OffsetDistance").GetValue(0))
    # The panel's read-only values of the last Apply (information properties).
    result["panel_used"] = {name: (list(shell.GetPropertyValue(name)) if name == "GridDimensionsUsed" else
                                   shell.GetPropertyValue(name))
                            for name in ("OffsetDistanceUsed", "SampleSpacingUsed", "ClosingRadiusUsed",
                                         "GridUsed", "GridDimensionsUsed")}
    # The read-only values the panel draws, as pqProxyWidget chooses them
    # from the proxy's definition: an information property gets a widget
    # (one line edit per element) unless its visibility is "never" or the
    # proxy's hints hide it (<Property name=... show="0"/>); [class, number
    # of elements, visibility] of each.
    hints = shell.SMProxy.GetHints()
    hidden = set()
    for n in range(hints.GetNumberOfNestedElements() if hints else 0):
        hint = hints.GetNestedElement(n)
        if hint.GetName() == "Property" and hint.GetAttribute("show") == "0":
            hidden.add(hint.GetAttribute("name"))
    result["panel_hidden"] = sorted(hidden)
    iterator = shell.SMProxy.NewPropertyIterator()
    iterator.Begin()
    result["panel_information"] = {}
    while not iterator.IsAtEnd():
        prop = iterator.GetProperty()
        if prop.GetInformationOnly() and prop.GetPanelVisibility() != "never" and iterator.GetKey() not in hidden:
            result["panel_information"][iterator.GetKey()] = [prop.GetClassName(), prop.GetNumberOfElements(),
                                                              prop.GetPanelVisibility()]
        iterator.Next()
    result["field_used"] = {name: float(field.GetArray(name).GetValue(0))
                            for name in ("OffsetDistance", "SampleSpacing", "ClosingRadius")}
    result["volume_dimensions"] = list(algorithm.GetOutputDataObject(0).GetDimensions())
    result["offset_slider"] = [shell.GetProperty("OffsetDistance").SMProperty.GetDomain("bounds").GetMinimum(0),
                               shell.GetProperty("OffsetDistance").SMProperty.GetDomain("bounds").GetMaximum(0)]
    result["cloud_extent"] = max(b - a for a, b in zip(cloud.GetDataInformation().GetBounds()[::2],
                                                         cloud.GetDataInformation().GetBounds()[1::2]))
    # The points alone, as they show after Apply: drawn pixels differ from the background.
    pvs.Hide(OutputPort(shell, 1), view)
    pvs.Hide(OutputPort(shell, 0), view)
    result["cloud_pixels"] = drawn_pixels(view, os.environ["NV_SCREENSHOT"].replace(".png", "_points.png"))
    pvs.Show(OutputPort(shell, 1), view)
    pvs.Show(OutputPort(shell, 0), view)
    # ParaView's filters on the Volume port, as a user applies them (and
    # Apply shows them), with their defaults except for what the test needs:
    # Slice and Clip through the centre of the bounds, Threshold phi in
    # [0, 1], Contour phi = 0, ResampleToImage 100^3, Plot Over Line along the
    # bounds' diagonal. On a second run of the cloud at twice the spacing
    # (an eighth of the nodes): on the defaults' 17 million nodes, Clip,
    # Threshold and their rendering in Mesa took a minute of the test, and
    # what they must show (points, cells, phi in [-1, 1]) does not depend on
    # the grid; test_pipeline_pvpython.py checks their values on the
    # defaults' grid. The defaults' shell stays shown beside them (the view's
    # geometry beyond its level-of-detail threshold, as with the defaults).
    coarse = NarrowVolumeReconstruction(Input=cloud)  # noqa: F821 (from LoadPlugin)
    coarse.SampleSpacing = 2.0 * result["field_used"]["SampleSpacing"]
    coarse.UpdatePipeline()
    result["downstream_grid"] = list(coarse.GetClientSideObject().GetOutputDataObject(0).GetDimensions())
    volume_port = OutputPort(coarse, 0)
    downstream = {"Slice": pvs.Slice(Input=volume_port), "Clip": pvs.Clip(Input=volume_port)}
    threshold = pvs.Threshold(Input=volume_port)
    threshold.Scalars = ["POINTS", "phi"]
    threshold.LowerThreshold = 0.0
    threshold.UpperThreshold = 1.0
    downstream["Threshold"] = threshold
    contour = pvs.Contour(Input=volume_port)
    contour.ContourBy = ["POINTS", "phi"]
    contour.Isosurfaces = [0.0]
    downstream["Contour"] = contour
    downstream["ResampleToImage"] = pvs.ResampleToImage(Input=volume_port)
    downstream["PlotOverLine"] = pvs.PlotOverLine(Input=volume_port)
    for name, proxy in downstream.items():
        Show(proxy, view)
        information = proxy.GetDataInformation()
        phi_range = proxy.PointData["phi"].GetRange() if "phi" in proxy.PointData.keys() else None
        result["downstream_" + name] = {"points": information.GetNumberOfPoints(),
                                        "cells": information.GetNumberOfCells(), "phi_range": phi_range}
    Render(view)
    if os.environ.get("NV_POINTS_PLY"):
        frame_in_a_view_that_drew_nothing(os.environ["NV_POINTS_PLY"], result)
    result["ok"] = True
except SystemExit:  # the PLY run's end
    pass
except Exception:  # reported to the test, which fails on it
    result["error"] = traceback.format_exc()
with open(os.environ["NV_GUI_RESULT"], "w") as f:
    json.dump(result, f, default=repr)  # a value JSON lacks shows as its repr, and the client still closes
os._exit(0)
