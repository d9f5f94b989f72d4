// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// Small pieces removed from the surface (the rule is nvPieces.h's). Each
// connected part of the surface bounds a region whose signed volume (by the
// divergence theorem, normals pointing out of the shell) is positive for a
// piece of the shell and negative for a void; a piece smaller than a ball of
// radius 2 l and a void smaller than a ball of radius l are dropped.
#ifndef vtkNarrowVolumePieces_h
#define vtkNarrowVolumePieces_h

#include "nvPieces.h"

#include <array>
#include <vector>

class vtkPolyData;

namespace nv
{

/// A part that was dropped: one of its vertices, and whether it was a piece
/// (around phi > 0) or a void.
struct DroppedPart
{
  std::array<double, 3> Vertex;
  bool Piece;
};

/// Drops the small closed parts of a triangle surface, in place; `dropped`
/// (if not null) receives them, for FlipRegion.
RemovedPieces RemoveSmallSurfacePieces(vtkPolyData* surface, double offset, std::vector<DroppedPart>* dropped);

} // namespace nv

#endif
