// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// Small pieces of the shell: loose balls around lone points or small clumps
// of points (a point farther than 2 l from every other one gets a ball of its
// own, eq. 2), and tiny voids left inside a wall where the sampling is uneven.
// Neither is part of the narrow volume a user wants to print or measure, so by
// default both are removed:
//
// - a piece (a connected region of phi > 0) smaller than a ball of radius
//   2 l, that is, than about eight loose balls together, becomes outside;
// - a void (a connected region of phi < 0 that does not reach the grid's
//   boundary) smaller than a ball of radius l becomes inside.
//
// Larger regions stay: the shell itself, the cavity it encloses, and parts
// of the model that are separate but not small.
#ifndef nvPieces_h
#define nvPieces_h

#include "nvGrid.h"

#include <cstdint>

namespace nv
{

struct RemovedPieces
{
  std::int64_t Pieces = 0; ///< loose pieces made outside
  std::int64_t Voids = 0;  ///< tiny voids made inside
};

/// The volume below which a piece is removed: a ball of radius 2 l.
double SmallPieceVolume(double offset);
/// The volume below which a void is removed: a ball of radius l.
double SmallVoidVolume(double offset);

/**
 * Removes the small pieces and voids from phi on the dense grid (one value
 * per node, 6-connected regions), by flipping the sign of their nodes so that
 * no phi = 0 surface is left around them. Needs one byte per node beside phi.
 */
RemovedPieces RemoveSmallPieces(const Grid& grid, float* phi, double offset);

} // namespace nv

#endif
