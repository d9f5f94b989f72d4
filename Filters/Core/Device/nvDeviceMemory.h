// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// A launcher's memory on its device: buffers that own it (DeviceBuffer,
// freed when they go, whatever throws), the count of bytes they hold
// (DeviceLedger), the error a launcher throws (DeviceError), and what a run
// needs on the device, counted from the CUDA launcher's arrays, for the
// run's checks against the device's free memory before the band and before
// the evolution (Run/nvDeviceEngine.cxx).
//
// Both launchers hold their arrays in DeviceBuffers over one ledger: the
// CUDA launcher's memory is cudaMalloc's, the host launcher's malloc's. The
// ledger's limit (a test hook of the host launcher, MakeHostLauncher) makes
// an allocation fail as a full GPU's would, so that the suite checks that
// no buffer leaks and the count does not drift after a failed allocation
// (TestCoreDevice).
#ifndef nvDeviceMemory_h
#define nvDeviceMemory_h

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

namespace nv
{
/// The copies between the host's memory and the GPU's during a run: bytes
/// and seconds each way (the benchmarks' bandwidths; none on the CPU or
/// through the host launcher, whose arrays are the host's).
struct CopyCounts
{
  double ToHostBytes = 0.0;
  double ToHostSeconds = 0.0;
  double ToDeviceBytes = 0.0;
  double ToDeviceSeconds = 0.0;
};

namespace device
{

/// What a launcher throws when the device fails (an allocation, a copy, a
/// launch): the message says which kernel or array, with the CUDA runtime's
/// words.
class DeviceError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

/// Bytes in words: "12.3 MB" below a GB, "4.56 GB" above (decimal units,
/// three digits).
std::string ByteWords(double bytes);

/// The bytes a launcher's buffers hold now, the most they held at once,
/// and the most they may hold (a test hook: an allocation beyond it fails
/// as a full device's does; no limit by default).
class DeviceLedger
{
public:
  double Held() const { return this->Bytes; }
  double Peak() const { return this->Most; }
  void SetLimit(double bytes) { this->Limit = bytes; }
  /// Throws DeviceError naming `what` if `bytes` more would pass the limit.
  void CheckLimit(std::size_t bytes, const char* what) const;
  void Add(std::size_t bytes)
  {
    this->Bytes += static_cast<double>(bytes);
    this->Most = std::max(this->Most, this->Bytes);
  }
  void Remove(std::size_t bytes) { this->Bytes -= static_cast<double>(bytes); }

private:
  double Bytes = 0.0;
  double Most = 0.0;
  double Limit = std::numeric_limits<double>::infinity();
};

/**
 * `count` values of T in a device's memory, which this buffer owns: freed
 * when it is reset, given new memory, or destroyed, and counted in its
 * ledger meanwhile. `Memory` allocates and frees: static void*
 * Allocate(std::size_t bytes, const char* what), which throws DeviceError
 * naming `what` when it cannot, and static void Free(void*), which does not
 * throw. Moves, does not copy.
 */
template <typename T, typename Memory>
class DeviceBuffer
{
public:
  DeviceBuffer() = default;
  ~DeviceBuffer() { this->Reset(); }
  DeviceBuffer(const DeviceBuffer&) = delete;
  DeviceBuffer& operator=(const DeviceBuffer&) = delete;
  DeviceBuffer(DeviceBuffer&& other) noexcept { this->Take(other); }
  DeviceBuffer& operator=(DeviceBuffer&& other) noexcept
  {
    if (this != &other)
    {
      this->Reset();
      this->Take(other);
    }
    return *this;
  }

  /// Frees what this buffer held, then holds `count` values (at least one
  /// is allocated), unset, counted in `ledger`. On a failure (DeviceError)
  /// it holds nothing and the ledger is as before minus the freed memory.
  void Allocate(DeviceLedger& ledger, std::int64_t count, const char* what)
  {
    this->Reset();
    const std::size_t bytes = static_cast<std::size_t>(std::max<std::int64_t>(count, 1)) * sizeof(T);
    ledger.CheckLimit(bytes, what);
    this->Values = static_cast<T*>(Memory::Allocate(bytes, what)); // throws, holding nothing
    this->Count = std::max<std::int64_t>(count, 0);
    this->Bytes = bytes;
    this->Ledger = &ledger;
    ledger.Add(bytes);
  }
  /// Frees the memory (none held: nothing).
  void Reset() noexcept
  {
    if (this->Values)
    {
      Memory::Free(this->Values);
      this->Ledger->Remove(this->Bytes);
    }
    this->Values = nullptr;
    this->Count = 0;
    this->Bytes = 0;
    this->Ledger = nullptr;
  }
  T* Data() const { return this->Values; }
  /// The values asked for (0 when none is held).
  std::int64_t Size() const { return this->Count; }

private:
  void Take(DeviceBuffer& other) noexcept
  {
    this->Values = other.Values;
    this->Count = other.Count;
    this->Bytes = other.Bytes;
    this->Ledger = other.Ledger;
    other.Values = nullptr;
    other.Count = 0;
    other.Bytes = 0;
    other.Ledger = nullptr;
  }

  T* Values = nullptr;
  std::int64_t Count = 0;
  std::size_t Bytes = 0;
  DeviceLedger* Ledger = nullptr;
};

// What a run needs on the device, counted from the CUDA launcher's arrays
// (nvCudaLauncher.cu; doc/performance.md, "On a GPU"), for the run's checks
// before each stage (Run/nvDeviceEngine.cxx).

/**
 * The band's construction before the band's own arrays: the points' sort
 * (56 bytes a point: the cloud, the sorted points, each point's brick; 17
 * a brick of the grid: the buckets, their free slots, the reached marks;
 * 16 a chunk of 256 bricks), or after it, whichever is more, the sorted
 * points and their buckets (24 a point, 8 a brick) with `dense` bytes of
 * dense arrays (DenseBytes) and a batch's buffers (DistanceBricks,
 * BandNodes: 4,193 bytes a brick of `batch`). The list of the bricks
 * reached (8 bytes each) is left out: the grid's bricks are far more.
 */
double BandBuildBytes(std::int64_t points, std::int64_t bricks, std::int64_t batch, double dense);
/// The evolution's arrays on a band of `nodes` nodes, on top of the band's
/// (Upload): phi with its two slots, phi^n, the coupling (8 bytes a node
/// each) and the decay (4), less the distances (8) and node places (2),
/// let go before phi^n, the coupling and the decay come (InitialField):
/// 18 bytes a node and 16 (the band's 34 and these, 52 a node at the peak).
double EvolutionBytes(std::int64_t nodes);

/// The surface's tables (ContourCounts, ContourGeometry's firsts), on top
/// of phi: per band brick its bricks, starts and inside bits (88 bytes) and
/// psi (2,048); the node places (2 a node); per cut brick 386 (the cut
/// edges 192, the corners' signs 162, the counts 8, the list 8, the first
/// vertex and triangle 16). The outputs come after, slab by slab
/// (SurfaceSlabs).
double SurfaceTableBytes(std::int64_t bandBricks, std::int64_t nodes, std::int64_t cutBricks);

/// The dense arrays of `nodes` nodes: 4 bytes a node for each of phi,
/// phi0 and d asked for, 1 for the band flags.
double DenseBytes(std::int64_t nodes, int floatArrays, bool bandFlags);

/// The host's memory available now, in bytes (Linux: MemAvailable; elsewhere
/// the free physical memory); infinity if unknown.
double HostAvailableBytes();

} // namespace device
} // namespace nv

#endif
