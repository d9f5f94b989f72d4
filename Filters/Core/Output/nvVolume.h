// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// Writes the solution on the grid's nodes (dense arrays) for output, for the
// whole grid or for a slab of z layers. Band nodes take the evolved phi;
// every other node keeps its initial value phi0 of eq. (2), which the scheme
// never changes there.
//
// The distances are computed once per run, by the band's construction: the
// writer takes each brick's distances from there (WriteBrick), so it runs in
// three steps: every node as if no point reached it (Clear), the reached
// bricks during the band's construction, and the band's phi after the
// evolution (WriteBand).
//
// The node values are nvVolumeTerms.h's, which the device back end's dense
// kernels (Device/nvVolumeKernels.h, for Device GPU) call too;
// TestCoreDevice checks that they agree.
#ifndef nvVolume_h
#define nvVolume_h

#include "nvGrid.h"
#include "nvNarrowBand.h"
#include "nvParameters.h"
#include "nvTruncatedDistance.h"
#include "nvVolumeTerms.h"

#include <cstdint>
#include <vector>

namespace nv
{

class VolumeWriter
{
public:
  /// The arrays of the node layers [kBegin, kEnd).
  VolumeWriter(const Grid& grid, const Parameters& parameters, const VolumeArrays& arrays, std::int64_t kBegin,
    std::int64_t kEnd);

  /// Every node beyond reach: d truncated (eq. 6), phi0 = tanh(-inf) = -1. In parallel.
  void Clear() const;
  /// The nodes of one brick from their distances (eq. 2, 6); thread-safe for distinct bricks.
  void WriteBrick(std::int64_t brick, const double distance[BrickNodes]) const;
  /// The band nodes: the evolved phi. In parallel.
  void WriteBand(const NarrowBand& band, const BandValues& phi) const;

private:
  Grid TheGrid;
  Parameters Scheme;
  VolumeArrays Arrays;
  std::int64_t Begin, End;
};

} // namespace nv

#endif
