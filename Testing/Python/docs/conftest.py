# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""The documentation tests' own option: --readme, the README whose snippets
run (test_readme_snippets.py). The shared options and fixtures
(--source-dir, --plugin, --scans-dir, ...) are in ../conftest.py."""
import os

import pytest


def pytest_addoption(parser):
    group = parser.getgroup("narrowvolume-docs", "NarrowVolume's documentation tests")
    group.addoption("--readme", help="the README whose snippets run (default: the source tree's)")


@pytest.fixture(scope="session")
def readme(request, source_dir):
    return request.config.getoption("readme") or os.path.join(source_dir, "README.md")
