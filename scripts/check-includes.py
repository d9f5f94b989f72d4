#!/usr/bin/env python3
# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""Checks that the core's includes only go down its layers.

Filters/Core has one folder per stage of the method, listed from the bottom
layer up in Filters/Core/CMakeLists.txt (narrowvolume_core_folders). A file
may include the headers of its own folder and of the folders listed before
its own, never of a later one: the run knows the scheme, the scheme does not
know the run. The CUDA sources (.cu, .cuh) are read as the C++ ones. The
core includes nothing of VTK (vtk*.h) either, but for the vtkSMPTools
backend of its loops (VTK_BACKEND): the VTK glue lives in Filters/. Prints
each offending include and exits 1 when there is one.

    scripts/check-includes.py [source folder]
"""
import os
import re
import sys

# The one core file that may use VTK: the loops on vtkSMPTools (nvParallel.h).
VTK_BACKEND = "Parallel/nvParallelVTK.cxx"
INCLUDE = re.compile(r'^\s*#\s*include\s+[<"]([^">]+)[">]')
HEADERS = (".h", ".cuh")
SOURCES = HEADERS + (".cxx", ".cu")


def core_folders(core):
    """The folders in their layer order, read from the core's CMakeLists.txt."""
    with open(os.path.join(core, "CMakeLists.txt"), encoding="utf-8") as cmake:
        match = re.search(r"set\(narrowvolume_core_folders([^)]*)\)", cmake.read())
    if not match:
        sys.exit("check-includes: no narrowvolume_core_folders in %s/CMakeLists.txt" % core)
    return match.group(1).split()


def main():
    source = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..")
    core = os.path.join(source, "Filters", "Core")
    folders = core_folders(core)
    layer_of = {}  # header name -> (layer, folder)
    files = []
    for layer, folder in enumerate(folders):
        for name in sorted(os.listdir(os.path.join(core, folder))):
            if name.endswith(SOURCES):
                files.append((layer, folder, name))
                if name.endswith(HEADERS):
                    layer_of[name] = (layer, folder)
    stray = [n for n in os.listdir(core) if n.endswith(SOURCES)]
    problems = ["Filters/Core/%s: outside the stage folders" % n for n in stray]
    for layer, folder, name in files:
        with open(os.path.join(core, folder, name), encoding="utf-8") as text:
            for number, line in enumerate(text, 1):
                match = INCLUDE.match(line)
                if not match:
                    continue
                header = os.path.basename(match.group(1))
                where = "Filters/Core/%s/%s:%d" % (folder, name, number)
                if header.startswith("vtk") and "%s/%s" % (folder, name) != VTK_BACKEND:
                    problems.append("%s: includes %s (the core knows nothing of VTK)" % (where, header))
                elif header in layer_of and layer_of[header][0] > layer:
                    problems.append("%s: %s (%s) includes %s of %s, a later layer" %
                                    (where, name, folder, header, layer_of[header][1]))
                elif header.startswith("nv") and header not in layer_of:
                    problems.append("%s: includes %s, which no stage folder holds" % (where, header))
    for problem in problems:
        print(problem)
    print("check-includes: %d files in %d layers (%s), %s" %
          (len(files), len(folders), " < ".join(folders),
           "%d FAILED" % len(problems) if problems else "every include goes down"))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
