// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// Small pieces removed from the surface itself, for runs without a dense
// volume (on the dense grid, nvPieces.h does it to phi). The rule is
// nvPieces.h's: each connected part of the surface bounds a region whose
// signed volume (by the divergence theorem, normals pointing out of the
// shell) is positive for a piece of the shell and negative for a void; a
// piece smaller than a ball of radius 2 l and a void smaller than a ball of
// radius l are dropped.
#ifndef vtkNarrowVolumePieces_h
#define vtkNarrowVolumePieces_h

#include "nvPieces.h"

class vtkPolyData;

namespace nv
{

/// Drops the small closed parts of a triangle surface, in place.
RemovedPieces RemoveSmallSurfacePieces(vtkPolyData* surface, double offset);

} // namespace nv

#endif
