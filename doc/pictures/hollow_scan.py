# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""Renders doc/images/hollow_scan.png for the how-to "Hollow a scan": closed
scans hollowed, cut open, so that the wall and the cavity show.

    scripts/with-xvfb.sh pvpython doc/pictures/hollow_scan.py

Left: the armadillo (the how-to's scan.ply) with the automatic offset, then
with l = 2 % of its bounding box's diagonal. Right: the bunny, whose scan
has holes under its base, with the defaults: the filter warns of the holes,
and the cut through the centre of the widest (LargestGapCenter) shows the
wall open there. Every value is the run's own (the Volume's field data) or a
fraction of the scan's diagonal. The scans are read from ../shared/data/scans
($NV_SCANS_DIR); a missing one is skipped with a message.
"""
import numpy as np

import nvpictures as nv

pvs = nv.plugin()
DIRECTION = [0.55, 0.35, 1.0]  # from the front (+z), a little from the right and above
UP = [0, 1, 0]


def diagonal(xyz):
    return float(np.linalg.norm(xyz.max(axis=0) - xyz.min(axis=0)))


def panel(strip, xyz, title, cut=None, direction=DIRECTION, focus=None, zoom=1.0, **properties):
    """The shell of `xyz` with these properties, the half in front of the
    plane z = cut[2] (default: the middle) cut away, seen from `direction`
    (closer by `zoom` on `focus`); the title gets {l}, {pct}, {gaps},
    {largest}. (number of gaps, largest gap, its centre)."""
    center = (xyz.min(axis=0) + xyz.max(axis=0)) / 2
    origin = center if cut is None else np.array([center[0], center[1], cut[2]])
    shell = nv.reconstruct(nv.cloud_source(xyz), **properties)
    shell.UpdatePipeline()
    offset = nv.field_value(shell, "OffsetDistance")
    gaps = int(nv.field_value(shell, "NumberOfGaps") or 0)
    largest = nv.field_value(shell, "LargestGap") or 0.0
    info = shell.GetDataInformation(0).GetFieldDataInformation().GetArrayInformation("LargestGapCenter")
    where = [info.GetComponentRange(k)[0] for k in range(3)] if info else None
    view = nv.new_view()
    nv.show_cut_open(view, shell, origin, [0, 0, 1], points=xyz, slab=0.5 * offset)
    nv.look(view, origin, direction, UP, zoom=1.2)
    if focus is not None:  # closer, on this point of the cut
        camera = view.GetActiveCamera()
        shift = np.array(focus) - np.array(camera.GetFocalPoint())
        camera.SetFocalPoint(*(np.array(camera.GetFocalPoint()) + shift))
        camera.SetPosition(*(np.array(camera.GetPosition()) + shift))
        camera.Zoom(zoom)
        pvs.Render(view)
    strip.add(view, title.format(l=offset, pct=100 * offset / diagonal(xyz), gaps=gaps, largest=largest))
    pvs.Delete(view)
    return gaps, largest, where


strip = nv.Strip()
armadillo = nv.scan_points("armadillo")
if armadillo is not None:
    d = diagonal(armadillo)
    panel(strip, armadillo, "armadillo, defaults:\nl = {l:.3g} ({pct:.1f} % of the diagonal)")
    panel(strip, armadillo, "armadillo, OffsetDistance 2 % of the diagonal:\nl = {l:.3g}",
          OffsetDistance=0.02 * d)
bunny = nv.scan_points("bunny")
if bunny is not None:
    # The holes are under the base: seen from the front and a little from below.
    below = [0.45, -0.35, 1.0]
    shell = nv.reconstruct(nv.cloud_source(bunny))
    shell.UpdatePipeline()
    info = shell.GetDataInformation(0).GetFieldDataInformation().GetArrayInformation("LargestGapCenter")
    hole = [info.GetComponentRange(k)[0] for k in range(3)] if info else None
    pvs.Delete(shell)
    panel(strip, bunny, "bunny, defaults: {gaps} gaps open; cut through\nthe widest ({largest:.2g}), close up",
          cut=hole, direction=below, focus=hole, zoom=2.5)
if not strip.panels:
    raise SystemExit("hollow_scan: neither armadillo nor bunny in %s: no picture" % nv.SCANS_DIR)
strip.save("hollow_scan.png", columns=len(strip.panels), panel_inches=3.8,
           title="Closed scans hollowed, front half cut away",
           caption="Orange: the outer and inner sheets. Dark red: the wall, 2 l thick, around the points (blue). "
                   "Inside the inner sheet: the cavity.\nA hole in the sampling that gap closing leaves "
                   "open pierces the wall and opens the cavity to the outside.")
