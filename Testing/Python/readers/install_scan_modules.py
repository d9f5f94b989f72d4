# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""The set-up of the ScanReaders and ReaderRoundTrip tests: installs laspy,
lazrs and pye57 for ParaView's Python with the very pip command the LAZ and
E57 readers give in their error when the modules are missing, with HOME set
to a folder of the build tree (so the --user install lands there, and the
tests find it by running with the same HOME). Nothing is installed when the
modules already import. If pip fails (no network), the tests that need the
modules skip and say why.

    pvpython install_scan_modules.py PLUGIN HOME
"""
import os
import shlex
import subprocess
import sys

plugin, home = sys.argv[1:3]
os.makedirs(home, exist_ok=True)

import paraview.simple as pvs  # noqa: E402

pvs.LoadPlugin(plugin, ns={})
import NarrowVolumeScanReaders as readers  # noqa: E402  (loaded by the plugin)

environment = dict(os.environ, HOME=home)
environment.pop("PYTHONPATH", None)
for requirements in (["laspy[lazrs]"], ["pye57"]):
    command = readers.install_command(*requirements)
    print("install_scan_modules: %s" % command)
    run = subprocess.run(shlex.split(command), env=environment, capture_output=True, text=True, timeout=600)
    last = (run.stdout.strip().splitlines() or [""])[-1]
    print("  exit %d: %s" % (run.returncode, last if run.returncode == 0 else run.stderr.strip()[-500:]))
probe = subprocess.run([os.path.join(sys.base_prefix, "bin", "python%d.%d" % sys.version_info[:2]), "-c",
                        "import laspy, lazrs, pye57; print(laspy.__version__, lazrs.__name__, pye57.__name__)"],
                       env=environment, capture_output=True, text=True)
print("install_scan_modules: laspy, lazrs and pye57 %s" % (
    "import: " + probe.stdout.strip() if probe.returncode == 0 else "do not import; the tests needing them skip"))
sys.exit(0)
