# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""Renders doc/images/scan_surface.png for the how-to "A surface from a
scan": the same noisy cloud as the shell, the part to print and the scan
surface, each cut open, with the points near the cut drawn over it.

    scripts/with-xvfb.sh pvpython doc/pictures/scan_surface.py

The cloud is made here: a torus (radii 0.5 and 0.2) sampled at random,
uniform by area, with Gaussian noise of 1 % of its diagonal along each
axis. Left: the shell at the defaults (Sheets Both). Middle: the part to
print (WallThickness 2 % of the diagonal). Right: Sheets Scan. The titles
give each run's own figures and the mean distance of the surface's vertices
to the true torus (its outer surface, for the part).
"""
import math

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkPlane
from vtkmodules.vtkFiltersCore import vtkCutter, vtkPolyDataNormals
from vtkmodules.vtkFiltersGeneral import vtkContourTriangulator

import nvpictures as nv

pvs = nv.plugin()
R, r = 0.5, 0.2
DIRECTION = [0.45, -1.0, 0.75]
UP = [0, 0, 1]
CENTER = [0.0, 0.0, 0.0]
NORMAL = [0.0, -1.0, 0.0]   # the half y < 0 is cut away, the camera looks from there
SCAN = [0.55, 0.80, 0.55]   # the scan surface's section (light green)


def noisy_torus(n=40000, noise=0.01, seed=5):
    rng = np.random.default_rng(seed)
    u = rng.uniform(0.0, 2.0 * math.pi, 3 * n)
    v = rng.uniform(0.0, 2.0 * math.pi, 3 * n)
    keep = rng.uniform(0.0, 1.0, 3 * n) < (R + r * np.cos(v)) / (R + r)
    u, v = u[keep][:n], v[keep][:n]
    xyz = np.c_[(R + r * np.cos(v)) * np.cos(u), (R + r * np.cos(v)) * np.sin(u), r * np.sin(v)]
    diagonal = float(np.linalg.norm(xyz.max(axis=0) - xyz.min(axis=0)))
    return xyz + rng.normal(scale=noise * diagonal, size=xyz.shape), noise * diagonal, diagonal


def off_torus(p):
    """Signed distance to the true torus (> 0 outside), and the direction away from its core circle."""
    rho = np.hypot(p[:, 0], p[:, 1])
    away = p - np.c_[R * p[:, 0] / rho, R * p[:, 1] / rho, np.zeros(len(p))]
    tube = np.linalg.norm(away, axis=1)
    return tube - r, away / tube[:, None]


def surface_points(shell):
    data = shell.GetClientSideObject().GetOutputDataObject(1)
    return vtk_to_numpy(data.GetPoints().GetData()), vtk_to_numpy(data.GetPointData().GetNormals()), data


def show_section_of_surface(view, surface, color):
    """The section of the closed surfaces by the cut plane, filled (the Volume
    output's phi is the shell's, not the part's nor the scan surface's)."""
    plane = vtkPlane()
    plane.SetOrigin(CENTER)
    plane.SetNormal(NORMAL)
    cutter = vtkCutter()
    cutter.SetCutFunction(plane)
    cutter.SetInputData(surface)
    fill = vtkContourTriangulator()
    fill.SetInputConnection(cutter.GetOutputPort())
    fill.Update()
    shown = pvs.Show(nv.producer(fill.GetOutput()), view)
    nv._solid(shown, color, 0.0)
    shown.Ambient, shown.Diffuse = 1.0, 0.0   # flat: the triangulation's own normals do not matter


def look_at_section(view):
    """The camera on the tube's section at x = R, from the side cut away."""
    pvs.Render(view)
    direction = np.asarray(DIRECTION) / np.linalg.norm(DIRECTION)
    focus = np.array([R, 0.0, 0.07])
    view.CameraFocalPoint = list(focus)
    view.CameraPosition = list(focus + 1.1 * direction)
    view.CameraViewUp = UP
    view.CameraViewAngle = 30
    view.CameraParallelProjection = 0
    pvs.Render(view)


xyz, sigma, diagonal = noisy_torus()
wall = 0.02 * diagonal
off = off_torus(xyz)[0]
print("points: %.3g off the torus on average (signed), 95 %% of them within %.3g outside it" % (
    off.mean(), np.quantile(off, 0.95)))
strip = nv.Strip()
for name, properties in (("shell", {}), ("part", dict(WallThickness=wall)), ("scan", dict(Sheets=3))):
    shell = nv.reconstruct(nv.cloud_source(xyz), **properties)
    shell.UpdatePipeline()
    l = nv.field_value(shell, "OffsetDistance")
    h = nv.field_value(shell, "SampleSpacing")
    p, normals, surface = surface_points(shell)
    d, away = off_torus(p)
    outer = np.sum(normals * away, axis=1) > 0   # the vertices of the outer sheet or surface (normals outward)
    view = nv.new_view()
    if name == "scan":
        nv.show_cut_open(view, shell, CENTER, NORMAL, sheet_only=True)
        show_section_of_surface(view, surface, SCAN)
        title = "Sheets Scan: on the points' middle,\n%.2g off the torus (mean)" % np.abs(d).mean()
        print("scan surface: ScanDistanceMean %.3g h, ScanDistance95 %.3g h, ScanDepth %.3g h, h %.4g, "
              "mean signed distance to the torus %.3g" % (
                  nv.field_value(shell, "ScanDistanceMean"), nv.field_value(shell, "ScanDistance95"),
                  nv.field_value(shell, "ScanDepth"), h, d.mean()))
    else:
        nv.show_cut_open(view, shell, CENTER, NORMAL, sheet_only=True)
        show_section_of_surface(view, surface, nv.SECTION)
        if name == "shell":
            title = "shell (Sheets Both), l = %.2g:\nouter sheet %.2g off the torus" % (l, np.abs(d[outer]).mean())
        else:
            title = "part, WallThickness %.2g:\nouter surface %.2g off the torus" % (wall, np.abs(d[outer]).mean())
        print("%s: l %.4g, h %.4g, outer surface's mean distance to the torus %.3g (signed %.3g)" % (
            name, l, h, np.abs(d[outer]).mean(), d[outer].mean()))
    # The points within a slab in front of the cut, drawn over it.
    ahead = xyz @ (np.asarray(NORMAL) / np.linalg.norm(NORMAL))
    nv.show_points(view, nv.cloud_source(xyz[(ahead > 0) & (ahead < sigma)]), size=3.0)
    look_at_section(view)
    strip.add(view, title)
    pvs.Delete(view)
strip.save("scan_surface.png", columns=3, panel_inches=3.2,
           title="A noisy torus (%d points, noise %.2g = 1 %% of the diagonal), cut open" % (len(xyz), sigma),
           caption="Red: the shell's or the part's material; green: inside the scan surface; orange: the surfaces; "
                   "blue: the points near\nthe cut. The shell's outer sheet lies l beyond the noisy points, the "
                   "part's outside on their outer edge;\nthe scan surface runs through their middle.")
