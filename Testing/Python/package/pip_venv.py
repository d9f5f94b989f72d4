# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""The wheel as a user gets it: pip install . in a fresh virtual environment
with a vtk from PyPI, then the Python tests. Run by ctest (Testing/CMakeLists.txt):

    python3 pip_venv.py wheels CACHE REQUIREMENT...
        downloads what the environments need into the folder CACHE, once:
        later runs find everything there and download nothing;
    python3 pip_venv.py build SOURCE CACHE WORK
        builds the wheel of SOURCE (pip wheel, scikit-build-core) into WORK/dist;
    python3 pip_venv.py test NAME CACHE WORK REFERENCE REQUIREMENT...
        makes the environment WORK/NAME, installs the wheel and the
        requirements from the cache (no index), and runs test_python_api.py
        with pytest against the wheel (NV_PIP_REFERENCE=REFERENCE).

Every step prints its time. The Python is the one running this script
(ParaView's, /usr/bin/python3: vtk has wheels for it).
"""
import os
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
# What every environment needs besides vtk, and the wheel's build requirements.
COMMON = ["numpy", "pytest", "scikit-build-core>=0.10", "nanobind>=2.0"]


def step(title, command, **kwargs):
    """Runs a command, prints its time; exits with its status if it fails."""
    start = time.perf_counter()
    print("pip_venv: %s: %s" % (title, " ".join(command)), flush=True)
    result = subprocess.run(command, **kwargs)
    print("pip_venv: %s took %.1f s" % (title, time.perf_counter() - start), flush=True)
    if result.returncode != 0:
        print("pip_venv: FAILED: %s (exit code %d)" % (title, result.returncode), flush=True)
        sys.exit(1)
    return result


def venv(folder):
    """A fresh virtual environment; its Python."""
    if os.path.isdir(folder):
        start = time.perf_counter()
        shutil.rmtree(folder)
        print("pip_venv: removing the previous %s took %.1f s" % (os.path.basename(folder), time.perf_counter() - start),
              flush=True)
    step("venv " + os.path.basename(folder), [sys.executable, "-m", "venv", folder])
    return os.path.join(folder, "bin", "python")


def offline(cache):
    return ["--no-index", "--find-links", cache]


def wheels(cache, requirements):
    """Fills the cache: each requirement set is checked offline first and
    downloaded only when something is missing."""
    os.makedirs(cache, exist_ok=True)
    pip = [sys.executable, "-m", "pip", "--disable-pip-version-check"]
    for requirement in requirements or [""]:  # none: the build's tools alone
        wanted = COMMON + requirement.split()
        check = subprocess.run(pip + ["download", "-q", "-d", cache] + offline(cache) + wanted,
                               capture_output=True, text=True)
        if check.returncode == 0:
            print("pip_venv: in the cache already: %s" % " ".join(wanted), flush=True)
            continue
        step("download " + requirement, pip + ["download", "-q", "-d", cache] + wanted)
    # The build's own tools (scikit-build-core's, with the venv's newer pip).
    size = sum(os.path.getsize(os.path.join(cache, f)) for f in os.listdir(cache))
    print("pip_venv: the cache holds %d files, %.0f MB" % (len(os.listdir(cache)), size / 2 ** 20), flush=True)


def build(source, cache, work):
    """The wheel of the source tree, built without VTK, in WORK/dist."""
    python = venv(os.path.join(work, "build-env"))
    dist = os.path.join(work, "dist")
    if os.path.isdir(dist):
        shutil.rmtree(dist)
    step("pip wheel .", [python, "-m", "pip", "wheel", "--no-deps", "-w", dist] + offline(cache) + [source])
    print("pip_venv: built %s" % " ".join(os.listdir(dist)), flush=True)


def test(name, cache, work, reference, requirements):
    python = venv(os.path.join(work, name))
    dist = os.path.join(work, "dist")
    step("pip install", [python, "-m", "pip", "install", "-q"] + offline(cache) + ["--find-links", dist,
                                                                                  "narrowvolume", "pytest"]
         + requirements)
    # vtkmodules.vtkCommonCore, not vtk: importing vtk loads every VTK module (seconds).
    versions = subprocess.run([python, "-c", "from vtkmodules.vtkCommonCore import vtkVersion; import numpy, narrowvolume; "
                               "print('vtk', vtkVersion.GetVTKVersion(), 'numpy', numpy.__version__, "
                               "narrowvolume.FLAVOUR, narrowvolume.__file__)"],
                              capture_output=True, text=True)
    print("pip_venv: %s %s" % (name, versions.stdout.strip() or versions.stderr.strip()), flush=True)
    environment = dict(os.environ, NV_EXPECT_FLAVOUR="wheel", NV_PIP_REFERENCE=reference)
    for variable in ("PYTHONPATH", "NV_PYTHON", "PYTHONHOME"):
        environment.pop(variable, None)
    # From the environment's folder, so that the tree's Filters/Python is not on the path.
    step("pytest", [python, "-m", "pytest", "-p", "no:cacheprovider", "-rs", "-v", "--durations=8",
                    os.path.join(HERE, "test_python_api.py")], env=environment, cwd=os.path.join(work, name))


def main():
    command = sys.argv[1]
    if command == "wheels":
        wheels(sys.argv[2], sys.argv[3:])
    elif command == "build":
        build(*sys.argv[2:5])
    elif command == "test":
        test(sys.argv[2], sys.argv[3], sys.argv[4], sys.argv[5], sys.argv[6:])
    else:
        sys.exit(__doc__)
    print("pip_venv: passed", flush=True)


if __name__ == "__main__":
    main()
