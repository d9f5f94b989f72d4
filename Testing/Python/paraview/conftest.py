# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""The ParaView tests' own option: --wheel-dir, the wheel PipWheel builds,
which test_python_plugin.py installs as ParaView's Python plugin. The shared
options and fixtures (--plugin, pvs, ...) are in ../conftest.py."""
import pytest


def pytest_addoption(parser):
    group = parser.getgroup("narrowvolume-paraview", "NarrowVolume's ParaView tests")
    group.addoption("--wheel-dir", help="where PipWheel put the wheel (test_python_plugin.py)")


@pytest.fixture(scope="session")
def wheel_dir(request):
    folder = request.config.getoption("wheel_dir")
    if not folder:
        pytest.fail("%s needs --wheel-dir, the folder of the wheel PipWheel builds (ctest passes it)"
                    % request.node.name)
    return folder
