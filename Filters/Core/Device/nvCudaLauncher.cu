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
// Memory: every array is a DeviceBuffer (nvDeviceMemory.h) that owns its
// device memory: freed when it is reset or replaced, when the launcher
// goes, and when an exception unwinds past a call's own copies (Scratch),
// and counted in the launcher's ledger meanwhile, so that a failed
// allocation leaks nothing and the count (DeviceBytes) does not drift.
//
// Errors: each allocation, copy and launch names its array or kernel in
// the DeviceError it throws ("The GPU failed (launching PsiKernel): ...").
// Launches are asynchronous: a kernel that faults is reported by the next
// call that waits for the device, a copy, under that copy's name. With the
// environment variable NV_CUDA_SYNC=1 (any value but empty or 0) the
// launcher waits for the device after each launch (cudaDeviceSynchronize),
// so that a fault is reported under the kernel that caused it ("running
// PsiKernel"); slower, for debugging. Without it, an error that may be an
// earlier kernel's says to set it.
//
// Copies: the host's arrays are ordinary (pageable) memory, which the GPU
// cannot read or write directly; a large copy goes through two pinned
// staging buffers on a stream of its own (Staging), chunk by chunk, the
// GPU's copy of one chunk overlapping the host threads' copy of the other,
// so that fresh host memory (a sink's vertices) is first written on all
// the host's threads rather than by the driver on one.
//
// Reductions (the sweeps' max change, the stopping rule's norms): each block
// reduces its nodes in shared memory and writes one partial, and one more
// block reduces the partials (FinishReduce), in a fixed order, so that one
// value comes back per reduction and a sweep or a time step reads the device
// once. With the fixed launch shape below the result does not depend on
// scheduling (no atomics), so a run repeats bit for bit on the same GPU.
#include "nvDeviceLauncher.h"
#include "nvParallel.h"

#include <cuda_runtime.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <mutex>
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

/// Whether NV_CUDA_SYNC asks to wait for the device after each launch.
bool SyncLaunches()
{
  const char* value = std::getenv("NV_CUDA_SYNC");
  return value && *value && std::strcmp(value, "0") != 0;
}

/// Throws the DeviceError of a failed CUDA call; `what` names the call's
/// kernel or array.
void Check(cudaError_t status, const std::string& what)
{
  if (status == cudaSuccess)
  {
    return;
  }
  std::string message = "The GPU failed (" + what + "): " + cudaGetErrorString(status);
  if (status != cudaErrorMemoryAllocation && !SyncLaunches())
  {
    message += " (it may be an earlier kernel's fault: set NV_CUDA_SYNC=1 to have it reported under that kernel)";
  }
  throw DeviceError(message);
}

/// Whether the current device has stream-ordered memory pools (CUDA 11.2
/// and later on most GPUs): asked once per process.
bool Pooled()
{
  static const bool pooled = []() {
    int device = 0, supported = 0;
    const bool asked = cudaGetDevice(&device) == cudaSuccess &&
      cudaDeviceGetAttribute(&supported, cudaDevAttrMemoryPoolsSupported, device) == cudaSuccess;
    cudaGetLastError(); // not the run's error: without pools, cudaMalloc
    return asked && supported != 0;
  }();
  return pooled;
}

/// Device memory from the device's default stream-ordered pool
/// (cudaMallocAsync on the default stream), where it has one: a free is
/// ordered after the kernels before it and does not wait for the device
/// (cudaFree waits for all its work); else cudaMalloc and cudaFree.
struct CudaMemory
{
  static void* Allocate(std::size_t bytes, const char* what)
  {
    void* memory = nullptr;
    Check(Pooled() ? cudaMallocAsync(&memory, bytes, 0) : cudaMalloc(&memory, bytes),
      std::string("allocating ") + what + ", " + ByteWords(static_cast<double>(bytes)));
    return memory;
  }
  static void Free(void* memory) // errors ignored: it may run while one unwinds
  {
    if (Pooled())
    {
      cudaFreeAsync(memory, 0);
    }
    else
    {
      cudaFree(memory);
    }
  }
};

/// Copies between host memory that the caller owns (pageable) and the
/// device. A copy of Direct bytes or more goes in chunks through two pinned
/// buffers on a stream of its own, ordered after the kernels launched
/// before it (a blocking stream waits for the default one): the device
/// copies one chunk while the host's threads copy the other (ParallelFor).
/// Smaller copies, and all copies where the pinned buffers cannot be had,
/// go straight (cudaMemcpy). Each copy waits for the kernels before it
/// (as a copy on the default stream would), then is timed (Counted), and
/// returns once its bytes are where they go. One Staging serves the process (SharedStaging): pinning memory takes
/// time, so the buffers (2 Chunk bytes) are made at the first large copy and
/// kept; a copy holds them alone (Busy).
class Staging
{
public:
  /// `bytes` of device memory into host memory.
  void ToHost(void* host, const void* device, std::size_t bytes, const std::string& what)
  {
    this->Copy(host, device, bytes, cudaMemcpyDeviceToHost, what, [&](std::size_t chunks) {
      const auto issue = [&](std::size_t c) {
        const std::size_t begin = c * Chunk;
        Check(cudaMemcpyAsync(this->Buffer[c % 2], static_cast<const char*>(device) + begin,
                std::min(Chunk, bytes - begin), cudaMemcpyDeviceToHost, this->Stream),
          "copying " + what);
        Check(cudaEventRecord(this->Done[c % 2], this->Stream), "copying " + what);
      };
      issue(0);
      for (std::size_t c = 0; c < chunks; ++c)
      {
        if (c + 1 < chunks)
        {
          issue(c + 1); // into the buffer the host emptied at chunk c - 1
        }
        Check(cudaEventSynchronize(this->Done[c % 2]), "copying " + what);
        const std::size_t begin = c * Chunk;
        HostCopy(static_cast<char*>(host) + begin, this->Buffer[c % 2], std::min(Chunk, bytes - begin));
      }
    });
  }

  /// `bytes` of host memory into device memory.
  void ToDevice(void* device, const void* host, std::size_t bytes, const std::string& what)
  {
    this->Copy(device, host, bytes, cudaMemcpyHostToDevice, what, [&](std::size_t chunks) {
      for (std::size_t c = 0; c < chunks; ++c)
      {
        if (c >= 2)
        {
          // The buffer's previous chunk is on the device.
          Check(cudaEventSynchronize(this->Done[c % 2]), "copying " + what);
        }
        const std::size_t begin = c * Chunk, n = std::min(Chunk, bytes - begin);
        HostCopy(this->Buffer[c % 2], static_cast<const char*>(host) + begin, n);
        Check(cudaMemcpyAsync(static_cast<char*>(device) + begin, this->Buffer[c % 2], n, cudaMemcpyHostToDevice,
                this->Stream),
          "copying " + what);
        Check(cudaEventRecord(this->Done[c % 2], this->Stream), "copying " + what);
      }
      Check(cudaStreamSynchronize(this->Stream), "copying " + what);
    });
  }

  /// The process's copies so far, each way.
  CopyCounts Counted() const
  {
    std::lock_guard<std::mutex> alone(this->Counting);
    return this->Counts;
  }

private:
  /// A copy either way: after the kernels before it, timed; `staged(chunks)`
  /// moves a large one chunk by chunk through the buffers (held alone),
  /// any other goes straight.
  template <typename Staged>
  void Copy(void* to, const void* from, std::size_t bytes, cudaMemcpyKind kind, const std::string& what,
    const Staged& staged)
  {
    Check(cudaDeviceSynchronize(), "finishing the kernels before copying " + what);
    const Timer timer(this, bytes, kind == cudaMemcpyDeviceToHost); // the copy's own time
    if (bytes >= Direct)
    {
      std::lock_guard<std::mutex> alone(this->Busy);
      if (this->Ready())
      {
        // After a failed copy the stream may hold work: finish it first.
        Check(cudaStreamSynchronize(this->Stream), "copying " + what);
        staged((bytes + Chunk - 1) / Chunk);
        return;
      }
    }
    Check(cudaMemcpy(to, from, bytes, kind), "copying " + what);
  }

  /// Adds a copy's bytes and seconds to Counts when it ends.
  struct Timer
  {
    Staging* Self;
    std::size_t Bytes;
    bool ToHost;
    std::chrono::steady_clock::time_point Start = std::chrono::steady_clock::now();
    Timer(Staging* self, std::size_t bytes, bool toHost)
      : Self(self)
      , Bytes(bytes)
      , ToHost(toHost)
    {
    }
    ~Timer()
    {
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - this->Start).count();
      std::lock_guard<std::mutex> alone(this->Self->Counting);
      CopyCounts& c = this->Self->Counts;
      (this->ToHost ? c.ToHostBytes : c.ToDeviceBytes) += static_cast<double>(this->Bytes);
      (this->ToHost ? c.ToHostSeconds : c.ToDeviceSeconds) += seconds;
    }
  };

  static constexpr std::size_t Chunk = std::size_t(16) << 20;  ///< bytes a staging buffer holds
  static constexpr std::size_t Direct = std::size_t(4) << 20;  ///< smaller copies go straight

  /// The pinned buffers, the stream and its events, made at the first
  /// large copy; false (and every copy straight) where they cannot be had.
  bool Ready()
  {
    if (!this->Tried)
    {
      this->Tried = true;
      bool made = cudaStreamCreate(&this->Stream) == cudaSuccess;
      for (int b = 0; b < 2 && made; ++b)
      {
        made = cudaHostAlloc(&this->Buffer[b], Chunk, cudaHostAllocDefault) == cudaSuccess &&
          cudaEventCreateWithFlags(&this->Done[b], cudaEventDisableTiming) == cudaSuccess;
      }
      cudaGetLastError(); // a failure here is not the run's: the copies go straight
      this->Have = made;
    }
    return this->Have;
  }

  /// memcpy on the host's threads, a megabyte a task.
  static void HostCopy(void* to, const void* from, std::size_t bytes)
  {
    const std::int64_t grain = std::int64_t(1) << 20;
    ParallelFor(0, static_cast<std::int64_t>(bytes), grain, [&](std::int64_t begin, std::int64_t end) {
      std::memcpy(static_cast<char*>(to) + begin, static_cast<const char*>(from) + begin,
        static_cast<std::size_t>(end - begin));
    });
  }

  std::mutex Busy;
  mutable std::mutex Counting;
  CopyCounts Counts;
  void* Buffer[2] = { nullptr, nullptr };
  cudaEvent_t Done[2] = { nullptr, nullptr }; ///< each buffer's copy done
  cudaStream_t Stream = nullptr;
  bool Tried = false;
  bool Have = false;
};

/// The process's Staging, made once and never freed (the process's end
/// gives its pinned memory back; a static destructor could run after the
/// CUDA runtime's).
Staging& SharedStaging()
{
  static Staging* const staging = new Staging;
  return *staging;
}

/// An array in the GPU's memory, owned and counted (nvDeviceMemory.h).
template <typename T>
using Array = DeviceBuffer<T, CudaMemory>;

/// Device copies and work arrays of one call (the sort's, the neighbour
/// table's, the surface's uploads), freed together when this goes or is
/// cleared.
class Scratch
{
public:
  explicit Scratch(Staging& staging)
    : Copies(staging)
  {
  }

  /// Device memory for `count` values.
  template <typename T>
  T* Get(DeviceLedger& ledger, std::int64_t count, const char* what)
  {
    Array<unsigned char> memory;
    memory.Allocate(ledger, std::max<std::int64_t>(count, 1) * static_cast<std::int64_t>(sizeof(T)), what);
    T* values = reinterpret_cast<T*>(memory.Data());
    this->Held.push_back(std::move(memory));
    return values;
  }
  /// A device copy of `count` values of host memory.
  template <typename T>
  T* Copy(DeviceLedger& ledger, const T* host, std::int64_t count, const char* what)
  {
    T* values = this->Get<T>(ledger, count, what);
    if (count > 0)
    {
      this->Copies.ToDevice(values, host, sizeof(T) * count, what);
    }
    return values;
  }
  void Clear() { this->Held.clear(); }

private:
  Staging& Copies;
  std::vector<Array<unsigned char>> Held;
};

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

/// The max (Max = true) or the sum of the block's threads' values, in a
/// fixed order (a tree over the threads): thread 0's result.
template <bool Max>
__device__ double BlockReduce(double value)
{
  __shared__ double cache[Threads];
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
  return cache[0];
}

/// partial[blockIdx.x] = the max (Max = true) or the sum of kernel(s) over this block's nodes.
template <bool Max, typename Kernel>
__global__ void Reduce(std::int64_t begin, std::int64_t end, Kernel kernel, double* partial)
{
  const std::int64_t stride = static_cast<std::int64_t>(gridDim.x) * blockDim.x;
  double value = 0.0;
  for (std::int64_t s = begin + static_cast<std::int64_t>(blockIdx.x) * blockDim.x + threadIdx.x; s < end; s += stride)
  {
    const double v = kernel(s);
    value = Max ? fmax(value, v) : value + v;
  }
  const double block = BlockReduce<Max>(value);
  if (threadIdx.x == 0)
  {
    partial[blockIdx.x] = block;
  }
}

/// *result = the max or the sum of partial[0 .. count), by one block: the
/// reduction's last stage on the device, so that one value comes back.
template <bool Max>
__global__ void FinishReduce(const double* partial, int count, double* result)
{
  double value = 0.0;
  for (int b = static_cast<int>(threadIdx.x); b < count; b += static_cast<int>(blockDim.x))
  {
    value = Max ? fmax(value, partial[b]) : value + partial[b];
  }
  const double block = BlockReduce<Max>(value);
  if (threadIdx.x == 0)
  {
    *result = block;
  }
}

/// The device's name, asked once per process (cudaGetDeviceProperties
/// asks the device for all its properties, which takes a while; the CUDA
/// context, made at the process's first CUDA call, stays for the process
/// too, so that a later run pays neither).
std::string NameOf(int device)
{
  static std::mutex asking;
  static std::vector<std::string> names;
  std::lock_guard<std::mutex> alone(asking);
  if (names.size() <= static_cast<std::size_t>(device))
  {
    names.resize(static_cast<std::size_t>(device) + 1);
  }
  if (names[device].empty())
  {
    cudaDeviceProp properties;
    Check(cudaGetDeviceProperties(&properties, device), "cudaGetDeviceProperties");
    names[device] = properties.name;
  }
  return names[device];
}

class CudaLauncher : public Launcher
{
public:
  explicit CudaLauncher(int device)
    : Synchronous(SyncLaunches())
  {
    Check(cudaSetDevice(device), "cudaSetDevice");
    this->DeviceName = NameOf(device);
    this->Partial.Allocate(this->Ledger, Slots * MaximumBlocks, "the reductions' partials");
    this->Results.Allocate(this->Ledger, Slots, "the reductions' results");
  }
  // The arrays free their memory themselves (errors ignored: the launcher
  // may go while a DeviceError unwinds).
  ~CudaLauncher() override = default;

  std::string Name() const override { return "CUDA (" + this->DeviceName + ")"; }
  double DeviceBytes() const override { return this->Ledger.Peak(); }
  double HeldBytes() const override { return this->Ledger.Held(); }
  /// The process's copies since this launcher was made.
  CopyCounts Copies() const override
  {
    const CopyCounts now = this->Transfers.Counted();
    CopyCounts since;
    since.ToHostBytes = now.ToHostBytes - this->CopiedBefore.ToHostBytes;
    since.ToHostSeconds = now.ToHostSeconds - this->CopiedBefore.ToHostSeconds;
    since.ToDeviceBytes = now.ToDeviceBytes - this->CopiedBefore.ToDeviceBytes;
    since.ToDeviceSeconds = now.ToDeviceSeconds - this->CopiedBefore.ToDeviceSeconds;
    return since;
  }
  double FreeBytes() const override
  {
    std::size_t free = 0, total = 0;
    Check(cudaMemGetInfo(&free, &total), "asking for the free memory (cudaMemGetInfo)");
    double bytes = static_cast<double>(free);
    if (Pooled())
    {
      // Memory the pool holds but no array uses is free to this launcher.
      int device = 0;
      cudaMemPool_t pool;
      std::uint64_t reserved = 0, used = 0; // cuuint64_t
      Check(cudaGetDevice(&device), "asking for the device");
      Check(cudaDeviceGetDefaultMemPool(&pool, device), "asking for the memory pool");
      Check(cudaMemPoolGetAttribute(pool, cudaMemPoolAttrReservedMemCurrent, &reserved),
        "asking for the pool's memory");
      Check(cudaMemPoolGetAttribute(pool, cudaMemPoolAttrUsedMemCurrent, &used), "asking for the pool's memory");
      bytes += static_cast<double>(reserved > used ? reserved - used : 0);
    }
    return bytes;
  }

  void Upload(std::int64_t size, const std::uint32_t* neighbor, const double* distance, double inside,
    double outside) override
  {
    const bool held = !neighbor && !distance && size > 0; // the band built here (StoreBand, ConnectBand)
    if (held && (this->BandSize != size || !this->Neighbor.Data() || !this->Distance.Data()))
    {
      throw DeviceError("The GPU holds no band of " + std::to_string(size) + " nodes to evolve.");
    }
    if (held)
    {
      this->BandOffset.Reset(); // the host has its copy
    }
    this->A = EvolutionArrays();
    this->A.Size = size;
    if (!held)
    {
      this->Neighbor.Allocate(this->Ledger, 6 * size, "the neighbour table");
      this->Distance.Allocate(this->Ledger, size, "the distances");
    }
    // Phi only: the other arrays come once the distances are let go
    // (InitialField), 8 bytes a node less at the evolution's peak.
    this->Phi.Allocate(this->Ledger, size + 2, "phi");
    if (!held)
    {
      this->Transfers.ToDevice(this->Neighbor.Data(), neighbor, sizeof(std::uint32_t) * 6 * size,
        "the neighbour table");
      this->Transfers.ToDevice(this->Distance.Data(), distance, sizeof(double) * size, "the distances");
    }
    const double slots[2] = { inside, outside };
    this->Transfers.ToDevice(this->Phi.Data() + size, slots, sizeof(slots), "eq. (5)'s values into phi");
    this->A.Neighbor = this->Neighbor.Data();
    this->A.Distance = this->Distance.Data();
    this->A.Phi = this->Phi.Data();
  }
  void InitialField(const EvolutionConstants& constants) override
  {
    this->Launch("InitialPhiKernel", 0, this->A.Size, InitialPhiKernel{ this->A, constants });
    Check(cudaDeviceSynchronize(), "running InitialPhiKernel");
    this->Distance.Reset();
    this->A.Distance = nullptr;
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
    this->Launch("CoefficientsKernel", 0, this->A.Size, CoefficientsKernel{ this->A, constants });
  }
  void KeepPrevious() override
  {
    this->Launch("KeepPreviousKernel", 0, this->A.Size, KeepPreviousKernel{ this->A });
  }
  double Sweep(const std::int64_t red[2], const std::int64_t black[2], double omega) override
  {
    this->Reduction<true>("RelaxKernel (red nodes)", red[0], red[1], RelaxKernel{ this->A, omega }, 0);
    this->Reduction<true>("RelaxKernel (black nodes)", black[0], black[1], RelaxKernel{ this->A, omega }, 1);
    double change[2];
    this->ReadResults(2, change, "the sweep's change");
    return std::max(change[0], change[1]);
  }
  void React() override { this->Launch("ReactKernel", 0, this->A.Size, ReactKernel{ this->A }); }
  void StepSums(const std::int64_t red[2], const std::int64_t black[2], double sums[4]) override
  {
    this->Reduction<false>("ChangeSquaredKernel (red nodes)", red[0], red[1], ChangeSquaredKernel{ this->A }, 0);
    this->Reduction<false>("ChangeSquaredKernel (black nodes)", black[0], black[1], ChangeSquaredKernel{ this->A }, 1);
    this->Reduction<false>("NormSquaredKernel (red nodes)", red[0], red[1], NormSquaredKernel{ this->A }, 2);
    this->Reduction<false>("NormSquaredKernel (black nodes)", black[0], black[1], NormSquaredKernel{ this->A }, 3);
    this->ReadResults(4, sums, "the step's change and norm");
  }
  void Download(UninitializedVector<double>& phi) override
  {
    phi.resize(static_cast<std::size_t>(this->A.Size + 2));
    this->Transfers.ToHost(phi.data(), this->Phi.Data(), sizeof(double) * (this->A.Size + 2), "phi back");
  }

  void ReleaseEvolution() override
  {
    this->Previous.Reset();
    this->Coupling.Reset();
    this->Decay.Reset();
    this->ReleaseBand();
    this->A.Previous = this->A.Coupling = nullptr;
    this->A.Decay = nullptr;
    this->A.Neighbor = nullptr;
    this->A.Distance = nullptr;
  }
  void SortPoints(const double* cloud, std::int64_t numberOfPoints, const PointConstants& constants,
    std::vector<std::int64_t>& reached) override
  {
    PointArrays a;
    a.NumberOfPoints = numberOfPoints;
    a.NumberOfBricks = constants.BrickDims[0] * constants.BrickDims[1] * constants.BrickDims[2];
    const std::int64_t chunks = (a.NumberOfBricks + ChunkBricks - 1) / ChunkBricks;
    // Held until FreePoints: the sorted points and their buckets.
    this->Points.Allocate(this->Ledger, 3 * numberOfPoints, "the points");
    this->BucketStart.Allocate(this->Ledger, a.NumberOfBricks + 1, "the points' buckets");
    // Freed on the way out, whatever happens: the cloud, each point's
    // brick, the buckets' free slots, the marks of the reached bricks, the chunks.
    Scratch scratch(this->Transfers);
    a.Cloud = scratch.Copy(this->Ledger, cloud, 3 * numberOfPoints, "the cloud");
    a.BrickOf = scratch.Get<std::int64_t>(this->Ledger, numberOfPoints, "each point's brick");
    a.Next = scratch.Get<std::int64_t>(this->Ledger, a.NumberOfBricks, "the buckets' free slots");
    a.Reached = scratch.Get<std::uint8_t>(this->Ledger, a.NumberOfBricks, "the reached bricks' marks");
    a.ChunkCount = scratch.Get<std::int64_t>(this->Ledger, chunks, "the chunks' sums");
    std::int64_t* chunkFirst = scratch.Get<std::int64_t>(this->Ledger, chunks, "the chunks' starts");
    a.ChunkFirst = chunkFirst;
    a.BucketStart = this->BucketStart.Data();
    a.Points = this->Points.Data();
    Check(cudaMemset(a.BucketStart, 0, sizeof(std::int64_t) * (a.NumberOfBricks + 1)),
      "clearing the points' buckets");
    Check(cudaMemset(a.Reached, 0, static_cast<std::size_t>(a.NumberOfBricks)), "clearing the reached bricks' marks");
    std::vector<std::int64_t> sums(static_cast<std::size_t>(chunks)), firsts;
    // The counting sort: counts, their sums chunk by chunk, the points placed.
    this->Launch("BucketPointsKernel", 0, numberOfPoints, BucketPointsKernel{ a, constants });
    this->Launch("ChunkSumKernel (the buckets)", 0, chunks, ChunkSumKernel<std::int64_t>{ a, a.BucketStart + 1 });
    this->ChunkFirsts(a.ChunkCount, chunkFirst, sums, firsts);
    this->Launch("ChunkScanKernel", 0, chunks, ChunkScanKernel{ a });
    this->Launch("ScatterPointsKernel", 0, numberOfPoints, ScatterPointsKernel{ a, constants });
    // The bricks reached, marked and listed in order.
    this->Launch("ReachKernel", 0, numberOfPoints, ReachKernel{ a, constants });
    this->Launch("ChunkSumKernel (the reached bricks)", 0, chunks, ChunkSumKernel<std::uint8_t>{ a, a.Reached });
    const std::int64_t total = this->ChunkFirsts(a.ChunkCount, chunkFirst, sums, firsts);
    a.ReachList = scratch.Get<std::int64_t>(this->Ledger, total, "the reached bricks");
    this->Launch("ReachListKernel", 0, chunks, ReachListKernel{ a });
    reached.resize(static_cast<std::size_t>(total));
    if (total > 0)
    {
      this->Transfers.ToHost(reached.data(), a.ReachList, sizeof(std::int64_t) * total, "the reached bricks back");
    }
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
      this->BatchCapacity = 0; // until all three are there
      this->Bricks.Allocate(this->Ledger, count, "the bricks of a batch");
      this->BrickDistance.Allocate(this->Ledger, count * 512, "the distances of a batch");
      this->Covered.Allocate(this->Ledger, count, "the covered bricks of a batch");
      this->BatchCapacity = count;
    }
    this->Transfers.ToDevice(this->Bricks.Data(), bricks, sizeof(std::int64_t) * count, "the bricks of a batch");
    DistanceArrays arrays;
    arrays.Points = this->Points.Data();
    arrays.BucketStart = this->BucketStart.Data();
    arrays.Bricks = this->Bricks.Data();
    arrays.Distance = this->BrickDistance.Data();
    arrays.Covered = this->Covered.Data();
    this->Launch("CoveredKernel", 0, count, CoveredKernel{ arrays, constants });
    // One thread a node: a block of 256 threads is half a brick.
    this->Launch("DistanceKernel", 0, count * 512, DistanceKernel{ arrays, constants });
    if (covered)
    {
      this->Transfers.ToHost(covered, this->Covered.Data(), count, "the covered bricks back");
    }
    if (distance)
    {
      this->Transfers.ToHost(distance, this->BrickDistance.Data(), sizeof(double) * 512 * count,
        "the distances of a batch back");
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
      this->NodeCapacity = 0; // until all five are there
      this->RedCount.Allocate(this->Ledger, count, "the red counts of a batch");
      this->BlackCount.Allocate(this->Ledger, count, "the black counts of a batch");
      this->RedFirst.Allocate(this->Ledger, count, "the red nodes' places in a batch");
      this->BlackFirst.Allocate(this->Ledger, count, "the black nodes' places in a batch");
      this->Inside.Allocate(this->Ledger, 8 * count, "the inside bits of a batch");
      this->NodeCapacity = count;
    }
    BandNodeArrays arrays;
    arrays.Bricks = this->Bricks.Data();
    arrays.Distance = this->BrickDistance.Data();
    arrays.Covered = this->Covered.Data();
    arrays.RedCount = this->RedCount.Data();
    arrays.BlackCount = this->BlackCount.Data();
    arrays.RedFirst = this->RedFirst.Data();
    arrays.BlackFirst = this->BlackFirst.Data();
    arrays.Inside = this->Inside.Data();
    this->Launch("BandCountKernel", 0, count, BandCountKernel{ arrays, constants });
    this->Transfers.ToHost(red, arrays.RedCount, sizeof(std::int32_t) * count, "the red counts back");
    this->Transfers.ToHost(black, arrays.BlackCount, sizeof(std::int32_t) * count, "the black counts back");
    this->Transfers.ToHost(inside, arrays.Inside, sizeof(std::uint64_t) * 8 * count, "the inside bits back");
    std::vector<std::int64_t> redFirst, blackFirst;
    FirstNodes(red, black, count, redFirst, blackFirst);
    this->Transfers.ToDevice(this->RedFirst.Data(), redFirst.data(), sizeof(std::int64_t) * count,
      "the red nodes' places");
    this->Transfers.ToDevice(this->BlackFirst.Data(), blackFirst.data(), sizeof(std::int64_t) * count,
      "the black nodes' places");
    // The batch's list of band nodes, kept until StoreBand (freed here if
    // anything below fails).
    BatchNodes batch;
    batch.Red = redFirst[count];
    batch.Offset.Allocate(this->Ledger, blackFirst[count], "the band nodes of a batch");
    batch.Distance.Allocate(this->Ledger, blackFirst[count], "the band nodes' distances");
    arrays.NodeOffset = batch.Offset.Data();
    arrays.NodeDistance = batch.Distance.Data();
    this->Launch("BandCompactKernel", 0, count, BandCompactKernel{ arrays, constants });
    this->Batches.push_back(std::move(batch));
  }
  void StoreBand(std::int64_t redCount, std::int64_t size, std::uint16_t* offset) override
  {
    this->ReleaseBand();
    this->BandOffset.Allocate(this->Ledger, size, "the band's node places");
    this->Distance.Allocate(this->Ledger, size, "the distances");
    // Each batch's red nodes after the batches' before it, its black ones
    // likewise after all the red ones: two copies a batch and array.
    std::int64_t red = 0, black = redCount;
    for (const BatchNodes& batch : this->Batches)
    {
      const std::int64_t blacks = batch.Offset.Size() - batch.Red;
      const std::uint16_t* batchOffset = batch.Offset.Data();
      const double* batchDistance = batch.Distance.Data();
      CopyOnDevice(this->BandOffset.Data() + red, batchOffset, batch.Red, "joining the batches' node places");
      CopyOnDevice(this->BandOffset.Data() + black, batchOffset + batch.Red, blacks, "joining the batches' node places");
      CopyOnDevice(this->Distance.Data() + red, batchDistance, batch.Red, "joining the batches' distances");
      CopyOnDevice(this->Distance.Data() + black, batchDistance + batch.Red, blacks, "joining the batches' distances");
      red += batch.Red;
      black += blacks;
    }
    this->Batches.clear();
    if (size > 0)
    {
      this->Transfers.ToHost(offset, this->BandOffset.Data(), sizeof(std::uint16_t) * size,
        "the band's node places back");
    }
    this->BandSize = size;
    this->BandRedCount = redCount;
  }
  void ConnectBand(const std::int64_t* bricks, const std::int64_t* redStart, const std::int64_t* blackStart,
    std::int64_t numberOfBricks, const NeighbourConstants& constants) override
  {
    Scratch scratch(this->Transfers); // the copies below, freed on the way out
    NeighbourArrays band;
    band.NumberOfBricks = numberOfBricks;
    band.RedCount = this->BandRedCount;
    band.Size = this->BandSize;
    band.Bricks = scratch.Copy(this->Ledger, bricks, numberOfBricks, "the band's bricks");
    band.RedStart = scratch.Copy(this->Ledger, redStart, numberOfBricks + 1, "the band's red starts");
    band.BlackStart = scratch.Copy(this->Ledger, blackStart, numberOfBricks + 1, "the band's black starts");
    band.Offset = this->BandOffset.Data();
    band.Distance = this->Distance.Data();
    band.Adjacent = scratch.Get<std::int32_t>(this->Ledger, 6 * numberOfBricks, "the adjacent bricks");
    this->Neighbor.Allocate(this->Ledger, 6 * this->BandSize, "the neighbour table");
    band.Neighbor = this->Neighbor.Data();
    this->Launch("AdjacentBricksKernel", 0, numberOfBricks, AdjacentBricksKernel{ band, constants });
    this->Launch("NeighboursKernel", 0, this->BandSize, NeighboursKernel{ band, constants });
    Check(cudaDeviceSynchronize(), "running NeighboursKernel");
  }
  void DownloadBand(double* distance, std::uint32_t* neighbor) override
  {
    if (this->BandSize > 0)
    {
      this->Transfers.ToHost(distance, this->Distance.Data(), sizeof(double) * this->BandSize,
        "the band's distances back");
      this->Transfers.ToHost(neighbor, this->Neighbor.Data(), sizeof(std::uint32_t) * 6 * this->BandSize,
        "the neighbour table back");
    }
  }
  void FreePoints() override
  {
    this->Points.Reset();
    this->BucketStart.Reset();
    this->BatchCapacity = 0;
    this->Bricks.Reset();
    this->BrickDistance.Reset();
    this->Covered.Reset();
    this->NodeCapacity = 0;
    this->RedCount.Reset();
    this->BlackCount.Reset();
    this->RedFirst.Reset();
    this->BlackFirst.Reset();
    this->Inside.Reset();
    this->Batches.clear();
  }

  void CutBricks(const ContourArrays& band, const ContourConstants& constants, std::vector<std::int64_t>& cut) override
  {
    // Up: the band's bricks, their starts and inside bits; here: a mark a
    // grid brick and the chunks' sums; back: the chunks' sums and the list.
    // All freed on the way out (ContourCounts uploads the band again).
    Scratch scratch(this->Transfers);
    ContourArrays k;
    const std::int64_t bricks = band.NumberOfBricks;
    k.NumberOfBricks = bricks;
    k.Bricks = scratch.Copy(this->Ledger, band.Bricks, bricks, "the band's bricks, for the cut bricks");
    k.RedStart = scratch.Copy(this->Ledger, band.RedStart, bricks + 1, "the band's red starts, for the cut bricks");
    k.BlackStart =
      scratch.Copy(this->Ledger, band.BlackStart, bricks + 1, "the band's black starts, for the cut bricks");
    k.Inside = scratch.Copy(this->Ledger, band.Inside, 8 * bricks, "the band's inside bits, for the cut bricks");
    PointArrays list;
    list.NumberOfBricks = constants.BrickDims[0] * constants.BrickDims[1] * constants.BrickDims[2];
    const std::int64_t chunks = (list.NumberOfBricks + ChunkBricks - 1) / ChunkBricks;
    list.Reached = scratch.Get<std::uint8_t>(this->Ledger, list.NumberOfBricks, "the cut bricks' marks");
    list.ChunkCount = scratch.Get<std::int64_t>(this->Ledger, chunks, "the cut bricks' chunk sums");
    std::int64_t* chunkFirst = scratch.Get<std::int64_t>(this->Ledger, chunks, "the cut bricks' chunk starts");
    list.ChunkFirst = chunkFirst;
    Check(cudaMemset(list.Reached, 0, static_cast<std::size_t>(list.NumberOfBricks)), "clearing the cut bricks' marks");
    this->Launch("CutMarkKernel", 0, bricks, CutMarkKernel{ k, constants, list.Reached });
    this->Launch("ChunkSumKernel (the cut bricks)", 0, chunks, ChunkSumKernel<std::uint8_t>{ list, list.Reached });
    std::vector<std::int64_t> sums(static_cast<std::size_t>(chunks)), firsts;
    const std::int64_t total = this->ChunkFirsts(list.ChunkCount, chunkFirst, sums, firsts);
    list.ReachList = scratch.Get<std::int64_t>(this->Ledger, total, "the cut bricks");
    this->Launch("ReachListKernel (the cut bricks)", 0, chunks, ReachListKernel{ list });
    cut.resize(static_cast<std::size_t>(total));
    if (total > 0)
    {
      this->Transfers.ToHost(cut.data(), list.ReachList, sizeof(std::int64_t) * total, "the cut bricks back");
    }
  }
  void ContourCounts(const ContourArrays& band, std::int64_t numberOfNodes, const ContourConstants& constants,
    std::int32_t* vertices, std::int32_t* triangles) override
  {
    this->ReleaseContour();
    this->KC = constants;
    ContourArrays& k = this->K;
    k.NumberOfBricks = band.NumberOfBricks;
    k.NumberOfCutBricks = band.NumberOfCutBricks;
    const std::int64_t bricks = band.NumberOfBricks, cut = band.NumberOfCutBricks;
    Scratch& up = this->ContourUploads; // until ContourGeometry's end
    k.Bricks = up.Copy(this->Ledger, band.Bricks, bricks, "the band's bricks");
    k.RedStart = up.Copy(this->Ledger, band.RedStart, bricks + 1, "the band's red starts");
    k.BlackStart = up.Copy(this->Ledger, band.BlackStart, bricks + 1, "the band's black starts");
    k.Inside = up.Copy(this->Ledger, band.Inside, 8 * bricks, "the band's inside bits");
    k.Offset = up.Copy(this->Ledger, band.Offset, numberOfNodes, "the band's node places");
    // The evolution's phi, still here (ReleaseEvolution kept it), or a copy.
    const bool held = this->Phi.Data() && this->A.Size == numberOfNodes;
    k.Phi = held ? this->Phi.Data() : up.Copy(this->Ledger, band.Phi, numberOfNodes, "phi for the surface");
    k.CutBricks = up.Copy(this->Ledger, band.CutBricks, cut, "the cut bricks");
    k.Cases = up.Copy(this->Ledger, band.Cases, 1, "the case table");
    this->Psi.Allocate(this->Ledger, 512 * bricks, "psi");
    this->Cut.Allocate(this->Ledger, CutWords * cut, "the cut edges");
    this->Above.Allocate(this->Ledger, AboveRows * cut, "the corners' signs");
    this->VertexCount.Allocate(this->Ledger, cut, "the vertex counts");
    this->TriangleCount.Allocate(this->Ledger, cut, "the triangle counts");
    k.Psi = this->Psi.Data();
    k.Cut = this->Cut.Data();
    k.Above = this->Above.Data();
    k.VertexCount = this->VertexCount.Data();
    k.TriangleCount = this->TriangleCount.Data();
    this->Launch("PsiKernel", 0, bricks, PsiKernel{ k, constants });
    this->Launch("CutCellsKernel", 0, cut, CutCellsKernel{ k, constants });
    if (cut > 0)
    {
      this->Transfers.ToHost(vertices, k.VertexCount, sizeof(std::int32_t) * cut, "the vertex counts back");
      this->Transfers.ToHost(triangles, k.TriangleCount, sizeof(std::int32_t) * cut, "the triangle counts back");
    }
  }
  void ContourGeometry(const std::int64_t* firstVertex, const std::int64_t* firstTriangle,
    std::int64_t numberOfVertices, std::int64_t numberOfTriangles, double* points, float* normals,
    long long* triangles) override
  {
    ContourArrays& k = this->K;
    const std::int64_t cut = k.NumberOfCutBricks;
    Scratch& up = this->ContourUploads;
    k.FirstVertex = up.Copy(this->Ledger, firstVertex, cut, "the first vertices");
    k.FirstTriangle = up.Copy(this->Ledger, firstTriangle, cut, "the first triangles");
    // Slab by slab of cut bricks, each slab's outputs in the same device
    // arrays (sized for the largest), then to the sink's arrays.
    const std::vector<SurfaceSlab> slabs =
      SurfaceSlabs(firstVertex, firstTriangle, cut, numberOfVertices, numberOfTriangles, SurfaceSlabBytes);
    std::int64_t mostVertices = 0, mostTriangles = 0;
    for (const SurfaceSlab& slab : slabs)
    {
      mostVertices = std::max(mostVertices, slab.Vertices);
      mostTriangles = std::max(mostTriangles, slab.Triangles);
    }
    this->OutPoints.Allocate(this->Ledger, 3 * mostVertices, "the vertices");
    this->OutNormals.Allocate(this->Ledger, 3 * mostVertices, "the normals");
    this->OutTriangles.Allocate(this->Ledger, 3 * mostTriangles, "the triangles");
    k.Points = this->OutPoints.Data();
    k.Normals = this->OutNormals.Data();
    k.Triangles = this->OutTriangles.Data();
    for (const SurfaceSlab& slab : slabs)
    {
      k.PointsBase = slab.FirstVertex;
      k.TrianglesBase = slab.FirstTriangle;
      this->Launch("VerticesKernel", slab.Begin, slab.End, VerticesKernel{ k, this->KC });
      this->Launch("TrianglesKernel", slab.Begin, slab.End, TrianglesKernel{ k, this->KC });
      if (slab.Vertices > 0)
      {
        this->Transfers.ToHost(
          points + 3 * slab.FirstVertex, k.Points, sizeof(double) * 3 * slab.Vertices, "the vertices back");
        this->Transfers.ToHost(
          normals + 3 * slab.FirstVertex, k.Normals, sizeof(float) * 3 * slab.Vertices, "the normals back");
      }
      if (slab.Triangles > 0)
      {
        this->Transfers.ToHost(triangles + 3 * slab.FirstTriangle, k.Triangles,
          sizeof(long long) * 3 * slab.Triangles, "the triangles back");
      }
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
      this->DensePhi.Allocate(this->Ledger, nodes, "the dense phi");
    if (arrays.InitialPhi)
      this->DenseInitialPhi.Allocate(this->Ledger, nodes, "the dense phi0");
    if (arrays.Distance)
      this->DenseDistance.Allocate(this->Ledger, nodes, "the dense distances");
    if (arrays.Band)
      this->DenseFlags.Allocate(this->Ledger, nodes, "the dense band flags");
    this->V.Phi = this->DensePhi.Data();
    this->V.InitialPhi = this->DenseInitialPhi.Data();
    this->V.Distance = this->DenseDistance.Data();
    this->V.Band = this->DenseFlags.Data();
    this->Launch("DenseClearKernel", 0, nodes, DenseClearKernel{ this->V, constants });
  }
  void DenseBricks(std::int64_t count) override
  {
    DistanceArrays batch;
    batch.Bricks = this->Bricks.Data();
    batch.Distance = this->BrickDistance.Data();
    batch.Covered = this->Covered.Data();
    this->Launch("DenseBrickKernel", 0, count * 512, DenseBrickKernel{ batch, this->V, this->VC });
  }
  void DenseBand(const DenseBandArrays& band, std::int64_t numberOfBricks, std::int64_t numberOfNodes) override
  {
    Scratch scratch(this->Transfers); // the band's copies, freed on the way out
    DenseBandArrays onDevice;
    onDevice.Bricks = scratch.Copy(this->Ledger, band.Bricks, numberOfBricks, "the band's bricks");
    onDevice.RedStart = scratch.Copy(this->Ledger, band.RedStart, numberOfBricks + 1, "the band's red starts");
    onDevice.BlackStart = scratch.Copy(this->Ledger, band.BlackStart, numberOfBricks + 1, "the band's black starts");
    onDevice.Offset = scratch.Copy(this->Ledger, band.Offset, numberOfNodes, "the band's node places");
    // The evolution's phi, still here (Download copied it, kept it).
    onDevice.Phi = this->Phi.Data() && this->A.Size == numberOfNodes
      ? this->Phi.Data()
      : scratch.Copy(this->Ledger, band.Phi, numberOfNodes, "phi");
    this->Launch("DenseBandKernel", 0, numberOfBricks, DenseBandKernel{ onDevice, this->V, this->VC });
    Check(cudaDeviceSynchronize(), "running DenseBandKernel");
  }
  void DenseDownload() override
  {
    const std::int64_t nodes = this->VC.Nodes();
    const std::size_t floats = sizeof(float) * static_cast<std::size_t>(nodes);
    if (this->V.Phi)
      this->Transfers.ToHost(this->HostDense.Phi, this->V.Phi, floats, "the dense phi back");
    if (this->V.InitialPhi)
      this->Transfers.ToHost(this->HostDense.InitialPhi, this->V.InitialPhi, floats, "the dense phi0 back");
    if (this->V.Distance)
      this->Transfers.ToHost(this->HostDense.Distance, this->V.Distance, floats, "the dense distances back");
    if (this->V.Band)
      this->Transfers.ToHost(this->HostDense.Band, this->V.Band, static_cast<std::size_t>(nodes),
        "the dense band flags back");
    this->ReleaseDense();
  }

private:
  void ReleaseDense()
  {
    this->DensePhi.Reset();
    this->DenseInitialPhi.Reset();
    this->DenseDistance.Reset();
    this->DenseFlags.Reset();
    this->V = DenseArrays();
    this->HostDense = DenseArrays();
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
    this->Transfers.ToHost(hostSums.data(), sums, sizeof(std::int64_t) * hostSums.size(), "the chunks' sums back");
    const std::int64_t total = ChunkStarts(hostSums, hostFirst);
    this->Transfers.ToDevice(first, hostFirst.data(), sizeof(std::int64_t) * hostFirst.size(), "the chunks' starts");
    return total;
  }
  void ReleaseContour()
  {
    this->ContourUploads.Clear();
    this->Psi.Reset();
    this->Cut.Reset();
    this->Above.Reset();
    this->VertexCount.Reset();
    this->TriangleCount.Reset();
    this->OutPoints.Reset();
    this->OutNormals.Reset();
    this->OutTriangles.Reset();
    this->K = ContourArrays();
  }
  /// A band built before (StoreBand, ConnectBand) and not evolved, or the
  /// evolution's distances and neighbour table.
  void ReleaseBand()
  {
    this->BandOffset.Reset();
    this->Distance.Reset();
    this->Neighbor.Reset();
    this->BandSize = 0;
  }
  template <typename T>
  static void CopyOnDevice(T* to, const T* from, std::int64_t count, const char* what)
  {
    if (count > 0)
    {
      Check(cudaMemcpy(to, from, sizeof(T) * count, cudaMemcpyDeviceToDevice), what);
    }
  }
  /// `kernel` on [begin, end), `name` in its errors; waits for it with
  /// NV_CUDA_SYNC.
  template <typename Kernel>
  void Launch(const char* name, std::int64_t begin, std::int64_t end, const Kernel& kernel)
  {
    if (end > begin)
    {
      ForEach<<<BlocksFor(end - begin), Threads>>>(begin, end, kernel);
      Check(cudaGetLastError(), std::string("launching ") + name);
      if (this->Synchronous)
      {
        Check(cudaDeviceSynchronize(), std::string("running ") + name);
      }
    }
  }
  /// The max or the sum of kernel over [begin, end) into Results[slot], on
  /// the device (0 for an empty range); ReadResults brings it back.
  template <bool Max, typename Kernel>
  void Reduction(const char* name, std::int64_t begin, std::int64_t end, const Kernel& kernel, int slot)
  {
    double* partial = this->Partial.Data() + static_cast<std::int64_t>(slot) * MaximumBlocks;
    double* result = this->Results.Data() + slot;
    if (end <= begin)
    {
      Check(cudaMemset(result, 0, sizeof(double)), std::string("clearing ") + name + "'s result");
      return;
    }
    const int blocks = BlocksFor(end - begin);
    Reduce<Max><<<blocks, Threads>>>(begin, end, kernel, partial);
    Check(cudaGetLastError(), std::string("launching ") + name);
    FinishReduce<Max><<<1, Threads>>>(partial, blocks, result);
    Check(cudaGetLastError(), std::string("launching ") + name + "'s last stage");
    if (this->Synchronous)
    {
      Check(cudaDeviceSynchronize(), std::string("running ") + name);
    }
  }
  /// Results[0 .. count) into host memory: one small read, after the kernels.
  void ReadResults(int count, double* values, const char* what)
  {
    this->Transfers.ToHost(values, this->Results.Data(), sizeof(double) * count, std::string(what) + " back");
  }

  std::string DeviceName;
  bool Synchronous = false; ///< NV_CUDA_SYNC: wait for each launch
  /// Counts the arrays below; declared first, so that it outlives them.
  DeviceLedger Ledger;
  /// The copies to and from host memory (pinned buffers, a stream).
  Staging& Transfers = SharedStaging();
  CopyCounts CopiedBefore = Transfers.Counted(); ///< the process's copies before this launcher
  // The truncated distance's arrays (DistanceArrays), until FreePoints.
  Array<double> Points;
  Array<std::int64_t> BucketStart;
  std::int64_t BatchCapacity = 0; ///< bricks the batch's buffers hold
  Array<std::int64_t> Bricks;
  Array<double> BrickDistance;
  Array<std::uint8_t> Covered;
  // The band nodes of a batch (BandNodeArrays): the counts' buffers, and
  // each batch's list until StoreBand.
  std::int64_t NodeCapacity = 0; ///< bricks the counts' buffers hold
  Array<std::int32_t> RedCount;
  Array<std::int32_t> BlackCount;
  Array<std::int64_t> RedFirst;
  Array<std::int64_t> BlackFirst;
  Array<std::uint64_t> Inside;
  struct BatchNodes
  {
    std::int64_t Red = 0; ///< its red nodes first
    Array<std::uint16_t> Offset;
    Array<double> Distance;
  };
  std::vector<BatchNodes> Batches;
  // The band built here (StoreBand, ConnectBand): its Offset until the
  // evolution's Upload; Distance and Neighbor until InitialField and
  // ReleaseEvolution.
  std::int64_t BandSize = 0;
  std::int64_t BandRedCount = 0;
  Array<std::uint16_t> BandOffset;
  Array<double> Distance;
  Array<std::uint32_t> Neighbor;
  // The evolution's arrays (A points into them); phi stays after
  // ReleaseEvolution for the dense volume and the surface.
  EvolutionArrays A;
  Array<double> Phi;
  Array<double> Previous;
  Array<double> Coupling;
  Array<float> Decay;
  // The dense volume (DenseArrays): on the device in V, the host's in
  // HostDense, until DenseDownload.
  DenseArrays V;
  DenseArrays HostDense;
  DenseConstants VC;
  Array<float> DensePhi;
  Array<float> DenseInitialPhi;
  Array<float> DenseDistance;
  Array<std::uint8_t> DenseFlags;
  // The surface's arrays (ContourArrays): the uploaded ones in
  // ContourUploads, the others below, until ContourGeometry ends.
  ContourArrays K;
  ContourConstants KC;
  Scratch ContourUploads{ this->Transfers };
  Array<float> Psi;
  Array<std::uint64_t> Cut;
  Array<std::uint16_t> Above;
  Array<std::int32_t> VertexCount;
  Array<std::int32_t> TriangleCount;
  Array<double> OutPoints;
  Array<float> OutNormals;
  Array<long long> OutTriangles;
  static constexpr int Slots = 4; ///< reductions read back together (StepSums)
  Array<double> Partial;          ///< MaximumBlocks per slot
  Array<double> Results;          ///< one value per slot
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
