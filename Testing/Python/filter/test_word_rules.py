# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""The two word rules of the messages, fed the same texts (issue 49).

The core names the properties in its messages (OffsetDistance); two
functions rename them where each stands as a whole name: the core's
nv::InPanelWords (the panel's labels: the VTK filter and the wheel's filter
with PanelLabelsInMessages) and the package's _properties.in_words (the
command line's options, --offset-distance). Given the panel's labels,
in_words must give what InPanelWords gives, on every name beside every kind
of neighbour and on texts of names run together. InPanelWords runs in
PanelWords (Testing/Cxx/PanelWords.cxx), a program of the build.

    NV_PANEL_WORDS=.../bin/PanelWords pvpython -m pytest test_word_rules.py
"""
import os
import random
import subprocess

import pytest
from narrowvolume import _properties

NAMES = [p.name for p in _properties.PROPERTIES + _properties.LIST_PROPERTIES]
# What can stand beside a name: nothing, white space, punctuation, letters,
# digits and the underscore (parts of a longer word), a hyphen (an option's),
# and letters and signs beyond ASCII.
NEIGHBOURS = ["", " ", "\n", "(", ")", ".", ",", "-", "--", "_", "a", "Z", "0", "'", "/", "\u00e9", "\u00b7"]


def panel_words(texts):
    """nv::InPanelWords of each text, from PanelWords."""
    program = os.environ.get("NV_PANEL_WORDS")
    if not program:
        pytest.fail("NV_PANEL_WORDS names no PanelWords program (ctest sets it)")
    run = subprocess.run([program], input="\0".join(texts).encode("utf-8"), capture_output=True, timeout=120)
    assert run.returncode == 0, run.stderr
    return run.stdout.decode("utf-8").split("\0")


def label(name):
    return _properties.NAMED[name].label


def texts():
    """Every name beside every pair of neighbours, and 400 texts of names,
    their parts and neighbours run together (seeded)."""
    out = [before + name + after for name in NAMES for before in NEIGHBOURS for after in NEIGHBOURS]
    rng = random.Random(49)
    parts = NAMES + NEIGHBOURS + ["Offset", "Distance", "Gauss-Seidel", "Set ", " to 0.", "Sheets (", "Xi"]
    out += ["".join(rng.choice(parts) for _ in range(rng.randint(1, 12))) for _ in range(400)]
    return out


def test_in_words_gives_what_the_core_gives():
    given = texts()
    core = panel_words(given)
    assert len(core) == len(given)
    differ = [(text, ours, theirs) for text, theirs in zip(given, core)
              for ours in [_properties.in_words(text, label)] if ours != theirs]
    print("%d texts, %d differ" % (len(given), len(differ)))
    assert not differ, "in_words (first) and nv::InPanelWords (second) differ on %d of %d texts, e.g. %r" % (
        len(differ), len(given), differ[:4])


def test_the_command_line_names_its_options():
    assert _properties.in_words("Set OffsetDistance (0.5) or ClosingRadius.", _properties.option) == \
        "Set --offset-distance (0.5) or --closing-radius."
