# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""Benchmark: where the core's time goes, stage by stage, for a grid size and
several thread counts, without VTK: the numerical core as the pip package
builds it (its module narrowvolume._core), so that it runs on any machine
with Python and numpy, a workstation or a GPU machine without VTK.

    python -m venv venv && venv/bin/pip install .      # the core, built by pip
    venv/bin/python benchmarks/core_stages.py --grid 1024 --threads 1 2 4 8 16 [--repeat 3]
    venv/bin/python benchmarks/core_stages.py --grid 1024 --threads 16 --device cpu gpu

--device picks where the evolution runs (the property Device): cpu (the
default), gpu (CUDA: a build with NARROWVOLUME_CUDA and a GPU; see
scripts/test-gpu.sh), or gpu-host (the GPU back end's kernels through its
host launcher, which runs anywhere: a check of this script and of the
kernels, not a timing of the GPU). Each device runs at each thread count
(the stages other than the evolution stay on the CPU's threads); the table
has a column for each, and the GPU's peak device memory.

The cloud is the performance benchmarks' sphere (table2.py's sphere-1024):
points on a sphere of radius 0.45 in the unit box, 500,000 of them at 1024³
and as many more as the surface's nodes grow (x4 per doubling), offset 4 h,
xi 2 h, 3 time steps, no volume output. Each run is a process of its own
(its peak memory is its own): it prints one JSON line (grid, points,
threads, the core's stages in seconds, the whole call, peak resident
memory); the parent prints the table of the medians, each stage's speed-up
from the fewest threads to the most, and its share of the run.
"""
import argparse
import glob
import importlib.machinery
import importlib.util
import json
import os
import resource
import statistics
import subprocess
import sys
import time

import numpy as np

import clouds  # the benchmarks' clouds (numpy only)


def load_core():
    """The pip package's module narrowvolume._core, loaded without the
    package (whose filter needs VTK)."""
    spec = importlib.util.find_spec("narrowvolume")
    if spec is None or not spec.submodule_search_locations:
        sys.exit("core_stages.py: the narrowvolume package is not installed here (pip install . first)")
    found = [path for folder in spec.submodule_search_locations for path in glob.glob(os.path.join(folder, "_core*"))]
    if not found:
        sys.exit("core_stages.py: narrowvolume has no _core module: this is the CMake build's package; "
                 "install the pip package (pip install .)")
    loader = importlib.machinery.ExtensionFileLoader("narrowvolume._core", found[0])
    module_spec = importlib.util.spec_from_loader("narrowvolume._core", loader)
    module = importlib.util.module_from_spec(module_spec)
    loader.exec_module(module)
    return module


def set_device(core, settings, device):
    """Settings.Device for "cpu", "gpu" or "gpu-host"."""
    settings.Device = core.ComputeDevice.CPU if device == "cpu" else core.ComputeDevice.GPU


def reconstruction(core, settings, device):
    """The run on `device` ("gpu-host": the GPU's kernels through the host launcher)."""
    set_device(core, settings, device)
    return core.Reconstruction(settings, host_launcher=device == "gpu-host")


def stage_seconds(outcome):
    """{stage: seconds} of a run's Outcome (its StageSeconds field data)."""
    for name, kind, components, values, names in outcome.Summary:
        if name == "StageSeconds":
            return dict(zip(names, values))
    return {}


def sphere(grid):
    """The sphere of radius 0.45 in the unit box (clouds.load's "sphere1024"
    at 1024³), with as many points at other sizes as keep their spacing."""
    n = int(round(500000 * (grid / 1024.0) ** 2))
    return np.ascontiguousarray(clouds.nvclouds.sphere_points(n, 0.45, (0.5, 0.5, 0.5)))


def child(args):
    core = load_core()
    xyz = sphere(args.grid)
    task = dict(cells=args.grid, offset_cells=4, xi=2)  # table2.py's sphere-1024
    h = clouds.spacing(xyz, task)
    settings = core.Settings()
    settings.OffsetDistance = task["offset_cells"] * h
    settings.SampleSpacing = h
    settings.XiCells = task["xi"]
    settings.MaximumNumberOfIterations = 3
    settings.OutputVolume = False
    settings.NumberOfThreads = args.threads
    settings.MemoryLimit = 0.0
    run = reconstruction(core, settings, args.device)
    sink = core.MeshSink()
    start = time.perf_counter()
    outcome = run.Reconstruct(xyz, None, sink)
    whole = time.perf_counter() - start
    if outcome.Error:
        sys.exit("core_stages.py: the run failed: %s" % outcome.Error)
    stages = stage_seconds(outcome)
    record = dict(grid=args.grid, points=len(xyz), threads=args.threads, device=args.device,
                  device_used=run.DeviceUsed(), band_nodes=run.NumberOfBandNodes(),
                  stages=stages, whole=whole,
                  peak_mb=resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0,
                  device_mb=run.DeviceBytes() / 2.0 ** 20)
    print(json.dumps(record), flush=True)


def parent(args):
    records = []
    columns = [(device, threads) for device in args.device for threads in args.threads]
    for repeat in range(args.repeat):
        for device, threads in columns:
            command = [sys.executable, os.path.abspath(__file__), "--child", "--grid", str(args.grid),
                       "--threads", str(threads), "--device", device]
            result = subprocess.run(command, capture_output=True, text=True)
            if result.returncode != 0:
                sys.exit("core_stages.py: a run failed:\n%s%s" % (result.stdout, result.stderr))
            line = result.stdout.strip().splitlines()[-1]
            print(line, flush=True)
            records.append(json.loads(line))
    if args.json:
        with open(args.json, "w") as out:
            out.writelines(json.dumps(r) + "\n" for r in records)

    def median(column, pick):
        return statistics.median(pick(r) for r in records if (r["device"], r["threads"]) == column)

    def label(column):
        device, threads = column
        return "%s, %d thread%s" % (device.upper() if device != "gpu-host" else "GPU on the host", threads,
                                    "" if threads == 1 else "s")

    names = []
    for r in records:
        names += [name for name in r["stages"] if name not in names]
    first, last = columns[0], columns[-1]
    whole_last = median(last, lambda r: r["whole"])
    print()
    print("%d³ grid, %d points, %d band nodes, medians of %d runs (seconds)" % (
        args.grid, records[0]["points"], records[0]["band_nodes"], args.repeat))
    print()
    header = "| stage | " + " | ".join(label(c) for c in columns)
    print(header + " | speed-up %s → %s | share at the last |" % (label(first), label(last)))
    print("|---" * (len(columns) + 3) + "|")
    rows = [(name, lambda r, name=name: r["stages"].get(name, 0.0)) for name in names]
    rows.append(("whole (the core's call)", lambda r: r["whole"]))
    for name, pick in rows:
        seconds = [median(c, pick) for c in columns]
        speedup = seconds[0] / seconds[-1] if seconds[-1] > 0 else float("nan")
        print("| %s | %s | %.1fx | %.1f %% |" % (name, " | ".join("%.3f" % s for s in seconds), speedup,
                                              100.0 * seconds[-1] / whole_last))
    print("| peak memory (MB) | %s | | |" % " | ".join("%.0f" % median(c, lambda r: r["peak_mb"]) for c in columns))
    if any(device != "cpu" for device, _ in columns):
        print("| peak GPU memory of the evolution (MB) | %s | | |" % " | ".join(
            "%.0f" % median(c, lambda r: r["device_mb"]) for c in columns))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--grid", type=int, default=256, help="cells along the box's side (default 256)")
    parser.add_argument("--threads", type=int, nargs="+", default=[1, os.cpu_count() or 1],
                        help="thread counts (default: 1 and every core)")
    parser.add_argument("--repeat", type=int, default=3, help="runs per thread count (default 3)")
    parser.add_argument("--device", nargs="+", default=["cpu"], choices=["cpu", "gpu", "gpu-host"],
                        help="where the evolution runs (default cpu; gpu-host: the GPU's kernels on the host)")
    parser.add_argument("--json", help="also write the runs' JSON lines to this file")
    parser.add_argument("--child", action="store_true", help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.child:
        args.threads = args.threads[0]
        args.device = args.device[0]
        child(args)
    else:
        parent(args)


if __name__ == "__main__":
    main()
