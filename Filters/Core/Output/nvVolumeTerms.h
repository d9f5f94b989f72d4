// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The dense volume's node values, written once for the CPU core's
// VolumeWriter (nvVolume.h) and the device's dense kernels
// (Device/nvVolumeKernels.h), which both call them (NV_HD, as
// Band/nvPointSort.h), so that the host launcher fills the same values bit
// for bit (TestCoreDevice). What stays with each caller is which node it
// writes: the CPU core a brick's nodes in a loop, a kernel one node.
//
//   a node beyond reach      d truncated (eq. 6), phi = phi0 = tanh(-inf) = -1
//                            (eq. 2), not in the band;
//   a node within reach      d, and phi = phi0 of eq. (2), rounded to float;
//   a band node              the evolved phi (eq. 10-12), rounded to float,
//                            and the band flag.
//
// phi0 itself is the scheme's (eq. 2), which each caller computes and
// passes. The CPU core clears the arrays with fills of these values (one
// memset-like pass per array), a kernel node by node (ClearNode).
#ifndef nvVolumeTerms_h
#define nvVolumeTerms_h

#include "nvHostDevice.h"

#include <cfloat>
#include <cmath>
#include <cstdint>

namespace nv
{

/**
 * Dense arrays to fill, each of Nx Ny (kEnd - kBegin) values, node (i, j,
 * k) at i + Nx (j + Ny (k - kBegin)); null ones are skipped. Float for phi,
 * phi0 and d (the output's types, and half the bytes of the grid), one byte
 * for the band flag; phi is rounded to float from the double the evolution
 * keeps.
 */
struct VolumeArrays
{
  float* Phi = nullptr;
  float* InitialPhi = nullptr;
  float* Distance = nullptr;     ///< eq. (6): beyond reach, h sqrt(Nx^2 + Ny^2 + Nz^2)
  unsigned char* Band = nullptr; ///< 1 on band nodes
};

/// phi and phi0 at a node beyond reach: tanh(-inf).
constexpr float PhiBeyondReach = -1.0f;

/// Node `node` as if no point reached it; far: the output's d there
/// (Grid::FarDistance).
NV_HD inline void ClearNode(const VolumeArrays& arrays, std::int64_t node, float far)
{
  if (arrays.Phi)
    arrays.Phi[node] = PhiBeyondReach;
  if (arrays.InitialPhi)
    arrays.InitialPhi[node] = PhiBeyondReach;
  if (arrays.Distance)
    arrays.Distance[node] = far;
  if (arrays.Band)
    arrays.Band[node] = 0;
}

/// Whether a truncated distance d (eq. 6) is within reach: finite, as
/// std::isfinite (beyond reach it is +inf).
NV_HD inline bool WithinReach(double d)
{
  return ::fabs(d) <= DBL_MAX;
}

/// Node `node` within reach, at distance d with phi0 of eq. (2) (before
/// the evolution, phi = phi0).
NV_HD inline void WriteReachedNode(const VolumeArrays& arrays, std::int64_t node, double d, double phi0)
{
  const float value = static_cast<float>(phi0);
  if (arrays.Phi)
    arrays.Phi[node] = value;
  if (arrays.InitialPhi)
    arrays.InitialPhi[node] = value;
  if (arrays.Distance)
    arrays.Distance[node] = static_cast<float>(d);
}

/// Band node `node` with its evolved phi.
NV_HD inline void WriteBandNode(const VolumeArrays& arrays, std::int64_t node, double phi)
{
  if (arrays.Phi)
    arrays.Phi[node] = static_cast<float>(phi);
  if (arrays.Band)
    arrays.Band[node] = 1;
}

} // namespace nv

#endif
