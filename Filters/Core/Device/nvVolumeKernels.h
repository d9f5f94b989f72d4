// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The device back end's dense volume (the Volume output: phi on the grid's
// nodes, or a slab of node layers), one source for the host and the GPU, as
// nvDeviceKernels.h. The CPU core's VolumeWriter (Output/nvVolume.h) in
// three kernels, which call its node values (Output/nvVolumeTerms.h) and
// keep only which node they write, so that the host launcher fills the
// same values bit for bit (TestCoreDevice):
//
//   DenseClearKernel  a node: as if no point reached it, d truncated
//                     (eq. 6) and phi = phi0 = tanh(-inf) = -1 (eq. 2);
//   DenseBrickKernel  a node of a batch of bricks, from the distances the
//                     batch's DistanceKernel left on the device: d and
//                     phi = phi0 of eq. (2);
//   DenseBandKernel   a band brick: its band nodes' evolved phi (eq. 10-12)
//                     and the band flag.
//
// On the GPU the dense arrays stay on the device from the band's
// construction (step 5) to the evolution's end (step 6), and come back to
// the host once, filled; only the distances of each batch, not all of them,
// are ever on the device at once.
#ifndef nvVolumeKernels_h
#define nvVolumeKernels_h

#include "nvDeviceKernels.h"
#include "nvVolumeTerms.h"

#include <cstdint>

namespace nv
{
namespace device
{

/// The dense arrays: the Volume output's (nvVolumeTerms.h's VolumeArrays),
/// their precision and layout.
using DenseArrays = ::nv::VolumeArrays;

/// The grid, the slab and the scheme's constants, computed on the host.
struct DenseConstants
{
  std::int64_t GridDims[3] = { 0, 0, 0 };
  std::int64_t BrickDims[3] = { 0, 0, 0 };
  std::int64_t Begin = 0;    ///< the slab's first node layer
  std::int64_t End = 0;      ///< past its last one
  double Offset = 0.0;       ///< l
  double Xi = 0.0;           ///< xi of eq. (2)
  float Far = 0.0f;          ///< d beyond reach in the output: h sqrt(Nx^2 + Ny^2 + Nz^2)

  NV_HD std::int64_t Nodes() const { return (this->End - this->Begin) * this->GridDims[0] * this->GridDims[1]; }
};

/// Node t of the slab as if no point reached it (VolumeWriter::Clear).
struct DenseClearKernel
{
  DenseArrays A;
  DenseConstants C;
  NV_HD void operator()(std::int64_t t) const { ClearNode(A, t, C.Far); }
};

/// Node t of a batch of bricks (brick a = t / 512, node n = t % 512), from
/// the batch's distances (DistanceArrays' Bricks, Distance, Covered), as
/// VolumeWriter::WriteBrick: d and phi0 = tanh((l - d) / (sqrt(2) xi)) of
/// eq. (2), where d is within reach and the node in the grid and the slab.
struct DenseBrickKernel
{
  DistanceArrays D;
  DenseArrays A;
  DenseConstants C;
  NV_HD void operator()(std::int64_t t) const
  {
    const std::int64_t a = t >> 9;
    const int n = static_cast<int>(t & 511);
    if (D.Covered[a])
    {
      return; // its distances not computed (the dense volume asks for none covered)
    }
    const double d = D.Distance[t];
    if (!WithinReach(d))
    {
      return; // beyond reach: as cleared
    }
    std::int64_t brick = D.Bricks[a];
    const std::int64_t i = (brick % C.BrickDims[0]) * 8 + (n & 7);
    brick /= C.BrickDims[0];
    const std::int64_t j = (brick % C.BrickDims[1]) * 8 + ((n >> 3) & 7);
    const std::int64_t k = (brick / C.BrickDims[1]) * 8 + (n >> 6);
    if (i >= C.GridDims[0] || j >= C.GridDims[1] || k < C.Begin || k >= C.End)
    {
      return;
    }
    const std::int64_t node = i + C.GridDims[0] * (j + C.GridDims[1] * (k - C.Begin));
    WriteReachedNode(A, node, d, InitialPhi(d, C.Offset, C.Xi));
  }
};

/// The band's arrays that DenseBandKernel reads (nvNarrowBand.h's, unchanged).
struct DenseBandArrays
{
  const std::int64_t* Bricks = nullptr;
  const std::int64_t* RedStart = nullptr;
  const std::int64_t* BlackStart = nullptr;
  const std::uint16_t* Offset = nullptr;
  const double* Phi = nullptr; ///< the evolved phi (double, L + 2 values)
};

/// Band brick a's band nodes: phi and the band flag, as VolumeWriter::WriteBand.
struct DenseBandKernel
{
  DenseBandArrays B;
  DenseArrays A;
  DenseConstants C;
  NV_HD void Write(const std::int64_t first[3], std::int64_t s) const
  {
    const int offset = B.Offset[s];
    const std::int64_t i = first[0] + (offset & 7), j = first[1] + ((offset >> 3) & 7), k = first[2] + (offset >> 6);
    if (k < C.Begin || k >= C.End)
    {
      return;
    }
    WriteBandNode(A, i + C.GridDims[0] * (j + C.GridDims[1] * (k - C.Begin)), B.Phi[s]);
  }
  NV_HD void operator()(std::int64_t a) const
  {
    std::int64_t brick = B.Bricks[a];
    std::int64_t first[3];
    first[0] = (brick % C.BrickDims[0]) * 8;
    brick /= C.BrickDims[0];
    first[1] = (brick % C.BrickDims[1]) * 8;
    first[2] = (brick / C.BrickDims[1]) * 8;
    for (std::int64_t s = B.RedStart[a]; s < B.RedStart[a + 1]; ++s)
    {
      this->Write(first, s);
    }
    for (std::int64_t s = B.BlackStart[a]; s < B.BlackStart[a + 1]; ++s)
    {
      this->Write(first, s);
    }
  }
};

} // namespace device
} // namespace nv

#endif
