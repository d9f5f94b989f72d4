# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""OutputVolume off: the same surface, without the dense volume, and a peak
memory that follows the band rather than the box (the volume costs its
dense phi and nothing more).

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
# Rows sorted (the points are doubles: compare them as such).
on, off = (nvtesting.points_of(surfaces[v]) for v in (True, False))
on, off = (x[np.lexsort(x.T[::-1])] for x in (on, off))
t.check(on.shape == off.shape and bool((on == off).all()), "same vertices with and without the volume")
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
before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
f.Update()
print(json.dumps(dict(rss=resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0, before=before,
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
    # The volume costs its dense phi, 4 bytes a node, and nothing more: the
    # surface is made from the band (no dense isosurfacer memory), and without
    # the volume nothing follows the box. Each child's peak is taken above its
    # own memory before the run (Python's varies by a few MiB). The
    # allocator's reuse of freed pages moves the difference by up to 2 %
    # either way (measured: 471.8 to 485.1 MiB for a phi of 479.7 MiB); a
    # dense array of the box without the volume would make it about 0.
    phi = 4.0 * on["nodes"] / 2 ** 20
    cost = (on["rss"] - on["before"]) - (off["rss"] - off["before"])
    print("the volume costs %.1f MiB, its phi %.1f MiB" % (cost, phi))
    t.check(0.95 * phi < cost < 1.05 * phi, "memory follows the band without the volume")
    # Without the volume the peak is the evolution's: 54 bytes a band node
    # (README, "Where the memory goes"), if the memory the band's
    # construction freed was handed back before its neighbour indices were
    # made (nvMemory.h). Measured: 53.5 to 57.3 bytes a band node above the
    # child's start; 73.2 when the freed memory is kept.
    per_node = (off["rss"] - off["before"]) * 2 ** 20 / off["band"]
    print("without the volume: %.1f bytes a band node" % per_node)
    t.check(per_node < 64.0, "the peak without the volume is the band's (%.1f bytes a node)" % per_node)
t.finish()
