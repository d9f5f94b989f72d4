# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""NarrowVolume: narrow volume (thick shell) reconstruction from point clouds.

    from narrowvolume import vtkNarrowVolumeReconstruction, reconstruct

vtkNarrowVolumeReconstruction is a VTK algorithm: set its input to any
vtkPointSet and read the phase field (output port 0, vtkImageData) and the
offset surfaces (output port 1, vtkPolyData). reconstruct(points, ...) does
the same in one call for an (n, 3) array, a vtkPointSet or a pyvista point
set. `python -m narrowvolume` (or the `narrowvolume` command) reconstructs a
cloud file.

The package comes in two flavours with the same API:
- built by CMake with the project (for ParaView's Python, pvpython): the
  C++ filter wrapped by VTK (FLAVOUR "vtk-module"), with
  vtkPointCloudTextReader for .xyz / .pts text clouds;
- installed by pip (`pip install .`): the same C++ core, built without VTK,
  driven by a Python filter that uses the VTK installed beside it
  (FLAVOUR "wheel"); vtkPointCloudTextReader is None there.
"""
import importlib.util
import sys

if importlib.util.find_spec(__name__ + ".NarrowVolumeFilters") is not None:
    from .NarrowVolumeFilters import vtkNarrowVolumeReconstruction, vtkPointCloudTextReader
    FLAVOUR = "vtk-module"
else:
    from ._filter import vtkNarrowVolumeReconstruction
    vtkPointCloudTextReader = None
    FLAVOUR = "wheel"

from ._reconstruct import ReconstructionError, ReconstructionWarning, reconstruct

__all__ = ["vtkNarrowVolumeReconstruction", "vtkPointCloudTextReader", "reconstruct", "ReconstructionError",
           "ReconstructionWarning", "FLAVOUR"]

# With pyvista already imported, point sets get cloud.narrowvolume.reconstruct()
# now (otherwise pyvista 0.48 and later load it through the wheel's entry point).
if "pyvista" in sys.modules:
    from . import _pyvista  # noqa: F401
