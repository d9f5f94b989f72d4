# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""One reconstruction through a wheel's compiled core alone, with nothing
but the standard library: for the wheels whose whole package cannot run
where they are tested (the aarch64 core under qemu-user, the Windows core
under wine, where numpy and vtk are not at hand). scripts/test-wheels.sh
runs it there and with the Linux x86_64 wheel, and compares the two.

    python core_probe.py PATH/TO/_core.<suffix>

Prints one JSON object: the Python, the band's nodes, the sweeps and their
last relative change, and the volume's field data (but the seconds) for a
sphere of 2,000 points.
"""
import importlib.util
import json
import math
import sys
import sysconfig
from array import array


def sphere(count):
    """Points on the unit sphere, a Fibonacci spiral: the same on every machine."""
    values = array("d")
    golden = math.pi * (3.0 - math.sqrt(5.0))
    for i in range(count):
        z = 1.0 - 2.0 * (i + 0.5) / count
        r = math.sqrt(1.0 - z * z)
        values.extend((r * math.cos(golden * i), r * math.sin(golden * i), z))
    return memoryview(values).cast("B").cast("d", [count, 3])


def main():
    spec = importlib.util.spec_from_file_location("_core", sys.argv[1])
    core = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(core)
    settings = core.Settings()
    settings.SampleSpacing = 0.04
    settings.NumberOfThreads = 1
    run = core.Reconstruction(settings)
    outcome = run.Reconstruct(sphere(2000), None, core.MeshSink())
    changes = run.RelativeChanges()
    print(json.dumps({
        # Not the platform module: Python 3.12's asks Windows' WMI, which wine 8 lacks.
        "python": "%s %s" % (sys.version.split()[0], sysconfig.get_platform()),
        "error": outcome.Error,
        "band nodes": run.NumberOfBandNodes(),
        "sweeps": len(changes),
        "last change": changes[-1] if changes else None,
        # Every field data array but the stages' seconds.
        "field data": {name: values for name, _, _, values, _ in outcome.Summary if "Seconds" not in name},
    }, sort_keys=True))


if __name__ == "__main__":
    main()
