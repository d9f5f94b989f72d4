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

On the GPU (--device gpu) each process first makes a small run on the GPU
(the CUDA context, the kernels' loading and the launcher's first
allocations) and reports its seconds apart, in the row "GPU context and
first run", not in the stages; during the timed run a thread samples the
device's memory in use (CuPy's cudaMemGetInfo, else nvidia-smi), shown
beside the launcher's own count; the run's copies between the host and the
GPU (Reconstruction.DeviceCopies: bytes each way, and the bandwidth over
the copies' own time) get rows of their own. --timeout caps the runs together: a run
not done in time is left out of the table with a line saying so (the GPU's
runs go before the CPU's, so that they are the ones kept). --table prints
one table of several grids from the --json files of earlier runs
(scripts/test-gpu.sh: 1024³ and 4096³ side by side).
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
import threading
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


class DeviceMemory:
    """The GPU's memory in use, sampled on a thread while a run computes:
    through CuPy (cudaMemGetInfo, the whole device), else nvidia-smi's
    memory.used every 20 ms; `how` None where neither is at hand. The
    launcher's own count (DeviceBytes) is what it allocated; this is what
    the device had in use, the context and the driver's reserves included."""

    def __init__(self):
        self.how, self.peak, self.before, self._stop, self._thread, self._smi = None, 0.0, 0.0, None, None, None
        for how in ("cudaMemGetInfo (CuPy)", "nvidia-smi"):
            self.how = how
            try:
                self.used_mb()  # CuPy missing, no device, or no number: the next way
                return
            except Exception:
                self.how = None

    def used_mb(self):
        if self.how and self.how.startswith("cudaMemGetInfo"):
            import cupy  # optional: the first way, where it is installed
            free, total = cupy.cuda.runtime.memGetInfo()
            return (total - free) / 2.0 ** 20
        result = subprocess.run(["nvidia-smi", "--query-gpu=memory.used", "--format=csv,noheader,nounits",
                                 "-i", gpu_index()], capture_output=True, text=True, timeout=10)
        return float(result.stdout.split()[0])

    def start(self):
        if not self.how:
            return
        self.before = self.peak = self.used_mb()
        self._stop = threading.Event()
        if self.how == "nvidia-smi":
            self._smi = subprocess.Popen(["nvidia-smi", "--query-gpu=memory.used", "--format=csv,noheader,nounits",
                                          "-i", gpu_index(), "-lms", "20"], stdout=subprocess.PIPE, text=True)
            self._thread = threading.Thread(target=self._read_smi, daemon=True)
        else:
            self._thread = threading.Thread(target=self._poll, daemon=True)
        self._thread.start()

    def _poll(self):
        while not self._stop.is_set():
            self.peak = max(self.peak, self.used_mb())
            self._stop.wait(0.005)

    def _read_smi(self):
        for line in self._smi.stdout:
            try:
                self.peak = max(self.peak, float(line.split()[0]))
            except (ValueError, IndexError):
                pass

    def stop(self):
        if not self.how:
            return
        self._stop.set()
        if self._smi:
            time.sleep(0.05)  # a last sample
            self._smi.terminate()
        self._thread.join(timeout=5)
        self.peak = max(self.peak, self.used_mb())


def gpu_index():
    """nvidia-smi's index of the GPU the run uses (CUDA_VISIBLE_DEVICES' first, else 0)."""
    first = os.environ.get("CUDA_VISIBLE_DEVICES", "0").split(",")[0].strip()
    return first if first else "0"


def warm_up(core):
    """A small run on the GPU (the 64³ sphere): the CUDA context, the
    kernels' loading and the launcher's first allocations, made once per
    process before anything is timed; its seconds."""
    settings = core.Settings()
    xyz = sphere(64)
    h = clouds.spacing(xyz, dict(cells=64, offset_cells=4, xi=2))
    settings.OffsetDistance, settings.SampleSpacing, settings.OutputVolume = 4 * h, h, False
    settings.MaximumNumberOfIterations = 1
    start = time.perf_counter()
    outcome = reconstruction(core, settings, "gpu").Reconstruct(xyz, None, core.MeshSink())
    seconds = time.perf_counter() - start
    if outcome.Error:
        sys.exit("core_stages.py: the GPU's first run failed: %s" % outcome.Error)
    return seconds


def child(args):
    core = load_core()
    context = warm_up(core) if args.device == "gpu" else None
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
    memory = DeviceMemory() if args.device == "gpu" else None
    if memory:
        memory.start()
    start = time.perf_counter()
    outcome = run.Reconstruct(xyz, None, sink)
    whole = time.perf_counter() - start
    if memory:
        memory.stop()
    if outcome.Error:
        sys.exit("core_stages.py: the run failed: %s" % outcome.Error)
    stages = stage_seconds(outcome)
    record = dict(grid=args.grid, points=len(xyz), threads=args.threads, device=args.device,
                  device_used=run.DeviceUsed(), band_nodes=run.NumberOfBandNodes(),
                  stages=stages, whole=whole,
                  peak_mb=resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0,
                  device_mb=run.DeviceBytes() / 2.0 ** 20,
                  copies=list(run.DeviceCopies()))
    if context is not None:
        record["context_s"] = context
    if memory and memory.how:
        record.update(device_used_mb=memory.peak, device_before_mb=memory.before, device_memory_by=memory.how)
    print(json.dumps(record), flush=True)


def parent(args):
    records = []
    columns = [(device, threads) for device in args.device for threads in args.threads]
    # The GPU's runs first: under --timeout, the CPU's are the ones cut.
    order = sorted(columns, key=lambda column: column[0] == "cpu")
    deadline = time.monotonic() + args.timeout if args.timeout else None
    missing = []
    saved = open(args.json, "w") if args.json else None
    for repeat in range(args.repeat):
        for device, threads in order:
            command = [sys.executable, os.path.abspath(__file__), "--child", "--grid", str(args.grid),
                       "--threads", str(threads), "--device", device]
            left = deadline - time.monotonic() if deadline else None
            if left is not None and left < 1:
                missing.append((device, threads))
                continue
            try:
                result = subprocess.run(command, capture_output=True, text=True, timeout=left)
            except subprocess.TimeoutExpired:
                print("core_stages.py: the run on %s with %d threads at %d³ was stopped at the %g s timeout" % (
                    device, threads, args.grid, args.timeout), flush=True)
                missing.append((device, threads))
                continue
            if result.returncode != 0:
                sys.exit("core_stages.py: a run failed:\n%s%s" % (result.stdout, result.stderr))
            line = result.stdout.strip().splitlines()[-1]
            print(line, flush=True)
            records.append(json.loads(line))
            if saved:
                saved.write(line + "\n")
                saved.flush()
    if saved:
        saved.close()
    if not records:
        sys.exit("core_stages.py: no run finished within the %g s timeout" % args.timeout)
    print()
    print_table(records)
    if missing:
        print()
        print("Runs not made or stopped (the %g s timeout): %s" % (args.timeout, ", ".join(
            "%s with %d threads" % column for column in sorted(set(missing)))))
        sys.exit(1)


def print_table(records):
    """The table of the medians of `records`, a column for each grid,
    device and thread count (by grid, the CPU before the GPU, by threads),
    with each grid's speed-up from its first column to its last and, for
    one grid, each stage's share of the last column's run."""
    columns = []
    for r in records:
        column = (r["grid"], r["device"], r["threads"])
        if column not in columns:
            columns.append(column)
    columns.sort(key=lambda c: (c[0], ["cpu", "gpu-host", "gpu"].index(c[1]), c[2]))
    grids = sorted(set(c[0] for c in columns))

    def of(column):
        return [r for r in records if (r["grid"], r["device"], r["threads"]) == column]

    def median(column, pick):
        values = [pick(r) for r in of(column) if pick(r) is not None]
        return statistics.median(values) if values else float("nan")

    def label(column):
        grid, device, threads = column
        return "%s%s, %d thread%s" % ("%d³ " % grid if len(grids) > 1 else "",
                                     device.upper() if device != "gpu-host" else "GPU on the host", threads,
                                     "" if threads == 1 else "s")

    names = []
    for r in records:
        names += [name for name in r["stages"] if name not in names]
    # Per grid: the speed-up from its first column to its last; one grid:
    # also each stage's share of the last column's run.
    ends = [([c for c in columns if c[0] == g][0], [c for c in columns if c[0] == g][-1]) for g in grids]
    ends = [(a, b) for a, b in ends if a != b]
    last = columns[-1]
    whole_last = median(last, lambda r: r["whole"])
    runs = sorted(set(len(of(c)) for c in columns))
    for grid in grids:
        r = next(r for r in records if r["grid"] == grid)
        print("%d³ grid, %d points, %d band nodes" % (grid, r["points"], r["band_nodes"]))
    print("medians of %s run%s (seconds)" % (" or ".join(map(str, runs)), "" if runs == [1] else "s"))
    print()
    extra = ["speed-up %s → %s" % ((label(a), label(b)) if len(grids) == 1 else (label(a), label(b)[len("%d³ " % a[0]):]))
             for a, b in ends]
    if len(grids) == 1:
        extra.append("share at the last")
    print("| stage | %s | %s |" % (" | ".join(label(c) for c in columns), " | ".join(extra)))
    print("|---" * (len(columns) + len(extra) + 1) + "|")

    def cell(value, form):
        return "" if value != value else form % value  # NaN: an empty cell

    def row(name, pick, form="%.3f", ratio=True):
        values = {c: median(c, pick) for c in columns}
        cells = [cell(values[c], form) for c in columns]
        for a, b in ends:
            cells.append(cell(values[a] / values[b] if ratio and values[b] > 0 else float("nan"), "%.1fx"))
        if len(grids) == 1:
            cells.append(cell(100.0 * values[last] / whole_last if ratio and whole_last > 0 else float("nan"),
                              "%.1f %%"))
        print("| %s | %s |" % (name, " | ".join(cells)))

    for name in names:
        row(name, lambda r, name=name: r["stages"].get(name, 0.0))
    row("whole (the core's call)", lambda r: r["whole"])
    row("peak memory (MB)", lambda r: r["peak_mb"], "%.0f", False)
    if any(c[1] != "cpu" for c in columns):
        row("GPU memory, the launcher's count (MB)",
            lambda r: r["device_mb"] if r["device"] != "cpu" else None, "%.0f", False)
    if any(r.get("copies") and (r["copies"][0] > 0 or r["copies"][2] > 0) for r in records):
        def copied(r, way):
            c = r.get("copies") or [0.0] * 4
            return c[2 * way] / 1e9 if r["device"] != "cpu" else None

        def bandwidth(r, way):
            c = r.get("copies") or [0.0] * 4
            return c[2 * way] / c[2 * way + 1] / 1e9 if r["device"] != "cpu" and c[2 * way + 1] > 0 else None

        row("copied to the host (GB)", lambda r: copied(r, 0), "%.2f", False)
        row("at (GB/s, the copies' own time)", lambda r: bandwidth(r, 0), "%.1f", False)
        row("copied to the GPU (GB)", lambda r: copied(r, 1), "%.2f", False)
        row("at (GB/s)", lambda r: bandwidth(r, 1), "%.1f", False)
    if any("device_used_mb" in r for r in records):
        row("GPU memory in use at the peak, the whole device (MB)", lambda r: r.get("device_used_mb"), "%.0f", False)
        row("of which before the run: the context and the launcher's reserves (MB)",
            lambda r: r.get("device_before_mb"), "%.0f", False)
    if any("context_s" in r for r in records):
        row("GPU context and first run, apart (seconds, not in the stages)", lambda r: r.get("context_s"),
            "%.3f", False)


def table(files):
    """print_table of the JSON lines in `files` (--json of earlier runs)."""
    records = []
    for name in files:
        if os.path.exists(name):
            with open(name) as lines:
                records += [json.loads(line) for line in lines if line.strip()]
    if not records:
        sys.exit("core_stages.py: no runs in %s" % " ".join(files))
    print_table(records)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--grid", type=int, default=256, help="cells along the box's side (default 256)")
    parser.add_argument("--threads", type=int, nargs="+", default=[1, os.cpu_count() or 1],
                        help="thread counts (default: 1 and every core)")
    parser.add_argument("--repeat", type=int, default=3, help="runs per thread count (default 3)")
    parser.add_argument("--device", nargs="+", default=["cpu"], choices=["cpu", "gpu", "gpu-host"],
                        help="where the evolution runs (default cpu; gpu-host: the GPU's kernels on the host)")
    parser.add_argument("--json", help="also write the runs' JSON lines to this file")
    parser.add_argument("--timeout", type=float, default=0.0,
                        help="seconds for all the runs together (default: no limit); the runs not done are left out")
    parser.add_argument("--table", nargs="+", metavar="JSON",
                        help="run nothing: one table of the runs in these --json files")
    parser.add_argument("--child", action="store_true", help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.table:
        table(args.table)
    elif args.child:
        args.threads = args.threads[0]
        args.device = args.device[0]
        child(args)
    else:
        parent(args)


if __name__ == "__main__":
    main()
