# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""Roughness against the number of steps on the Fig. 6 noisy spheres (5 %
noise, the clouds of test_noise_fig6.py and test_preserve_offset.py), with
PreserveOffset on and off. Prints a table: the mean angle, in degrees,
between neighbouring triangles' normals.

    pvpython benchmarks/noise_roughness.py [--steps 3 10 20 40]
"""
import argparse

from clouds import nvclouds, nvmeasures
from narrowvolume import vtkNarrowVolumeReconstruction

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
    return nvmeasures.face_normal_roughness(f.GetOutput(1))


print("Fig. 6 spheres, 5 % noise, xi = eps_4, eps = eps_12, h = 0.01: roughness (deg)")
print("| points | steps | PreserveOffset | paper's scheme |")
print("|---|---|---|---|")
for points, noise, xyz in nvclouds.fig6_spheres(H, R):  # the tests' clouds
    if noise != NOISE:
        continue
    cloud = nvclouds.cloud(xyz)
    for steps in args.steps:
        print("| %d | %d | %.2f | %.2f |" % (points, steps, roughness(cloud, steps, True),
                                             roughness(cloud, steps, False)), flush=True)
