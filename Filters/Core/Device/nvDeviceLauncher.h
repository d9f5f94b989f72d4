// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The two launchers of the device back end's kernels (nvDeviceKernels.h):
// the host launcher runs them over the thread pool on any machine, the CUDA
// launcher on a GPU. Each method is one kernel over a range of band nodes
// or bricks, or a copy; the loops that call them are in nvDeviceEvolution.cxx
// and nvDeviceDistance.cxx.
//
// The CUDA launcher is compiled only where CMake finds a CUDA compiler
// (NARROWVOLUME_CUDA); without it, MakeCudaLauncher says the build has no
// CUDA. The suite runs the kernels through the host launcher and compiles
// the CUDA one (scripts/test.sh); scripts/test-gpu.sh runs it on a machine
// with a GPU (where it stands: doc/performance.md, "On a GPU").
//
// Both launchers hold their arrays in DeviceBuffers (nvDeviceMemory.h):
// each owns its memory and is counted, so that nothing leaks and the count
// stays right whatever fails; a DeviceError names the kernel or array.
#ifndef nvDeviceLauncher_h
#define nvDeviceLauncher_h

#include "nvDeviceKernels.h"
#include "nvSurfaceKernels.h"
#include "nvVolumeKernels.h"
#include "nvDeviceMemory.h"
#include "nvMemory.h"

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace nv
{
namespace device
{

// A launcher's kernels come in four groups, one interface each, so that a
// stage's code sees only its own: the points' sort, the distances and the
// band (BandLauncher: nvDeviceDistance.h), the evolution
// (EvolutionLauncher: nvDeviceEvolution.h), the surface (SurfaceLauncher:
// nvDeviceSurface.h) and the dense volume (DenseLauncher). Launcher is all
// four, as the host and the CUDA launchers implement them.

/// The evolution's kernels (nvDeviceKernels.h), run by nvDeviceEvolution.h.
class EvolutionLauncher
{
public:
  virtual ~EvolutionLauncher();
  /// Holds the arrays of a band of `size` nodes (EvolutionArrays) and copies
  /// the neighbour table (6 per node) and the distances there; phi's two
  /// Dirichlet slots (eq. 5) get `inside` and `outside`. The host launcher
  /// reads the band's arrays in place, which must then outlive it. Both
  /// null: the band this launcher built (StoreBand, ConnectBand), already
  /// there; a DeviceError if it holds none of `size` nodes.
  virtual void Upload(std::int64_t size, const std::uint32_t* neighbor, const double* distance, double inside,
    double outside) = 0;
  /// phi^0 (InitialPhiKernel) on all nodes, then the distances are freed.
  virtual void InitialField(const EvolutionConstants& constants) = 0;
  /// CoefficientsKernel on all nodes.
  virtual void Coefficients(const EvolutionConstants& constants) = 0;
  /// KeepPreviousKernel on all nodes.
  virtual void KeepPrevious() = 0;
  /// One Gauss-Seidel sweep: RelaxKernel on the red nodes [red[0], red[1]),
  /// then on the black ones [black[0], black[1]); the max |change| of both,
  /// the sweep's one read from the device.
  virtual double Sweep(const std::int64_t red[2], const std::int64_t black[2], double omega) = 0;
  /// ReactKernel on all nodes.
  virtual void React() = 0;
  /// The sums of section 4's stopping rule, in one read from the device:
  /// ChangeSquaredKernel over the red nodes, then over the black ones
  /// (sums[0], sums[1]), NormSquaredKernel likewise (sums[2], sums[3]).
  virtual void StepSums(const std::int64_t red[2], const std::int64_t black[2], double sums[4]) = 0;
  /// A copy of phi's size + 2 values into `phi` (host memory), after the
  /// last kernel, before or after ReleaseEvolution; phi stays held here.
  /// Only where the host reads phi: the device's dense volume and surface
  /// take it where it is.
  virtual void Download(UninitializedVector<double>& phi) = 0;
  /// After the evolution: its arrays freed but phi, which stays on the
  /// device for the dense volume (DenseBand), the surface (ContourCounts)
  /// and Download, so that it does not go up again (until the launcher
  /// goes).
  virtual void ReleaseEvolution() = 0;
};

/// The truncated distance of eq. (6) and the band built from it
/// (DistanceKernel, CoveredKernel, the band's kernels), before the
/// evolution: nvDeviceDistance.h calls these.
class BandLauncher
{
public:
  virtual ~BandLauncher();
  /// Sorts the points on the device: `cloud` (host memory, 3 a point, world
  /// coordinates, all in the grid's box) copied to the device and sorted
  /// into the grid's bricks as TruncatedDistance's constructor does
  /// (BucketPointsKernel, ChunkSumKernel, ChunkScanKernel,
  /// ScatterPointsKernel), the sorted points held until FreePoints; the
  /// bricks they reach (ReachKernel, ChunkSumKernel, ReachListKernel) into
  /// `reached`, ascending: TruncatedDistance::ReachedBricks'.
  virtual void SortPoints(const double* cloud, std::int64_t numberOfPoints, const PointConstants& constants,
    std::vector<std::int64_t>& reached) = 0;
  /// CoveredKernel on the `count` bricks `bricks` (host memory, kept until
  /// the next batch), then DistanceKernel on their nodes; `distance`
  /// (BrickNodes per brick) and `covered` (one per brick), host memory, get
  /// them back, unless null (then they stay on the device for BandNodes).
  virtual void DistanceBricks(const std::int64_t* bricks, std::int64_t count, const DistanceConstants& constants,
    double* distance, std::uint8_t* covered) = 0;
  /// The collect pass, after DistanceBricks on the same `count` bricks:
  /// BandCountKernel, the sums of the counts (BandNodeArrays' RedFirst,
  /// BlackFirst), BandCompactKernel into a list of the batch's band nodes,
  /// kept here for StoreBand. Back into host memory come the counts (`red`,
  /// `black`: count each) and the Inside bits (8 words a brick).
  virtual void BandNodes(std::int64_t count, const BandNodeConstants& constants, std::int32_t* red,
    std::int32_t* black, std::uint64_t* inside) = 0;
  /// The store pass: the batches' lists joined into the band's Offset and Distance
  /// (`size` nodes, the `redCount` red ones first, each colour in brick
  /// order), held here for the evolution; the lists freed. Offset into host
  /// memory `offset` (size values), which the outputs read.
  virtual void StoreBand(std::int64_t redCount, std::int64_t size, std::uint16_t* offset) = 0;
  /// The connect pass, after StoreBand: the band's bricks and starts (host memory,
  /// NarrowBand's, of `numberOfBricks` bricks) copied here,
  /// AdjacentBricksKernel and NeighboursKernel: the neighbour table, held
  /// here for the evolution (Upload with null arrays).
  virtual void ConnectBand(const std::int64_t* bricks, const std::int64_t* redStart, const std::int64_t* blackStart,
    std::int64_t numberOfBricks, const NeighbourConstants& constants) = 0;
  /// The held band's distances (size values) and neighbour table (6 size)
  /// into host memory, for the checks against the CPU's band.
  virtual void DownloadBand(double* distance, std::uint32_t* neighbor) = 0;
  /// Lets the points go (their device memory freed), with the batches'
  /// lists of band nodes that StoreBand did not take; the held band stays.
  virtual void FreePoints() = 0;
};

/// The surface (nvSurfaceKernels.h), after the evolution:
/// nvDeviceSurface.h calls these.
class SurfaceLauncher
{
public:
  virtual ~SurfaceLauncher();
  /// The cut bricks of `band` (host memory: its Bricks, RedStart,
  /// BlackStart and Inside of NumberOfBricks bricks), ascending, into `cut`:
  /// CutMarkKernel on the band's bricks marks them, a byte a brick of the
  /// grid, and the marks are listed in order as the point sort's reached
  /// bricks (ChunkSumKernel, ChunkStarts on the host, ReachListKernel).
  /// CutBricksOf's list (nvDeviceSurface.h), made by kernels.
  virtual void CutBricks(const ContourArrays& band, const ContourConstants& constants,
    std::vector<std::int64_t>& cut) = 0;
  /// Holds the band's arrays, phi and the cut bricks of `band` (host memory:
  /// Bricks, RedStart, BlackStart, Inside of NumberOfBricks bricks, Offset
  /// and Phi of `numberOfNodes` nodes, CutBricks, Cases; the host launcher
  /// reads them in place, and they must then outlive it until
  /// ContourGeometry; both launchers take the evolution's phi where they
  /// still hold it, ReleaseEvolution, instead of reading Phi, which may
  /// then be null), runs PsiKernel on the band's bricks and
  /// CutCellsKernel on the cut bricks; `vertices` and `triangles` (host
  /// memory, one a cut brick) get their counts back.
  virtual void ContourCounts(const ContourArrays& band, std::int64_t numberOfNodes, const ContourConstants& constants,
    std::int32_t* vertices, std::int32_t* triangles) = 0;
  /// After ContourCounts: each cut brick's first vertex and first triangle
  /// (host memory), VerticesKernel and TrianglesKernel; the
  /// `numberOfVertices` vertices (3 coordinates and 3 normal components
  /// each) and `numberOfTriangles` triangles (3 vertex ids each) into host
  /// memory, slab by slab of cut bricks (SurfaceSlabs: the CUDA launcher
  /// holds one slab's outputs at a time, SurfaceSlabBytes at most unless a
  /// single brick needs more). Then the surface's arrays are freed.
  virtual void ContourGeometry(const std::int64_t* firstVertex, const std::int64_t* firstTriangle,
    std::int64_t numberOfVertices, std::int64_t numberOfTriangles, double* points, float* normals,
    long long* triangles) = 0;
};

/// The dense volume (nvVolumeKernels.h), when the run fills one with
/// Device GPU (Run/nvDeviceEngine.cxx): DenseBegin before the band's
/// construction, DenseBricks after each batch of its distances
/// (nvDeviceDistance.h), DenseBand and DenseDownload after the evolution.
class DenseLauncher
{
public:
  virtual ~DenseLauncher();
  /// Holds the dense arrays `arrays` (host memory, constants.Nodes() values
  /// each; a null one is not filled) and clears them (DenseClearKernel):
  /// the host launcher fills them in place, the CUDA launcher on the device
  /// until DenseDownload.
  virtual void DenseBegin(const DenseArrays& arrays, const DenseConstants& constants) = 0;
  /// DenseBrickKernel on the nodes of the `count` bricks of the last
  /// DistanceBricks.
  virtual void DenseBricks(std::int64_t count) = 0;
  /// DenseBandKernel on the band's `numberOfBricks` bricks (`band`: host
  /// memory; its Phi, `numberOfNodes` values, is read only where the
  /// launcher no longer holds the evolution's phi, and may then be null).
  virtual void DenseBand(const DenseBandArrays& band, std::int64_t numberOfBricks, std::int64_t numberOfNodes) = 0;
  /// The dense arrays into the host memory given to DenseBegin; then freed.
  virtual void DenseDownload() = 0;
};

/// A launcher: the four groups of kernels on one device.
class Launcher
  : public BandLauncher
  , public EvolutionLauncher
  , public SurfaceLauncher
  , public DenseLauncher
{
public:
  /// "host launcher" or "CUDA (device name)".
  virtual std::string Name() const = 0;
  /// The most bytes the launcher's buffers have held on its device at once
  /// (the host launcher: its own arrays, in host memory).
  virtual double DeviceBytes() const = 0;
  /// The bytes its buffers hold now: 0 once it has let everything go,
  /// whatever failed before.
  virtual double HeldBytes() const = 0;
  /// Its copies between the host and the device so far (none for the host
  /// launcher).
  virtual CopyCounts Copies() const = 0;
  /// The device's free memory now, in bytes: cudaMemGetInfo's on a GPU; the
  /// host launcher's, the host's available memory (HostAvailableBytes) or
  /// the test hook's (HostLauncherHooks). The run compares what it will
  /// need with it before the band and before the evolution.
  virtual double FreeBytes() const = 0;
};

/// Where each brick of a batch puts its band nodes (BandNodeArrays'
/// RedFirst, BlackFirst) from its counts: the batch's red nodes first,
/// brick after brick, then its black ones. count + 1 values each: the last
/// red one is the batch's number of red nodes, the last black one of all.
void FirstNodes(const std::int32_t* red, const std::int32_t* black, std::int64_t count,
  std::vector<std::int64_t>& redFirst, std::vector<std::int64_t>& blackFirst);

/// The device memory the surface's outputs may take at once: the vertices
/// (36 bytes each) and triangles (24) are made and copied to the host slab
/// by slab of cut bricks.
constexpr double SurfaceSlabBytes = 256.0 * 1024 * 1024;

/// One slab of cut bricks, [Begin, End): its Vertices vertices from id
/// FirstVertex on and its Triangles triangles from FirstTriangle on.
struct SurfaceSlab
{
  std::int64_t Begin = 0, End = 0;
  std::int64_t FirstVertex = 0, Vertices = 0;
  std::int64_t FirstTriangle = 0, Triangles = 0;
  /// The device memory of `vertices` vertices (36 bytes each: coordinates
  /// and normal) and `triangles` triangles (24).
  static double BytesOf(std::int64_t vertices, std::int64_t triangles)
  {
    return 36.0 * static_cast<double>(vertices) + 24.0 * static_cast<double>(triangles);
  }
  double Bytes() const { return BytesOf(this->Vertices, this->Triangles); }
};

/// Splits the `count` cut bricks into slabs, in order, whose outputs take
/// at most `maximumBytes` (a brick that alone needs more is a slab of its
/// own), from each brick's first vertex and first triangle
/// (ContourGeometry's) and the totals. At least one slab (0 to count).
std::vector<SurfaceSlab> SurfaceSlabs(const std::int64_t* firstVertex, const std::int64_t* firstTriangle,
  std::int64_t count, std::int64_t numberOfVertices, std::int64_t numberOfTriangles, double maximumBytes);

/// The host launcher's test hooks: a limit on the bytes its buffers may
/// hold at once (an allocation beyond it fails as on a full GPU, with a
/// DeviceError), and the free memory it reports (FreeBytes); both < 0: none
/// (the host's available memory is reported).
struct HostLauncherHooks
{
  double AllocationLimit = -1.0;
  double FreeBytes = -1.0;
  /// > 0: the surface's outputs written slab by slab of at most these
  /// bytes (SurfaceSlabs), as the CUDA launcher does; else in one.
  double SurfaceSlabBytes = -1.0;
};

/// The host launcher: the kernels over nv::ParallelFor and its reductions.
std::unique_ptr<Launcher> MakeHostLauncher(const HostLauncherHooks& hooks = HostLauncherHooks());

/// The bytes all host launchers' arrays hold now, counted by their
/// allocator apart from their ledgers: the tests' check that a failed
/// allocation leaks nothing.
double HostLauncherBytes();

/// Whether this build has the CUDA launcher (NARROWVOLUME_CUDA).
bool CudaCompiled();
/**
 * The CUDA launcher on the current CUDA device, or null with `why` set: the
 * build has no CUDA, or the CUDA runtime finds no device (its words in `why`).
 */
std::unique_ptr<Launcher> MakeCudaLauncher(std::string& why);

} // namespace device
} // namespace nv

#endif
