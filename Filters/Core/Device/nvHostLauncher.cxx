// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The host launcher: the device back end's kernels (nvDeviceKernels.h) run
// over the core's threads (nvParallel.h), node by node as a GPU thread runs
// them. The reductions split the ranges as the CPU core's solver does
// (ParallelMax, ParallelSum), so phi is the CPU core's bit for bit.
#include "nvDeviceLauncher.h"

#include "nvMemory.h"
#include "nvParallel.h"

#include <algorithm>
#include <vector>

namespace nv
{
namespace device
{
EvolutionLauncher::~EvolutionLauncher() = default;
BandLauncher::~BandLauncher() = default;
SurfaceLauncher::~SurfaceLauncher() = default;
DenseLauncher::~DenseLauncher() = default;

void FirstNodes(const std::int32_t* red, const std::int32_t* black, std::int64_t count,
  std::vector<std::int64_t>& redFirst, std::vector<std::int64_t>& blackFirst)
{
  redFirst.resize(static_cast<std::size_t>(count + 1));
  blackFirst.resize(static_cast<std::size_t>(count + 1));
  redFirst[0] = 0;
  for (std::int64_t c = 0; c < count; ++c)
  {
    redFirst[c + 1] = redFirst[c] + red[c];
  }
  blackFirst[0] = redFirst[count];
  for (std::int64_t c = 0; c < count; ++c)
  {
    blackFirst[c + 1] = blackFirst[c] + black[c];
  }
}

namespace
{
constexpr std::int64_t Grain = 4096;

template <typename Kernel>
void For(std::int64_t begin, std::int64_t end, const Kernel& kernel, std::int64_t grain = Grain)
{
  ParallelFor(begin, end, grain, [&](std::int64_t first, std::int64_t last) {
    for (std::int64_t s = first; s < last; ++s)
    {
      kernel(s);
    }
  });
}

template <typename Kernel>
double Max(std::int64_t begin, std::int64_t end, const Kernel& kernel)
{
  return ParallelMax(end - begin, [&](std::int64_t first, std::int64_t last) {
    double result = 0.0;
    for (std::int64_t s = begin + first; s < begin + last; ++s)
    {
      result = std::max(result, kernel(s));
    }
    return result;
  });
}

template <typename Kernel>
double Sum(std::int64_t begin, std::int64_t end, const Kernel& kernel)
{
  return ParallelSum(end - begin, [&](std::int64_t first, std::int64_t last) {
    double result = 0.0;
    for (std::int64_t s = begin + first; s < begin + last; ++s)
    {
      result += kernel(s);
    }
    return result;
  });
}

class HostLauncher : public Launcher
{
public:
  std::string Name() const override { return "host launcher"; }

  void Upload(std::int64_t size, const std::uint32_t* neighbor, const double* distance, double inside,
    double outside) override
  {
    // Allocated unset, first written by the kernels' parallel loops, as the
    // CPU core's arrays.
    this->Phi.resize(static_cast<std::size_t>(size + 2));
    this->Previous.resize(static_cast<std::size_t>(size));
    this->Coupling.resize(static_cast<std::size_t>(size));
    this->Decay.resize(static_cast<std::size_t>(size));
    this->Phi[size] = inside;
    this->Phi[size + 1] = outside;
    this->A.Size = size;
    this->A.Neighbor = neighbor;
    this->A.Distance = distance;
    if (!neighbor && !distance && size > 0) // the band built here (StoreBand, ConnectBand)
    {
      if (this->Band.Size != size || !this->Band.Neighbor)
      {
        throw DeviceError("The host launcher holds no band of " + std::to_string(size) + " nodes to evolve.");
      }
      this->A.Neighbor = this->Band.Neighbor;
      this->A.Distance = this->Band.Distance;
      Free(this->BandOffset); // the host has its copy
    }
    this->A.Phi = this->Phi.data();
    this->A.Previous = this->Previous.data();
    this->A.Coupling = this->Coupling.data();
    this->A.Decay = this->Decay.data();
  }
  void InitialField(const EvolutionConstants& constants) override
  {
    For(0, this->A.Size, InitialPhiKernel{ this->A, constants });
    this->A.Distance = nullptr; // the band's: its owner frees it
    Free(this->BandDistance); // if the band was built here
    this->Band.Distance = nullptr;
  }
  void Coefficients(const EvolutionConstants& constants) override
  {
    For(0, this->A.Size, CoefficientsKernel{ this->A, constants });
  }
  void KeepPrevious() override { For(0, this->A.Size, KeepPreviousKernel{ this->A }); }
  double Relax(std::int64_t begin, std::int64_t end, double omega) override
  {
    return Max(begin, end, RelaxKernel{ this->A, omega });
  }
  void React() override { For(0, this->A.Size, ReactKernel{ this->A }); }
  double ChangeSquared(std::int64_t begin, std::int64_t end) override
  {
    return Sum(begin, end, ChangeSquaredKernel{ this->A });
  }
  double NormSquared(std::int64_t begin, std::int64_t end) override
  {
    return Sum(begin, end, NormSquaredKernel{ this->A });
  }
  void Download(UninitializedVector<double>& phi) override
  {
    phi.swap(this->Phi); // already in host memory
    this->A = EvolutionArrays();
    Free(this->BandNeighbor); // if the band was built here
    this->Band = NeighbourArrays();
  }

  void ReleaseEvolution() override
  {
    // phi went to the caller (Download); the host launcher reads it there.
    Free(this->Previous);
    Free(this->Coupling);
    Free(this->Decay);
  }
  void SortPoints(const double* cloud, std::int64_t numberOfPoints, const PointConstants& constants,
    std::vector<std::int64_t>& reached) override
  {
    // The CPU core's sort and list (nvPointSort.h), the same kernels.
    const std::int64_t bricks = constants.BrickDims[0] * constants.BrickDims[1] * constants.BrickDims[2];
    this->SortedPoints.resize(static_cast<std::size_t>(3 * numberOfPoints));
    this->Bucket.resize(static_cast<std::size_t>(bricks + 1));
    nv::SortPoints(cloud, numberOfPoints, constants, this->SortedPoints.data(), this->Bucket.data());
    reached = ListReachedBricks(this->SortedPoints.data(), numberOfPoints, constants);
    this->D.Points = this->SortedPoints.data();
    this->D.BucketStart = this->Bucket.data();
  }
  void DistanceBricks(const std::int64_t* bricks, std::int64_t count, const DistanceConstants& constants,
    double* distance, std::uint8_t* covered) override
  {
    if (!distance) // kept here for BandNodes
    {
      this->BatchDistance.resize(static_cast<std::size_t>(count * 512));
      distance = this->BatchDistance.data();
    }
    if (!covered)
    {
      this->BatchCovered.resize(static_cast<std::size_t>(count));
      covered = this->BatchCovered.data();
    }
    DistanceArrays& arrays = this->D;
    arrays.Bricks = bricks;
    arrays.Distance = distance;
    arrays.Covered = covered;
    For(0, count, CoveredKernel{ arrays, constants }, 8);
    // 8 bricks of nodes a task: the nodes of a brick read the same points.
    For(0, count * 512, DistanceKernel{ arrays, constants }, 8 * 512);
  }
  void BandNodes(std::int64_t count, const BandNodeConstants& constants, std::int32_t* red, std::int32_t* black,
    std::uint64_t* inside) override
  {
    BandNodeArrays arrays;
    arrays.Bricks = this->D.Bricks;
    arrays.Distance = this->D.Distance;
    arrays.Covered = this->D.Covered;
    arrays.RedCount = red;
    arrays.BlackCount = black;
    arrays.Inside = inside;
    For(0, count, BandCountKernel{ arrays, constants }, 8);
    std::vector<std::int64_t> redFirst, blackFirst;
    this->Batches.emplace_back();
    BatchNodes& batch = this->Batches.back();
    FirstNodes(red, black, count, redFirst, blackFirst);
    batch.Red = redFirst[count];
    batch.Offset.resize(static_cast<std::size_t>(blackFirst[count]));
    batch.Distance.resize(batch.Offset.size());
    arrays.RedFirst = redFirst.data();
    arrays.BlackFirst = blackFirst.data();
    arrays.NodeOffset = batch.Offset.data();
    arrays.NodeDistance = batch.Distance.data();
    For(0, count, BandCompactKernel{ arrays, constants }, 8);
  }
  void StoreBand(std::int64_t redCount, std::int64_t size, std::uint16_t* offset) override
  {
    this->BandOffset.resize(static_cast<std::size_t>(size));
    this->BandDistance.resize(static_cast<std::size_t>(size));
    // Each batch's red nodes after the batches' before it, its black ones
    // likewise after all the red ones.
    std::int64_t red = 0, black = redCount;
    for (BatchNodes& batch : this->Batches)
    {
      const std::int64_t blacks = static_cast<std::int64_t>(batch.Offset.size()) - batch.Red;
      std::copy(batch.Offset.begin(), batch.Offset.begin() + batch.Red, this->BandOffset.begin() + red);
      std::copy(batch.Offset.begin() + batch.Red, batch.Offset.end(), this->BandOffset.begin() + black);
      std::copy(batch.Distance.begin(), batch.Distance.begin() + batch.Red, this->BandDistance.begin() + red);
      std::copy(batch.Distance.begin() + batch.Red, batch.Distance.end(), this->BandDistance.begin() + black);
      red += batch.Red;
      black += blacks;
      Free(batch.Offset);
      Free(batch.Distance);
    }
    std::vector<BatchNodes>().swap(this->Batches);
    std::copy(this->BandOffset.begin(), this->BandOffset.end(), offset);
    this->Band = NeighbourArrays();
    this->Band.Size = size;
    this->Band.RedCount = redCount;
    this->Band.Offset = this->BandOffset.data();
    this->Band.Distance = this->BandDistance.data();
  }
  void ConnectBand(const std::int64_t* bricks, const std::int64_t* redStart, const std::int64_t* blackStart,
    std::int64_t numberOfBricks, const NeighbourConstants& constants) override
  {
    this->Adjacent.resize(static_cast<std::size_t>(6 * numberOfBricks));
    this->BandNeighbor.resize(static_cast<std::size_t>(6 * this->Band.Size));
    this->Band.NumberOfBricks = numberOfBricks;
    this->Band.Bricks = bricks; // the host's, read in place
    this->Band.RedStart = redStart;
    this->Band.BlackStart = blackStart;
    this->Band.Adjacent = this->Adjacent.data();
    this->Band.Neighbor = this->BandNeighbor.data();
    For(0, numberOfBricks, AdjacentBricksKernel{ this->Band, constants }, 64);
    For(0, this->Band.Size, NeighboursKernel{ this->Band, constants });
    std::vector<std::int32_t>().swap(this->Adjacent);
    this->Band.Bricks = this->Band.RedStart = this->Band.BlackStart = nullptr;
    this->Band.Adjacent = nullptr;
  }
  void DownloadBand(double* distance, std::uint32_t* neighbor) override
  {
    std::copy(this->BandDistance.begin(), this->BandDistance.end(), distance);
    std::copy(this->BandNeighbor.begin(), this->BandNeighbor.end(), neighbor);
  }
  void FreePoints() override
  {
    this->D = DistanceArrays();
    Free(this->SortedPoints);
    std::vector<std::int64_t>().swap(this->Bucket);
    Free(this->BatchDistance);
    std::vector<std::uint8_t>().swap(this->BatchCovered);
    std::vector<BatchNodes>().swap(this->Batches);
  }

  void CutBricks(const ContourArrays& band, const ContourConstants& constants, std::vector<std::int64_t>& cut) override
  {
    // The band's arrays read in place; a mark a grid brick, listed in order.
    PointArrays list;
    list.NumberOfBricks = constants.BrickDims[0] * constants.BrickDims[1] * constants.BrickDims[2];
    const std::int64_t chunks = (list.NumberOfBricks + ChunkBricks - 1) / ChunkBricks;
    std::vector<std::uint8_t> marks(static_cast<std::size_t>(list.NumberOfBricks), 0);
    std::vector<std::int64_t> sums(static_cast<std::size_t>(chunks)), first;
    list.Reached = marks.data();
    list.ChunkCount = sums.data();
    For(0, band.NumberOfBricks, CutMarkKernel{ band, constants, marks.data() }, 64);
    For(0, chunks, ChunkSumKernel<std::uint8_t>{ list, marks.data() }, 64);
    cut.resize(static_cast<std::size_t>(ChunkStarts(sums, first)));
    list.ChunkFirst = first.data();
    list.ReachList = cut.data();
    For(0, chunks, ReachListKernel{ list }, 64);
  }
  void ContourCounts(const ContourArrays& band, std::int64_t, const ContourConstants& constants,
    std::int32_t* vertices, std::int32_t* triangles) override
  {
    // The band's arrays read in place; 8 bricks a task, as the CPU core's surface.
    this->K = band;
    this->KC = constants;
    this->Psi.resize(static_cast<std::size_t>(512 * band.NumberOfBricks));
    this->Cut.resize(static_cast<std::size_t>(CutWords * band.NumberOfCutBricks));
    this->Above.resize(static_cast<std::size_t>(AboveRows * band.NumberOfCutBricks));
    this->K.Psi = this->Psi.data();
    this->K.Cut = this->Cut.data();
    this->K.Above = this->Above.data();
    this->K.VertexCount = vertices;
    this->K.TriangleCount = triangles;
    For(0, band.NumberOfBricks, PsiKernel{ this->K, this->KC }, 8);
    For(0, band.NumberOfCutBricks, CutCellsKernel{ this->K, this->KC }, 8);
  }
  void ContourGeometry(const std::int64_t* firstVertex, const std::int64_t* firstTriangle, std::int64_t,
    std::int64_t, double* points, float* normals, long long* triangles) override
  {
    this->K.FirstVertex = firstVertex;
    this->K.FirstTriangle = firstTriangle;
    this->K.Points = points; // the sink's arrays, written in place
    this->K.Normals = normals;
    this->K.Triangles = triangles;
    For(0, this->K.NumberOfCutBricks, VerticesKernel{ this->K, this->KC }, 8);
    For(0, this->K.NumberOfCutBricks, TrianglesKernel{ this->K, this->KC }, 8);
    this->K = ContourArrays();
    Free(this->Psi);
    Free(this->Cut);
    Free(this->Above);
  }

  void DenseBegin(const DenseArrays& arrays, const DenseConstants& constants) override
  {
    this->V = arrays; // the host's arrays, filled in place
    this->VC = constants;
    For(0, constants.Nodes(), DenseClearKernel{ arrays, constants }, 1 << 16);
  }
  void DenseBricks(std::int64_t count) override
  {
    For(0, count * 512, DenseBrickKernel{ this->D, this->V, this->VC }, 8 * 512);
  }
  void DenseBand(const DenseBandArrays& band, std::int64_t numberOfBricks, std::int64_t) override
  {
    For(0, numberOfBricks, DenseBandKernel{ band, this->V, this->VC }, 32);
  }
  void DenseDownload() override { this->V = DenseArrays(); } // already in host memory

private:
  /// One batch's band nodes (BandNodes), its Red red ones first.
  struct BatchNodes
  {
    std::int64_t Red = 0;
    UninitializedVector<std::uint16_t> Offset;
    UninitializedVector<double> Distance;
  };
  std::vector<BatchNodes> Batches;
  UninitializedVector<double> SortedPoints; ///< SortPoints', until FreePoints
  std::vector<std::int64_t> Bucket;
  NeighbourArrays Band; ///< the band built here, until the evolution
  UninitializedVector<std::uint16_t> BandOffset;
  UninitializedVector<double> BandDistance;
  UninitializedVector<std::uint32_t> BandNeighbor;
  std::vector<std::int32_t> Adjacent;
  DenseArrays V;
  DenseConstants VC;
  ContourArrays K;
  ContourConstants KC;
  UninitializedVector<float> Psi;
  UninitializedVector<std::uint64_t> Cut;
  UninitializedVector<std::uint16_t> Above;
  DistanceArrays D;
  UninitializedVector<double> BatchDistance;
  std::vector<std::uint8_t> BatchCovered;
  EvolutionArrays A;
  UninitializedVector<double> Phi;
  UninitializedVector<double> Previous;
  UninitializedVector<double> Coupling;
  UninitializedVector<float> Decay;
};
} // namespace

std::unique_ptr<Launcher> MakeHostLauncher()
{
  return std::unique_ptr<Launcher>(new HostLauncher());
}

} // namespace device
} // namespace nv
