# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""Benchmark: the filter under MPI with 1, 2 and 4 ranks (mpiexec pvbatch
--symmetric), time and peak memory per rank.

    pvpython benchmarks/mpi_scaling.py [--case sphere-1024 | armadillo-fine | trefoil-5M] [--ranks 1 2 4]
                                       [--threads 1] [--repeat 3] [--volume 1] [--build build]

Each rank reads the cloud and keeps every N-th point (as a parallel reader
would give it a share), then runs vtkNarrowVolumeReconstruction as its piece
of N. Per rank: the layers of its slab, the filter's set-up, evolution and
output seconds (medians over --repeat runs), and its peak resident memory
(ru_maxrss; "input" is the peak before the filter ran), and the seconds
the points' spacing took (measured slab by slab on all ranks). The
trefoil-5M cloud (fig16.py's densest) is generated once, before the ranks
start, which each map and take their share of, so that "input" is not the
generator's. Threads per rank:
--threads (default 1, so that N ranks use N cores; this machine has 2, so 4
ranks share them). Prints Markdown tables.
"""
import argparse
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile

import clouds

HERE = os.path.dirname(os.path.abspath(__file__))
BUILD = os.path.join(HERE, "..", "build")

# name: (source, cells along the longest side, offset in cells, xi cells, steps)
CASES = {
    "armadillo-fine": ("armadillo.ply", 353, 4, 2, 5),
    "sphere-1024": ("sphere1024", 1024, 4, 2, 3),
    "trefoil-5M": ("trefoil:5000000", 215, 4, 2, 3),
}

RANK = r'''
import json, resource, sys, time
import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkParallelCore import vtkMultiProcessController
import clouds
controller = vtkMultiProcessController.GetGlobalController()
rank, size = controller.GetLocalProcessId(), controller.GetNumberOfProcesses()
task = json.loads(sys.argv[1])
xyz = np.load(task["npy"], mmap_mode="r") if "npy" in task else clouds.load(task)
m, lc = task["xi"], task["offset_cells"]
h = clouds.spacing(xyz, task)
share = np.ascontiguousarray(xyz[rank::size])
del xyz
points = vtkPoints(); points.SetData(numpy_to_vtk(share, deep=1))
cloud = vtkPolyData(); cloud.SetPoints(points)
input_mb = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
from narrowvolume import vtkNarrowVolumeReconstruction
f = vtkNarrowVolumeReconstruction()
f.SetInputData(cloud); f.SetSampleSpacing(h); f.SetOffsetDistance(lc * h); f.SetXiCells(m)
f.SetMaximumNumberOfIterations(task["steps"]); f.SetOutputVolume(task["volume"])
f.SetNumberOfThreads(task["threads"])
controller.Barrier()
start = time.perf_counter()
f.UpdatePiece(rank, size, 0)
wall = time.perf_counter() - start
extent = f.GetOutput(0).GetExtent()
open("%s/rank%d.json" % (task["out"], rank), "w").write(json.dumps(dict(rank=rank, points=len(share), grid=f.GetNumberOfGridNodes(),
      band=f.GetNumberOfBandNodes(), layers=[extent[4], extent[5]], spacing=f.GetSamplingTime(), setup=f.GetSetupTime(),
      evolution=f.GetEvolutionTime(), output=f.GetOutputTime(), wall=wall,
      triangles=f.GetOutput(1).GetNumberOfPolys(), input_mb=input_mb,
      peak_mb=resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0)))
'''


def run(ranks, task, build):
    env = {k: v for k, v in os.environ.items() if not k.startswith(("OMPI_", "PMIX_", "OPAL_", "PMI_"))}
    env["PYTHONPATH"] = os.pathsep.join([os.path.join(build, "lib", "python3.11", "dist-packages"), HERE])
    if shutil.which("pvbatch") is None:
        sys.exit("pvbatch not found")
    with tempfile.TemporaryDirectory(prefix="nv-mpi-scaling-") as out:
        task = dict(task, out=out)
        command = ["mpiexec", "--allow-run-as-root", "--oversubscribe", "-np", str(ranks), "pvbatch", "--symmetric",
                   "-c", RANK, json.dumps(task)]
        result = subprocess.run(command, capture_output=True, text=True, env=env)
        rows = [json.load(open(os.path.join(out, name))) for name in os.listdir(out)]
    if result.returncode != 0 or len(rows) != ranks:
        raise RuntimeError("%d ranks failed:\n%s\n%s" % (ranks, result.stdout[-2000:], result.stderr[-3000:]))
    return sorted(rows, key=lambda r: r["rank"])


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--scans", default=clouds.SCANS_DIR)
    parser.add_argument("--case", choices=list(CASES), default="sphere-1024")
    parser.add_argument("--ranks", type=int, nargs="+", default=[1, 2, 4])
    parser.add_argument("--threads", type=int, default=1)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--volume", type=int, default=1, help="OutputVolume (1) or surface only (0)")
    parser.add_argument("--build", default=BUILD, help="the build folder whose narrowvolume runs (default build/)")
    args = parser.parse_args()
    source, cells, offset_cells, xi, steps = CASES[args.case]
    task = dict(source=source, cells=cells, offset_cells=offset_cells, xi=xi, steps=steps, volume=bool(args.volume),
                threads=args.threads, path=os.path.join(args.scans, source))
    if source.endswith(".ply") and not os.path.exists(task["path"]):
        print("skipped: %s not found (../shared/data/scans)" % task["path"])
        return
    if source.startswith("trefoil"):
        import numpy as np
        scratch = tempfile.TemporaryDirectory(prefix="nv-mpi-scaling-")  # removed at exit
        task["npy"] = os.path.join(scratch.name, "cloud.npy")
        np.save(task["npy"], clouds.load(task))
    print("## %s under MPI, OutputVolume %d, %d thread(s) per rank, medians of %d runs\n"
          % (args.case, args.volume, args.threads, args.repeat))
    summary = []
    print("| ranks | rank | points | slab (z layers) | spacing s | set-up s | evolution s | output s | filter s | "
          "peak MB | input MB |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for ranks in args.ranks:
        runs = [run(ranks, task, args.build) for _ in range(args.repeat)]
        for r in range(ranks):
            median = {key: statistics.median(run_[r][key] for run_ in runs)
                      for key in ("spacing", "setup", "evolution", "output", "wall")}
            peak = max(run_[r]["peak_mb"] for run_ in runs)
            row = runs[0][r]
            print("| %d | %d | %d | %d-%d | %.2f | %.2f | %.2f | %.2f | %.2f | %.0f | %.0f |" % (
                ranks, r, row["points"], row["layers"][0], row["layers"][1], median["spacing"], median["setup"],
                median["evolution"], median["output"], median["wall"], peak, row["input_mb"]))
        walls = [statistics.median(max(rank_["wall"] for rank_ in run_) for run_ in runs)]
        summary.append((ranks, runs[0][0]["grid"], runs[0][0]["band"], walls[0],
                        max(rank_["peak_mb"] for run_ in runs for rank_ in run_),
                        sum(rank_["triangles"] for rank_ in runs[0])))
    if "npy" in task:
        os.remove(task["npy"])
        os.rmdir(os.path.dirname(task["npy"]))
    print("\n| ranks | grid nodes | band nodes | slowest rank s | speed-up | largest rank peak MB | triangles |")
    print("|---|---|---|---|---|---|---|")
    for ranks, grid, band, wall, peak, triangles in summary:
        print("| %d | %d | %d | %.2f | %.2fx | %.0f | %d |" % (ranks, grid, band, wall, summary[0][3] / wall, peak,
                                                            triangles))


if __name__ == "__main__":
    main()
