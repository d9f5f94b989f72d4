# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""Renders doc/images/scan_surface_open.png for the how-to "A surface from a
scan": an open scan (one side of a bumpy ball, as a scanner sees it from
the front, with noise) and what Sheets Both and Sheets Scan make of it.

    scripts/with-xvfb.sh pvpython doc/pictures/scan_surface_open.py

The cloud is made here: 20,000 points on the half y < 0 of the surface
r = 1 + 0.08 sin(5 theta) cos(4 phi), with Gaussian noise of 0.5 % of the
diagonal along each axis. Left: the shell (Sheets Both) cut open at
z = 0: it wraps the scan as one thick plate, round its rim. Right: the scan
surface (Sheets Scan): one open surface through the points' middle, its
boundary (dark red) at the scan's rim. The titles give the runs' own
figures and the mean radial distance of the scan surface to the true one.
"""
import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy

import nvpictures as nv
import nvmeasures  # noqa: E402 (in Data/, on the path nvpictures makes)

pvs = nv.plugin()
SCAN = [0.55, 0.80, 0.55]   # the scan surface (light green, as in scan_surface.png)
RIM = [0.55, 0.05, 0.05]    # its boundary (dark red)
DIRECTION = [-2.0, 1.3, 1.6]


def radius(theta, phi):
    return 1.0 + 0.08 * np.sin(5.0 * theta) * np.cos(4.0 * phi)


def front_of_bumpy_ball(n=20000, noise=0.005, seed=11):
    """Points on the front half (y < 0), near uniform by area, and the noise's sigma."""
    rng = np.random.default_rng(seed)
    v = rng.normal(size=(3 * n, 3))
    v /= np.linalg.norm(v, axis=1)[:, None]
    v = v[v[:, 1] < 0.0][:n]
    theta, phi = np.arccos(v[:, 2]), np.arctan2(v[:, 1], v[:, 0])
    xyz = v * radius(theta, phi)[:, None]
    diagonal = float(np.linalg.norm(xyz.max(axis=0) - xyz.min(axis=0)))
    return xyz + rng.normal(scale=noise * diagonal, size=xyz.shape), noise * diagonal


def radial_distance(p):
    r = np.linalg.norm(p, axis=1)
    return np.abs(r - radius(np.arccos(np.clip(p[:, 2] / r, -1, 1)), np.arctan2(p[:, 1], p[:, 0])))


xyz, sigma = front_of_bumpy_ball()
strip = nv.Strip()
for name in ("shell", "scan"):
    run = nv.reconstruct(nv.cloud_source(xyz), **({"Sheets": 3} if name == "scan" else {}))
    run.UpdatePipeline()
    l, h = nv.field_value(run, "OffsetDistance"), nv.field_value(run, "SampleSpacing")
    view = nv.new_view()
    if name == "shell":
        nv.show_cut_open(view, run, [0.0, 0.0, 0.0], [0.0, 0.0, 1.0], xyz, slab=2 * sigma)
        title = "shell (Sheets Both), l = %.2g:\none plate around the scan, cut at z = 0" % l
    else:
        surface = run.GetClientSideObject().GetOutputDataObject(1)
        shown = pvs.Show(nv.producer(surface), view)
        nv._solid(shown, SCAN)
        rim = pvs.Show(nv.producer(nvmeasures.boundary_of(surface)), view)
        nv._solid(rim, RIM, 0.0)
        rim.LineWidth = 3.0
        d = radial_distance(vtk_to_numpy(surface.GetPoints().GetData()))
        title = "Sheets Scan: %d open piece, its rim dark red;\n%.2g off the true surface (mean), noise %.2g" % (
            nv.field_value(run, "ScanSurfaceOpenPieces"), d.mean(), sigma)
        print("scan surface: ScanSurface %d, open pieces %d, ScanDistanceMean %.3g h, ScanDistance95 %.3g h, h %.4g, "
              "mean radial distance to the true surface %.3g (noise %.3g)" % (
                  nv.field_value(run, "ScanSurface"), nv.field_value(run, "ScanSurfaceOpenPieces"),
                  nv.field_value(run, "ScanDistanceMean"), nv.field_value(run, "ScanDistance95"), h, d.mean(), sigma))
        nv.show_points(view, nv.cloud_source(xyz[::8]), size=1.5)
    print("%s: l %.4g, h %.4g" % (name, l, h))
    nv.look(view, [0.0, -0.4, 0.0], DIRECTION, [0, 0, 1], zoom=1.15)
    strip.add(view, title)
    pvs.Delete(view)
strip.save("scan_surface_open.png", columns=2, panel_inches=3.4,
           title="An open scan: the front of a bumpy ball (%d points, noise %.2g)" % (len(xyz), sigma),
           caption="Orange: the shell; red: its wall, cut; green: the scan surface; blue: the points (every "
                   "eighth on the right).\nThe shell wraps the open scan round its rim; the scan surface "
                   "stops there.")
