# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""The pvpython and VTK-in-Python snippets of the README and of the Getting
started pages (doc/getting-started/*.md), run as written on a real scan: the
pvpython one with "scan.ply" replaced by a scan from ../shared/data/scans and
the plugin path by the build's; the VTK one with `points` read from that
scan. Each must write or produce a closed shell (DocSnippets runs every
block; this test also checks what they make on the dragon). Skipped, with a
message, without the scans.

    pvpython -m pytest test_readme_snippets.py --readme README --plugin PLUGIN [--scans-dir SCANS_DIR]
"""
import glob
import os
import re
import subprocess

import pytest

import nvclouds
import nvtesting


def dedent(block):
    lines = block.splitlines()
    indent = min(len(line) - len(line.lstrip()) for line in lines if line.strip())
    return "\n".join(line[indent:] for line in lines) + "\n"


@pytest.fixture(scope="module")
def snippets(readme):
    """The pvpython snippets and VTK-in-Python snippets, each once."""
    pages = [readme] + sorted(glob.glob(os.path.join(os.path.dirname(readme), "doc", "getting-started", "*.md")))
    blocks = []
    for page in pages:
        blocks += re.findall(r"```python\n(.*?)```", open(page).read(), re.S)
    pvpython_blocks = [dedent(b) for b in blocks if "LoadPlugin(" in b and "scan.ply" in b]
    vtk_blocks = [dedent(b) for b in blocks if "from narrowvolume import" in b and "SetInputData(points)" in b]
    return list(dict.fromkeys(pvpython_blocks)), list(dict.fromkeys(vtk_blocks))


@pytest.fixture(scope="module")
def dragon(require_scans, scans_dir):
    require_scans("dragon")
    return nvclouds.scan_path("dragon", scans_dir)


def test_found_the_two_snippets(snippets):
    pvpython_blocks, vtk_blocks = snippets
    assert len(pvpython_blocks) >= 1 and len(vtk_blocks) >= 1, "found the two snippets"


def test_pvpython_snippet(snippets, plugin_path, dragon):
    folder = nvtesting.scratch_folder(prefix="nv-readme-")
    code = snippets[0][0].replace("scan.ply", dragon)
    code = re.sub(r'LoadPlugin\("[^"]*"', 'LoadPlugin(%r' % plugin_path, code)
    run = subprocess.run(["pvpython", "--force-offscreen-rendering", "-c", code], cwd=folder,
                         capture_output=True, text=True)
    print(run.stdout.strip())
    stl = os.path.join(folder, "shell.stl")
    assert run.returncode == 0 and os.path.exists(stl), "the pvpython snippet ran: %s" % nvtesting.explain(run)
    from vtkmodules.vtkIOGeometry import vtkSTLReader
    reader = vtkSTLReader()
    reader.SetFileName(stl)
    reader.Update()
    triangles, open_edges, _ = nvtesting.merged_surface(reader.GetOutput())
    print("pvpython snippet: shell.stl has %d triangles, %d open edges" % (triangles, open_edges))
    assert triangles > 10000 and open_edges == 0, "the pvpython snippet wrote a closed shell"


def test_vtk_snippet(snippets, dragon):
    scope = {"points": nvclouds.read(dragon)}
    exec(snippets[1][0], scope)
    triangles, open_edges, _ = nvtesting.merged_surface(scope["surface"])
    print("VTK snippet: %d triangles, %d open edges, phi on %d nodes" % (
        triangles, open_edges, scope["phi"].GetNumberOfPoints()))
    assert triangles > 10000 and open_edges == 0, "the VTK snippet made a closed shell"
