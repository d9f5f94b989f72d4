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
- built by CMake with the project (for ParaView's Python, pvpython;
  FLAVOUR "vtk-module"): the C++ filter wrapped by VTK, and the readers
  (module NarrowVolume::Readers), which give vtkPolyData clouds with a vertex
  per point: vtkPointCloudTextReader reads .xyz / .pts text,
  vtkLASPointCloudReader LAS 1.0-1.4, vtkPCDPointCloudReader PCD (ascii,
  binary, binary_compressed); vtkPLYPointCloudReader reads PLY as
  vtkPLYReader does, once it has checked the file;
- installed by pip (`pip install .`; FLAVOUR "wheel"): the same C++ core,
  built without VTK, driven by a Python filter that uses the vtk installed
  beside it. The readers are None there.
"""
import importlib.util
import sys

if importlib.util.find_spec(__name__ + ".NarrowVolumeFilters") is not None:
    from .NarrowVolumeFilters import vtkNarrowVolumeReconstruction
    from .NarrowVolumeReaders import (vtkLASPointCloudReader, vtkPCDPointCloudReader, vtkPLYPointCloudReader,
                                      vtkPointCloudTextReader)
    FLAVOUR = "vtk-module"
else:
    from ._filter import vtkNarrowVolumeReconstruction
    vtkLASPointCloudReader = vtkPCDPointCloudReader = vtkPLYPointCloudReader = vtkPointCloudTextReader = None
    FLAVOUR = "wheel"

from ._reconstruct import ReconstructionError, ReconstructionWarning, reconstruct
from ._version import __version__

__all__ = ["vtkNarrowVolumeReconstruction", "vtkLASPointCloudReader", "vtkPCDPointCloudReader",
           "vtkPLYPointCloudReader", "vtkPointCloudTextReader", "reconstruct", "ReconstructionError", "ReconstructionWarning", "FLAVOUR", "__version__"]

# With pyvista already imported, point sets get cloud.narrowvolume.reconstruct()
# now (otherwise pyvista 0.48 and later load it through the wheel's entry point).
if "pyvista" in sys.modules:
    from . import _pyvista  # noqa: F401
