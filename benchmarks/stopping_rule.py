# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""How the relative change and the sheets move with the number of steps, on
the Table 1 sphere (radius 0.5, l = 0.1, default parameters): the measurement
behind the default stopping rule. Prints a table and writes a plot.

    pvpython benchmarks/stopping_rule.py [--spacing 0.01 0.005] [--steps 20] [--plot doc/images/stopping_rule.png]
"""
import argparse
import sys

import numpy as np

from clouds import nvclouds, nvmeasures, nvshapes
from narrowvolume import vtkNarrowVolumeReconstruction

parser = argparse.ArgumentParser()
parser.add_argument("--spacing", type=float, nargs="+", default=[0.01, 0.005])
parser.add_argument("--steps", type=int, default=20)
parser.add_argument("--plot", default="")
args = parser.parse_args()

OFFSET = 0.1
curves = {}
for h in args.spacing:
    cloud = nvclouds.cloud(nvclouds.shape_points("sphere", h))
    steps = list(range(0, min(args.steps, 10) + 1)) + list(range(12, args.steps + 1, 4))
    rows = []
    print("\nsphere, h = %g" % h)
    print("| steps | relative change of the last step | inner max error | inner mean error | outer max error | outer mean error |")
    print("|---|---|---|---|---|---|")
    for n in steps:
        f = vtkNarrowVolumeReconstruction()
        f.SetInputData(cloud)
        f.SetOffsetDistance(OFFSET)
        f.SetSampleSpacing(h)
        f.SetMaximumNumberOfIterations(n)
        f.Update()
        x = nvmeasures.points_of(f.GetOutput(1))
        r = np.linalg.norm(x - nvshapes.CENTER, axis=1)
        inner, outer = np.abs(r[r < 0.5] - 0.4), np.abs(r[r >= 0.5] - 0.6)
        change = f.GetRelativeChanges()[-1] if n else float("nan")
        rows.append((n, change, inner.max(), inner.mean(), outer.max(), outer.mean()))
        print("| %d | %.2e | %.3e | %.3e | %.3e | %.3e |" % rows[-1])
        sys.stdout.flush()
    curves[h] = np.array(rows)

if args.plot:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 3.8))
    for h, rows in curves.items():
        left.semilogy(rows[1:, 0], rows[1:, 1], "o-", label="h = %g" % h)
        line, = right.semilogy(rows[:, 0], rows[:, 2], "o-", label="inner max, h = %g" % h)
        right.semilogy(rows[:, 0], rows[:, 3], "s--", color=line.get_color(), label="inner mean, h = %g" % h)
        paper = nvshapes.PAPER_TABLE1.get(("sphere", h))
        if paper:
            right.axhline(paper[0], color=line.get_color(), linestyle=":", linewidth=1)
    left.axhline(1e-5, color="gray", linestyle=":")
    left.text(0.5, 1.3e-5, "paper's tolerance 1e-5", color="gray")
    left.set_xlabel("time steps")
    left.set_ylabel("||phi(n+1) - phi(n)|| / ||phi(n)||")
    left.set_title("relative change per step")
    left.legend()
    right.axvline(3, color="gray", linestyle=":")
    right.set_xlabel("time steps")
    right.set_ylabel("error of the inner sheet")
    right.set_title("sphere, l = 0.1 (dotted: paper's max)")
    right.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(args.plot, dpi=110)
    print("wrote", args.plot)
