# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""Runs inside the real ParaView client (paraview --script=gui_script.py):
loads the plugin, opens a point cloud, applies the filter with the panel's
defaults, shows both outputs beside the points, saves a screenshot, writes
what it saw to NV_GUI_RESULT (JSON) and closes the client."""
import json
import os
import traceback

result = {"ok": False}
try:
    from paraview.simple import (GetActiveViewOrCreate, LoadPlugin, OpenDataFile, OutputPort, Render,
                                 ResetCamera, SaveScreenshot, Show)
    import paraview.simple as pvs

    LoadPlugin(os.environ["NV_PLUGIN"], ns=globals())
    cloud = OpenDataFile(os.environ["NV_CLOUD"])
    view = GetActiveViewOrCreate("RenderView")
    Show(cloud, view)
    cloud.UpdatePipeline()
    shell = NarrowVolumeReconstruction(Input=cloud)  # noqa: F821 (from LoadPlugin)
    result["offset_default"] = shell.OffsetDistance
    result["label"] = shell.GetXMLLabel()
    surface = Show(OutputPort(shell, 1), view)
    volume = Show(OutputPort(shell, 0), view)  # an image shows as its outline
    surface.DiffuseColor = [0.9, 0.5, 0.2]
    Render(view)
    ResetCamera(view)
    Render(view)
    result["surface_cells"] = shell.GetDataInformation(1).GetNumberOfCells()
    result["volume_points"] = shell.GetDataInformation(0).GetNumberOfPoints()
    result["cloud_visible"] = bool(pvs.GetDisplayProperties(cloud, view).Visibility)
    SaveScreenshot(os.environ["NV_SCREENSHOT"], view, ImageResolution=[800, 600])
    result["ok"] = True
except Exception:  # reported to the test, which fails on it
    result["error"] = traceback.format_exc()
with open(os.environ["NV_GUI_RESULT"], "w") as f:
    json.dump(result, f)
os._exit(0)
