# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""Whether two builds give the same outputs, bit for bit: for a change that
is speed, not a new answer. Each build runs the filter in a process of its
own on the same clouds at 1 and 2 threads (the scans of ../shared at their
defaults when they are there, a sphere, a sphere with three holes with gap
closing on and off, a noisy sphere and the cube), and the SHA-256 of each
output is compared: phi, the surface's points, normals and triangles, and
every field data array both builds have (StageSeconds, timings, left out).

    pvpython benchmarks/same_outputs.py BUILD_A BUILD_B [--scans DIR]

BUILD_*: build folders (their lib/python3.*/dist-packages hold narrowvolume),
e.g. a worktree of the commit before the change built beside this one.
Prints what differs; exit status 1 if anything does.
"""
import argparse
import glob
import hashlib
import json
import os
import subprocess
import sys
import tempfile

import clouds
import table2  # PYTHON: the children's pvpython


def site(build):
    found = glob.glob(os.path.join(build, "lib", "python3*", "*-packages"))
    if not found:
        sys.exit("same_outputs.py: no narrowvolume package under %s" % build)
    return found[0]


def cases(scans):
    """{name: (points, settings)}."""
    import numpy as np
    nvclouds = clouds.nvclouds
    rng = np.random.default_rng(5)
    sphere = nvclouds.sphere_points(20000, 0.5)
    holey = sphere
    for direction, radius in zip(np.eye(3), (0.06, 0.1, 0.15)):
        holey = holey[np.linalg.norm(holey - 0.5 * direction, axis=1) > radius]
    out = {"sphere": (sphere, {}),
           "holey sphere": (holey, dict(OffsetDistance=0.04, SampleSpacing=0.01)),
           "holey sphere, closing off": (holey, dict(OffsetDistance=0.04, SampleSpacing=0.01, CloseGaps=False)),
           "noisy sphere": (sphere + rng.normal(scale=0.01, size=sphere.shape), {}),
           "cube": (nvclouds.shape_points("cube", 0.02), dict(OffsetDistance=0.05))}
    for name in nvclouds.SCANS:
        if nvclouds.have_scans([name], scans):
            out[name] = (nvclouds.scan_points(name, scans), {})
    return out


def child(scans, path):
    """The digests of this build's outputs, into the JSON file `path`."""
    import numpy as np
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from narrowvolume import vtkNarrowVolumeReconstruction

    def digest(array):
        return hashlib.sha256(np.ascontiguousarray(vtk_to_numpy(array)).tobytes()).hexdigest()

    out = {}
    for name, (xyz, settings) in cases(scans).items():
        for threads in (1, 2):
            f = vtkNarrowVolumeReconstruction()
            f.GlobalWarningDisplayOff()
            f.SetInputData(clouds.nvclouds.cloud(xyz))
            for key, value in settings.items():
                getattr(f, "Set" + key)(value)
            f.SetNumberOfThreads(threads)
            f.Update()
            volume, surface = f.GetOutput(0), f.GetOutput(1)
            record = {"phi": digest(volume.GetPointData().GetArray("phi"))}
            if surface.GetNumberOfPoints():
                record["points"] = digest(surface.GetPoints().GetData())
                record["normals"] = digest(surface.GetPointData().GetNormals())
                record["triangles"] = digest(surface.GetPolys().GetConnectivityArray())
            fields = volume.GetFieldData()
            for a in range(fields.GetNumberOfArrays()):
                if fields.GetArrayName(a) != "StageSeconds":
                    record["field " + fields.GetArrayName(a)] = digest(fields.GetArray(a))
            out["%s, %d thread%s" % (name, threads, "" if threads == 1 else "s")] = record
    with open(path, "w") as f:
        json.dump(out, f)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("builds", nargs="*", help="BUILD_A BUILD_B")
    parser.add_argument("--scans", default=clouds.SCANS_DIR)
    parser.add_argument("--child", nargs=2, metavar=("SITE", "OUT"), help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.child:
        sys.path.insert(0, args.child[0])
        child(args.scans, args.child[1])
        return 0
    if len(args.builds) != 2:
        parser.error("two build folders")
    records = []
    with tempfile.TemporaryDirectory() as folder:
        for i, build in enumerate(args.builds):
            path = os.path.join(folder, "%d.json" % i)
            subprocess.run([table2.PYTHON, os.path.abspath(__file__), "--child", site(build), path,
                            "--scans", args.scans], check=True)
            with open(path) as f:
                records.append(json.load(f))
    a, b = records
    compared = differ = 0
    for case in a:
        for output in sorted(set(a[case]) & set(b.get(case, {}))):
            compared += 1
            if a[case][output] != b[case][output]:
                differ += 1
                print("differs: %s: %s" % (case, output))
    print("same_outputs.py: %d of %d outputs differ (%d cases; outputs only one build has are not compared)"
          % (differ, compared, len(a)))
    return 1 if differ else 0


if __name__ == "__main__":
    sys.exit(main())
