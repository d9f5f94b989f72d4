# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""The C++ filter's record for the wheel's tests (nvflavours.py), in pvpython
with the CMake build's package:

    pvpython pip_reference.py OUT_DIR

OUT_DIR/reference.json: the filter's public names, each property's default
and clamping, and a summary (SHA-256 digests) of the outputs of each run of
nvflavours.CASES on OUT_DIR/points.npy (the demo cloud's points, a sphere
and lone points, saved so that both flavours run on the same bytes).
"""
import json
import os
import sys

import numpy as np

import narrowvolume
from narrowvolume import _properties
import nvclouds
import nvflavours

out = sys.argv[1]
os.makedirs(out, exist_ok=True)
if narrowvolume.FLAVOUR != "vtk-module":
    sys.exit("FAILED: pip_reference.py records the C++ filter; this is the %s flavour" % narrowvolume.FLAVOUR)
cls = narrowvolume.vtkNarrowVolumeReconstruction
trefoil = nvclouds.points_of_file(nvclouds.data_file("trefoil.vtp"))
# Lone points (gaps, and loose pieces that RemoveSmallPieces drops).
lone = np.array([[2.5, 0.0, 1.0], [-2.0, 2.2, 0.3], [1.0, -2.3, -0.4]])
points = np.vstack([trefoil, nvclouds.sphere_points(4000, 0.4, (2.5, 0.0, 0.0)), lone])
np.save(os.path.join(out, "points.npy"), points)
cloud = nvclouds.cloud(points)
record = {"api": nvflavours.public_api(cls), "properties": nvflavours.property_report(cls, _properties.PROPERTIES),
          "cases": {name: nvflavours.summary(nvflavours.run_case(cls, cloud, properties))
                    for name, properties in nvflavours.CASES.items()}}
with open(os.path.join(out, "reference.json"), "w") as f:
    json.dump(record, f, indent=1)
print("pip_reference: %d names, %d properties, %d runs recorded in %s" % (
    len(record["api"]), len(record["properties"]), len(nvflavours.CASES), out))
