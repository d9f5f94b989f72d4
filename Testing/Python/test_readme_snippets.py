# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""The README's pvpython and VTK-in-Python snippets, run as written on a real
scan: the pvpython one with "scan.ply" replaced by a scan from
../shared/data/scans and the plugin path by the build's; the VTK one with
`points` read from that scan. Each must write or produce a closed shell.
Skipped, with a message, without the scans.

    pvpython test_readme_snippets.py README PLUGIN SCANS_DIR
"""
import os
import re
import subprocess
import sys
import tempfile

import nvtesting

readme, plugin, scans = sys.argv[1:4]
scan = os.path.join(scans, "dragon.ply")
if not os.path.isfile(scan):
    print("SKIPPED: no scans in %s (../shared/data/scans is not beside the source tree)" % scans)
    sys.exit(77)
t = nvtesting.Checker("test_readme_snippets")
blocks = re.findall(r"```python\n(.*?)```", open(readme).read(), re.S)


def dedent(block):
    lines = block.splitlines()
    indent = min(len(line) - len(line.lstrip()) for line in lines if line.strip())
    return "\n".join(line[indent:] for line in lines) + "\n"


pvpython_blocks = [dedent(b) for b in blocks if "LoadPlugin(" in b and "scan.ply" in b]
vtk_blocks = [dedent(b) for b in blocks if "from narrowvolume import" in b and "SetInputData(points)" in b]
t.check(len(pvpython_blocks) == 1 and len(vtk_blocks) == 1, "found the two snippets")

with tempfile.TemporaryDirectory() as folder:
    if pvpython_blocks:
        code = pvpython_blocks[0].replace("scan.ply", scan)
        code = re.sub(r'LoadPlugin\("[^"]*"', 'LoadPlugin(%r' % plugin, code)
        run = subprocess.run(["pvpython", "--force-offscreen-rendering", "-c", code], cwd=folder,
                             capture_output=True, text=True)
        print(run.stdout.strip())
        stl = os.path.join(folder, "shell.stl")
        t.check(run.returncode == 0 and os.path.exists(stl), "the pvpython snippet ran: %s" % nvtesting.explain(run))
        if os.path.exists(stl):
            from vtkmodules.vtkIOGeometry import vtkSTLReader
            reader = vtkSTLReader()
            reader.SetFileName(stl)
            reader.Update()
            triangles, open_edges, _ = nvtesting.merged_surface(reader.GetOutput())
            print("pvpython snippet: shell.stl has %d triangles, %d open edges" % (triangles, open_edges))
            t.check(triangles > 10000 and open_edges == 0, "the pvpython snippet wrote a closed shell")
    if vtk_blocks:
        from vtkmodules.vtkIOPLY import vtkPLYReader
        reader = vtkPLYReader()
        reader.SetFileName(scan)
        reader.Update()
        scope = {"points": reader.GetOutput()}
        exec(vtk_blocks[0], scope)
        triangles, open_edges, _ = nvtesting.merged_surface(scope["surface"])
        print("VTK snippet: %d triangles, %d open edges, phi on %d nodes" % (
            triangles, open_edges, scope["phi"].GetNumberOfPoints()))
        t.check(triangles > 10000 and open_edges == 0, "the VTK snippet made a closed shell")
t.finish()
