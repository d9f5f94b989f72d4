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

class HostLauncher : public EvolutionLauncher
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
    this->A.Phi = this->Phi.data();
    this->A.Previous = this->Previous.data();
    this->A.Coupling = this->Coupling.data();
    this->A.Decay = this->Decay.data();
  }
  void InitialField(const EvolutionConstants& constants) override
  {
    For(0, this->A.Size, InitialPhiKernel{ this->A, constants });
    this->A.Distance = nullptr; // the band's: its owner frees it
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
  }

  void UploadPoints(const double* points, std::int64_t, const std::int64_t* bucketStart, std::int64_t) override
  {
    this->D.Points = points; // read in place
    this->D.BucketStart = bucketStart;
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
    std::uint64_t* inside, UninitializedVector<std::uint16_t>& offset, UninitializedVector<double>& distance) override
  {
    BandNodeArrays arrays;
    arrays.Bricks = this->D.Bricks;
    arrays.Distance = this->D.Distance;
    arrays.Covered = this->D.Covered;
    arrays.RedCount = red;
    arrays.BlackCount = black;
    arrays.Inside = inside;
    For(0, count, BandCountKernel{ arrays, constants }, 8);
    std::vector<std::int64_t> first(static_cast<std::size_t>(count));
    std::int64_t total = 0;
    for (std::int64_t c = 0; c < count; ++c)
    {
      first[c] = total;
      total += red[c] + black[c];
    }
    offset.resize(static_cast<std::size_t>(total));
    distance.resize(static_cast<std::size_t>(total));
    arrays.First = first.data();
    arrays.NodeOffset = offset.data();
    arrays.NodeDistance = distance.data();
    For(0, count, BandCompactKernel{ arrays, constants }, 8);
  }
  void FreePoints() override
  {
    this->D = DistanceArrays();
    Free(this->BatchDistance);
    std::vector<std::uint8_t>().swap(this->BatchCovered);
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

std::unique_ptr<EvolutionLauncher> MakeHostLauncher()
{
  return std::unique_ptr<EvolutionLauncher>(new HostLauncher());
}

} // namespace device
} // namespace nv
