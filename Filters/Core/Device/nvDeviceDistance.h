// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The device back end's truncated distance (eq. 6): the distances of the
// band's bricks computed by a launcher's kernels (DistanceKernel,
// CoveredKernel in nvDeviceKernels.h), on the GPU or through the host
// launcher, batch by batch, for the band's collect pass (BuildNarrowBand's
// BrickDistanceSource). They are TruncatedDistance::ComputeBrick's and
// BrickWithin's bit for bit through the host launcher (TestCoreDevice), and
// are written to be on the GPU too, so the band is the CPU's.
//
// The band is built on the device too (BuildsBand: the collect, store and connect passes): each
// batch's band nodes are picked there and kept, only their counts and
// Inside bits come back; the store pass joins the batches there and sends Offset
// back (2 bytes a node), the connect pass makes the neighbour table there. The
// distances and the neighbour table stay on the device for the evolution
// (nvDeviceEvolution.h). The dense volume, when asked for, is filled from
// each batch's distances on the device too (FillDense, nvVolumeKernels.h).
// The points are sorted into bricks there too, and the bricks they reach
// listed (SortPoints): the cloud goes up as it is, the list comes back.
// What stays on the host: the store pass's tables from the counts (one sum over
// the band's bricks) and the sums over chunks of 256 bricks between the
// sort's passes.
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

/// The constants of DistanceKernel and CoveredKernel: those that
/// ComputeBrick and BrickWithin(brick, coverRadius) read
/// (TruncatedDistance::GetConstants, nvBandTerms.h's DistanceConstantsOf;
/// coverRadius 0: no brick is tested).
DistanceConstants DistanceConstantsOf(const TruncatedDistance& distance, double coverRadius);

class LauncherDistance : public BrickDistanceSource
{
public:
  /// Bricks a batch by default: 256 MiB of distances (double, 512 a
  /// brick), so that a 1024^3 grid's band is built in a few batches, each
  /// with its handful of launches and reads; fewer where the device has
  /// too little free memory (Run/nvDeviceEngine.cxx), down to MinimumBatch.
  static constexpr std::int64_t DefaultBatch = 65536;
  static constexpr std::int64_t MinimumBatch = 256;

  /// Sorts the points `cloud` (numberOfPoints xyz triples, world
  /// coordinates in the grid's box; host memory, read during this call
  /// only) into bricks on `launcher`'s device (SortPoints), with the bricks
  /// they reach: `grid` is a TruncatedDistance of the grid and the reach
  /// only, made without points. `grid` and `launcher` must outlive this
  /// object, which lets the points go (FreePoints).
  LauncherDistance(const TruncatedDistance& grid, const double* cloud, std::int64_t numberOfPoints,
    Launcher& launcher, std::int64_t batch = DefaultBatch);
  ~LauncherDistance() override;
  LauncherDistance(const LauncherDistance&) = delete;
  LauncherDistance& operator=(const LauncherDistance&) = delete;

  /// After the launcher's DenseBegin: each batch's distances fill the dense
  /// arrays on the device too (DenseBricks), and no brick is skipped as
  /// covered (the dense arrays want every reached node's phi0, as the CPU's
  /// BrickVisitor does).
  void FillDense() { this->Dense = true; }

  std::int64_t BatchSize() const override { return this->Batch; }
  /// The bricks the points reach, as this object sorted them.
  const std::vector<std::int64_t>* ReachedBricks() const override { return &this->Reached; }
  /// Throws DeviceError when the device fails.
  void Compute(const std::int64_t* bricks, std::int64_t count, double coverRadius, double* distance,
    std::uint8_t* covered) override;
  /// The collect, store and connect passes on the device (BandNodes, StoreBand, ConnectBand), the
  /// band held there for the launcher's evolution. Throw DeviceError.
  bool BuildsBand() const override { return true; }
  void CountNodes(const std::int64_t* bricks, std::int64_t count, double coverRadius, double lower, double upper,
    bool whole, std::int32_t* red, std::int32_t* black, std::uint64_t* inside) override;
  void StoreNodes(std::int64_t redCount, std::int64_t size, std::uint16_t* offset) override;
  void ConnectNeighbours(const NarrowBand& band, double offsetDistance) override;

private:
  const TruncatedDistance& Distance;
  Launcher& Kernels;
  std::int64_t Batch;
  bool Dense = false;
  std::vector<std::int64_t> Reached;
};

/// The distances and neighbour table of the band that `launcher` built
/// (BuildNarrowBand with a LauncherDistance) into `band`, as the CPU's band
/// holds them: for the checks against it. Throws DeviceError.
void DownloadBand(BandLauncher& launcher, NarrowBand& band);

} // namespace device
} // namespace nv

#endif
