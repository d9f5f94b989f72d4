# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""OutputVolume off: the same surface, without the dense volume, and a peak
memory that follows the band rather than the box.

Each memory figure is the peak resident set of a fresh child process that
runs the filter once on a sphere (500 cells across: 125 million grid nodes,
whose float phi alone is 500 MB; the band is a few million nodes).
"""
import json
import subprocess
import sys

import numpy as np

from narrowvolume import vtkNarrowVolumeReconstruction
import nvshapes
import nvtesting

t = nvtesting.Checker("test_volume_off")

# Same surface, vertex for vertex, on a small case.
cloud = nvtesting.cloud(nvshapes.sphere_points(0.02))
surfaces = {}
for volume in (True, False):
    f = vtkNarrowVolumeReconstruction()
    f.SetInputData(cloud)
    f.SetOffsetDistance(0.1)
    f.SetSampleSpacing(0.02)
    f.SetOutputVolume(volume)
    f.Update()
    surfaces[volume] = f.GetOutput(1)
    image = f.GetOutput(0)
    t.check(image.GetPointData().GetArray("phi") is not None if volume else image.GetPointData().GetNumberOfArrays() == 0,
            "volume arrays only when asked (OutputVolume %s)" % volume)
    t.check(image.GetDimensions()[0] > 1, "the grid's geometry is there either way")
on, off = (np.sort(nvtesting.points_of(surfaces[v]).view("f4,f4,f4").ravel()) for v in (True, False))
t.check(len(on) == len(off) and bool((on == off).all()), "same vertices with and without the volume")
t.check(surfaces[True].GetNumberOfPolys() == surfaces[False].GetNumberOfPolys(), "same triangles")
t.check(nvtesting.boundary_edges(surfaces[False]) == 0, "closed without the volume")
t.check(nvtesting.regions(surfaces[False]) == 2, "two sheets without the volume")

CHILD = r"""
import json, resource, sys
sys.path[:0] = %r
import nvshapes, nvtesting
from narrowvolume import vtkNarrowVolumeReconstruction
f = vtkNarrowVolumeReconstruction()
f.SetInputData(nvtesting.cloud(nvshapes.sphere_points(0.004)))
f.SetOffsetDistance(0.008)
f.SetMaximumDimension(500)
f.SetOutputVolume(%s)
f.Update()
print(json.dumps(dict(rss=resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0,
                      nodes=f.GetNumberOfGridNodes(), band=f.GetNumberOfBandNodes(),
                      triangles=f.GetOutput(1).GetNumberOfPolys())))
"""
peaks = {}
for volume in (True, False):
    result = subprocess.run(nvtesting.python_command() + ["-c", CHILD % (sys.path, volume)],
                            capture_output=True, text=True)
    lines = [l for l in result.stdout.splitlines() if l.startswith("{")]
    t.check(result.returncode == 0 and lines, "child ran: %s" % nvtesting.explain(result))
    if lines:
        peaks[volume] = json.loads(lines[-1])
if len(peaks) == 2:
    on, off = peaks[True], peaks[False]
    print("grid %d nodes, band %d: peak %.0f MB with the volume, %.0f MB without" % (
        on["nodes"], on["band"], on["rss"], off["rss"]))
    t.check(on["triangles"] == off["triangles"], "same surface in both children")
    # The dense phi alone is 4 bytes a node; without it, the peak must drop by at least that.
    t.check(on["rss"] - off["rss"] > 4.0 * on["nodes"] / 2 ** 20, "memory follows the band without the volume")
t.finish()
