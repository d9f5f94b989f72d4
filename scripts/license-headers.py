#!/usr/bin/env python3
# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""Checks that every source file git tracks opens with the project's
copyright and SPDX lines (as VTK's files do); with --add, adds them where
they are missing. Exit code 1 lists the files without them.

    scripts/license-headers.py [--add] [SOURCE_DIR]
"""
import os
import subprocess
import sys

COPYRIGHT = "SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers"
LICENSE = "SPDX-License-Identifier: BSD-3-Clause"
# How each kind of file writes a comment line.
COMMENTS = {".cxx": "// ", ".cpp": "// ", ".h": "// ", ".py": "# ", ".sh": "# ", ".txt": "# ",
            ".cmake": "# ", ".in": "# ", ".xml": None, ".toml": "# ", ".ini": "# "}


def comment_style(path):
    name = os.path.basename(path)
    if name in ("CMakeLists.txt", "run"):
        return "# "
    return COMMENTS.get(os.path.splitext(name)[1], False)


def header(style):
    if style is None:  # XML
        return "<!-- %s -->\n<!-- %s -->\n" % (COPYRIGHT, LICENSE)
    return "%s%s\n%s%s\n" % (style, COPYRIGHT, style, LICENSE)


def main():
    args = [a for a in sys.argv[1:] if a != "--add"]
    add = "--add" in sys.argv[1:]
    top = args[0] if args else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
    try:
        listing = subprocess.run(["git", "ls-files"], cwd=top, capture_output=True, text=True)
    except FileNotFoundError:
        print("license headers: skipped, git is not installed")
        return 77
    if listing.returncode != 0:
        print("license headers: skipped, %s is not a git checkout" % top)
        return 77
    files = listing.stdout.split()
    missing = []
    for relative in files:
        style = comment_style(relative)
        if style is False:
            continue  # data, pictures, prose
        path = os.path.join(top, relative)
        with open(path) as f:
            text = f.read()
        if LICENSE in text[:400]:
            continue
        missing.append(relative)
        if add:
            lines = text.splitlines(keepends=True)
            keep = 1 if lines and lines[0].startswith("#!") else 0
            with open(path, "w") as f:
                f.write("".join(lines[:keep]) + header(style) + "".join(lines[keep:]))
    if missing:
        print("%s the copyright and SPDX lines: %s" % ("added" if add else "missing in", " ".join(missing)))
    print("license headers: %d files checked, %d %s" % (len(files), len(missing), "fixed" if add else "missing"))
    return 1 if missing and not add else 0


if __name__ == "__main__":
    sys.exit(main())
