// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The split of the grid between processes for a distributed (MPI) run.
//
// The grid is cut along z into slabs of whole brick layers (8 node layers,
// see nvTruncatedDistance.h). Each process owns one slab: it updates the band
// nodes there and outputs that part of phi and of the surface. It also
// computes one brick layer on each side of its slab, the ghost layers, whose
// band values it receives from the neighbouring owners after every half sweep
// (nvHalo.h), so that its own nodes see exactly the neighbours a serial run
// would give them.
#ifndef nvPartition_h
#define nvPartition_h

#include <array>
#include <cstdint>
#include <vector>

namespace nv
{

/// Brick layers [Begin, End) along z.
struct LayerRange
{
  std::int64_t Begin = 0;
  std::int64_t End = 0;
  bool Empty() const { return this->End <= this->Begin; }
  bool Contains(std::int64_t layer) const { return this->Begin <= layer && layer < this->End; }
};

/// One process's part of the grid: the layers it owns and the layers it computes.
struct Subdomain
{
  LayerRange Owned;
  LayerRange Computed; ///< Owned plus one ghost layer on each side, within the grid

  /// The whole grid of `layers` brick layers, owned by one process.
  static Subdomain Whole(std::int64_t layers);
  /// Owned layers `owned` of a grid of `layers` brick layers, with their ghost layers.
  static Subdomain Around(LayerRange owned, std::int64_t layers);
};

/**
 * Splits the brick layers 0 .. weights.size() - 1 into `parts` consecutive
 * ranges of about equal total weight (weights >= 0, e.g. the number of points
 * per layer). Every range is non-empty when there are at least `parts`
 * layers; the later ranges are empty otherwise.
 */
std::vector<LayerRange> SplitLayers(const std::vector<double>& weights, int parts);

class Communicator;

/**
 * Every process gets the points (xyz triples) of all processes whose z lies
 * in its interval zRanges[rank] = {zmin, zmax} (zmin > zmax: none); returns
 * this process's. Collective.
 */
std::vector<double> ExchangePoints(
  Communicator& communicator, const std::vector<double>& xyz, const std::vector<std::array<double, 2>>& zRanges);

} // namespace nv

#endif
