# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""Sphinx configuration of NarrowVolume's documentation (scripts/docs.sh builds it)."""
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "_ext"))


def _version():
    with open(os.path.join(HERE, "..", "CMakeLists.txt"), encoding="utf-8") as cmake:
        return re.search(r"project\(NarrowVolume\s+VERSION\s+([0-9.]+)", cmake.read()).group(1)


project = "NarrowVolume"
author = "the NarrowVolume developers"
copyright = "2026, the NarrowVolume developers"
release = version = _version()

extensions = [
    "myst_parser",
    "sphinx.ext.autodoc",
    "nvdocs",  # _ext/nvdocs.py: the parameter reference from the property table, the C++ class from its header
    "sphinx.ext.mathjax",
    "sphinx-mathjax-offline",  # MathJax served from the site itself (_static/mathjax), not from a CDN
]
source_suffix = {".md": "markdown", ".rst": "restructuredtext"}
exclude_patterns = ["requirements.txt", "_ext", "images/README.md"]
myst_enable_extensions = ["dollarmath", "deflist"]
myst_heading_anchors = 3

# The Python API: the built package (scripts/docs.sh puts it on PYTHONPATH).
# pyvista is not part of Debian: the accessor's module imports it, so it is mocked.
autodoc_mock_imports = ["pyvista"]
autodoc_member_order = "bysource"
autodoc_typehints = "description"

# -n checks every reference. The C++ signatures name types of VTK and the
# standard library, which this site does not document: those alone may stay
# unresolved.
nitpick_ignore_regex = [
    ("cpp:identifier", r"vtk\w*|std|ostream|size_t|uint\w*|int\w*_t|nv"),
    ("py:class", r"vtkmodules\..*|vtk\w+|numpy\..*|pyvista\..*|Any|Callable|Optional|Tuple"),
]

html_theme = "furo"
html_title = "NarrowVolume %s" % release
html_static_path = []
# The equations ($...$, $$...$$) are typeset by the MathJax that
# sphinx-mathjax-offline copies into _static/mathjax: the pages read offline,
# and scripts/docs.sh checks that no page loads a script from elsewhere.
mathjax_path = "mathjax/tex-chtml.js"
