# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""Renders doc/images/closing_radius_effect.png: a sphere sampled with three
holes (empty caps of radius 1.5 l, 2.5 l and 3.5 l, l = 0.04), its shell cut
open, with CloseGaps off and on with three ClosingRadius values.

    scripts/with-xvfb.sh pvpython doc/pictures/closing_radius_effect.py

Without gap closing each hole pierces the wall (the outer and inner sheets
join through it: no cavity); ClosingRadius is the widest hole bridged (its
default 0 means 3 l).
"""
import nvpictures as nv

pvs = nv.plugin()
L = 0.04
HOLES = (1.5, 2.5, 3.5)  # radii, in l
xyz = nv.holey_sphere(L, HOLES)
cloud = nv.cloud_source(xyz)

settings = [("CloseGaps off", dict(CloseGaps=0)),
            ("ClosingRadius 2 l", dict(ClosingRadius=2 * L)),
            ("ClosingRadius 0 (automatic: 3 l)", dict()),
            ("ClosingRadius 4 l", dict(ClosingRadius=4 * L))]
strip = nv.Strip()
for title, properties in settings:
    shell = nv.reconstruct(cloud, OffsetDistance=L, SampleSpacing=L / 4, **properties)
    shell.UpdatePipeline()
    added = int(nv.field_value(shell, "AddedPoints") or 0)
    gaps = int(nv.field_value(shell, "NumberOfGaps") or 0)
    view = nv.new_view()
    nv.show_cut_open(view, shell, [0, 0, 0], [0, 0, 1], points=xyz, slab=0.5 * L)
    nv.look(view, [0, 0, -0.1], [0.0, -0.45, 1.0], [0, 1, 0], zoom=1.45)
    strip.add(view, "%s\n%d points added, %d hole%s open" % (title, added, gaps, "" if gaps == 1 else "s"))
    pvs.Delete(view)
strip.save("closing_radius_effect.png", panel_inches=3.4,
           title="CloseGaps and ClosingRadius: a sphere sampled with holes of radius 1.5 l, 2.5 l and 3.5 l "
                 "(l = 0.04), cut open",
           caption="A hole wider than l pierces the wall: the sheets join through it and the shell has no cavity. "
                   "Gap closing adds points in the holes up to ClosingRadius.")
