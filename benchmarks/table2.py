# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""Benchmark: the paper's Table 2 rows that can run here, in Narrow Band and
Whole Domain modes, beside the two routes a user would otherwise take on the
same grid: VTK's dense offset pipeline (vtkUnsignedDistance +
vtkFlyingEdges3D, unsmoothed) and OpenVDB's (ParticlesToLevelSet +
LevelSetFilter mean-curvature steps + volumeToMesh).

    pvpython benchmarks/table2.py [--scans ../shared/data/scans] [--openvdb build/bin/openvdb_shell]
                                  [--cases sphere armadillo-coarse ...] [--repeat 3]

Every run is a fresh child process, so that its peak resident memory (ru_maxrss)
is its own; "baseline" is a child that only loads the input. Times are medians
over --repeat runs. Prints Markdown tables.
"""
import argparse
import json
import math
import os
import platform
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile

import clouds

HERE = os.path.dirname(os.path.abspath(__file__))
# The children run in pvpython, whose Python finds ParaView's VTK.
PYTHON = shutil.which("pvpython") or "/usr/bin/pvpython"

# name: (source, cells along the longest side, offset in cells, xi cells, steps,
#        paper row: points, grid, N/W, iterations W/N, CPU(ini) W/N, CPU(pro) W/N)
CASES = {
    "sphere": ("sphere", 100, 4, 2, 7, "Fig. 5", "2,964", "100x100x100", 0.363, "7/7", "0.17/0.24", "3.93/1.60"),
    "teacup": ("teacup.ply", 276, 10, 1, 7, "Fig. 8(a)", "26,103", "276x182x146", 0.127, "7/7", "1.29/1.59", "18.00/2.92"),
    "armadillo-coarse": ("armadillo.ply", 123, 4, 2, 6, "Fig. 10(b)", "43,244", "107x123x98", 0.205, "5/6", "1.08/1.42", "2.23/0.78"),
    "armadillo-fine": ("armadillo.ply", 353, 4, 2, 5, "Fig. 10(c)", "43,244", "303x353x278", 0.209, "5/5", "21.31/27.64", "111.92/27.13"),
    "dragon": ("dragon.ply", 462, 4, 2, 4, "Fig. 11(a)", "218,823", "462x330x215", 0.158, "4/4", "6.82/8.54", "44.55/10.17"),
}
# Memory with the volume output on and off: (source, cells, offset cells, xi, steps).
MEMORY_CASES = {
    "armadillo-fine": ("armadillo.ply", 353, 4, 2, 5),
    "sphere-1024": ("sphere1024", 1024, 4, 2, 3),
}

CHILD = r'''
import json, math, resource, sys, time
import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData
import clouds
task = json.loads(sys.argv[1])
xyz = clouds.load(task)
points = vtkPoints(); points.SetData(numpy_to_vtk(np.ascontiguousarray(xyz), deep=1))
cloud = vtkPolyData(); cloud.SetPoints(points)
lo, hi = xyz.min(axis=0), xyz.max(axis=0)
m, lc = task["xi"], task["offset_cells"]
h = task.get("spacing") or clouds.spacing(xyz, task)
l = lc * h
out = {"points": len(xyz), "h": h}
if task["kind"] == "ours":
    from narrowvolume import vtkNarrowVolumeReconstruction
    f = vtkNarrowVolumeReconstruction()
    f.SetInputData(cloud); f.SetSampleSpacing(h); f.SetOffsetDistance(l); f.SetXiCells(m)
    f.SetMaximumNumberOfIterations(task["steps"]); f.SetDomain(task["domain"])
    f.SetOutputVolume(task.get("volume", True))
    start = time.perf_counter()
    f.Update()
    # update: the whole Update() as a user waits for it; sampling: the
    # points' spacing measured in it (builds before 1a8d960 have no getter).
    out.update(update=time.perf_counter() - start,
               sampling=f.GetSamplingTime() if hasattr(f, "GetSamplingTime") else float("nan"))
    out.update(grid="x".join(str(d) for d in f.GetOutput(0).GetDimensions()), band=f.GetNumberOfBandNodes(),
               nodes=f.GetNumberOfGridNodes(), iterations=f.GetNumberOfIterations(), setup=f.GetSetupTime(),
               evolution=f.GetEvolutionTime(), surface=f.GetOutputTime(),
               triangles=f.GetOutput(1).GetNumberOfPolys())
elif task["kind"] == "vtk":
    from vtkmodules.vtkFiltersPoints import vtkUnsignedDistance
    from vtkmodules.vtkFiltersCore import vtkFlyingEdges3D
    pad = l + m * h + 2 * h
    dims = [int(math.ceil((hi[a] - lo[a] + 2 * pad) / h - 1e-9)) + 1 for a in range(3)]
    distance = vtkUnsignedDistance()
    distance.SetInputData(cloud); distance.SetDimensions(dims)
    distance.SetBounds(lo[0] - pad, lo[0] - pad + (dims[0] - 1) * h, lo[1] - pad, lo[1] - pad + (dims[1] - 1) * h,
                       lo[2] - pad, lo[2] - pad + (dims[2] - 1) * h)
    distance.AdjustBoundsOff(); distance.SetRadius(l + 2 * h); distance.CappingOn()
    start = time.perf_counter(); distance.Update(); t1 = time.perf_counter() - start
    contour = vtkFlyingEdges3D(); contour.SetInputConnection(distance.GetOutputPort()); contour.SetValue(0, l)
    start = time.perf_counter(); contour.Update(); t2 = time.perf_counter() - start
    out.update(grid="x".join(str(d) for d in dims), distance=t1, surface=t2,
               triangles=contour.GetOutput().GetNumberOfPolys())
elif task["kind"] == "none":
    pass
elif task["kind"] == "openvdb":
    import subprocess, tempfile
    path = tempfile.mktemp(suffix=".xyz")
    xyz.astype(np.float32).tofile(path)
    # GNU time reports the program's own peak (a forked child's maxrss would
    # count the Python image it was forked from).
    result = subprocess.run(["/usr/bin/time", "-f", "%M", task["openvdb"], path, repr(h), repr(l), str(task["steps"])],
                            capture_output=True, text=True, check=True)
    out.update(json.loads(result.stdout))
    out["openvdb_maxrss_mb"] = int(result.stderr.strip().splitlines()[-1]) / 1024.0
out["maxrss_mb"] = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
out["child_maxrss_mb"] = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024.0
print("RESULT " + json.dumps(out))
'''


def run(task):
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(p for p in (HERE, os.environ.get("PYTHONPATH")) if p))
    result = subprocess.run([PYTHON, "-c", CHILD, json.dumps(task)], capture_output=True, text=True, env=env)
    for line in result.stdout.splitlines():
        if line.startswith("RESULT "):
            return json.loads(line[7:])
    raise RuntimeError("benchmark child failed: %s\n%s" % (task, result.stderr[-3000:]))


def median_run(task, repeat, keys):
    runs = [run(task) for _ in range(repeat)]
    best = dict(runs[0])
    for key in keys:
        if key in best:
            best[key] = statistics.median(r[key] for r in runs)
    best["maxrss_mb"] = max(r["maxrss_mb"] for r in runs)
    best["child_maxrss_mb"] = max(r["child_maxrss_mb"] for r in runs)
    if "openvdb_maxrss_mb" in best:
        best["openvdb_maxrss_mb"] = max(r["openvdb_maxrss_mb"] for r in runs)
    return best


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--scans", default=clouds.SCANS_DIR)
    parser.add_argument("--openvdb", default=os.path.join(HERE, "..", "build", "bin", "openvdb_shell"))
    parser.add_argument("--cases", nargs="+", default=list(CASES))
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--memory-cases", nargs="*", default=list(MEMORY_CASES))
    args = parser.parse_args()

    print("Machine: %s, %d cores, Python %s; times are medians of %d runs (seconds), memory is peak RSS (MB)."
          % (platform.processor() or platform.machine(), os.cpu_count(), platform.python_version(), args.repeat))
    ours_rows, peer_rows, memory_rows = [], [], []
    for name in args.cases:
        source, cells, lc, xi, steps, *paper = CASES[name]
        task = dict(source=source, cells=cells, offset_cells=lc, xi=xi, steps=steps)
        if source != "sphere":
            task["path"] = os.path.join(args.scans, source)
            if not os.path.exists(task["path"]):
                print("skipped %s: %s not found" % (name, task["path"]))
                continue
        if source == "sphere":
            task["spacing"] = 0.01
        timing = ["sampling", "setup", "evolution", "surface", "update", "distance", "rasterize", "smooth", "mesh"]
        baseline = run(dict(task, kind="none"))
        n = median_run(dict(task, kind="ours", domain=0), args.repeat, timing)
        w = median_run(dict(task, kind="ours", domain=1), args.repeat, timing)
        v = median_run(dict(task, kind="vtk"), args.repeat, timing)
        o = median_run(dict(task, kind="openvdb", openvdb=args.openvdb), args.repeat, timing) \
            if os.path.exists(args.openvdb) else None
        paper_n = sum(float(x.split("/")[1]) for x in paper[5:7])
        ours_n = n["setup"] + n["evolution"]
        ours_w = w["setup"] + w["evolution"]
        ours_rows.append("| %s (%s) | %d | %s | %.3f | %d | %.2f / %.2f | %.2f / %.2f | %.2f / %.2f | %.1fx | %.1fx | %s / %s |" % (
            name, paper[0], n["points"], n["grid"], n["band"] / n["nodes"], n["iterations"],
            w["setup"], n["setup"], w["evolution"], n["evolution"], w["surface"], n["surface"],
            paper_n / ours_n, ours_w / ours_n, paper[5], paper[6]))
        peer_rows.append("| %s | %.2f + %.2f = %.2f | %.2f + %.2f = %.2f | %s |" % (
            name, n["sampling"], n["setup"] + n["evolution"] + n["surface"],
            n["sampling"] + n["setup"] + n["evolution"] + n["surface"], v["distance"], v["surface"], v["distance"] + v["surface"],
            "%.2f + %.2f + %.2f = %.2f (%d steps)" % (o["rasterize"], o["smooth"], o["mesh"],
                                                     o["rasterize"] + o["smooth"] + o["mesh"], steps) if o else "not built"))
        memory_rows.append("| %s | %.0f | %.0f | %.0f | %.0f | %s |" % (
            name, baseline["maxrss_mb"], n["maxrss_mb"], w["maxrss_mb"], v["maxrss_mb"],
            "%.0f (grid %.1f MB)" % (o["openvdb_maxrss_mb"], o["grid_bytes"] / 1e6) if o else "-"))
        sys.stdout.flush()

    print("\n### Ours, Whole Domain / Narrow Band, beside the paper's Table 2 (one 3.4 GHz core)\n")
    print("| case | points | grid | N/W nodes | iterations | set-up W / N | evolution W / N | surface W / N "
          "| paper N / ours N | ours W / ours N | paper CPU(ini) W/N, CPU(pro) W/N |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    print("\n".join(ours_rows))
    print("\n### The whole job against the routes a user would otherwise take, same grid\n")
    print("| case | ours, Narrow Band: spacing + (set-up + evolution + surface) | VTK: vtkUnsignedDistance + vtkFlyingEdges3D (unsmoothed) "
          "| OpenVDB: rasterize + smooth + mesh |")
    print("|---|---|---|---|")
    print("\n".join(peer_rows))
    volume_rows = []
    for name in args.memory_cases:
        source, cells, lc, xi, steps = MEMORY_CASES[name]
        task = dict(source=source, cells=cells, offset_cells=lc, xi=xi, steps=steps, kind="ours", domain=0)
        if not source.startswith("sphere"):
            task["path"] = os.path.join(args.scans, source)
            if not os.path.exists(task["path"]):
                continue
        baseline = run(dict(task, kind="none"))
        on, off = run(dict(task, volume=True)), run(dict(task, volume=False))
        volume_rows.append("| %s | %d | %s | %d | %.0f | %.0f | %.0f | %.1f / %.1f |" % (
            name, on["points"], on["grid"], on["band"], baseline["maxrss_mb"], on["maxrss_mb"], off["maxrss_mb"],
            on["sampling"] + on["setup"] + on["evolution"] + on["surface"],
            off["sampling"] + off["setup"] + off["evolution"] + off["surface"]))
        sys.stdout.flush()

    print("\n### Peak resident memory (MB) of one run in a fresh process\n")
    print("| case | baseline (load the points) | ours N | ours W | VTK | OpenVDB program (its own process) |")
    print("|---|---|---|---|---|---|")
    print("\n".join(memory_rows))
    print("\n### Memory with the volume output on and off (ours, Narrow Band)\n")
    print("| case | points | grid | band nodes | baseline | peak, volume on | peak, volume off | time on / off (s) |")
    print("|---|---|---|---|---|---|---|---|")
    print("\n".join(volume_rows))


if __name__ == "__main__":
    main()
