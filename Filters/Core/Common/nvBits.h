// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// Bit counts over the 64-bit masks of a brick's nodes and edges, once for
// the CPU core and the device's kernels (NV_HD): the band's Inside bits
// (nvTruncatedDistance.h), the surface's cut edges and vertex ids
// (Output/nvSurfaceTerms.h).
#ifndef nvBits_h
#define nvBits_h

#include "nvHostDevice.h"

#include <cstdint>

namespace nv
{

/// Set bits of x. On the host the portable form (no popcnt instruction is
/// assumed), on the GPU its instruction: the same count.
NV_HD inline int Popcount(std::uint64_t x)
{
#if defined(__CUDA_ARCH__)
  return __popcll(x);
#else
  x = x - ((x >> 1) & 0x5555555555555555ULL);
  x = (x & 0x3333333333333333ULL) + ((x >> 2) & 0x3333333333333333ULL);
  x = (x + (x >> 4)) & 0x0F0F0F0F0F0F0F0FULL;
  return static_cast<int>((x * 0x0101010101010101ULL) >> 56);
#endif
}

} // namespace nv

#endif
