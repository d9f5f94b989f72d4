# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""Renders doc/images/shell_cut_open.png: the shell around real scans
(../shared/data/scans), with the filter's defaults, cut open so that the
wall's thickness and the cavity show, beside the input points.

    scripts/with-xvfb.sh pvpython doc/pictures/shell_cut_open.py [SCAN ...]

Top row: the points; bottom row: the shell with its front half cut away,
the wall's section dark red, the points near the cut on it. A scan that is
missing is skipped with a message.
"""
import argparse

import numpy as np

import nvpictures as nv

parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
parser.add_argument("scans", nargs="*", default=["bunny", "dragon", "teapot"])
args = parser.parse_args()

pvs = nv.plugin()
found = []
for name in args.scans:
    xyz = nv.scan_points(name)
    if xyz is not None:
        found.append((name, xyz))
if not found:
    raise SystemExit("shell_cut_open: none of the scans %s in %s: no picture" % (args.scans, nv.SCANS_DIR))

# All the scans stand with y up; we look at them from the front (+z), a little from the right and above.
DIRECTION = [0.55, 0.45, 1.0]
UP = [0, 1, 0]
strip = nv.Strip()
shells = []
for name, xyz in found:
    center = (xyz.min(axis=0) + xyz.max(axis=0)) / 2
    view = nv.new_view()
    nv.show_points(view, nv.cloud_source(xyz), size=1.5)
    nv.look(view, center, DIRECTION, UP, zoom=1.15)
    strip.add(view, "%s: %s points" % (name, format(len(xyz), ",")))
    pvs.Delete(view)
for name, xyz in found:
    center = (xyz.min(axis=0) + xyz.max(axis=0)) / 2
    shell = nv.reconstruct(nv.cloud_source(xyz))  # the defaults: offset and grid follow the cloud
    shell.UpdatePipeline()
    offset = nv.field_value(shell, "OffsetDistance")
    view = nv.new_view()
    nv.show_cut_open(view, shell, center, [0, 0, 1], points=xyz, slab=0.5 * offset)
    nv.look(view, center, DIRECTION, UP, zoom=1.15)
    extent = xyz.max(axis=0) - xyz.min(axis=0)
    strip.add(view, "shell cut open, l = %.2g (%.1f %% of its height)" % (offset, 100 * offset / extent[1]))
    pvs.Delete(view)
strip.save("shell_cut_open.png", columns=len(found), panel_inches=4.4,
           title="The narrow volume of real scans, with the filter's defaults",
           caption="Orange: the shell's two sheets (phi = 0), at distance l from the points. Dark red: the wall "
                   "cut open (phi > 0), with the points near the cut (blue).\nThe cavity inside is the hollow "
                   "of the scanned object.")
