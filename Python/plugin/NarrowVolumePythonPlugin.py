# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""NarrowVolume as a ParaView Python plugin, for the ParaView people
already have (paraview.org's binaries, other distributions' builds).

Load this file: Tools > Manage Plugins > Load New in the GUI,
LoadPlugin("<this file>") in pvpython or pvbatch, or its folder in
PV_PLUGIN_PATH (ParaView 5.12 and later, or with a Python before 3.11). It gives the filter Narrow Volume Reconstruction (Filters >
Point Interpolation), the proxy of the compiled plugin with the same
properties, run by the numerical core of the pip package this file belongs
to, and the readers of the clouds ParaView lacks (LAS, LAZ, E57, PCD, .xyz
text: _readers.py), under the compiled plugin's names. `narrowvolume --paraview-plugin` prints its path.

The file makes its package importable itself (no PYTHONPATH to set): the
package is the folder above this file's, installed for ParaView's Python
(see the README, "ParaView from paraview.org").

ParaView 5.11 built with Python 3.11 (Debian 12's) cannot load any Python
plugin: its loader imports inspect.getargspec, which Python 3.11 removed,
before it reads the plugin. There, run
`import inspect; inspect.getargspec = inspect.getfullargspec` first (the
GUI's Python Shell, a script's first line), or run this file as a script,
`pvpython <this file>`: it mends that, then loads itself as the plugin.
"""
import os
import sys

paraview_plugin_name = "NarrowVolumePython"

# This file is narrowvolume/plugin/NarrowVolumePythonPlugin.py: alone in its
# folder, so that PV_PLUGIN_PATH can name that folder.
_PACKAGE_PARENT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def _mend_getargspec():
    """ParaView 5.11's paraview.detail.pythonalgorithm imports
    inspect.getargspec, gone in Python 3.11; getfullargspec's result has the
    .args it uses (ParaView 5.12 stopped using it)."""
    import inspect
    if not hasattr(inspect, "getargspec"):
        inspect.getargspec = inspect.getfullargspec


if __name__ == "__main__":
    # Run as a script (pvpython this file): load this
    # file as the plugin, after the mending it may need.
    _mend_getargspec()
    from paraview.simple import LoadPlugin
    LoadPlugin(os.path.abspath(__file__), ns=globals())
else:
    if _PACKAGE_PARENT not in sys.path:
        sys.path.insert(0, _PACKAGE_PARENT)
    from narrowvolume import __version__ as paraview_plugin_version  # noqa: F401 (the plugin manager shows it)
    from narrowvolume._paraview import NarrowVolumeReconstruction  # noqa: F401 (ParaView reads its proxy)
    from narrowvolume._readers import (E57PointCloudReader, LASPointCloudReader, LAZPointCloudReader,  # noqa: F401
                                       PCDPointCloudReader, PointCloudTextReader)
    from narrowvolume import _paraview_client
    _paraview_client.start()  # the panel's values of the last run, the camera on the shell
