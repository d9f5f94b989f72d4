# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""Roughness against the number of steps on the Fig. 6 noisy spheres (5 %
noise, the clouds of test_noise_fig6.py and test_preserve_offset.py), with
PreserveOffset on and off. Prints a table: the mean angle, in degrees,
between neighbouring triangles' normals.

    pvpython benchmarks/noise_roughness.py [--steps 3 10 20 40]
"""
import argparse
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "Testing", "Python"))
import nvshapes  # noqa: E402
import nvtesting  # noqa: E402
from narrowvolume import vtkNarrowVolumeReconstruction  # noqa: E402

parser = argparse.ArgumentParser()
parser.add_argument("--steps", type=int, nargs="+", default=[3, 10, 20, 40])
args = parser.parse_args()

R, L, H, NOISE = 0.5, 0.1, 0.01, 0.05


def roughness(cloud, steps, preserve):
    f = vtkNarrowVolumeReconstruction()
    f.SetInputData(cloud)
    f.SetOffsetDistance(L)
    f.SetSampleSpacing(H)
    f.SetXiCells(4)
    f.SetEpsilonCells(12)
    f.SetMaximumNumberOfIterations(steps)
    f.SetPreserveOffset(preserve)
    f.Update()
    return nvtesting.face_normal_roughness(f.GetOutput(1))


print("Fig. 6 spheres, 5 % noise, xi = eps_4, eps = eps_12, h = 0.01: roughness (deg)")
print("| points | steps | PreserveOffset | paper's scheme |")
print("|---|---|---|---|")
for points in (2964, len(nvshapes.sphere_points(H, R))):
    clean = nvshapes.sphere_points(H, R, count=points)
    rng = np.random.default_rng(6)  # the tests' clouds: the same seed, the first noise level
    radial = (clean - nvshapes.CENTER) * (1.0 + NOISE * rng.uniform(-1.0, 1.0, len(clean)))[:, None]
    cloud = nvtesting.cloud(nvshapes.CENTER + radial)
    for steps in args.steps:
        print("| %d | %d | %.2f | %.2f |" % (points, steps, roughness(cloud, steps, True),
                                             roughness(cloud, steps, False)), flush=True)
