// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// Writes the solution on the grid's nodes (dense arrays) for output and for
// isosurfacing, for the whole grid or for a slab of z layers. Band nodes take
// the evolved phi; every other node keeps its initial value phi0 of eq. (2),
// which the scheme never changes there.
#ifndef nvVolume_h
#define nvVolume_h

#include "nvParameters.h"

#include <cstdint>
#include <vector>

namespace nv
{
class Monitor;
struct NarrowBand;
class TruncatedDistance;

/// Dense arrays to fill, each of Nx Ny (kEnd - kBegin) values; null ones are skipped.
struct VolumeArrays
{
  float* Phi = nullptr;
  float* InitialPhi = nullptr;
  float* Distance = nullptr;     ///< eq. (6): beyond reach, h sqrt(Nx^2 + Ny^2 + Nz^2)
  unsigned char* Band = nullptr; ///< 1 on band nodes
};

/**
 * Fills the arrays for the nodes with kBegin <= k < kEnd (the whole grid by
 * default). phi: the solver's values at band nodes (at least band.Size()).
 * reachedBricks: distance.ReachedBricks(), passed in so that slab after slab
 * need not recompute it. monitor: progress, and a request to stop, after
 * which the arrays are left incomplete.
 */
void FillVolume(const TruncatedDistance& distance, const NarrowBand& band,
  const std::vector<double>& phi, const Parameters& parameters, const std::vector<std::int64_t>& reachedBricks,
  const VolumeArrays& arrays, std::int64_t kBegin = 0, std::int64_t kEnd = -1, Monitor* monitor = nullptr);

} // namespace nv

#endif
