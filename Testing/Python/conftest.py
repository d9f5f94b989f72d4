# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""The Python tests' harness: pytest, run by ctest one module at a time
(Testing/CMakeLists.txt), e.g. in build/:

    PYTHONPATH=lib/python3.11/dist-packages pvpython --force-offscreen-rendering \\
        -m pytest -v -r s -s ../Testing/Python/readers/test_las_reader.py

(`ctest -R '^LASReader$' -V` prints the command with the build's paths;
pvpython takes -rs for its own --rs, hence -r s.)

The tests are in folders by area: filter/ (the filter in Python: settings,
messages, robustness, the printed part), fidelity/ (the paper's tables and
figures, the scans), readers/ (the point cloud readers and files),
paraview/ (the plugin in pvpython, the GUI, MPI, the Python plugin; with
the scripts they run in child processes), package/ (the Python package,
the pip wheel in virtual environments) and docs/ (the README's and the
documentation's snippets). This folder holds what they share: this
harness, pytest.ini, nvtesting.py (the filter run once, child processes,
scratch folders) and nvpointfiles.py (LAS and PCD files written for the
readers); pytest puts it on sys.path (it is the rootdir). The clouds and
the surface measures, which the benchmarks and the doc pictures use too,
are in Data/ (nvclouds.py, nvshapes.py, nvmeasures.py), which this file
puts on sys.path.

Options (what ctest passes), each a fixture of the same name without the
dashes: --plugin (the ParaView plugin, NarrowVolume.so), --plugins-xml
(narrowvolume.plugins.xml), --trefoil (the demo cloud, default
Data/trefoil.vtp), --scans-dir (default ../shared/data/scans beside the
source tree, or $NV_SCANS_DIR), --with-xvfb, --source-dir. An area's own
options are in its conftest.py: --spacing and --steps (fidelity/),
--wheel-dir (paraview/), --readme (docs/).

Fixtures for the shared clouds (Data/nvclouds.py): `trefoil`, `scans_dir`,
`scan` and `scan_points` (a scan by name, the test skipped with a message
saying where they were looked for when ../shared is absent); `pvs`:
paraview.simple with the plugin loaded; `flavour`: the package's flavour
(narrowvolume.FLAVOUR, "vtk-module" for the CMake build's, "wheel" for
pip's), checked against $NV_EXPECT_FLAVOUR. Tests marked `pip` run with the
wheel only. Markers: pytest.ini.

ctest's skip: the run exits with 77 (SKIP_RETURN_CODE) when no test failed
and every test skipped, or, with --exit-77-on-skip, when any test skipped.
A failed test keeps the scratch folders of nvtesting.scratch_folder.
"""
import os
import sys

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
SKIP_RETURN_CODE = 77
# Data/: nvclouds, nvshapes, nvmeasures (ctest puts it on PYTHONPATH too, for
# the scripts that run outside pytest; the wheel's virtual environments do not).
DATA_DIR = os.path.normpath(os.path.join(HERE, "..", "..", "Data"))
if DATA_DIR not in sys.path:
    sys.path.insert(0, DATA_DIR)


def pytest_addoption(parser):
    group = parser.getgroup("narrowvolume", "NarrowVolume's tests (ctest passes these)")
    group.addoption("--plugin", help="the ParaView plugin, .../plugins/NarrowVolume/NarrowVolume.so")
    group.addoption("--plugins-xml", help="the plugins' XML for auto-loading, .../plugins/narrowvolume.plugins.xml")
    group.addoption("--trefoil", help="the demo cloud (default: Data/trefoil.vtp)")
    group.addoption("--scans-dir", help="the real scans (default: ../shared/data/scans beside the source tree, "
                                        "or $NV_SCANS_DIR)")
    group.addoption("--with-xvfb", help="scripts/with-xvfb.sh (default: the source tree's)")
    group.addoption("--source-dir", help="the source tree (default: the one holding this file)")
    group.addoption("--exit-77-on-skip", action="store_true",
                    help="exit with 77 (ctest's SKIP_RETURN_CODE) when a test skipped and none failed "
                         "(without it: when every test skipped)")


def _required(request, option, what):
    value = request.config.getoption(option)
    if not value:
        pytest.fail("%s needs %s %s (ctest passes it)" % (request.node.name, "--" + option.replace("_", "-"), what))
    return value


# --- Paths.

@pytest.fixture(scope="session")
def source_dir(request):
    return request.config.getoption("source_dir") or os.path.normpath(os.path.join(HERE, "..", ".."))


@pytest.fixture(scope="session")
def plugin_path(request):
    return _required(request, "plugin", "PATH/NarrowVolume.so")


@pytest.fixture(scope="session")
def plugins_xml(request):
    return _required(request, "plugins_xml", "PATH/narrowvolume.plugins.xml")


@pytest.fixture(scope="session")
def with_xvfb(request, source_dir):
    return request.config.getoption("with_xvfb") or os.path.join(source_dir, "scripts", "with-xvfb.sh")


# --- The shared clouds (Data/nvclouds.py).

@pytest.fixture(scope="session")
def trefoil(request):
    """The path of the demo cloud, Data/trefoil.vtp."""
    import nvclouds
    return request.config.getoption("trefoil") or nvclouds.data_file("trefoil.vtp")


@pytest.fixture(scope="session")
def scans_dir(request):
    import nvclouds
    return request.config.getoption("scans_dir") or nvclouds.SCANS_DIR


def _skip_without(scans_dir, names):
    import nvclouds
    if not nvclouds.have_scans(names, scans_dir):
        pytest.skip(str(nvclouds.ScansMissing(scans_dir)))


@pytest.fixture(scope="session")
def require_scans(scans_dir):
    """require_scans(*names): skips the test, with a message, unless every
    scan named (default: all of them) is in scans_dir."""
    import nvclouds

    def require(*names):
        _skip_without(scans_dir, names or nvclouds.SCANS)
    return require


@pytest.fixture(scope="session")
def scan(scans_dir):
    """scan(name): the scan as a vtkPolyData; skips the test without it."""
    import nvclouds

    def read(name):
        _skip_without(scans_dir, (name,))
        return nvclouds.scan(name, scans_dir)
    return read


@pytest.fixture(scope="session")
def scan_points(scans_dir):
    """scan_points(name): the scan's points, an (n, 3) float array; skips the test without it."""
    import nvclouds

    def read(name):
        _skip_without(scans_dir, (name,))
        return nvclouds.scan_points(name, scans_dir)
    return read


# --- ParaView and the package.

@pytest.fixture(scope="session")
def pvs(plugin_path):
    """paraview.simple with the plugin loaded (its proxies, e.g.
    pvs.NarrowVolumeReconstruction, added to the module)."""
    import paraview.simple
    paraview.simple.LoadPlugin(plugin_path)
    return paraview.simple


@pytest.fixture(scope="session")
def flavour():
    """narrowvolume.FLAVOUR: "vtk-module" (the CMake build's package, the C++
    filter) or "wheel" (pip's); $NV_EXPECT_FLAVOUR, when set, must match."""
    import narrowvolume
    expected = os.environ.get("NV_EXPECT_FLAVOUR")
    assert not expected or narrowvolume.FLAVOUR == expected, (
        "narrowvolume %s from %s, expected the %s flavour" % (narrowvolume.FLAVOUR, narrowvolume.__file__, expected))
    return narrowvolume.FLAVOUR


def pytest_report_header(config):
    try:
        import narrowvolume
        package = "narrowvolume %s from %s" % (narrowvolume.FLAVOUR, narrowvolume.__file__)
    except ImportError as error:
        package = "narrowvolume does not import: %s" % error
    import nvclouds
    folder = config.getoption("scans_dir") or nvclouds.SCANS_DIR
    return [package, "scans: %s (%s)" % (folder, "present" if nvclouds.have_scans(folder=folder) else "absent")]


def pytest_runtest_setup(item):
    if item.get_closest_marker("pip"):
        import narrowvolume
        if narrowvolume.FLAVOUR != "wheel":
            pytest.skip("the wheel's Python filter and binding only")


# --- Outcomes: scratch folders, and ctest's skip.

_outcomes = {}  # test id: "passed", "failed" or "skipped"


def pytest_runtest_logreport(report):
    if report.failed:
        import nvtesting
        nvtesting.keep_scratch()
        _outcomes[report.nodeid] = "failed"
    elif report.skipped and _outcomes.get(report.nodeid) != "failed":
        _outcomes[report.nodeid] = "skipped"
    elif report.when == "call":
        _outcomes.setdefault(report.nodeid, "passed")


def pytest_sessionfinish(session, exitstatus):
    outcomes = list(_outcomes.values())
    if exitstatus != 0 or "skipped" not in outcomes or "failed" in outcomes:
        return
    if "passed" not in outcomes or session.config.getoption("exit_77_on_skip"):
        print("\n%d of %d tests skipped: exit code %d (ctest: skipped)" % (
            outcomes.count("skipped"), len(outcomes), SKIP_RETURN_CODE))
        session.exitstatus = SKIP_RETURN_CODE
