# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""Runs inside the ParaView client for doc/pictures/gui_panel.py
(paraview --script=...): loads the plugin (NV_PLUGIN), opens the cloud
(NV_CLOUD), applies Narrow Volume Reconstruction with the panel's defaults,
shows the Surface beside the points, leaves the filter selected (its
Properties panel showing) and writes NV_READY. The client stays open for the
screenshot; gui_panel.py closes it."""
import os
import traceback

try:
    import paraview.simple as pvs

    names = {"__name__": "gui"}
    pvs.LoadPlugin(os.environ["NV_PLUGIN"], ns=names)
    cloud = pvs.OpenDataFile(os.environ["NV_CLOUD"])
    pvs.RenameSource("trefoil.vtp", cloud)
    view = pvs.GetActiveViewOrCreate("RenderView")
    view.OrientationAxesVisibility = 1
    points = pvs.Show(cloud, view)
    points.AmbientColor = points.DiffuseColor = [0.1, 0.2, 0.6]
    shell = names["NarrowVolumeReconstruction"](Input=cloud)
    surface = pvs.Show(pvs.OutputPort(shell, 1), view)
    surface.AmbientColor = surface.DiffuseColor = [0.85, 0.55, 0.3]
    pvs.Show(pvs.OutputPort(shell, 0), view)  # the Volume shows as its outline
    clip = None
    pvs.SetActiveSource(shell)
    pvs.Render(view)
    view.CameraPosition = [0.3, -0.8, 3.2]
    view.CameraFocalPoint = [0, 0, 0]
    view.CameraViewUp = [0, 1, 0]
    pvs.ResetCamera(view)
    pvs.Render(view)
    message = "ok"
except Exception:
    message = traceback.format_exc()
with open(os.environ["NV_READY"], "w") as f:
    f.write(message)
