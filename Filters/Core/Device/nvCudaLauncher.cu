// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The CUDA launcher: the kernels of nvDeviceKernels.h on the GPU. This file
// only allocates, copies and launches; what a node computes is in the
// kernels, which the host launcher runs too, and the loops around them are
// in nvDeviceEvolution.cxx (the evolution), nvDeviceDistance.cxx (the
// truncated distance and the band, batch by batch of bricks: only each
// batch's counts and Inside bits come back to the host, then the band's
// Offset; its distances and neighbour table stay here for the evolution)
// and nvDeviceSurface.cxx (the surface: the band's tables go up,
// phi is the evolution's, still here, the vertices and triangles come
// back).
//
// Compiled where CMake finds a CUDA compiler (NARROWVOLUME_CUDA): the suite
// compiles and links it on machines without a GPU (scripts/test.sh, nvcc
// from PyPI); scripts/test-gpu.sh runs it on a machine with a GPU (where it
// stands: doc/performance.md, "On a GPU").
//
// Reductions (the sweeps' max change, the stopping rule's norms): each block
// reduces its nodes in shared memory and writes one partial; the host adds
// the partials in block order. With the fixed launch shape below the result
// does not depend on scheduling (no atomics), so a run repeats bit for bit
// on the same GPU.
#include "nvDeviceLauncher.h"

#include <cuda_runtime.h>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

namespace nv
{
namespace device
{
namespace
{
constexpr int Threads = 256;      ///< threads a block
constexpr int MaximumBlocks = 4096; ///< blocks of a launch: grid-stride loops beyond

void Check(cudaError_t status, const char* what)
{
  if (status != cudaSuccess)
  {
    throw DeviceError(std::string("The GPU failed (") + what + "): " + cudaGetErrorString(status));
  }
}

int BlocksFor(std::int64_t n)
{
  return static_cast<int>(std::max<std::int64_t>(1, std::min<std::int64_t>(MaximumBlocks, (n + Threads - 1) / Threads)));
}

template <typename Kernel>
__global__ void ForEach(std::int64_t begin, std::int64_t end, Kernel kernel)
{
  const std::int64_t stride = static_cast<std::int64_t>(gridDim.x) * blockDim.x;
  for (std::int64_t s = begin + static_cast<std::int64_t>(blockIdx.x) * blockDim.x + threadIdx.x; s < end; s += stride)
  {
    kernel(s);
  }
}

/// partial[blockIdx.x] = the max (Max = true) or the sum of kernel(s) over this block's nodes.
template <bool Max, typename Kernel>
__global__ void Reduce(std::int64_t begin, std::int64_t end, Kernel kernel, double* partial)
{
  __shared__ double cache[Threads];
  const std::int64_t stride = static_cast<std::int64_t>(gridDim.x) * blockDim.x;
  double value = 0.0;
  for (std::int64_t s = begin + static_cast<std::int64_t>(blockIdx.x) * blockDim.x + threadIdx.x; s < end; s += stride)
  {
    const double v = kernel(s);
    value = Max ? fmax(value, v) : value + v;
  }
  cache[threadIdx.x] = value;
  __syncthreads();
  for (int width = Threads / 2; width > 0; width /= 2)
  {
    if (static_cast<int>(threadIdx.x) < width)
    {
      cache[threadIdx.x] = Max ? fmax(cache[threadIdx.x], cache[threadIdx.x + width])
                               : cache[threadIdx.x] + cache[threadIdx.x + width];
    }
    __syncthreads();
  }
  if (threadIdx.x == 0)
  {
    partial[blockIdx.x] = cache[0];
  }
}

template <typename T>
T* Allocate(std::int64_t count, double& bytes, double& peak, const char* what)
{
  void* memory = nullptr;
  const std::size_t size = static_cast<std::size_t>(std::max<std::int64_t>(count, 1)) * sizeof(T);
  Check(cudaMalloc(&memory, size), what);
  bytes += static_cast<double>(size);
  peak = std::max(peak, bytes);
  return static_cast<T*>(memory);
}

/// Frees what Allocate<T>(count) gave (null: nothing) and sets it null.
template <typename T>
void Release(T*& memory, std::int64_t count, double& bytes)
{
  if (memory)
  {
    cudaFree(memory);
    bytes -= static_cast<double>(static_cast<std::size_t>(std::max<std::int64_t>(count, 1)) * sizeof(T));
    memory = nullptr;
  }
}

class CudaLauncher : public Launcher
{
public:
  explicit CudaLauncher(int device)
  {
    Check(cudaSetDevice(device), "cudaSetDevice");
    cudaDeviceProp properties;
    Check(cudaGetDeviceProperties(&properties, device), "cudaGetDeviceProperties");
    this->DeviceName = properties.name;
    this->Partial = Allocate<double>(MaximumBlocks, this->Bytes, this->Peak, "the reductions' partials");
    this->HostPartial.resize(MaximumBlocks);
  }
  ~CudaLauncher() override
  {
    // Errors are ignored here: the destructor may run while a DeviceError unwinds.
    this->ReleaseContour();
    this->ReleaseDense();
    for (void* memory : { static_cast<void*>(this->Partial), static_cast<void*>(this->Neighbor),
           static_cast<void*>(this->Distance), static_cast<void*>(this->A.Phi), static_cast<void*>(this->A.Previous),
           static_cast<void*>(this->A.Coupling), static_cast<void*>(this->A.Decay), static_cast<void*>(this->Points),
           static_cast<void*>(this->BucketStart), static_cast<void*>(this->Bricks),
           static_cast<void*>(this->BrickDistance), static_cast<void*>(this->Covered),
           static_cast<void*>(this->RedCount), static_cast<void*>(this->BlackCount),
           static_cast<void*>(this->RedFirst), static_cast<void*>(this->BlackFirst),
           static_cast<void*>(this->Inside), static_cast<void*>(this->BandOffset) })
    {
      cudaFree(memory);
    }
    for (const BatchNodes& batch : this->Batches)
    {
      cudaFree(batch.Offset);
      cudaFree(batch.Distance);
    }
  }

  std::string Name() const override { return "CUDA (" + this->DeviceName + ")"; }
  double DeviceBytes() const override { return this->Peak; }

  void Upload(std::int64_t size, const std::uint32_t* neighbor, const double* distance, double inside,
    double outside) override
  {
    const bool held = !neighbor && !distance && size > 0; // the band built here (StoreBand, ConnectBand)
    if (held && (this->BandSize != size || !this->Neighbor || !this->Distance))
    {
      throw DeviceError("The GPU holds no band of " + std::to_string(size) + " nodes to evolve.");
    }
    if (held)
    {
      Release(this->BandOffset, size, this->Bytes); // the host has its copy
    }
    this->A.Size = size;
    if (!held)
    {
      this->Neighbor = Allocate<std::uint32_t>(6 * size, this->Bytes, this->Peak, "the neighbour table");
      this->Distance = Allocate<double>(size, this->Bytes, this->Peak, "the distances");
    }
    this->A.Phi = Allocate<double>(size + 2, this->Bytes, this->Peak, "phi");
    this->A.Previous = Allocate<double>(size, this->Bytes, this->Peak, "phi^n");
    this->A.Coupling = Allocate<double>(size, this->Bytes, this->Peak, "the coupling");
    this->A.Decay = Allocate<float>(size, this->Bytes, this->Peak, "the decay");
    this->A.Neighbor = this->Neighbor;
    this->A.Distance = this->Distance;
    if (!held)
    {
      Check(cudaMemcpy(this->Neighbor, neighbor, sizeof(std::uint32_t) * 6 * size, cudaMemcpyHostToDevice),
        "copying the neighbour table");
      Check(cudaMemcpy(this->Distance, distance, sizeof(double) * size, cudaMemcpyHostToDevice),
        "copying the distances");
    }
    const double slots[2] = { inside, outside };
    Check(cudaMemcpy(this->A.Phi + size, slots, sizeof(slots), cudaMemcpyHostToDevice), "copying eq. (5)'s values");
  }
  void InitialField(const EvolutionConstants& constants) override
  {
    this->For(0, this->A.Size, InitialPhiKernel{ this->A, constants });
    Check(cudaDeviceSynchronize(), "phi0");
    Check(cudaFree(this->Distance), "freeing the distances");
    this->Bytes -= static_cast<double>(sizeof(double) * std::max<std::int64_t>(this->A.Size, 1));
    this->Distance = nullptr;
    this->A.Distance = nullptr;
  }
  void Coefficients(const EvolutionConstants& constants) override
  {
    this->For(0, this->A.Size, CoefficientsKernel{ this->A, constants });
  }
  void KeepPrevious() override { this->For(0, this->A.Size, KeepPreviousKernel{ this->A }); }
  double Relax(std::int64_t begin, std::int64_t end, double omega) override
  {
    return this->Reduction<true>(begin, end, RelaxKernel{ this->A, omega });
  }
  void React() override { this->For(0, this->A.Size, ReactKernel{ this->A }); }
  double ChangeSquared(std::int64_t begin, std::int64_t end) override
  {
    return this->Reduction<false>(begin, end, ChangeSquaredKernel{ this->A });
  }
  double NormSquared(std::int64_t begin, std::int64_t end) override
  {
    return this->Reduction<false>(begin, end, NormSquaredKernel{ this->A });
  }
  void Download(UninitializedVector<double>& phi) override
  {
    phi.resize(static_cast<std::size_t>(this->A.Size + 2));
    Check(cudaMemcpy(phi.data(), this->A.Phi, sizeof(double) * (this->A.Size + 2), cudaMemcpyDeviceToHost),
      "copying phi back");
  }

  void ReleaseEvolution() override
  {
    const std::int64_t size = this->A.Size;
    Release(this->A.Previous, size, this->Bytes);
    Release(this->A.Coupling, size, this->Bytes);
    Release(this->A.Decay, size, this->Bytes);
    Release(this->Neighbor, 6 * size, this->Bytes);
    Release(this->Distance, size, this->Bytes);
    Release(this->BandOffset, this->BandSize, this->Bytes);
    this->A.Neighbor = nullptr;
    this->A.Distance = nullptr;
    this->BandSize = 0;
  }
  void SortPoints(const double* cloud, std::int64_t numberOfPoints, const PointConstants& constants,
    std::vector<std::int64_t>& reached) override
  {
    PointArrays a;
    a.NumberOfPoints = numberOfPoints;
    a.NumberOfBricks = constants.BrickDims[0] * constants.BrickDims[1] * constants.BrickDims[2];
    const std::int64_t chunks = (a.NumberOfBricks + ChunkBricks - 1) / ChunkBricks;
    this->NumberOfPoints = numberOfPoints;
    this->NumberOfBricks = a.NumberOfBricks;
    // Held until FreePoints: the sorted points and their buckets.
    this->Points = Allocate<double>(3 * numberOfPoints, this->Bytes, this->Peak, "the points");
    this->BucketStart = Allocate<std::int64_t>(a.NumberOfBricks + 1, this->Bytes, this->Peak, "the points' bricks");
    // Freed below, through ScratchMemory: the cloud, each point's brick,
    // the buckets' free slots, the marks of the reached bricks, the chunks.
    a.Cloud = this->ToDevice(cloud, 3 * numberOfPoints, "the cloud");
    a.BrickOf = this->Scratch<std::int64_t>(numberOfPoints, "each point's brick");
    a.Next = this->Scratch<std::int64_t>(a.NumberOfBricks, "the buckets' free slots");
    a.Reached = this->Scratch<std::uint8_t>(a.NumberOfBricks, "the reached bricks' marks");
    a.ChunkCount = this->Scratch<std::int64_t>(chunks, "the chunks' sums");
    std::int64_t* chunkFirst = this->Scratch<std::int64_t>(chunks, "the chunks' starts");
    a.ChunkFirst = chunkFirst;
    a.BucketStart = this->BucketStart;
    a.Points = this->Points;
    Check(cudaMemset(this->BucketStart, 0, sizeof(std::int64_t) * (a.NumberOfBricks + 1)), "clearing the counts");
    Check(cudaMemset(a.Reached, 0, static_cast<std::size_t>(a.NumberOfBricks)), "clearing the marks");
    std::vector<std::int64_t> sums(static_cast<std::size_t>(chunks)), firsts;
    // The counting sort: counts, their sums chunk by chunk, the points placed.
    this->For(0, numberOfPoints, BucketPointsKernel{ a, constants });
    this->For(0, chunks, ChunkSumKernel<std::int64_t>{ a, a.BucketStart + 1 });
    this->ChunkFirsts(a.ChunkCount, chunkFirst, sums, firsts);
    this->For(0, chunks, ChunkScanKernel{ a });
    this->For(0, numberOfPoints, ScatterPointsKernel{ a, constants });
    // The bricks reached, marked and listed in order.
    this->For(0, numberOfPoints, ReachKernel{ a, constants });
    this->For(0, chunks, ChunkSumKernel<std::uint8_t>{ a, a.Reached });
    const std::int64_t total = this->ChunkFirsts(a.ChunkCount, chunkFirst, sums, firsts);
    a.ReachList = this->Scratch<std::int64_t>(total, "the reached bricks");
    this->For(0, chunks, ReachListKernel{ a });
    reached.resize(static_cast<std::size_t>(total));
    if (total > 0)
    {
      Check(cudaMemcpy(reached.data(), a.ReachList, sizeof(std::int64_t) * total, cudaMemcpyDeviceToHost),
        "copying the reached bricks back");
    }
    this->ReleaseScratch(); // the arrays above but the sorted points and their buckets
  }
  void DistanceBricks(const std::int64_t* bricks, std::int64_t count, const DistanceConstants& constants,
    double* distance, std::uint8_t* covered) override
  {
    if (count <= 0)
    {
      return;
    }
    if (count > this->BatchCapacity) // the batch's buffers, kept from batch to batch
    {
      this->ReleaseBatch();
      this->Bricks = Allocate<std::int64_t>(count, this->Bytes, this->Peak, "the bricks of a batch");
      this->BrickDistance = Allocate<double>(count * 512, this->Bytes, this->Peak, "the distances of a batch");
      this->Covered = Allocate<std::uint8_t>(count, this->Bytes, this->Peak, "the covered bricks of a batch");
      this->BatchCapacity = count;
    }
    Check(cudaMemcpy(this->Bricks, bricks, sizeof(std::int64_t) * count, cudaMemcpyHostToDevice),
      "copying the bricks of a batch");
    DistanceArrays arrays;
    arrays.Points = this->Points;
    arrays.BucketStart = this->BucketStart;
    arrays.Bricks = this->Bricks;
    arrays.Distance = this->BrickDistance;
    arrays.Covered = this->Covered;
    this->For(0, count, CoveredKernel{ arrays, constants });
    // One thread a node: a block of 256 threads is half a brick.
    this->For(0, count * 512, DistanceKernel{ arrays, constants });
    if (covered)
    {
      Check(cudaMemcpy(covered, this->Covered, count, cudaMemcpyDeviceToHost), "copying the covered bricks back");
    }
    if (distance)
    {
      Check(cudaMemcpy(distance, this->BrickDistance, sizeof(double) * 512 * count, cudaMemcpyDeviceToHost),
        "copying the distances back");
    }
  }
  void BandNodes(std::int64_t count, const BandNodeConstants& constants, std::int32_t* red, std::int32_t* black,
    std::uint64_t* inside) override
  {
    if (count <= 0)
    {
      return;
    }
    if (count > this->NodeCapacity) // the counts' buffers, kept from batch to batch
    {
      this->ReleaseNodes();
      this->RedCount = Allocate<std::int32_t>(count, this->Bytes, this->Peak, "the red counts of a batch");
      this->BlackCount = Allocate<std::int32_t>(count, this->Bytes, this->Peak, "the black counts of a batch");
      this->RedFirst = Allocate<std::int64_t>(count, this->Bytes, this->Peak, "the red nodes' places in a batch");
      this->BlackFirst = Allocate<std::int64_t>(count, this->Bytes, this->Peak, "the black nodes' places in a batch");
      this->Inside = Allocate<std::uint64_t>(8 * count, this->Bytes, this->Peak, "the inside bits of a batch");
      this->NodeCapacity = count;
    }
    BandNodeArrays arrays;
    arrays.Bricks = this->Bricks;
    arrays.Distance = this->BrickDistance;
    arrays.Covered = this->Covered;
    arrays.RedCount = this->RedCount;
    arrays.BlackCount = this->BlackCount;
    arrays.RedFirst = this->RedFirst;
    arrays.BlackFirst = this->BlackFirst;
    arrays.Inside = this->Inside;
    this->For(0, count, BandCountKernel{ arrays, constants });
    Check(cudaMemcpy(red, this->RedCount, sizeof(std::int32_t) * count, cudaMemcpyDeviceToHost),
      "copying the red counts back");
    Check(cudaMemcpy(black, this->BlackCount, sizeof(std::int32_t) * count, cudaMemcpyDeviceToHost),
      "copying the black counts back");
    Check(cudaMemcpy(inside, this->Inside, sizeof(std::uint64_t) * 8 * count, cudaMemcpyDeviceToHost),
      "copying the inside bits back");
    std::vector<std::int64_t> redFirst, blackFirst;
    FirstNodes(red, black, count, redFirst, blackFirst);
    Check(cudaMemcpy(this->RedFirst, redFirst.data(), sizeof(std::int64_t) * count, cudaMemcpyHostToDevice),
      "copying the red nodes' places");
    Check(cudaMemcpy(this->BlackFirst, blackFirst.data(), sizeof(std::int64_t) * count, cudaMemcpyHostToDevice),
      "copying the black nodes' places");
    // The batch's list of band nodes, kept until StoreBand.
    BatchNodes batch;
    batch.Red = redFirst[count];
    batch.Size = blackFirst[count];
    batch.Offset = Allocate<std::uint16_t>(batch.Size, this->Bytes, this->Peak, "the band nodes of a batch");
    batch.Distance = Allocate<double>(batch.Size, this->Bytes, this->Peak, "the band nodes' distances");
    this->Batches.push_back(batch);
    arrays.NodeOffset = batch.Offset;
    arrays.NodeDistance = batch.Distance;
    this->For(0, count, BandCompactKernel{ arrays, constants });
  }
  void StoreBand(std::int64_t redCount, std::int64_t size, std::uint16_t* offset) override
  {
    this->ReleaseBand();
    this->BandSize = size;
    this->BandRedCount = redCount;
    this->BandOffset = Allocate<std::uint16_t>(size, this->Bytes, this->Peak, "the band's node places");
    this->Distance = Allocate<double>(size, this->Bytes, this->Peak, "the distances");
    // Each batch's red nodes after the batches' before it, its black ones
    // likewise after all the red ones: two copies a batch and array.
    std::int64_t red = 0, black = redCount;
    for (BatchNodes& batch : this->Batches)
    {
      const std::int64_t blacks = batch.Size - batch.Red;
      this->CopyOnDevice(this->BandOffset + red, batch.Offset, batch.Red);
      this->CopyOnDevice(this->BandOffset + black, batch.Offset + batch.Red, blacks);
      this->CopyOnDevice(this->Distance + red, batch.Distance, batch.Red);
      this->CopyOnDevice(this->Distance + black, batch.Distance + batch.Red, blacks);
      red += batch.Red;
      black += blacks;
    }
    this->ReleaseBatchNodes();
    if (size > 0)
    {
      Check(cudaMemcpy(offset, this->BandOffset, sizeof(std::uint16_t) * size, cudaMemcpyDeviceToHost),
        "copying the band's node places back");
    }
  }
  void ConnectBand(const std::int64_t* bricks, const std::int64_t* redStart, const std::int64_t* blackStart,
    std::int64_t numberOfBricks, const NeighbourConstants& constants) override
  {
    NeighbourArrays band;
    band.NumberOfBricks = numberOfBricks;
    band.RedCount = this->BandRedCount;
    band.Size = this->BandSize;
    band.Bricks = this->ToDevice(bricks, numberOfBricks, "the band's bricks");
    band.RedStart = this->ToDevice(redStart, numberOfBricks + 1, "the band's red starts");
    band.BlackStart = this->ToDevice(blackStart, numberOfBricks + 1, "the band's black starts");
    band.Offset = this->BandOffset;
    band.Distance = this->Distance;
    band.Adjacent = this->Scratch<std::int32_t>(6 * numberOfBricks, "the adjacent bricks");
    this->Neighbor = Allocate<std::uint32_t>(6 * this->BandSize, this->Bytes, this->Peak, "the neighbour table");
    band.Neighbor = this->Neighbor;
    this->For(0, numberOfBricks, AdjacentBricksKernel{ band, constants });
    this->For(0, this->BandSize, NeighboursKernel{ band, constants });
    Check(cudaDeviceSynchronize(), "the neighbour table");
    this->ReleaseScratch(); // the copies above
  }
  void DownloadBand(double* distance, std::uint32_t* neighbor) override
  {
    if (this->BandSize > 0)
    {
      Check(cudaMemcpy(distance, this->Distance, sizeof(double) * this->BandSize, cudaMemcpyDeviceToHost),
        "copying the band's distances back");
      Check(cudaMemcpy(neighbor, this->Neighbor, sizeof(std::uint32_t) * 6 * this->BandSize, cudaMemcpyDeviceToHost),
        "copying the neighbour table back");
    }
  }
  void FreePoints() override
  {
    Release(this->Points, 3 * this->NumberOfPoints, this->Bytes);
    Release(this->BucketStart, this->NumberOfBricks + 1, this->Bytes);
    this->ReleaseBatch();
    this->ReleaseNodes();
    this->ReleaseBatchNodes();
  }

  void CutBricks(const ContourArrays& band, const ContourConstants& constants, std::vector<std::int64_t>& cut) override
  {
    // Up: the band's bricks, their starts and inside bits; here: a mark a
    // grid brick and the chunks' sums; back: the chunks' sums and the list.
    // All freed below, through ScratchMemory (ContourCounts uploads the band again).
    ContourArrays k;
    const std::int64_t bricks = band.NumberOfBricks;
    k.NumberOfBricks = bricks;
    k.Bricks = this->ToDevice(band.Bricks, bricks, "the band's bricks, for the cut bricks");
    k.RedStart = this->ToDevice(band.RedStart, bricks + 1, "the band's red starts, for the cut bricks");
    k.BlackStart = this->ToDevice(band.BlackStart, bricks + 1, "the band's black starts, for the cut bricks");
    k.Inside = this->ToDevice(band.Inside, 8 * bricks, "the band's inside bits, for the cut bricks");
    PointArrays list;
    list.NumberOfBricks = constants.BrickDims[0] * constants.BrickDims[1] * constants.BrickDims[2];
    const std::int64_t chunks = (list.NumberOfBricks + ChunkBricks - 1) / ChunkBricks;
    list.Reached = this->Scratch<std::uint8_t>(list.NumberOfBricks, "the cut bricks' marks");
    list.ChunkCount = this->Scratch<std::int64_t>(chunks, "the cut bricks' chunk sums");
    std::int64_t* chunkFirst = this->Scratch<std::int64_t>(chunks, "the cut bricks' chunk starts");
    list.ChunkFirst = chunkFirst;
    Check(cudaMemset(list.Reached, 0, static_cast<std::size_t>(list.NumberOfBricks)), "clearing the cut bricks' marks");
    this->For(0, bricks, CutMarkKernel{ k, constants, list.Reached });
    this->For(0, chunks, ChunkSumKernel<std::uint8_t>{ list, list.Reached });
    std::vector<std::int64_t> sums(static_cast<std::size_t>(chunks)), firsts;
    const std::int64_t total = this->ChunkFirsts(list.ChunkCount, chunkFirst, sums, firsts);
    list.ReachList = this->Scratch<std::int64_t>(total, "the cut bricks");
    this->For(0, chunks, ReachListKernel{ list });
    cut.resize(static_cast<std::size_t>(total));
    if (total > 0)
    {
      Check(cudaMemcpy(cut.data(), list.ReachList, sizeof(std::int64_t) * total, cudaMemcpyDeviceToHost),
        "copying the cut bricks back");
    }
    this->ReleaseScratch();
  }
  void ContourCounts(const ContourArrays& band, std::int64_t numberOfNodes, const ContourConstants& constants,
    std::int32_t* vertices, std::int32_t* triangles) override
  {
    this->ReleaseContour();
    this->KC = constants;
    ContourArrays& k = this->K;
    k.NumberOfBricks = band.NumberOfBricks;
    k.NumberOfCutBricks = band.NumberOfCutBricks;
    this->ContourNodes = numberOfNodes;
    const std::int64_t bricks = band.NumberOfBricks, cut = band.NumberOfCutBricks;
    k.Bricks = this->ToDevice(band.Bricks, bricks, "the band's bricks");
    k.RedStart = this->ToDevice(band.RedStart, bricks + 1, "the band's red starts");
    k.BlackStart = this->ToDevice(band.BlackStart, bricks + 1, "the band's black starts");
    k.Inside = this->ToDevice(band.Inside, 8 * bricks, "the band's inside bits");
    k.Offset = this->ToDevice(band.Offset, numberOfNodes, "the band's node places");
    // The evolution's phi, still here (ReleaseEvolution kept it), or a copy.
    const bool held = this->A.Phi && this->A.Size == numberOfNodes;
    k.Phi = held ? this->A.Phi : this->ToDevice(band.Phi, numberOfNodes, "phi for the surface");
    k.CutBricks = this->ToDevice(band.CutBricks, cut, "the cut bricks");
    k.Cases = this->ToDevice(band.Cases, 1, "the case table");
    k.Psi = Allocate<float>(512 * bricks, this->Bytes, this->Peak, "psi");
    k.Cut = Allocate<std::uint64_t>(CutWords * cut, this->Bytes, this->Peak, "the cut edges");
    k.Above = Allocate<std::uint16_t>(AboveRows * cut, this->Bytes, this->Peak, "the corners' signs");
    k.VertexCount = Allocate<std::int32_t>(cut, this->Bytes, this->Peak, "the vertex counts");
    k.TriangleCount = Allocate<std::int32_t>(cut, this->Bytes, this->Peak, "the triangle counts");
    this->For(0, bricks, PsiKernel{ k, constants });
    this->For(0, cut, CutCellsKernel{ k, constants });
    if (cut > 0)
    {
      Check(cudaMemcpy(vertices, k.VertexCount, sizeof(std::int32_t) * cut, cudaMemcpyDeviceToHost),
        "copying the vertex counts back");
      Check(cudaMemcpy(triangles, k.TriangleCount, sizeof(std::int32_t) * cut, cudaMemcpyDeviceToHost),
        "copying the triangle counts back");
    }
  }
  void ContourGeometry(const std::int64_t* firstVertex, const std::int64_t* firstTriangle,
    std::int64_t numberOfVertices, std::int64_t numberOfTriangles, double* points, float* normals,
    long long* triangles) override
  {
    ContourArrays& k = this->K;
    const std::int64_t cut = k.NumberOfCutBricks;
    this->NumberOfVertices = numberOfVertices;
    this->NumberOfTriangles = numberOfTriangles;
    k.FirstVertex = this->ToDevice(firstVertex, cut, "the first vertices");
    k.FirstTriangle = this->ToDevice(firstTriangle, cut, "the first triangles");
    k.Points = Allocate<double>(3 * numberOfVertices, this->Bytes, this->Peak, "the vertices");
    k.Normals = Allocate<float>(3 * numberOfVertices, this->Bytes, this->Peak, "the normals");
    k.Triangles = Allocate<long long>(3 * numberOfTriangles, this->Bytes, this->Peak, "the triangles");
    this->For(0, cut, VerticesKernel{ k, this->KC });
    this->For(0, cut, TrianglesKernel{ k, this->KC });
    if (numberOfVertices > 0)
    {
      Check(cudaMemcpy(points, k.Points, sizeof(double) * 3 * numberOfVertices, cudaMemcpyDeviceToHost),
        "copying the vertices back");
      Check(cudaMemcpy(normals, k.Normals, sizeof(float) * 3 * numberOfVertices, cudaMemcpyDeviceToHost),
        "copying the normals back");
    }
    if (numberOfTriangles > 0)
    {
      Check(cudaMemcpy(triangles, k.Triangles, sizeof(long long) * 3 * numberOfTriangles, cudaMemcpyDeviceToHost),
        "copying the triangles back");
    }
    this->ReleaseContour();
  }

  void DenseBegin(const DenseArrays& arrays, const DenseConstants& constants) override
  {
    this->ReleaseDense();
    this->HostDense = arrays;
    this->VC = constants;
    const std::int64_t nodes = constants.Nodes();
    if (arrays.Phi)
      this->V.Phi = Allocate<float>(nodes, this->Bytes, this->Peak, "the dense phi");
    if (arrays.InitialPhi)
      this->V.InitialPhi = Allocate<float>(nodes, this->Bytes, this->Peak, "the dense phi0");
    if (arrays.Distance)
      this->V.Distance = Allocate<float>(nodes, this->Bytes, this->Peak, "the dense distances");
    if (arrays.Band)
      this->V.Band = Allocate<std::uint8_t>(nodes, this->Bytes, this->Peak, "the dense band flags");
    this->For(0, nodes, DenseClearKernel{ this->V, constants });
  }
  void DenseBricks(std::int64_t count) override
  {
    DistanceArrays batch;
    batch.Bricks = this->Bricks;
    batch.Distance = this->BrickDistance;
    batch.Covered = this->Covered;
    this->For(0, count * 512, DenseBrickKernel{ batch, this->V, this->VC });
  }
  void DenseBand(const DenseBandArrays& band, std::int64_t numberOfBricks, std::int64_t numberOfNodes) override
  {
    DenseBandArrays onDevice;
    onDevice.Bricks = this->ToDevice(band.Bricks, numberOfBricks, "the band's bricks");
    onDevice.RedStart = this->ToDevice(band.RedStart, numberOfBricks + 1, "the band's red starts");
    onDevice.BlackStart = this->ToDevice(band.BlackStart, numberOfBricks + 1, "the band's black starts");
    onDevice.Offset = this->ToDevice(band.Offset, numberOfNodes, "the band's node places");
    // The evolution's phi, still here (Download copied it, kept it).
    onDevice.Phi = this->A.Phi && this->A.Size == numberOfNodes ? this->A.Phi
                                                                : this->ToDevice(band.Phi, numberOfNodes, "phi");
    this->For(0, numberOfBricks, DenseBandKernel{ onDevice, this->V, this->VC });
    Check(cudaDeviceSynchronize(), "the dense volume's band");
    this->ReleaseScratch(); // the band's copies
  }
  void DenseDownload() override
  {
    const std::int64_t nodes = this->VC.Nodes();
    const std::size_t floats = sizeof(float) * static_cast<std::size_t>(nodes);
    if (this->V.Phi)
      Check(cudaMemcpy(this->HostDense.Phi, this->V.Phi, floats, cudaMemcpyDeviceToHost), "copying the dense phi back");
    if (this->V.InitialPhi)
      Check(cudaMemcpy(this->HostDense.InitialPhi, this->V.InitialPhi, floats, cudaMemcpyDeviceToHost),
        "copying the dense phi0 back");
    if (this->V.Distance)
      Check(cudaMemcpy(this->HostDense.Distance, this->V.Distance, floats, cudaMemcpyDeviceToHost),
        "copying the dense distances back");
    if (this->V.Band)
      Check(cudaMemcpy(this->HostDense.Band, this->V.Band, static_cast<std::size_t>(nodes), cudaMemcpyDeviceToHost),
        "copying the dense band flags back");
    this->ReleaseDense();
  }

private:
  void ReleaseDense()
  {
    const std::int64_t nodes = this->VC.Nodes();
    Release(this->V.Phi, nodes, this->Bytes);
    Release(this->V.InitialPhi, nodes, this->Bytes);
    Release(this->V.Distance, nodes, this->Bytes);
    Release(this->V.Band, nodes, this->Bytes);
    this->HostDense = DenseArrays();
  }
  /// A device copy of `count` values of host memory (freed by ReleaseScratch).
  template <typename T>
  T* ToDevice(const T* host, std::int64_t count, const char* what)
  {
    T* memory = this->Scratch<T>(count, what);
    if (count > 0)
    {
      Check(cudaMemcpy(memory, host, sizeof(T) * count, cudaMemcpyHostToDevice), what);
    }
    return memory;
  }
  /// Device memory for `count` values, freed by ReleaseScratch.
  template <typename T>
  T* Scratch(std::int64_t count, const char* what)
  {
    T* memory = Allocate<T>(count, this->Bytes, this->Peak, what);
    this->ScratchMemory.push_back({ memory, static_cast<std::size_t>(std::max<std::int64_t>(count, 1)) * sizeof(T) });
    return memory;
  }
  /// The chunks' sums (`sums` on the device) to the host, where each
  /// chunk's part begins (ChunkStarts) back to `first` on the device;
  /// returns the total.
  std::int64_t ChunkFirsts(const std::int64_t* sums, std::int64_t* first, std::vector<std::int64_t>& hostSums,
    std::vector<std::int64_t>& hostFirst)
  {
    if (hostSums.empty())
    {
      return 0;
    }
    Check(cudaMemcpy(hostSums.data(), sums, sizeof(std::int64_t) * hostSums.size(), cudaMemcpyDeviceToHost),
      "copying the chunks' sums back");
    const std::int64_t total = ChunkStarts(hostSums, hostFirst);
    Check(cudaMemcpy(first, hostFirst.data(), sizeof(std::int64_t) * hostFirst.size(), cudaMemcpyHostToDevice),
      "copying the chunks' starts");
    return total;
  }
  /// Frees what Scratch and ToDevice gave.
  void ReleaseScratch()
  {
    for (const auto& held : this->ScratchMemory)
    {
      cudaFree(held.first);
      this->Bytes -= static_cast<double>(held.second);
    }
    this->ScratchMemory.clear();
  }
  void ReleaseContour()
  {
    this->ReleaseScratch();
    const std::int64_t bricks = this->K.NumberOfBricks, cut = this->K.NumberOfCutBricks;
    Release(this->K.Psi, 512 * bricks, this->Bytes);
    Release(this->K.Cut, CutWords * cut, this->Bytes);
    Release(this->K.Above, AboveRows * cut, this->Bytes);
    Release(this->K.VertexCount, cut, this->Bytes);
    Release(this->K.TriangleCount, cut, this->Bytes);
    Release(this->K.Points, 3 * this->NumberOfVertices, this->Bytes);
    Release(this->K.Normals, 3 * this->NumberOfVertices, this->Bytes);
    Release(this->K.Triangles, 3 * this->NumberOfTriangles, this->Bytes);
    this->K = ContourArrays();
  }
  void ReleaseBatch()
  {
    Release(this->Bricks, this->BatchCapacity, this->Bytes);
    Release(this->BrickDistance, 512 * this->BatchCapacity, this->Bytes);
    Release(this->Covered, this->BatchCapacity, this->Bytes);
    this->BatchCapacity = 0;
  }
  void ReleaseNodes()
  {
    Release(this->RedCount, this->NodeCapacity, this->Bytes);
    Release(this->BlackCount, this->NodeCapacity, this->Bytes);
    Release(this->RedFirst, this->NodeCapacity, this->Bytes);
    Release(this->BlackFirst, this->NodeCapacity, this->Bytes);
    Release(this->Inside, 8 * this->NodeCapacity, this->Bytes);
    this->NodeCapacity = 0;
  }
  void ReleaseBatchNodes()
  {
    for (BatchNodes& batch : this->Batches)
    {
      Release(batch.Offset, batch.Size, this->Bytes);
      Release(batch.Distance, batch.Size, this->Bytes);
    }
    this->Batches.clear();
  }
  /// A band built before (StoreBand, ConnectBand) and not evolved.
  void ReleaseBand()
  {
    Release(this->BandOffset, this->BandSize, this->Bytes);
    Release(this->Distance, this->BandSize, this->Bytes);
    Release(this->Neighbor, 6 * this->BandSize, this->Bytes);
    this->BandSize = 0;
  }
  template <typename T>
  void CopyOnDevice(T* to, const T* from, std::int64_t count)
  {
    if (count > 0)
    {
      Check(cudaMemcpy(to, from, sizeof(T) * count, cudaMemcpyDeviceToDevice), "joining the band's batches");
    }
  }
  template <typename Kernel>
  void For(std::int64_t begin, std::int64_t end, const Kernel& kernel)
  {
    if (end > begin)
    {
      ForEach<<<BlocksFor(end - begin), Threads>>>(begin, end, kernel);
      Check(cudaGetLastError(), "a kernel's launch");
    }
  }
  template <bool Max, typename Kernel>
  double Reduction(std::int64_t begin, std::int64_t end, const Kernel& kernel)
  {
    if (end <= begin)
    {
      return 0.0;
    }
    const int blocks = BlocksFor(end - begin);
    Reduce<Max><<<blocks, Threads>>>(begin, end, kernel, this->Partial);
    Check(cudaGetLastError(), "a reduction's launch");
    Check(cudaMemcpy(this->HostPartial.data(), this->Partial, sizeof(double) * blocks, cudaMemcpyDeviceToHost),
      "copying a reduction back");
    double result = 0.0;
    for (int b = 0; b < blocks; ++b)
    {
      result = Max ? std::max(result, this->HostPartial[b]) : result + this->HostPartial[b];
    }
    return result;
  }

  std::string DeviceName;
  double Bytes = 0.0; ///< held now
  double Peak = 0.0;  ///< the most held at once
  // The truncated distance's arrays (DistanceArrays), until FreePoints.
  std::int64_t NumberOfPoints = 0;
  std::int64_t NumberOfBricks = 0;
  std::int64_t BatchCapacity = 0;
  double* Points = nullptr;
  std::int64_t* BucketStart = nullptr;
  std::int64_t* Bricks = nullptr;
  double* BrickDistance = nullptr;
  std::uint8_t* Covered = nullptr;
  // The band nodes of a batch (BandNodeArrays): the counts' buffers, and
  // each batch's list until StoreBand.
  std::int64_t NodeCapacity = 0;
  std::int32_t* RedCount = nullptr;
  std::int32_t* BlackCount = nullptr;
  std::int64_t* RedFirst = nullptr;
  std::int64_t* BlackFirst = nullptr;
  std::uint64_t* Inside = nullptr;
  struct BatchNodes
  {
    std::int64_t Red = 0;  ///< its red nodes first
    std::int64_t Size = 0; ///< all of them
    std::uint16_t* Offset = nullptr;
    double* Distance = nullptr;
  };
  std::vector<BatchNodes> Batches;
  // The band built here (StoreBand, ConnectBand): its Offset until the
  // evolution's Upload; Distance and Neighbor below, until InitialField and
  // the launcher's end.
  std::int64_t BandSize = 0;
  std::int64_t BandRedCount = 0;
  std::uint16_t* BandOffset = nullptr;
  // The dense volume (DenseArrays): on the device in V, the host's in
  // HostDense, until DenseDownload.
  DenseArrays V;
  DenseArrays HostDense;
  DenseConstants VC;
  // The surface's arrays (ContourArrays): the uploaded ones in
  // ScratchMemory, the others in K, until ContourGeometry ends.
  ContourArrays K;
  ContourConstants KC;
  std::int64_t ContourNodes = 0;
  std::int64_t NumberOfVertices = 0;
  std::int64_t NumberOfTriangles = 0;
  /// Copies and work arrays of one call (the sort's, the neighbour table's,
  /// the surface's uploads): pointer and bytes, freed by ReleaseScratch.
  std::vector<std::pair<void*, std::size_t>> ScratchMemory;
  EvolutionArrays A;
  std::uint32_t* Neighbor = nullptr;
  double* Distance = nullptr;
  double* Partial = nullptr;
  std::vector<double> HostPartial;
};
} // namespace

bool CudaCompiled()
{
  return true;
}

std::unique_ptr<Launcher> MakeCudaLauncher(std::string& why)
{
  int count = 0;
  const cudaError_t status = cudaGetDeviceCount(&count);
  if (status != cudaSuccess || count == 0)
  {
    why = std::string("no CUDA device was found (the CUDA runtime says: ") +
      (status != cudaSuccess ? cudaGetErrorString(status) : "no device") + ")";
    return nullptr;
  }
  int device = 0;
  Check(cudaGetDevice(&device), "cudaGetDevice");
  return std::unique_ptr<Launcher>(new CudaLauncher(device));
}

} // namespace device
} // namespace nv
