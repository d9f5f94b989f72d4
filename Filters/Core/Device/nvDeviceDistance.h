// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The device back end's truncated distance (eq. 6): the distances of the
// band's bricks computed by a launcher's kernels (DistanceKernel,
// CoveredKernel in nvDeviceKernels.h), on the GPU or through the host
// launcher, batch by batch, for the band's step 1 (BuildNarrowBand's
// BrickDistanceSource). They are TruncatedDistance::ComputeBrick's and
// BrickWithin's bit for bit through the host launcher (TestCoreDevice), and
// are written to be on the GPU too (not yet run there), so the band is the
// CPU's.
//
// The band's nodes of each batch are picked on the device too (CollectNodes):
// only they come back. The dense volume, when asked for, is filled from
// each batch's distances on the device too (FillDense, nvVolumeKernels.h). What stays on the
// host for now: the points' sort into bricks (TruncatedDistance's
// constructor), the bricks to visit (ReachedBricks), the band's arrays
// stored in order and its neighbours (nvNarrowBand.cxx, steps 2 and 3).
#ifndef nvDeviceDistance_h
#define nvDeviceDistance_h

#include "nvDeviceLauncher.h"
#include "nvNarrowBand.h"
#include "nvTruncatedDistance.h"

#include <cstdint>

namespace nv
{
namespace device
{

/// The constants of DistanceKernel and CoveredKernel, by the expressions
/// of ComputeBrick and BrickWithin(brick, coverRadius) (coverRadius 0: no
/// brick is tested).
DistanceConstants DistanceConstantsOf(const TruncatedDistance& distance, double coverRadius);

class LauncherDistance : public BrickDistanceSource
{
public:
  /// Bricks a batch by default: 16 MiB of distances (double, 512 a brick).
  static constexpr std::int64_t DefaultBatch = 4096;

  /// Hands the points of `distance` to `launcher` (UploadPoints); both must
  /// outlive this object, which lets the points go (FreePoints).
  LauncherDistance(const TruncatedDistance& distance, EvolutionLauncher& launcher, std::int64_t batch = DefaultBatch);
  ~LauncherDistance() override;
  LauncherDistance(const LauncherDistance&) = delete;
  LauncherDistance& operator=(const LauncherDistance&) = delete;

  /// After the launcher's DenseBegin: each batch's distances fill the dense
  /// arrays on the device too (DenseBricks), and no brick is skipped as
  /// covered (the dense arrays want every reached node's phi0, as the CPU's
  /// BrickVisitor does).
  void FillDense() { this->Dense = true; }

  std::int64_t BatchSize() const override { return this->Batch; }
  /// Throws DeviceError when the device fails.
  void Compute(const std::int64_t* bricks, std::int64_t count, double coverRadius, double* distance,
    std::uint8_t* covered) override;
  /// The band's nodes picked on the device too (BandCountKernel,
  /// BandCompactKernel): only they come back. Throws DeviceError.
  bool PicksNodes() const override { return true; }
  void CollectNodes(const std::int64_t* bricks, std::int64_t count, double coverRadius, double lower, double upper,
    bool whole, std::int32_t* red, std::int32_t* black, std::uint64_t* inside,
    UninitializedVector<std::uint16_t>& offset, UninitializedVector<double>& distance) override;

private:
  const TruncatedDistance& Distance;
  EvolutionLauncher& Launcher;
  std::int64_t Batch;
  bool Dense = false;
};

} // namespace device
} // namespace nv

#endif
