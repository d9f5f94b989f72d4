# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""The paper's Fig. 8 (effect of xi) and Fig. 9 (effect of eps) on real scans
from ../shared/data/scans. Skipped, with a message, when the folder is absent.

- Fig. 8, teacup (unevenly sampled, thin wall), l = 4h, 250 cells, 10 steps:
  with xi = eps_1 the shell keeps the holes of the sparse parts (many
  separate pieces); with xi = eps_2 and eps_4 they close into two clean
  sheets (inner and outer, each with the handle's tunnel: Euler
  characteristic 0 each).
  The points are taken as given (CloseGaps off), as in the paper.
- Fig. 9, bunny, l = 4h, 200 cells: with a sixth of the points the initial
  surface is wrinkled (rougher than with all points), and eps = eps_12
  smooths it more than eps_6.

    pvpython test_scans_fig8_fig9.py SCANS_DIR
"""
import os
import sys

from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOPLY import vtkPLYReader

from narrowvolume import vtkNarrowVolumeReconstruction
import nvtesting

SKIP = 77
scans = sys.argv[1]
if not os.path.isfile(os.path.join(scans, "teacup.ply")):
    print("SKIPPED: no scans in %s (../shared/data/scans is not beside the source tree)" % scans)
    sys.exit(SKIP)
t = nvtesting.Checker("test_scans_fig8_fig9")


def read(name):
    reader = vtkPLYReader()
    reader.SetFileName(os.path.join(scans, name + ".ply"))
    reader.Update()
    return vtk_to_numpy(reader.GetOutput().GetPoints().GetData()).astype(float)


def shell(xyz, cells, offset_cells, **settings):
    lo, hi = xyz.min(axis=0), xyz.max(axis=0)
    h = float((hi - lo).max()) / cells
    f = vtkNarrowVolumeReconstruction()
    f.SetInputData(nvtesting.cloud(xyz))
    f.SetSampleSpacing(h)
    f.SetOffsetDistance(offset_cells * h)
    f.SetRemoveSmallPieces(False)  # the paper's figures show every piece
    f.SetCloseGaps(False)  # of the points as given (gap closing: test_gap_closing.py)
    for key, value in settings.items():
        getattr(f, "Set" + key)(value)
    f.Update()
    return f.GetOutput(1)


# Fig. 8: xi.
teacup = read("teacup")
pieces, euler = {}, {}
for xi in (1, 2, 4):
    s = shell(teacup, 250, 4, XiCells=xi, MaximumNumberOfIterations=10)
    pieces[xi], euler[xi] = nvtesting.regions(s), nvtesting.euler_characteristic(s)
    print("Fig. 8 teacup, xi = eps_%d: %d pieces, Euler characteristic %d" % (xi, pieces[xi], euler[xi]))
t.check(pieces[1] >= 10, "xi_1 leaves the sparse parts open (%d pieces)" % pieces[1])
for xi in (2, 4):
    t.check(pieces[xi] == 2 and euler[xi] == 0, "xi_%d closes them: %d pieces, chi %d" % (xi, pieces[xi], euler[xi]))

# Fig. 9: eps and the number of points.
bunny = read("bunny")
sixth = bunny[::6]
rough_all = nvtesting.face_normal_roughness(shell(bunny, 200, 4, MaximumNumberOfIterations=0))
rough_sixth = nvtesting.face_normal_roughness(shell(sixth, 200, 4, MaximumNumberOfIterations=0))
rough_eps6 = nvtesting.face_normal_roughness(shell(sixth, 200, 4, EpsilonCells=6))
rough_eps12 = nvtesting.face_normal_roughness(shell(sixth, 200, 4, EpsilonCells=12))
print("Fig. 9 bunny: initial surface roughness %.2f deg with %d points, %.2f with %d" % (
    rough_all, len(bunny), rough_sixth, len(sixth)))
print("Fig. 9 bunny, %d points, 3 steps: roughness %.2f with eps_6, %.2f with eps_12" % (
    len(sixth), rough_eps6, rough_eps12))
t.check(rough_sixth > 1.5 * rough_all, "fewer points: wrinkled initial surface")
t.check(rough_eps12 < 0.8 * rough_eps6, "a larger eps smooths more")
t.check(rough_eps6 < rough_sixth, "the evolution smooths the initial surface")
t.finish()
