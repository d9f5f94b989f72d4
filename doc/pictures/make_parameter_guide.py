# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""Renders doc/images/parameter_guide.png: what l, xi and eps do, on a sparse
version of the demo cloud (every 6th point of Data/trefoil.vtp).

    scripts/with-xvfb.sh pvpython doc/pictures/make_parameter_guide.py
"""
import os
import tempfile

import numpy as np
import paraview.simple as pvs

import nvpictures

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.normpath(os.path.join(HERE, "..", ".."))
BUILD = os.environ.get("BUILD_DIR") or os.path.join(SOURCE, "build")
PLUGIN = os.path.join(BUILD, "lib", "paraview-5.11", "plugins", "NarrowVolume", "NarrowVolume.so")
pvs.LoadPlugin(PLUGIN, ns=globals())

reader = pvs.XMLPolyDataReader(FileName=[os.path.join(SOURCE, "Data", "trefoil.vtp")])
sparse = pvs.MaskPoints(Input=reader, OnRatio=6, MaximumNumberofPoints=10 ** 7, GenerateVertices=1)
sparse.UpdatePipeline()
H = 2.2 / 120  # cells of the 120-cell grid used below

panels = [
    ("l = 2h, 3 steps", dict(OffsetDistance=2 * H)),
    ("l = 6h, 3 steps", dict(OffsetDistance=6 * H)),
    ("l = 3h, xi = eps_1, 10 steps", dict(OffsetDistance=3 * H, XiCells=1, MaximumNumberOfIterations=10)),
    ("l = 3h, xi = eps_4, 10 steps", dict(OffsetDistance=3 * H, XiCells=4, MaximumNumberOfIterations=10)),
    ("l = 3h, eps = eps_3, 10 steps", dict(OffsetDistance=3 * H, EpsilonCells=3, MaximumNumberOfIterations=10)),
    ("l = 3h, eps = eps_12, 10 steps", dict(OffsetDistance=3 * H, EpsilonCells=12, MaximumNumberOfIterations=10)),
]
scratch = tempfile.TemporaryDirectory()  # the panels, removed at exit
folder = scratch.name
images = []
for title, settings in panels:
    view = nvpictures.new_view((500, 420))
    shell = NarrowVolumeReconstruction(Input=sparse, SampleSpacing=H, Sheets="Outer", **settings)  # noqa: F821
    shown = pvs.Show(pvs.OutputPort(shell, 1), view)
    shown.ColorArrayName = ["POINTS", ""]
    shown.DiffuseColor = [0.85, 0.55, 0.3]
    pvs.Render(view)
    view.CameraPosition = [0.3, -0.8, 3.2]
    view.CameraFocalPoint = [0, 0, 0]
    view.CameraViewUp = [0, 1, 0]
    view.ResetCamera()
    pvs.Render(view)
    path = os.path.join(folder, "%d.png" % len(images))
    pvs.SaveScreenshot(path, view, ImageResolution=[500, 420])
    images.append((title, path))
    pvs.Delete(shell)
    pvs.Delete(view)

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import matplotlib.image as mpimg

fig, axes = plt.subplots(3, 2, figsize=(8, 10))
for ax, (title, path) in zip(axes.ravel(), images):
    ax.imshow(mpimg.imread(path))
    ax.set_title(title, fontsize=11)
    ax.axis("off")
fig.suptitle("Outer sheet of the shell around 5,000 sparse points (h = 1/120 of the cloud)", fontsize=11)
fig.tight_layout()
fig.savefig(os.path.join(SOURCE, "doc", "images", "parameter_guide.png"), dpi=80)
print("wrote doc/images/parameter_guide.png")
