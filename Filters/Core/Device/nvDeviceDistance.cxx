// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nvDeviceDistance.h"

#include <algorithm>

namespace nv
{
namespace device
{

DistanceConstants DistanceConstantsOf(const TruncatedDistance& distance, double coverRadius)
{
  return distance.GetConstants(coverRadius); // as ComputeBrick and BrickWithin
}

LauncherDistance::LauncherDistance(const TruncatedDistance& grid, const double* cloud, std::int64_t numberOfPoints,
  Launcher& launcher, std::int64_t batch)
  : Distance(grid)
  , Kernels(launcher)
  , Batch(std::max<std::int64_t>(1, batch))
{
  launcher.SortPoints(cloud, numberOfPoints, PointConstantsOf(grid.GetGrid(), grid.GetReach()), this->Reached);
}

LauncherDistance::~LauncherDistance()
{
  this->Kernels.FreePoints();
}

void LauncherDistance::Compute(
  const std::int64_t* bricks, std::int64_t count, double coverRadius, double* distance, std::uint8_t* covered)
{
  this->Kernels.DistanceBricks(
    bricks, count, DistanceConstantsOf(this->Distance, this->Dense ? 0.0 : coverRadius), distance, covered);
  if (this->Dense)
  {
    this->Kernels.DenseBricks(count);
  }
}

void LauncherDistance::CountNodes(const std::int64_t* bricks, std::int64_t count, double coverRadius, double lower,
  double upper, bool whole, std::int32_t* red, std::int32_t* black, std::uint64_t* inside)
{
  BandNodeConstants constants;
  constants.Grid = DistanceConstantsOf(this->Distance, this->Dense ? 0.0 : coverRadius);
  constants.Bounds.Lower = lower;
  constants.Bounds.Upper = upper;
  constants.Bounds.Whole = whole;
  this->Kernels.DistanceBricks(bricks, count, constants.Grid, nullptr, nullptr); // kept on the device
  if (this->Dense)
  {
    this->Kernels.DenseBricks(count); // phi0 and d of eq. (2), (6) into the dense arrays
  }
  this->Kernels.BandNodes(count, constants, red, black, inside);
}

void LauncherDistance::StoreNodes(std::int64_t redCount, std::int64_t size, std::uint16_t* offset)
{
  this->Kernels.StoreBand(redCount, size, offset);
}

void LauncherDistance::ConnectNeighbours(const NarrowBand& band, double offsetDistance)
{
  NeighbourConstants constants;
  for (int a = 0; a < 3; ++a)
  {
    constants.BrickDims[a] = this->Distance.GetBrickDims()[a];
  }
  constants.Offset = offsetDistance;
  this->Kernels.ConnectBand(band.Bricks.data(), band.RedStart.data(), band.BlackStart.data(),
    static_cast<std::int64_t>(band.Bricks.size()), constants);
}

void DownloadBand(BandLauncher& launcher, NarrowBand& band)
{
  band.Distance.resize(static_cast<std::size_t>(band.Size()));
  band.Neighbor.resize(static_cast<std::size_t>(6 * band.Size()));
  launcher.DownloadBand(band.Distance.data(), band.Neighbor.data());
}

} // namespace device
} // namespace nv
