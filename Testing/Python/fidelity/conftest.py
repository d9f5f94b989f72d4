# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""The fidelity tests' options (the paper's tables and figures, the scans);
the shared options and fixtures are in ../conftest.py."""


def pytest_addoption(parser):
    group = parser.getgroup("narrowvolume-fidelity", "NarrowVolume's fidelity tests")
    group.addoption("--spacing", type=float, action="append",
                    help="test_table1.py: a sample spacing h, repeatable (default: 0.01 and 0.005)")
    group.addoption("--steps", type=int, default=10, help="test_preserve_offset_scans.py: the steps (default 10)")
