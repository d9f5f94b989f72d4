# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""The GPU back end against the CPU core, through the pip package's core
(narrowvolume._core, no VTK): the check scripts/test-gpu.sh runs on a
machine with a GPU.

    venv/bin/python benchmarks/gpu_check.py [--device gpu | gpu-host] [--scans-dir DIR]
    venv/bin/python benchmarks/gpu_check.py --grid 512 [--reference gpu-host]

For the Table 1 sphere (diameter 1, l = 0.1) at h = 0.01 and 0.005, and a
torus, it runs the whole reconstruction with Device CPU and Device GPU and
checks that: the GPU ran (DeviceUsed), the band has the CPU's number of
nodes (the truncated distance on the device is the CPU's bit for bit), both
surfaces have the same vertices
and triangles, every vertex within 0.05 h of the CPU's, both surfaces closed
(each edge in two triangles) with the Euler characteristic of two sheets
(4 for the sphere's two spheres, 0 for the torus's two tori) (a device
that fails is the run's error: Device GPU never falls back to the CPU); for the sphere, the inner
sheet's error against the radius 0.4 at or below the paper's Table 1 (max
1.307e-3 and 3.723e-4, average 9.938e-4 and 2.173e-4); and, for the torus,
with the Volume output, the dense phi (filled on the device) within 1e-6 of
the CPU's. Then three scans of ../shared/data/scans (armadillo, dragon,
teapot; --scans-dir elsewhere, skipped with a line when absent) with their
default offset and spacing, as a user runs them: the same checks, the
surfaces' Euler characteristic the CPU's. Each line gives the stages' seconds, device and CPU: the
distance and band nodes, the evolution, the surface (and the volume).
One line per case, then PASSED or FAILED; exit 1 on a failure.
gpu-host runs the GPU back end's kernels through the host launcher: the
same check on any machine (the host launcher gives the CPU's surface
exactly). In every case the runs also make as many time steps, and their
relative changes (the stopping rule's) are within 1e-9 of each other.

--grid N checks the benchmarks' sphere at N³ instead (core_stages.py's,
4 h offset, 3 steps), against --reference (default gpu-host: the same
kernels through the host launcher, whose results are the CPU core's bit
for bit; or cpu), with the Volume output and its optional arrays: the
same band (as many nodes; the dense distance and band flags bit for
bit), the same steps, the same number of vertices and triangles, every
vertex within 0.05 h, the dense phi within 1e-6 (scripts/test-gpu.sh at
512³). On the GPU a small run first makes the CUDA context, timed apart.
"""
import argparse
import math
import sys
import time

import numpy as np

import clouds  # the benchmarks' clouds (numpy only)
from core_stages import load_core, reconstruction as make_run, sphere as benchmark_sphere, stage_seconds, warm_up

# Table 1 (sphere, l = 0.1): h -> (max error, average error) on the inner sheet.
TABLE1 = {0.01: (1.307e-3, 9.938e-4), 0.005: (3.723e-4, 2.173e-4)}


def torus_points(n, big, small):
    around = int(math.sqrt(n * big / small))
    tube = max(3, n // around)
    u = 2 * np.pi * np.arange(around)[:, None] / around
    v = 2 * np.pi * (np.arange(tube)[None, :] + 0.5 * (np.arange(around)[:, None] % 2)) / tube
    x = (big + small * np.cos(v)) * np.cos(u)
    y = (big + small * np.cos(v)) * np.sin(u)
    z = small * np.sin(v) + 0 * u
    return np.ascontiguousarray(np.stack([x.ravel(), y.ravel(), z.ravel()], axis=1))


# The scans checked: closed and open, thick and thin parts.
SCANS = ("armadillo", "dragon", "teapot")


def run(core, xyz, offset, spacing, device, volume=False, steps=None):
    """A whole run on `device`; offset and spacing None: the defaults.
    volume "all": the Volume output with its optional arrays (the initial
    phi, the distance and the band flags)."""
    settings = core.Settings()
    if offset is not None:
        settings.OffsetDistance = offset
    if spacing is not None:
        settings.SampleSpacing = spacing
    if steps is not None:
        settings.MaximumNumberOfIterations = steps
    settings.OutputVolume = bool(volume)
    if volume == "all":
        settings.OutputInitialPhi = settings.OutputDistance = settings.OutputNarrowBand = True
    reconstruction = make_run(core, settings, device)
    sink = core.MeshSink()
    start = time.perf_counter()
    outcome = reconstruction.Reconstruct(xyz, None, sink)
    seconds = time.perf_counter() - start
    if outcome.Error:
        raise RuntimeError("%s: %s" % (device, outcome.Error))
    points, _, triangles = sink.Take()
    stages = stage_seconds(outcome)
    stages["dense"] = {name: np.asarray(a) for name, a in reconstruction.TakeVolume().items()} if volume else None
    return reconstruction, np.asarray(points), np.asarray(triangles), seconds, stages


def euler(points, triangles):
    """(closed, V - E + F) of a triangle mesh."""
    edges = np.sort(np.concatenate([triangles[:, [0, 1]], triangles[:, [1, 2]], triangles[:, [2, 0]]]), axis=1)
    unique, counts = np.unique(edges, axis=0, return_counts=True)
    return bool(len(counts) and np.all(counts == 2)), len(points) - len(unique) + len(triangles)


def check(core, name, xyz, offset, spacing, device, chi=None, radius=None, volume=False, reference="cpu",
          steps=None):
    """compare()'s checks, False on a failure; chi None: the reference's surface's."""
    try:
        return compare(core, name, xyz, offset, spacing, device, chi, radius, volume, reference, steps)
    except RuntimeError as error:
        print("%s: FAILED: %s" % (name, error), flush=True)
        return False


def compare(core, name, xyz, offset, spacing, device, chi, radius, volume, reference="cpu", steps=None):
    """The run on `device` against the run on `reference` ("cpu" or
    "gpu-host"); the cpu_ names are the reference's."""
    failures = []
    cpu_run, cpu_points, cpu_triangles, cpu_seconds, cpu_stages = run(
        core, xyz, offset, spacing, reference, volume, steps)
    gpu_run, gpu_points, gpu_triangles, gpu_seconds, gpu_stages = run(core, xyz, offset, spacing, device, volume, steps)
    who = {"cpu": "CPU", "gpu-host": "host launcher"}[reference]
    h = cpu_run.GetParameters().Spacing  # used (chosen by the run where not given)
    if chi is None:
        chi = euler(cpu_points, cpu_triangles)[1]
    expected = {"gpu": "GPU", "gpu-host": "GPU on the host"}[device]
    if gpu_run.DeviceUsed() != expected:
        failures.append("DeviceUsed %r, not %r" % (gpu_run.DeviceUsed(), expected))
    dense = ""
    cpu_dense, gpu_dense = cpu_stages.pop("dense"), gpu_stages.pop("dense")
    if volume:
        cpu_phi, gpu_phi = cpu_dense.get("phi", np.zeros(0)), gpu_dense.get("phi", np.zeros(0))
        if cpu_phi.shape != gpu_phi.shape or not cpu_phi.size:
            failures.append("dense phi of %s values, the %s's %s" % (gpu_phi.shape, who, cpu_phi.shape))
        else:
            largest = float(np.max(np.abs(gpu_phi.astype(np.float64) - cpu_phi)))
            dense = ", dense phi within %.3g of the %s's" % (largest, who)
            if not largest <= 1e-6:
                failures.append("the dense phi %.3g from the %s's" % (largest, who))
        # The band's arrays (volume "all"): the distance and the band flags
        # bit for bit, the initial phi within float's last bits.
        for array, tolerance in (("Distance", 0.0), ("NarrowBand", 0.0), ("InitialPhi", 1e-6)):
            if array not in cpu_dense:
                continue
            a, b = gpu_dense.get(array, np.zeros(0)), cpu_dense[array]
            if a.shape != b.shape:
                failures.append("the dense %s of %s values, the %s's %s" % (array, a.shape, who, b.shape))
                continue
            apart_most = float(np.max(np.abs(a.astype(np.float64) - b))) if b.size else 0.0
            dense += ", %s %s" % (array, "the same" if apart_most == 0 else "within %.3g" % apart_most)
            if not apart_most <= tolerance:
                failures.append("the dense %s %.3g from the %s's" % (array, apart_most, who))
    # The same steps, the stopping rule's relative changes within 1e-9.
    gpu_changes, cpu_changes = list(gpu_run.RelativeChanges()), list(cpu_run.RelativeChanges())
    if len(gpu_changes) != len(cpu_changes):
        failures.append("%d time steps, the %s's %d" % (len(gpu_changes), who, len(cpu_changes)))
    elif gpu_changes and max(abs(a - b) for a, b in zip(gpu_changes, cpu_changes)) > 1e-9:
        failures.append("relative changes %s, the %s's %s" % (gpu_changes, who, cpu_changes))
    # The truncated distance on the device is the CPU's bit for bit, and so
    # is the band: the same number of nodes.
    if gpu_run.NumberOfBandNodes() != cpu_run.NumberOfBandNodes():
        failures.append("%d band nodes, the %s's %d (the distances differ)" % (
            gpu_run.NumberOfBandNodes(), who, cpu_run.NumberOfBandNodes()))
    apart = float("nan")
    if len(gpu_points) != len(cpu_points) or len(gpu_triangles) != len(cpu_triangles):
        failures.append("%d vertices and %d triangles, the %s's %d and %d" % (
            len(gpu_points), len(gpu_triangles), who, len(cpu_points), len(cpu_triangles)))
    else:
        apart = float(np.max(np.linalg.norm(gpu_points - cpu_points, axis=1))) / h if len(cpu_points) else 0.0
        if not apart <= 0.05:
            failures.append("a vertex %.3g h from the %s's" % (apart, who))
    for whose, points, triangles in (("GPU", gpu_points, gpu_triangles), (who, cpu_points, cpu_triangles)):
        closed, characteristic = euler(points, triangles)
        if not closed or characteristic != chi:
            failures.append("the %s's surface: closed %s, V - E + F = %d (want %d)" % (
                whose, closed, characteristic, chi))
    errors = ""
    if radius is not None:
        r = np.linalg.norm(gpu_points, axis=1)
        inner = r < radius + offset / 2  # the inner sheet, near radius - l
        error = np.abs(r[inner] - (radius - offset))
        table = TABLE1.get(spacing)
        errors = ", inner sheet error max %.3e average %.3e" % (error.max(), error.mean())
        if table and (error.max() > table[0] or error.mean() > table[1]):
            errors += " (Table 1: %.3e, %.3e)" % table
            failures.append("the inner sheet's error exceeds Table 1's")
    collect = "band: collect"  # the distances (eq. 6) and the band's nodes, the collect pass
    nan = float("nan")
    print("%s: %d band nodes, %d vertices, %d steps, the farthest %.3g h from the %s's%s%s; whole run %.3f s (%s), "
          "%.3f s (%s); distance and band nodes %.3f s and %.3f s; evolution %.3f s and %.3f s; "
          "surface %.3f s and %.3f s%s; GPU memory %.0f MB: %s" % (
              name, gpu_run.NumberOfBandNodes(), len(gpu_points), len(gpu_changes), apart, who, errors, dense,
              gpu_seconds, expected, cpu_seconds, who, gpu_stages.get(collect, nan), cpu_stages.get(collect, nan),
              gpu_run.EvolutionSeconds(), cpu_run.EvolutionSeconds(),
              gpu_stages.get("surface", nan), cpu_stages.get("surface", nan),
              "; volume %.3f s and %.3f s" % (gpu_stages.get("volume", nan), cpu_stages.get("volume", nan))
              if volume else "",
              gpu_run.DeviceBytes() / 2 ** 20, "; ".join(failures) or "ok"), flush=True)
    return not failures


def check_scans(core, device, folder=None, names=SCANS):
    """check() on the scans `names` with their defaults; True, with a line,
    when they are not in `folder`."""
    if not clouds.nvclouds.have_scans(names, folder):
        print("the scans: skipped, not in %s" % (folder or clouds.SCANS_DIR), flush=True)
        return True
    ok = True
    for name in names:
        xyz = np.ascontiguousarray(clouds.nvclouds.scan_points(name, folder))
        ok &= check(core, "%s (defaults)" % name, xyz, None, None, device)
    return ok


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--device", default="gpu", choices=["gpu", "gpu-host"])
    parser.add_argument("--scans-dir", default=clouds.SCANS_DIR, help="the scans (default ../shared/data/scans)")
    parser.add_argument("--grid", type=int, help="only the benchmarks' sphere at this grid (e.g. 512)")
    parser.add_argument("--reference", choices=["gpu-host", "cpu"],
                        help="what --grid compares with (default gpu-host; the other cases: cpu)")
    args = parser.parse_args()
    core = load_core()
    if args.device == "gpu":
        print("the GPU's context and first run (a 64³ sphere, apart from the times below): %.3f s" % warm_up(core),
              flush=True)
    if args.grid:
        xyz = benchmark_sphere(args.grid)
        h = clouds.spacing(xyz, dict(cells=args.grid, offset_cells=4, xi=2))
        ok = check(core, "the benchmarks' sphere at %d³" % args.grid, xyz, 4 * h, h, args.device, chi=4,
                   volume="all", reference=args.reference or "gpu-host", steps=3)
        print("gpu_check.py: %s" % ("PASSED" if ok else "FAILED"), flush=True)
        sys.exit(0 if ok else 1)
    center = (0.0, 0.0, 0.0)
    ok = True
    for h in (0.01, 0.005):
        n = int(30000 * (0.01 / h) ** 2)
        sphere = np.ascontiguousarray(clouds.nvclouds.sphere_points(n, 0.5, center))
        ok &= check(core, "sphere (Table 1), h = %g" % h, sphere, 0.1, h, args.device, chi=4, radius=0.5)
    ok &= check(core, "torus", torus_points(40000, 0.6, 0.25), 0.08, 0.01, args.device, chi=0)
    ok &= check(core, "torus, the Volume output", torus_points(40000, 0.6, 0.25), 0.08, 0.01, args.device,
                chi=0, volume=True)
    ok &= check_scans(core, args.device, args.scans_dir)
    print("gpu_check.py: %s" % ("PASSED" if ok else "FAILED"), flush=True)
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
