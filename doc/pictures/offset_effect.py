# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""Renders doc/images/offset_effect.png: the demo cloud (Data/trefoil.vtp)
at four OffsetDistance values, cut open, on one grid (SampleSpacing 0.01,
the automatic offset's spacing rounded up), so that only the offset changes.

    scripts/with-xvfb.sh pvpython doc/pictures/offset_effect.py
"""
import nvpictures as nv

pvs = nv.plugin()
xyz = nv.trefoil_points()
cloud = nv.cloud_source(xyz)
center = (xyz.min(axis=0) + xyz.max(axis=0)) / 2
SPACING = 0.01
strip = nv.Strip()
automatic = None
for factor in (0, 2, 4, 7):
    if factor and automatic is None:
        raise SystemExit("offset_effect: the automatic offset was not reported")
    offset = factor * automatic if factor else 0.0
    shell = nv.reconstruct(cloud, OffsetDistance=offset, SampleSpacing=SPACING)
    shell.UpdatePipeline()
    used = nv.field_value(shell, "OffsetDistance")
    if not factor:
        automatic = used
    view = nv.new_view()
    nv.show_cut_open(view, shell, center, [0, 0, 1], points=xyz, slab=0.25 * used, point_size=2)
    nv.look(view, center, [0.25, -0.55, 1.0], [0, 1, 0], zoom=1.2)
    strip.add(view, ("l = %.3f (automatic)" % used) if not factor else "l = %.3f (%d x automatic)" % (used, factor))
    pvs.Delete(view)
strip.save("offset_effect.png", panel_inches=3.4,
           title="OffsetDistance l: the half-thickness of the wall (demo cloud, a tube of radius 0.25, cut at z = 0)",
           caption="Red: the wall cut open; blue: the points near the cut. The wall grows to l on each side of the "
                   "points; where it exceeds the tube's radius the cavity closes.")
