# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""The scan surface (Sheets SCAN_SURFACE, 3) beside Open3D's screened
Poisson on the same points: how close each lies to the true surface, whether
it is watertight, and how long it takes (issue 52). Prints a markdown table,
a row per input, and a summary against the issue's targets (on noisy closed
scans, sigma 1 % of the diagonal, our mean Chamfer distance at most 1.5
times Poisson's; on clean scans F-score at 1 % of the diagonal at least
0.97; ours watertight).

    python3 -m venv build/bench-venv
    build/bench-venv/bin/pip install -r benchmarks/scan_surface-requirements.txt
    build/bench-venv/bin/python benchmarks/scan_surface.py [--build build] [--quick]
        [--points 40000] [--scans ../shared/data/scans]

Open3D's Linux wheel needs libusb-1.0 (Debian: the package libusb-1.0-0);
where it is not installed, put its libusb-1.0.so.0 in a folder named by
LD_LIBRARY_PATH.

The inputs:

- Synthetic shapes with known surfaces, sampled area-uniformly (fixed
  seeds), --points points each: a sphere; a torus in millimetres (100 mm
  across); a cube (sharp edges and corners); a sphere with a thin limb (a
  capped cylinder of radius 2.4 % of the diagonal); a sphere sampled
  unevenly (the density rises 10 times from one pole to the other). Each
  clean and with Gaussian noise of sigma 0.5 % and 1 % of the bounding box's
  diagonal (on every coordinate). The truth: 200,000 area-uniform samples of
  the surface and the exact distance to it (the limb's: the union's signed
  distance, exact outside the solid and, inside it, only near the crease
  where limb and sphere meet a lower bound).
- The closed scans of ../shared/data/scans (armadillo, dragon, teapot,
  bunny), read there (never copied), clean and with noise of sigma 1 %; the
  truth is the clean points (their distances are to the nearest clean
  point). Skipped with a message when the folder is absent.

The measures, the same for every method, on the mesh's vertices (those of
its triangles): Chamfer, the mean of the two mean distances (vertices to the
true surface, true samples to the nearest vertex; scipy's cKDTree), as % of
the diagonal; the F-score at 1 % of the diagonal (precision: vertices within
it of the truth; recall: true samples within it of a vertex); watertight
when every edge is shared by exactly two triangles; pieces (connected sets
of triangles); seconds, the wall time of the reconstruction call.

Ours: narrowvolume.reconstruct(points, Sheets=3, OutputVolume=False), its
defaults otherwise, in a child process under pvpython with
PYTHONPATH=<build>/lib/python3.X/dist-packages (ParaView's VTK); the points
and the surface go through .npy/.npz files in a temporary folder. Open3D as a
new user would: estimate_normals (hybrid search, radius 3 times the mean
nearest-neighbour distance, max_nn 30), orient_normals_consistent_tangent_plane
(k 15), create_from_point_cloud_poisson (depth 9) - its seconds count all
three - untrimmed and trimmed where the density is below its 5 % quantile
(as the common tutorial does). A mesh that is not watertight shows its open
edges (one triangle) and its edges shared by more than two triangles.

The whole run takes about 15 minutes on 2 cores, most of it Open3D's normal
orientation on the clean cube and limb (1.5 and 7 minutes with Open3D 0.20);
--quick about a minute.
"""
import argparse
import glob
import json
import math
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
import zlib

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))

parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
parser.add_argument("--build", default=os.path.join(HERE, "..", "build"),
                    help="the build folder whose lib/python3.X/dist-packages holds narrowvolume")
parser.add_argument("--pvpython", default=shutil.which("pvpython"), help="the Python that runs our reconstructions")
parser.add_argument("--scans", default=None, help="the folder of the scans (default ../shared/data/scans)")
parser.add_argument("--points", type=int, default=None, help="points per synthetic shape (40000; --quick 10000)")
parser.add_argument("--quick", action="store_true", help="fewer inputs, fewer points")
parser.add_argument("--child", nargs=2, metavar=("POINTS_NPY", "OUT_NPZ"), help=argparse.SUPPRESS)
args = parser.parse_args()

TRUE_SAMPLES = 200000
F_THRESHOLD = 0.01  # of the diagonal
SIGMAS = (0.0, 0.005, 0.01)
NOISY = 0.01
SCANS = ("armadillo", "dragon", "teapot", "bunny")
SHAPES = ("sphere", "torus_mm", "cube", "limb", "sphere_uneven")
QUICK_SHAPES, QUICK_SIGMAS, QUICK_SCANS = ("sphere", "limb"), (0.0, 0.01), ("bunny",)


# --- Our run: the child, under pvpython.

def child(points_file, out_file):
    """One reconstruct() of the points in points_file; its surface and summary into out_file."""
    import warnings
    import narrowvolume
    from vtkmodules.util.numpy_support import vtk_to_numpy
    xyz = np.load(points_file)
    info = dict(warnings=[], error=None)
    vertices, triangles = np.zeros((0, 3)), np.zeros((0, 3), dtype=np.int64)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        start = time.perf_counter()
        try:
            volume, surface = narrowvolume.reconstruct(xyz, Sheets=3, OutputVolume=False)
        except narrowvolume.ReconstructionError as error:
            info["error"] = str(error)
        info["seconds"] = time.perf_counter() - start
    info["warnings"] = [str(w.message).splitlines()[0] for w in caught]
    if info["error"] is None:
        fields = volume.GetFieldData()
        for name in ("ScanSurface", "ScanSurfacePieces", "ScanSurfaceOpenPieces", "ScanSurfaceVolume",
                     "ScanDistanceMean", "ScanDistance95", "SampleSpacing", "OffsetDistance"):
            array = fields.GetArray(name)
            info[name] = array.GetTuple1(0) if array is not None and array.GetNumberOfTuples() else None
        if surface.GetNumberOfPoints():
            vertices = vtk_to_numpy(surface.GetPoints().GetData()).astype(float)
        polys = surface.GetPolys()
        sizes = np.diff(vtk_to_numpy(polys.GetOffsetsArray()))
        if len(sizes) and not (sizes == 3).all():
            raise RuntimeError("the surface has cells other than triangles")
        triangles = vtk_to_numpy(polys.GetConnectivityArray()).reshape(-1, 3).astype(np.int64)
        info["other cells"] = surface.GetNumberOfStrips() + surface.GetNumberOfLines()
    np.savez(out_file, vertices=vertices, triangles=triangles, info=json.dumps(info))


def python_path(build):
    found = sorted(glob.glob(os.path.join(build, "lib", "python3*", "dist-packages")))
    if not found:
        sys.exit("no lib/python3.X/dist-packages in %s: give the build folder with --build" % build)
    return found[-1]


def ours(points, folder):
    """(vertices, triangles, seconds, info) of our scan surface, from a child process."""
    points_file, out_file = os.path.join(folder, "points.npy"), os.path.join(folder, "ours.npz")
    np.save(points_file, points)
    env = dict(os.environ, PYTHONPATH=python_path(args.build))
    run = subprocess.run([args.pvpython, os.path.abspath(__file__), "--child", points_file, out_file],
                         env=env, capture_output=True, text=True)
    if run.returncode != 0:
        raise RuntimeError("our run failed:\n" + run.stderr[-3000:])
    with np.load(out_file) as out:
        info = json.loads(str(out["info"]))
        return out["vertices"], out["triangles"], info["seconds"], info


# --- Open3D's screened Poisson, in this process.

def poisson(points):
    """(untrimmed (vertices, triangles), trimmed (vertices, triangles), seconds) of Open3D's Poisson."""
    import open3d as o3d
    o3d.utility.set_verbosity_level(o3d.utility.VerbosityLevel.Error)
    start = time.perf_counter()
    cloud = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(points))
    spacing = float(np.mean(cloud.compute_nearest_neighbor_distance()))
    cloud.estimate_normals(o3d.geometry.KDTreeSearchParamHybrid(radius=3.0 * spacing, max_nn=30))
    cloud.orient_normals_consistent_tangent_plane(15)
    mesh, densities = o3d.geometry.TriangleMesh.create_from_point_cloud_poisson(cloud, depth=9)
    seconds = time.perf_counter() - start
    untrimmed = (np.asarray(mesh.vertices).copy(), np.asarray(mesh.triangles).astype(np.int64))
    densities = np.asarray(densities)
    mesh.remove_vertices_by_mask(densities < np.quantile(densities, 0.05))
    trimmed = (np.asarray(mesh.vertices).copy(), np.asarray(mesh.triangles).astype(np.int64))
    return untrimmed, trimmed, seconds


# --- The synthetic shapes: area-uniform samples and the exact distance.

def unit_vectors(rng, n):
    v = rng.normal(size=(n, 3))
    return v / np.linalg.norm(v, axis=1)[:, None]


def sphere_samples(rng, n, radius=0.5):
    return radius * unit_vectors(rng, n)


def sphere_sdf(x, radius=0.5):
    return np.linalg.norm(x, axis=1) - radius


def uneven_sphere_samples(rng, n, radius=0.5):
    """Points on the sphere whose density is 10 ** ((z / r + 1) / 2): 1 at the bottom, 10 at the top."""
    chunks, count = [], 0
    while count < n:
        candidates = sphere_samples(rng, 4 * n, radius)
        keep = rng.random(len(candidates)) < 10.0 ** ((candidates[:, 2] / radius + 1.0) / 2.0) / 10.0
        chunks.append(candidates[keep])
        count += int(keep.sum())
    return np.vstack(chunks)[:n]


TORUS_R, TORUS_r = 35.0, 15.0  # millimetres: 100 mm across


def torus_samples(rng, n):
    """Area-uniform on the torus (z its axis): the tube's angle v drawn with weight R + r cos v."""
    chunks, count = [], 0
    while count < n:
        u, v = rng.uniform(0, 2 * math.pi, (2, 2 * n))
        keep = rng.random(2 * n) < (TORUS_R + TORUS_r * np.cos(v)) / (TORUS_R + TORUS_r)
        u, v = u[keep], v[keep]
        ring = TORUS_R + TORUS_r * np.cos(v)
        chunks.append(np.c_[ring * np.cos(u), ring * np.sin(u), TORUS_r * np.sin(v)])
        count += len(u)
    return np.vstack(chunks)[:n]


def torus_sdf(x):
    q = np.linalg.norm(x[:, :2], axis=1) - TORUS_R
    return np.hypot(q, x[:, 2]) - TORUS_r


def cube_samples(rng, n, side=1.0):
    """Area-uniform on the cube [-side/2, side/2]^3: a face at random, a point at random on it."""
    x = rng.uniform(-side / 2, side / 2, (n, 3))
    face = rng.integers(0, 6, n)
    x[np.arange(n), face % 3] = np.where(face < 3, -side / 2, side / 2)
    return x


def box_sdf(x, half):
    q = np.abs(x) - half
    return np.linalg.norm(np.maximum(q, 0.0), axis=1) + np.minimum(q.max(axis=1), 0.0)


LIMB_RADIUS, LIMB_END = 0.05, 1.0  # a cylinder along x from the sphere's centre to x = 1


def limb_sdf(x):
    """The union's signed distance: the sphere of radius 0.5 and the capped cylinder along x from 0 to 1."""
    radial = np.linalg.norm(x[:, 1:], axis=1) - LIMB_RADIUS
    axial = np.abs(x[:, 0] - LIMB_END / 2) - LIMB_END / 2
    q = np.c_[radial, axial]
    cylinder = np.linalg.norm(np.maximum(q, 0.0), axis=1) + np.minimum(q.max(axis=1), 0.0)
    return np.minimum(sphere_sdf(x), cylinder)


def limb_samples(rng, n):
    """Area-uniform on the union's boundary: each part sampled by its area, the points inside the other dropped."""
    areas = np.array([4 * math.pi * 0.25, 2 * math.pi * LIMB_RADIUS * LIMB_END, math.pi * LIMB_RADIUS ** 2])
    chunks, count = [], 0
    while count < n:
        m = rng.multinomial(2 * n, areas / areas.sum())
        sphere = sphere_samples(rng, m[0])
        angle = rng.uniform(0, 2 * math.pi, m[1])
        side = np.c_[rng.uniform(0, LIMB_END, m[1]), LIMB_RADIUS * np.cos(angle), LIMB_RADIUS * np.sin(angle)]
        rho, angle = LIMB_RADIUS * np.sqrt(rng.random(m[2])), rng.uniform(0, 2 * math.pi, m[2])
        cap = np.c_[np.full(m[2], LIMB_END), rho * np.cos(angle), rho * np.sin(angle)]
        radial = np.linalg.norm(sphere[:, 1:], axis=1)
        sphere = sphere[~((radial < LIMB_RADIUS) & (sphere[:, 0] > 0))]
        side = side[sphere_sdf(side) > 0]
        chunk = np.vstack([sphere, side, cap])
        chunks.append(chunk[rng.permutation(len(chunk))])
        count += len(chunk)
    return np.vstack(chunks)[:n]


SYNTHETIC = {
    "sphere": (sphere_samples, sphere_sdf),
    "torus_mm": (torus_samples, torus_sdf),
    "cube": (cube_samples, lambda x: box_sdf(x, 0.5)),
    "limb": (limb_samples, limb_sdf),
    "sphere_uneven": (uneven_sphere_samples, sphere_sdf),  # the truth's samples stay area-uniform
}
LABELS = {"sphere": "sphere", "torus_mm": "torus (mm)", "cube": "cube", "limb": "sphere + thin limb",
          "sphere_uneven": "sphere, density 1-10x"}


def seed(name):
    return zlib.crc32(name.encode())


def synthetic_truth(name, n):
    """(clean points, truth) of a synthetic shape: truth has the dense samples, the distance and the diagonal."""
    samples, sdf = SYNTHETIC[name]
    points = samples(np.random.default_rng(seed(name)), n)
    dense = (sphere_samples if name == "sphere_uneven" else samples)(np.random.default_rng(seed(name) + 1),
                                                                      TRUE_SAMPLES)
    diagonal = float(np.linalg.norm(dense.max(axis=0) - dense.min(axis=0)))
    return points, dict(samples=dense, distance=lambda x: np.abs(sdf(x)), diagonal=diagonal)


def scan_truth(name, folder):
    """(clean points, truth) of a scan: the clean points are the truth."""
    from scipy.spatial import cKDTree
    sys.path.insert(0, HERE)
    from clouds import nvclouds
    points = nvclouds.ply_points(nvclouds.scan_path(name, folder))
    tree = cKDTree(points)
    diagonal = float(np.linalg.norm(points.max(axis=0) - points.min(axis=0)))
    return points, dict(samples=points, distance=lambda x: tree.query(x, workers=-1)[0], diagonal=diagonal)


def noisy(points, sigma, diagonal, name):
    if sigma == 0:
        return points
    rng = np.random.default_rng(seed(name) + int(round(sigma * 1e4)) + 7)
    return points + rng.normal(scale=sigma * diagonal, size=points.shape)


# --- The measures.

def edges(triangles):
    e = np.sort(np.vstack([triangles[:, [0, 1]], triangles[:, [1, 2]], triangles[:, [2, 0]]]), axis=1)
    return np.unique(e, axis=0, return_counts=True)


def measure(vertices, triangles, truth):
    """Chamfer (% of the diagonal), F-score at 1 % of it, watertight, pieces of a triangle mesh."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components
    from scipy.spatial import cKDTree
    if len(triangles) == 0:
        return dict(chamfer=math.nan, f=0.0, watertight=False, pieces=0, open_edges=0, shared_edges=0)
    used, local = np.unique(triangles, return_inverse=True)
    local = local.reshape(-1, 3)
    points = vertices[used]
    to_truth = truth["distance"](points)
    from_truth = cKDTree(points).query(truth["samples"], workers=-1)[0]
    diagonal = truth["diagonal"]
    chamfer = 100.0 * 0.5 * (to_truth.mean() + from_truth.mean()) / diagonal
    tau = F_THRESHOLD * diagonal
    precision, recall = float((to_truth < tau).mean()), float((from_truth < tau).mean())
    f = 2 * precision * recall / (precision + recall) if precision + recall > 0 else 0.0
    pairs, counts = edges(local)
    graph = coo_matrix((np.ones(len(pairs)), (pairs[:, 0], pairs[:, 1])), shape=(len(used), len(used)))
    pieces = connected_components(graph, directed=False)[0]
    return dict(chamfer=chamfer, f=f, watertight=bool((counts == 2).all()), pieces=int(pieces),
                open_edges=int((counts == 1).sum()), shared_edges=int((counts > 2).sum()))


# --- The table.

def number(value, digits):
    return "-" if value is None or (isinstance(value, float) and math.isnan(value)) else "%.*f" % (digits, value)


def tight(m):
    """"yes, pieces", or "no (open edges / edges of more than two triangles), pieces"."""
    if m["watertight"]:
        return "yes, %d" % m["pieces"]
    return "no (%d/%d), %d" % (m["open_edges"], m["shared_edges"], m["pieces"])


def run_case(label, sigma, points, truth, folder, kind):
    import open3d  # noqa: F401  (loaded before the first timing)
    noisy_points = noisy(points, sigma, truth["diagonal"], label)
    vertices, triangles, seconds, info = ours(noisy_points, folder)
    mine = measure(vertices, triangles, truth)
    mine["seconds"] = seconds
    (pv, pt), (tv, tt), poisson_seconds = poisson(noisy_points)
    theirs = measure(pv, pt, truth)
    theirs["seconds"] = poisson_seconds
    trimmed = measure(tv, tt, truth)
    ratio = mine["chamfer"] / theirs["chamfer"] if theirs["chamfer"] > 0 else math.nan
    row = dict(label=label, sigma=sigma, kind=kind, points=len(points), ours=mine, poisson=theirs, trimmed=trimmed,
               ratio=ratio, info=info)
    print("| %s | %s | %d | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
        label, number(100 * sigma, 1), len(points), number(mine["chamfer"], 3), number(mine["f"], 3), tight(mine),
        number(seconds, 1), number(theirs["chamfer"], 3), number(theirs["f"], 3), tight(theirs),
        number(poisson_seconds, 1), number(trimmed["chamfer"], 3), number(trimmed["f"], 3), tight(trimmed),
        number(ratio, 2)), flush=True)
    return row


def cases():
    """(label, sigma, kind, a function giving (points, truth)) of every input, and the notes on skipped ones."""
    shapes, sigmas, scans = (QUICK_SHAPES, QUICK_SIGMAS, QUICK_SCANS) if args.quick else (SHAPES, SIGMAS, SCANS)
    n = args.points or (10000 if args.quick else 40000)
    out, notes = [], []
    for name in shapes:
        for sigma in sigmas:
            out.append((LABELS[name], sigma, "synthetic", lambda name=name: synthetic_truth(name, n)))
    sys.path.insert(0, HERE)
    from clouds import nvclouds
    folder = args.scans or nvclouds.SCANS_DIR
    for name in scans:
        if not os.path.isfile(os.path.join(folder, name + ".ply")):
            notes.append("%s skipped: no %s.ply in %s (../shared/data/scans is not beside the source tree)"
                         % (name, name, folder))
            continue
        for sigma in (0.0, NOISY):
            out.append((name, sigma, "scan", lambda name=name: scan_truth(name, folder)))
    return out, notes


def summary(rows):
    noisy_rows = [r for r in rows if r["sigma"] == NOISY and not math.isnan(r["ratio"])]
    clean_rows = [r for r in rows if r["sigma"] == 0]
    lines = []
    for what, subset in (("all", noisy_rows), ("synthetic", [r for r in noisy_rows if r["kind"] == "synthetic"]),
                         ("scans", [r for r in noisy_rows if r["kind"] == "scan"])):
        if subset:
            worst = max(subset, key=lambda r: r["ratio"])
            lines.append("Noisy inputs (sigma 1 %%), %s: median ours/Poisson Chamfer %.2f (target at most 1.5), "
                         "%d of %d at most 1.5, worst %.2f (%s)." % (
                             what, statistics.median(r["ratio"] for r in subset),
                             sum(r["ratio"] <= 1.5 for r in subset), len(subset), worst["ratio"], worst["label"]))
    if clean_rows:
        worst = min(clean_rows, key=lambda r: r["ours"]["f"])
        lines.append("Clean inputs: min ours F@1%% %.3f (%s) (target at least 0.97); %d of %d at least 0.97; "
                     "Poisson's min %.3f." % (worst["ours"]["f"], worst["label"],
                                              sum(r["ours"]["f"] >= 0.97 for r in clean_rows), len(clean_rows),
                                              min(r["poisson"]["f"] for r in clean_rows)))
    for key, name in (("ours", "ours"), ("poisson", "Poisson"), ("trimmed", "trimmed Poisson")):
        lines.append("Watertight, %s: %d of %d inputs; one piece: %d of %d." % (
            name, sum(r[key]["watertight"] for r in rows), len(rows), sum(r[key]["pieces"] == 1 for r in rows),
            len(rows)))
    lines.append("Seconds, median: ours %.1f, Poisson (normals, orientation, depth 9) %.1f." % (
        statistics.median(r["ours"]["seconds"] for r in rows),
        statistics.median(r["poisson"]["seconds"] for r in rows)))
    return lines


def main():
    if args.pvpython is None:
        sys.exit("no pvpython on the PATH: give it with --pvpython")
    python_path(args.build)
    todo, notes = cases()
    print("Scan surface (Sheets 3) against Open3D's screened Poisson (depth 9); Chamfer in % of the diagonal, "
          "F at 1 % of it; watertight, pieces (when not watertight: open edges / edges of more than two "
          "triangles).\n")
    print("| input | sigma % | points | ours Chamfer % | ours F@1% | ours watertight, pieces | ours s |"
          " Poisson Chamfer % | Poisson F@1% | Poisson watertight, pieces | Poisson s |"
          " trimmed Chamfer % | trimmed F@1% | trimmed watertight, pieces | ours / Poisson Chamfer |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|", flush=True)
    rows, loaded = [], {}
    with tempfile.TemporaryDirectory(prefix="scan_surface-") as folder:
        for label, sigma, kind, make in todo:
            if label not in loaded:
                loaded.clear()
                loaded[label] = make()
            points, truth = loaded[label]
            rows.append(run_case(label, sigma, points, truth, folder, kind))
    print("\nOur runs' field data (ScanDistanceMean and ScanDistance95 in cells h; volume against the true one"
          " where known) and warnings:\n")
    print("| input | sigma % | h | ScanSurface | ScanSurfacePieces | ScanSurfaceOpenPieces | ScanSurfaceVolume / true |"
          " ScanDistanceMean (h) | ScanDistance95 (h) | warnings |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        info = r["info"]
        spacing = "%.4g" % info["SampleSpacing"] if info.get("SampleSpacing") else "-"
        true_volume = TRUE_VOLUMES.get(r["label"])
        volume = info.get("ScanSurfaceVolume")
        print("| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
            r["label"], number(100 * r["sigma"], 1), spacing,
            number(info.get("ScanSurface"), 0), number(info.get("ScanSurfacePieces"), 0),
            number(info.get("ScanSurfaceOpenPieces"), 0),
            number(volume / true_volume, 3) if volume is not None and true_volume else "-",
            number(info.get("ScanDistanceMean"), 2), number(info.get("ScanDistance95"), 2),
            "; ".join(([info["error"]] if info.get("error") else []) + info["warnings"]) or "-"))
    print()
    for line in notes + summary(rows):
        print(line)


def limb_volume():
    r, rc = 0.5, LIMB_RADIUS
    inside = 2 * math.pi / 3 * (r ** 3 - (r * r - rc * rc) ** 1.5)  # the cylinder's part within the sphere
    return 4 / 3 * math.pi * r ** 3 + math.pi * rc * rc * LIMB_END - inside


TRUE_VOLUMES = {"sphere": 4 / 3 * math.pi * 0.125, "sphere, density 1-10x": 4 / 3 * math.pi * 0.125,
                "torus (mm)": 2 * math.pi ** 2 * TORUS_R * TORUS_r ** 2, "cube": 1.0,
                "sphere + thin limb": limb_volume()}

if __name__ == "__main__":
    if args.child:
        child(*args.child)
    else:
        main()
