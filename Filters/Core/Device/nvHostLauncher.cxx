// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The host launcher: the device back end's kernels (nvDeviceKernels.h) run
// over the core's threads (nvParallel.h), node by node as a GPU thread runs
// them. The reductions split the ranges as the CPU core's solver does
// (ParallelMax, ParallelSum), so phi is the CPU core's bit for bit. Its
// arrays are DeviceBuffers in host memory, counted as the CUDA launcher's
// are on the GPU (nvDeviceMemory.h), so that a test can make an allocation
// fail (HostLauncherHooks) and check what is left held.
#include "nvDeviceLauncher.h"

#include "nvMemory.h"
#include "nvParallel.h"

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <cstring>
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

std::vector<SurfaceSlab> SurfaceSlabs(const std::int64_t* firstVertex, const std::int64_t* firstTriangle,
  std::int64_t count, std::int64_t numberOfVertices, std::int64_t numberOfTriangles, double maximumBytes)
{
  // Brick r's first vertex and triangle, the totals past the last one.
  const auto vertexAt = [&](std::int64_t r) { return r < count ? firstVertex[r] : numberOfVertices; };
  const auto triangleAt = [&](std::int64_t r) { return r < count ? firstTriangle[r] : numberOfTriangles; };
  const auto slabOf = [&](std::int64_t begin, std::int64_t end) {
    SurfaceSlab slab;
    slab.Begin = begin;
    slab.End = end;
    slab.FirstVertex = vertexAt(begin);
    slab.Vertices = vertexAt(end) - slab.FirstVertex;
    slab.FirstTriangle = triangleAt(begin);
    slab.Triangles = triangleAt(end) - slab.FirstTriangle;
    return slab;
  };
  std::vector<SurfaceSlab> slabs;
  std::int64_t first = 0;
  do
  {
    // The most bricks from `first` on that fit (at least one).
    std::int64_t low = std::min(first + 1, count), high = count;
    while (low < high)
    {
      const std::int64_t middle = low + (high - low + 1) / 2;
      if (slabOf(first, middle).Bytes() <= maximumBytes)
      {
        low = middle;
      }
      else
      {
        high = middle - 1;
      }
    }
    slabs.push_back(slabOf(first, low));
    first = low;
  } while (first < count);
  return slabs;
}

namespace
{
constexpr std::int64_t Grain = 4096;

/// The bytes the host launchers' arrays hold (HostLauncherBytes).
std::atomic<std::int64_t> Allocated{ 0 };

/// The host launcher's memory: malloc's, each block's size kept in 16 bytes
/// before it (so that the values stay 16-byte aligned) and counted in
/// Allocated, apart from the launcher's ledger.
struct HostMemory
{
  static constexpr std::size_t Header = 16;
  static void* Allocate(std::size_t bytes, const char* what)
  {
    unsigned char* block = static_cast<unsigned char*>(std::malloc(Header + bytes));
    if (!block)
    {
      throw DeviceError(std::string("The GPU failed (allocating ") + what + ", " +
        ByteWords(static_cast<double>(bytes)) + "): out of host memory");
    }
    std::memcpy(block, &bytes, sizeof(bytes));
    Allocated += static_cast<std::int64_t>(bytes);
    return block + Header;
  }
  static void Free(void* memory)
  {
    unsigned char* block = static_cast<unsigned char*>(memory) - Header;
    std::size_t bytes = 0;
    std::memcpy(&bytes, block, sizeof(bytes));
    Allocated -= static_cast<std::int64_t>(bytes);
    std::free(block);
  }
};

/// An array of the host launcher, counted in its ledger.
template <typename T>
using HostArray = DeviceBuffer<T, HostMemory>;

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
  explicit HostLauncher(const HostLauncherHooks& hooks)
    : Hooks(hooks)
  {
    if (hooks.AllocationLimit >= 0.0)
    {
      this->Ledger.SetLimit(hooks.AllocationLimit);
    }
  }

  std::string Name() const override { return "host launcher"; }
  double DeviceBytes() const override { return this->Ledger.Peak(); }
  double HeldBytes() const override { return this->Ledger.Held(); }
  double FreeBytes() const override
  {
    return this->Hooks.FreeBytes >= 0.0 ? this->Hooks.FreeBytes : HostAvailableBytes();
  }
  CopyCounts Copies() const override { return CopyCounts(); } // its arrays are the host's

  void Upload(std::int64_t size, const std::uint32_t* neighbor, const double* distance, double inside,
    double outside) override
  {
    // Allocated unset, first written by the kernels' parallel loops, as the
    // CPU core's arrays.
    // Phi only: the other arrays come once the distances are let go
    // (InitialField), 8 bytes a node less at the evolution's peak.
    this->Phi.Allocate(this->Ledger, size + 2, "phi");
    this->Phi.Data()[size] = inside;
    this->Phi.Data()[size + 1] = outside;
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
      this->BandOffset.Reset(); // the host has its copy
    }
    this->A.Phi = this->Phi.Data();
  }
  void InitialField(const EvolutionConstants& constants) override
  {
    For(0, this->A.Size, InitialPhiKernel{ this->A, constants });
    this->A.Distance = nullptr; // the band's: its owner frees it
    this->BandDistance.Reset(); // if the band was built here
    this->Band.Distance = nullptr;
    const std::int64_t size = this->A.Size;
    this->Previous.Allocate(this->Ledger, size, "phi^n");
    this->Coupling.Allocate(this->Ledger, size, "the coupling");
    this->Decay.Allocate(this->Ledger, size, "the decay");
    this->A.Previous = this->Previous.Data();
    this->A.Coupling = this->Coupling.Data();
    this->A.Decay = this->Decay.Data();
  }
  void Coefficients(const EvolutionConstants& constants) override
  {
    For(0, this->A.Size, CoefficientsKernel{ this->A, constants });
  }
  void KeepPrevious() override { For(0, this->A.Size, KeepPreviousKernel{ this->A }); }
  double Sweep(const std::int64_t red[2], const std::int64_t black[2], double omega) override
  {
    const double changeRed = Max(red[0], red[1], RelaxKernel{ this->A, omega });
    return std::max(changeRed, Max(black[0], black[1], RelaxKernel{ this->A, omega }));
  }
  void React() override { For(0, this->A.Size, ReactKernel{ this->A }); }
  void StepSums(const std::int64_t red[2], const std::int64_t black[2], double sums[4]) override
  {
    sums[0] = Sum(red[0], red[1], ChangeSquaredKernel{ this->A });
    sums[1] = Sum(black[0], black[1], ChangeSquaredKernel{ this->A });
    sums[2] = Sum(red[0], red[1], NormSquaredKernel{ this->A });
    sums[3] = Sum(black[0], black[1], NormSquaredKernel{ this->A });
  }
  void Download(UninitializedVector<double>& phi) override
  {
    const std::int64_t values = this->Phi.Size();
    phi.resize(static_cast<std::size_t>(values));
    const double* held = this->Phi.Data();
    double* out = phi.data();
    ParallelFor(0, values, 1 << 16, [&](std::int64_t begin, std::int64_t end) {
      std::copy(held + begin, held + end, out + begin);
    });
  }

  void ReleaseEvolution() override
  {
    // phi stays, as on the GPU: the dense volume, the surface and Download
    // read it here.
    this->Previous.Reset();
    this->Coupling.Reset();
    this->Decay.Reset();
    this->ReleaseBand(); // the band built here, evolved or not
    this->Band = NeighbourArrays();
    EvolutionArrays kept;
    kept.Size = this->A.Size;
    kept.Phi = this->Phi.Data();
    this->A = kept;
  }
  void SortPoints(const double* cloud, std::int64_t numberOfPoints, const PointConstants& constants,
    std::vector<std::int64_t>& reached) override
  {
    // The CPU core's sort and list (nvPointSort.h), the same kernels.
    const std::int64_t bricks = constants.BrickDims[0] * constants.BrickDims[1] * constants.BrickDims[2];
    this->SortedPoints.Allocate(this->Ledger, 3 * numberOfPoints, "the points");
    this->Bucket.Allocate(this->Ledger, bricks + 1, "the points' bricks");
    nv::SortPoints(cloud, numberOfPoints, constants, this->SortedPoints.Data(), this->Bucket.Data());
    reached = ListReachedBricks(this->SortedPoints.Data(), numberOfPoints, constants);
    this->D.Points = this->SortedPoints.Data();
    this->D.BucketStart = this->Bucket.Data();
  }
  void DistanceBricks(const std::int64_t* bricks, std::int64_t count, const DistanceConstants& constants,
    double* distance, std::uint8_t* covered) override
  {
    if (!distance) // kept here for BandNodes, from batch to batch
    {
      if (this->BatchDistance.Size() < count * 512)
      {
        this->BatchDistance.Allocate(this->Ledger, count * 512, "the distances of a batch");
      }
      distance = this->BatchDistance.Data();
    }
    if (!covered)
    {
      if (this->BatchCovered.Size() < count)
      {
        this->BatchCovered.Allocate(this->Ledger, count, "the covered bricks of a batch");
      }
      covered = this->BatchCovered.Data();
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
    FirstNodes(red, black, count, redFirst, blackFirst);
    BatchNodes batch; // kept until StoreBand; freed here if an allocation fails
    batch.Red = redFirst[count];
    batch.Offset.Allocate(this->Ledger, blackFirst[count], "the band nodes of a batch");
    batch.Distance.Allocate(this->Ledger, blackFirst[count], "the band nodes' distances");
    arrays.RedFirst = redFirst.data();
    arrays.BlackFirst = blackFirst.data();
    arrays.NodeOffset = batch.Offset.Data();
    arrays.NodeDistance = batch.Distance.Data();
    For(0, count, BandCompactKernel{ arrays, constants }, 8);
    this->Batches.push_back(std::move(batch));
  }
  void StoreBand(std::int64_t redCount, std::int64_t size, std::uint16_t* offset) override
  {
    this->ReleaseBand();
    this->BandOffset.Allocate(this->Ledger, size, "the band's node places");
    this->BandDistance.Allocate(this->Ledger, size, "the distances");
    // Each batch's red nodes after the batches' before it, its black ones
    // likewise after all the red ones.
    std::uint16_t* const bandOffset = this->BandOffset.Data();
    double* const bandDistance = this->BandDistance.Data();
    std::int64_t red = 0, black = redCount;
    for (BatchNodes& batch : this->Batches)
    {
      const std::int64_t nodes = batch.Offset.Size(), blacks = nodes - batch.Red;
      const std::uint16_t* const batchOffset = batch.Offset.Data();
      const double* const batchDistance = batch.Distance.Data();
      std::copy(batchOffset, batchOffset + batch.Red, bandOffset + red);
      std::copy(batchOffset + batch.Red, batchOffset + nodes, bandOffset + black);
      std::copy(batchDistance, batchDistance + batch.Red, bandDistance + red);
      std::copy(batchDistance + batch.Red, batchDistance + nodes, bandDistance + black);
      red += batch.Red;
      black += blacks;
      batch.Offset.Reset();
      batch.Distance.Reset();
    }
    std::vector<BatchNodes>().swap(this->Batches);
    std::copy(bandOffset, bandOffset + size, offset);
    this->Band = NeighbourArrays();
    this->Band.Size = size;
    this->Band.RedCount = redCount;
    this->Band.Offset = bandOffset;
    this->Band.Distance = bandDistance;
  }
  void ConnectBand(const std::int64_t* bricks, const std::int64_t* redStart, const std::int64_t* blackStart,
    std::int64_t numberOfBricks, const NeighbourConstants& constants) override
  {
    HostArray<std::int32_t> adjacent; // freed here, whatever happens
    adjacent.Allocate(this->Ledger, 6 * numberOfBricks, "the adjacent bricks");
    this->BandNeighbor.Allocate(this->Ledger, 6 * this->Band.Size, "the neighbour table");
    this->Band.NumberOfBricks = numberOfBricks;
    this->Band.Bricks = bricks; // the host's, read in place
    this->Band.RedStart = redStart;
    this->Band.BlackStart = blackStart;
    this->Band.Adjacent = adjacent.Data();
    this->Band.Neighbor = this->BandNeighbor.Data();
    For(0, numberOfBricks, AdjacentBricksKernel{ this->Band, constants }, 64);
    For(0, this->Band.Size, NeighboursKernel{ this->Band, constants });
    this->Band.Bricks = this->Band.RedStart = this->Band.BlackStart = nullptr;
    this->Band.Adjacent = nullptr;
  }
  void DownloadBand(double* distance, std::uint32_t* neighbor) override
  {
    std::copy(this->BandDistance.Data(), this->BandDistance.Data() + this->BandDistance.Size(), distance);
    std::copy(this->BandNeighbor.Data(), this->BandNeighbor.Data() + this->BandNeighbor.Size(), neighbor);
  }
  void FreePoints() override
  {
    this->D = DistanceArrays();
    this->SortedPoints.Reset();
    this->Bucket.Reset();
    this->BatchDistance.Reset();
    this->BatchCovered.Reset();
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
  void ContourCounts(const ContourArrays& band, std::int64_t numberOfNodes, const ContourConstants& constants,
    std::int32_t* vertices, std::int32_t* triangles) override
  {
    // The band's arrays read in place, phi where the evolution left it; 8
    // bricks a task, as the CPU core's surface.
    this->K = band;
    this->K.Phi = this->HeldPhi(band.Phi, numberOfNodes);
    this->KC = constants;
    this->Psi.Allocate(this->Ledger, 512 * band.NumberOfBricks, "psi");
    this->Cut.Allocate(this->Ledger, CutWords * band.NumberOfCutBricks, "the cut edges");
    this->Above.Allocate(this->Ledger, AboveRows * band.NumberOfCutBricks, "the corners' signs");
    this->K.Psi = this->Psi.Data();
    this->K.Cut = this->Cut.Data();
    this->K.Above = this->Above.Data();
    this->K.VertexCount = vertices;
    this->K.TriangleCount = triangles;
    For(0, band.NumberOfBricks, PsiKernel{ this->K, this->KC }, 8);
    For(0, band.NumberOfCutBricks, CutCellsKernel{ this->K, this->KC }, 8);
  }
  void ContourGeometry(const std::int64_t* firstVertex, const std::int64_t* firstTriangle,
    std::int64_t numberOfVertices, std::int64_t numberOfTriangles, double* points, float* normals,
    long long* triangles) override
  {
    this->K.FirstVertex = firstVertex;
    this->K.FirstTriangle = firstTriangle;
    // The sink's arrays, written in place; slab by slab where the hooks ask
    // (the CUDA launcher's slabs, each written from its own first vertex
    // and triangle on).
    const std::int64_t cut = this->K.NumberOfCutBricks;
    for (const SurfaceSlab& slab : SurfaceSlabs(firstVertex, firstTriangle, cut, numberOfVertices,
           numberOfTriangles, this->Hooks.SurfaceSlabBytes > 0.0 ? this->Hooks.SurfaceSlabBytes : 1e300))
    {
      this->K.PointsBase = slab.FirstVertex;
      this->K.TrianglesBase = slab.FirstTriangle;
      this->K.Points = points + 3 * slab.FirstVertex;
      this->K.Normals = normals + 3 * slab.FirstVertex;
      this->K.Triangles = triangles + 3 * slab.FirstTriangle;
      For(slab.Begin, slab.End, VerticesKernel{ this->K, this->KC }, 8);
      For(slab.Begin, slab.End, TrianglesKernel{ this->K, this->KC }, 8);
    }
    this->K = ContourArrays();
    this->Psi.Reset();
    this->Cut.Reset();
    this->Above.Reset();
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
  void DenseBand(const DenseBandArrays& band, std::int64_t numberOfBricks, std::int64_t numberOfNodes) override
  {
    DenseBandArrays arrays = band;
    arrays.Phi = this->HeldPhi(band.Phi, numberOfNodes);
    For(0, numberOfBricks, DenseBandKernel{ arrays, this->V, this->VC }, 32);
  }
  void DenseDownload() override { this->V = DenseArrays(); } // already in host memory

private:
  /// The evolution's phi where this launcher still holds it for a band of
  /// `nodes` nodes, else `given` (the caller's copy).
  const double* HeldPhi(const double* given, std::int64_t nodes) const
  {
    return this->Phi.Data() && this->A.Size == nodes ? this->Phi.Data() : given;
  }

  /// A band built before (StoreBand, ConnectBand), evolved or not.
  void ReleaseBand()
  {
    this->BandOffset.Reset();
    this->BandDistance.Reset();
    this->BandNeighbor.Reset();
    this->Band = NeighbourArrays();
  }

  HostLauncherHooks Hooks;
  /// Counts the arrays below; declared first, so that it outlives them.
  DeviceLedger Ledger;
  /// One batch's band nodes (BandNodes), its Red red ones first.
  struct BatchNodes
  {
    std::int64_t Red = 0;
    HostArray<std::uint16_t> Offset;
    HostArray<double> Distance;
  };
  std::vector<BatchNodes> Batches;
  HostArray<double> SortedPoints; ///< SortPoints', until FreePoints
  HostArray<std::int64_t> Bucket;
  NeighbourArrays Band; ///< the band built here, until the evolution
  HostArray<std::uint16_t> BandOffset;
  HostArray<double> BandDistance;
  HostArray<std::uint32_t> BandNeighbor;
  DenseArrays V;
  DenseConstants VC;
  ContourArrays K;
  ContourConstants KC;
  HostArray<float> Psi;
  HostArray<std::uint64_t> Cut;
  HostArray<std::uint16_t> Above;
  DistanceArrays D;
  HostArray<double> BatchDistance;
  HostArray<std::uint8_t> BatchCovered;
  EvolutionArrays A;
  HostArray<double> Phi;
  HostArray<double> Previous;
  HostArray<double> Coupling;
  HostArray<float> Decay;
};
} // namespace

double HostLauncherBytes()
{
  return static_cast<double>(Allocated.load());
}

std::unique_ptr<Launcher> MakeHostLauncher(const HostLauncherHooks& hooks)
{
  return std::unique_ptr<Launcher>(new HostLauncher(hooks));
}

} // namespace device
} // namespace nv
