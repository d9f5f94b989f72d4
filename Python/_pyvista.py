# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""cloud.narrowvolume.reconstruct(...) on pyvista point sets.

Through pyvista's dataset accessors (pyvista 0.48 and later): the wheel
declares this module under the entry point group "pyvista.accessors", so
pyvista imports it the first time `.narrowvolume` is used on a dataset, and
`import narrowvolume` registers it too when pyvista is already imported.
Earlier pyvista versions have no accessor mechanism; there, use
narrowvolume.reconstruct(mesh), which takes and returns pyvista objects.
"""
from __future__ import annotations

import pyvista
from typing import Any, Callable, Optional, Tuple

from vtkmodules.vtkCommonDataModel import vtkPointSet

from ._reconstruct import reconstruct as _reconstruct

NAMESPACE = "narrowvolume"


class NarrowVolumeAccessor:
    """NarrowVolume's methods on a pyvista point set: `cloud.narrowvolume.<method>(...)`."""

    def __init__(self, dataset: vtkPointSet):
        self._dataset = dataset

    def reconstruct(self, progress: Optional[Callable[[float], None]] = None,
                    **properties: Any) -> Tuple[Any, Any]:
        """The narrow volume around this point set's points: (volume, surface),
        pyvista.ImageData and pyvista.PolyData. The keyword arguments are
        those of narrowvolume.reconstruct (the filter's properties, and
        progress).

            volume, shell = cloud.narrowvolume.reconstruct(OffsetDistance=0.05)
        """
        return _reconstruct(self._dataset, progress=progress, **properties)


def register() -> bool:
    """Attaches the accessor to pyvista's point set classes; False when
    pyvista has no accessor mechanism (before 0.48)."""
    if not hasattr(pyvista, "register_dataset_accessor"):
        return False
    for name in ("PolyData", "PointSet", "UnstructuredGrid", "StructuredGrid", "ExplicitStructuredGrid"):
        target = getattr(pyvista, name, None)
        if isinstance(target, type) and issubclass(target, vtkPointSet):
            pyvista.register_dataset_accessor(NAMESPACE, target)(NarrowVolumeAccessor)
    return True


REGISTERED = register()
