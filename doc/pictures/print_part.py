# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""Renders doc/images/print_part.png for the how-to "Hollow a scan for
printing": the armadillo's shell beside its part to print, both cut open.

    scripts/with-xvfb.sh pvpython doc/pictures/print_part.py

Left: the shell at the defaults (the wall 2 l around the points, the outer
sheet l outside them). Right: WallThickness 2 % of the scan's diagonal: the
outer surface on the points, the wall inside it. The scan is read from
../shared/data/scans ($NV_SCANS_DIR); without it there is no picture.
"""
import numpy as np

import nvpictures as nv

pvs = nv.plugin()
DIRECTION = [0.55, 0.35, 1.0]
UP = [0, 1, 0]

armadillo = nv.scan_points("armadillo")
if armadillo is None:
    raise SystemExit("print_part: no armadillo in %s: no picture" % nv.SCANS_DIR)
diagonal = float(np.linalg.norm(armadillo.max(axis=0) - armadillo.min(axis=0)))
center = (armadillo.min(axis=0) + armadillo.max(axis=0)) / 2
size = armadillo.max(axis=0) - armadillo.min(axis=0)
strip = nv.Strip()
for title, properties in (("shell (defaults), l = {l:.3g}:\n{size}", {}),
                          ("WallThickness {w:.3g}: {size},\nwall {measured:.3g} or more, pockets merged: {removed}",
                           dict(WallThickness=0.02 * diagonal))):
    shell = nv.reconstruct(nv.cloud_source(armadillo), **properties)
    shell.UpdatePipeline()
    bounds = shell.GetDataInformation(1).GetBounds()
    view = nv.new_view()
    offset = nv.field_value(shell, "OffsetDistance")
    nv.show_cut_open(view, shell, center, [0, 0, 1], points=armadillo, slab=0.5 * offset)
    nv.look(view, center, DIRECTION, UP, zoom=1.2)
    strip.add(view, title.format(l=offset, w=properties.get("WallThickness", 0.0),
                                 measured=nv.field_value(shell, "MinimumWallThickness") or 0.0,
                                 removed=int(nv.field_value(shell, "RemovedCavities") or 0),
                                 size=" x ".join("%.3g" % (bounds[2 * a + 1] - bounds[2 * a]) for a in range(3))))
    pvs.Delete(view)
strip.save("print_part.png", columns=2, panel_inches=3.8,
           title="The armadillo (%s x %s x %s), front half cut away" % tuple("%.3g" % s for s in size),
           caption="Dark red: the material, orange: its surfaces, blue: the points. The shell's outside is l beyond\n"
                   "the scan; the part's outside is on the scan, its wall WallThickness (2 % of the diagonal) inside it.")
