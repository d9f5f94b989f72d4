# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""Every fenced code block of README.md and doc/**/*.md runs, or says why not.

Each block runs in a scratch folder of its own that holds the files the
pages name: scan.ply (the armadillo scan of ../shared/data/scans, 14,587
points), scan.xyz and scan.las (the same points), cloud.ply, and links to
the tree's examples/, Data/ and scripts/. `sh` blocks run in bash (set -e)
with `narrowvolume` (the CMake build's `pvpython -m narrowvolume`) first on
PATH; `python` blocks run in pvpython with the build's package on PYTHONPATH
and the build's plugin in LoadPlugin(...). A block passes when it exits with
0, prints no traceback nor VTK error, and writes every file it names after
`-o` or in SaveData(...).

A block that is not to be run carries an HTML comment on the line before it
(doc/developer/documentation.md):

    <!-- snippet: not run, REASON -->
    <!-- snippet: run by TEST, REASON -->     TEST must be a ctest of Testing/CMakeLists.txt
    <!-- snippet: continues -->               runs after the block before it, as one script
    <!-- snippet: given points, REASON -->    Python that works on `points` (the scan, a vtkPolyData)

`cmake` blocks run by InstallConsumer must use what Testing/Consumer/
uses (find_package(NarrowVolume), the targets); `cpp` blocks may call only
methods the class header declares. Any other block without a marker fails.
Skipped, with a message, without the scans.

    pvpython -m pytest test_doc_snippets.py --source-dir SOURCE --plugin PLUGIN [--scans-dir SCANS_DIR]
"""
import glob
import os
import re
import shutil
import subprocess
import time

import numpy as np
import pytest

import nvclouds
import nvpointfiles
import nvtesting

MARKER = re.compile(r"^\s*<!--\s*snippet:\s*(.*?)\s*-->\s*$")
FENCE = re.compile(r"^(\s*)(```+|~~~+)\s*([^\s`]*)")
RUNNABLE = {"sh": "sh", "bash": "sh", "shell": "sh", "python": "python", "py": "python"}
TIMEOUT = 120


class Block:
    """A fenced code block: where it is, its language, its text and its marker."""

    def __init__(self, page, line, language, code, marker):
        self.page, self.line, self.language, self.code, self.marker = page, line, language, code, marker
        self.continued = []  # blocks marked "continues" that run after this one

    def where(self):
        return "%s:%d" % (self.page, self.line)


def dedent(lines):
    indent = min((len(line) - len(line.lstrip()) for line in lines if line.strip()), default=0)
    return "\n".join(line[indent:] for line in lines) + "\n"


def blocks_of(path, name):
    """The fenced blocks of a Markdown file (MyST directives such as ```{toctree} are not code)."""
    lines = open(path, encoding="utf-8").read().splitlines()
    out, number = [], 0
    while number < len(lines):
        opening = FENCE.match(lines[number])
        if not opening:
            number += 1
            continue
        fence, language = opening.group(2), opening.group(3)
        end = number + 1
        while end < len(lines) and not lines[end].strip().startswith(fence[0] * len(fence)):
            end += 1
        previous = number - 1
        while previous >= 0 and not lines[previous].strip():
            previous -= 1
        marker = MARKER.match(lines[previous]) if previous >= 0 else None
        if not language.startswith("{"):
            out.append(Block(name, number + 1, language, dedent(lines[number + 1:end]),
                             marker.group(1) if marker else None))
        number = end + 1
    return out


def all_blocks(source_dir):
    pages = [os.path.join(source_dir, "README.md")]
    pages += sorted(glob.glob(os.path.join(source_dir, "doc", "**", "*.md"), recursive=True))
    blocks = []
    for page in pages:
        blocks += blocks_of(page, os.path.relpath(page, source_dir))
    return blocks


def ctest_names(source_dir):
    """The words of Testing/CMakeLists.txt: the names its tests are registered under are among them."""
    text = open(os.path.join(source_dir, "Testing", "CMakeLists.txt"), encoding="utf-8").read()
    return set(re.findall(r"[A-Za-z][A-Za-z0-9]+", text))


@pytest.fixture(scope="module")
def blocks(source_dir):
    return all_blocks(source_dir)


def test_every_block_is_run_or_says_why(blocks, source_dir):
    """No block is left without a way to run it or a reason, and every test
    a marker names exists; "continues" follows a block that runs."""
    tests = ctest_names(source_dir)
    problems, counts = [], {}
    last_runnable = {}
    for block in blocks:
        marker = block.marker
        if marker is None:
            kind = "run" if block.language in RUNNABLE else "unmarked"
        else:
            kind = marker.split(",")[0].split()[0] if marker.split() else ""
            kind = {"not": "not run", "run": "run by", "continues": "continues", "given": "given points"}.get(kind, kind)
        counts[kind] = counts.get(kind, 0) + 1
        if kind == "unmarked":
            problems.append("%s: a ```%s block that the test cannot run and no <!-- snippet: ... --> marker "
                            "saying why" % (block.where(), block.language or ""))
        elif kind == "not run" and not re.match(r"not run,\s*\S", marker):
            problems.append("%s: 'not run' needs a reason: <!-- snippet: not run, REASON -->" % block.where())
        elif kind == "run by":
            named = re.match(r"run by\s+(\w+)", marker)
            if not named or named.group(1) not in tests:
                problems.append("%s: %r names no test of Testing/CMakeLists.txt" % (block.where(), marker))
        elif kind == "continues" and block.page not in last_runnable:
            problems.append("%s: 'continues' but no block before it on the page runs" % block.where())
        elif kind == "given points" and block.language not in ("python", "py"):
            problems.append("%s: 'given points' is for python blocks" % block.where())
        elif kind not in ("run", "not run", "run by", "continues", "given points"):
            problems.append("%s: unknown marker %r" % (block.where(), marker))
        if kind in ("run", "given points"):
            last_runnable[block.page] = block
    print("code blocks: %d; %s" % (len(blocks), ", ".join("%s %d" % item for item in sorted(counts.items()))))
    assert not problems, "\n".join(problems)


def test_consumer_blocks_match_the_consumer(blocks, source_dir):
    """A cmake block that InstallConsumer stands for asks for the package and
    the targets Testing/Consumer/ builds with; a cpp block calls only methods
    that the class header declares (a Set/Get macro declares Set<Name>/Get<Name>)."""
    consumer = open(os.path.join(source_dir, "Testing", "Consumer", "CMakeLists.txt"), encoding="utf-8").read()
    header = open(os.path.join(source_dir, "Filters", "vtkNarrowVolumeReconstruction.h"), encoding="utf-8").read()
    declared = set(re.findall(r"\b(\w+)\(", header))
    for macro, name in re.findall(r"vtk(Set|Get|SetClamp|Boolean|GetObject|NarrowVolumeSetting|NarrowVolumeSwitch"
                                  r"|NarrowVolumeClamp)Macro\((\w+)", header):
        declared |= {"Set" + name, "Get" + name, name + "On", name + "Off"}
    declared |= {"SetInputData", "SetInputConnection", "GetOutputPort", "Update", "New"}
    checked = 0
    for block in blocks:
        if block.language == "cmake":
            for target in set(re.findall(r"NarrowVolume::\w+", block.code)):
                assert target in consumer, "%s: %s is not used by Testing/Consumer" % (block.where(), target)
            for command in ("find_package(NarrowVolume", "vtk_module_autoinit(", "target_link_libraries("):
                if command in block.code:
                    assert command in consumer, "%s: Testing/Consumer has no %s" % (block.where(), command)
            checked += 1
        elif block.language == "cpp":
            for method in re.findall(r"->(\w+)\(", block.code):
                assert method in declared, "%s: %s is not declared in the header" % (block.where(), method)
            checked += 1
    print("checked %d cmake/cpp blocks against Testing/Consumer and the header" % checked)


# --- Running the blocks.

@pytest.fixture(scope="module")
def fixtures(require_scans, scans_dir, source_dir, plugin_path):
    """A folder with the files the pages name, a bin/ with `narrowvolume`, and the environment."""
    require_scans("armadillo")
    folder = nvtesting.scratch_folder(prefix="nv-doc-files-")
    scan = nvclouds.scan_path("armadillo", scans_dir)
    shutil.copy(scan, os.path.join(folder, "scan.ply"))
    shutil.copy(scan, os.path.join(folder, "cloud.ply"))
    xyz = nvclouds.points_of_file(scan)
    np.savetxt(os.path.join(folder, "scan.xyz"), xyz)
    nvpointfiles.write_las(os.path.join(folder, "scan.las"), 4, 6, xyz, scale=(1e-5, 1e-5, 1e-5))
    bin_dir = os.path.join(folder, "bin")
    os.makedirs(bin_dir)
    with open(os.path.join(bin_dir, "narrowvolume"), "w") as script:
        script.write('#!/bin/sh\nexec pvpython -m narrowvolume "$@"\n')
    os.chmod(os.path.join(bin_dir, "narrowvolume"), 0o755)
    # pvpython may itself be an MPI singleton: its Open MPI variables must not
    # leak into an mpiexec a block starts (as in test_mpi.py).
    env = {k: v for k, v in os.environ.items() if not k.startswith(("OMPI_", "PMIX_", "OPAL_", "PMI_"))}
    env.pop("DISPLAY", None)
    env["PATH"] = bin_dir + os.pathsep + env["PATH"]
    env["PYTHONUNBUFFERED"] = "1"
    env["OMPI_ALLOW_RUN_AS_ROOT"] = env["OMPI_ALLOW_RUN_AS_ROOT_CONFIRM"] = "1"
    # The build the pages call build/ (examples/reconstruct.py looks there,
    # or in BUILD_DIR as scripts/build.sh takes it): the plugin's.
    env["BUILD_DIR"] = nvtesting.build_of(plugin_path)
    return {"folder": folder, "env": env, "source_dir": source_dir, "plugin": plugin_path}


def scratch_for(fixtures):
    folder = nvtesting.scratch_folder(prefix="nv-doc-")
    for name in os.listdir(fixtures["folder"]):
        if name != "bin":
            os.symlink(os.path.join(fixtures["folder"], name), os.path.join(folder, name))
    for name in ("examples", "Data", "scripts"):
        os.symlink(os.path.join(fixtures["source_dir"], name), os.path.join(folder, name))
    return folder


def written_files(code):
    """The files a block says it writes: after -o, and the first argument of SaveData."""
    return re.findall(r"(?:-o\s+|SaveData\(\")([\w./-]+\.(?:stl|vtp|vti|ply))", code)


def command_for(block, code, fixtures):
    if RUNNABLE[block.language] == "sh":
        return ["bash", "-e", "-o", "pipefail", "-c", code]
    code = re.sub(r'LoadPlugin\("[^"]*NarrowVolume\.so"', "LoadPlugin(%r" % fixtures["plugin"], code)
    if block.marker and block.marker.startswith("given points"):
        code = ("from vtkmodules.vtkIOPLY import vtkPLYReader\n_reader = vtkPLYReader()\n"
                "_reader.SetFileName('scan.ply')\n_reader.Update()\npoints = _reader.GetOutput()\n") + code
    return ["pvpython", "--force-offscreen-rendering", "-c", code]


def runnable_blocks():
    """The blocks to run, with the "continues" blocks joined to the one they follow (module level: parametrize)."""
    source_dir = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", ".."))
    runs, last = [], {}
    for block in all_blocks(source_dir):
        if block.marker is None and block.language in RUNNABLE or (block.marker or "").startswith("given points"):
            runs.append(block)
            last[block.page] = block
        elif block.marker == "continues" and block.page in last:
            last[block.page].continued.append(block)
    return runs


RUNS = runnable_blocks()


@pytest.mark.parametrize("block", RUNS, ids=[b.where() for b in RUNS])
def test_block_runs(block, fixtures):
    code = block.code + "".join(b.code for b in block.continued)
    folder = scratch_for(fixtures)
    start = time.perf_counter()
    run = subprocess.run(command_for(block, code, fixtures), cwd=folder, env=fixtures["env"],
                         capture_output=True, text=True, timeout=TIMEOUT)
    took = time.perf_counter() - start
    output = run.stdout + run.stderr
    print("%s (%s, %.1f s): %s" % (block.where(), block.language, took,
                                    run.stdout.strip().replace("\n", " | ")[-160:]))
    assert run.returncode == 0, "%s exited with %d:\n%s\n%s" % (block.where(), run.returncode, code,
                                                              nvtesting.explain(run))
    assert "Traceback" not in output and "ERR|" not in output, "%s:\n%s" % (block.where(), output[-2000:])
    for name in written_files(code):
        path = os.path.join(folder, name)
        assert os.path.isfile(path) and os.path.getsize(path) > 0, "%s did not write %s" % (block.where(), name)
