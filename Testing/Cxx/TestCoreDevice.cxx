// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The device back end (Filters/Core/Device) against the CPU core.
//
//   TestCoreDevice          its kernels through the host launcher: phi on
//                           the band is the CPU core's solver's bit for bit
//                           (the same formulas, the same reductions), on a
//                           sphere and a torus, both edge-stopping functions
//                           and the literal stopping rule; the truncated
//                           distance (eq. 6) the CPU core's bit for bit on
//                           every reached brick of a sphere and a torus, and
//                           the band built from it (its nodes picked on the
//                           device, or on the host from the distances) the
//                           CPU's array for array; the surface made by the
//                           surface kernels (nvDeviceSurface.h) from the
//                           device's phi the CPU core's (ContourBricks)
//                           bit for bit, both sheets closed;
//                           and the whole run with Device GPU (the property)
//                           against Device CPU: the surfaces the same bit
//                           for bit (within 0.05 h on a GPU), both sheets
//                           closed, and with the Volume output its dense
//                           arrays (filled on the device) the CPU's;
//   TestCoreDevice cuda     the same through the CUDA launcher, on a GPU
//                           (scripts/test-gpu.sh): phi within 1e-9 of the
//                           CPU core's (fused multiply-adds and the
//                           reductions' order change the last bits); the
//                           distances and the band bit for bit, as on the
//                           host (nvDeviceKernels.h keeps nvcc from fusing
//                           the distance's products and sums); the surfaces'
//                           vertices within 0.05 h of the CPU's, closed.
//   TestCoreDevice cuda small   one sphere through every kernel (the evolution
//                           and its surface, the distances and the band,
//                           the whole run with the Volume output): the case
//                           scripts/test-gpu.sh runs under compute-sanitizer,
//                           where kernels run many times slower.
//
// Device GPU where there is no GPU stops with an error that says why: the
// build has no CUDA, or the machine no CUDA device. A device that fails, or
// lacks the memory a stage needs (checked before the band and before the
// evolution against its free memory), stops the run with an error that
// says so; a failed allocation leaks nothing and the launcher's count of
// its bytes does not drift (both checked through the host launcher, whose
// test hooks limit its allocations and set the free memory it reports).
#include "nvAllenCahnSolver.h"
#include "nvDeviceDistance.h"
#include "nvDeviceEvolution.h"
#include "nvDeviceLauncher.h"
#include "nvDeviceSurface.h"
#include "nvEngine.h"
#include "nvGrid.h"
#include "nvNarrowBand.h"
#include "nvParameters.h"
#include "nvReconstruct.h"
#include "nvReconstruction.h"
#include "nvSurface.h"
#include "nvSurfaceField.h"
#include "nvTestUtilities.h"
#include "nvTruncatedDistance.h"
#include "nvVolume.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <memory>
#include <mutex>
#include <numeric>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#ifndef NV_TEST_NAME
#define NV_TEST_NAME "TestCoreDevice"
#endif

namespace
{
bool OnGpu = false; ///< the CUDA launcher instead of the host launcher

std::unique_ptr<nv::device::Launcher> Launcher()
{
  if (!OnGpu)
  {
    return nv::device::MakeHostLauncher();
  }
  std::string why;
  std::unique_ptr<nv::device::Launcher> launcher = nv::device::MakeCudaLauncher(why);
  if (!launcher)
  {
    std::printf("FAILED: no CUDA launcher: %s\n", why.c_str());
  }
  return launcher;
}

/// Points on a torus of radii R (the tube's centre) and r about the z axis.
std::vector<double> TorusPoints(int n, double R, double r)
{
  std::vector<double> xyz;
  const int around = static_cast<int>(std::sqrt(n * R / r));
  const int tube = std::max(3, n / around);
  for (int a = 0; a < around; ++a)
  {
    const double u = 2.0 * M_PI * a / around;
    for (int b = 0; b < tube; ++b)
    {
      const double v = 2.0 * M_PI * (b + 0.5 * (a % 2)) / tube;
      xyz.push_back((R + r * std::cos(v)) * std::cos(u));
      xyz.push_back((R + r * std::cos(v)) * std::sin(u));
      xyz.push_back(r * std::sin(v));
    }
  }
  return xyz;
}

/// The band of the points on a grid of spacing h padded for offset l.
nv::NarrowBand BandOf(const std::vector<double>& xyz, const nv::Parameters& parameters)
{
  double bounds[6] = { 1e300, -1e300, 1e300, -1e300, 1e300, -1e300 };
  for (std::size_t p = 0; p < xyz.size(); p += 3)
  {
    for (int a = 0; a < 3; ++a)
    {
      bounds[2 * a] = std::min(bounds[2 * a], xyz[p + a]);
      bounds[2 * a + 1] = std::max(bounds[2 * a + 1], xyz[p + a]);
    }
  }
  const nv::Grid grid = nv::MakeGrid(bounds, parameters.Spacing,
    nv::GridPadding(parameters.Reach(), parameters.Spacing));
  const nv::TruncatedDistance distance(
    grid, xyz.data(), static_cast<std::int64_t>(xyz.size() / 3), parameters.Reach());
  return nv::BuildNarrowBand(distance, parameters);
}

void CompareSurface(const char* what, const nv::NarrowBand& band, const nv::BandValues& cpuPhi,
  const nv::BandValues& devicePhi, const nv::Parameters& parameters, nv::device::Launcher& launcher);

/// The device back end's phi against the CPU core's solver on one band,
/// then its surface against the CPU core's.
void Compare(const char* what, const std::vector<double>& xyz, const nv::Parameters& parameters)
{
  const nv::NarrowBand band = BandOf(xyz, parameters);
  NV_CHECK(band.Size() > 1000);

  nv::AllenCahnSolver solver(band, parameters);
  const std::vector<nv::StepReport> cpu = solver.Run();

  std::unique_ptr<nv::device::Launcher> launcher = Launcher();
  if (!launcher)
  {
    NV_CHECK(false);
    return;
  }
  const std::vector<nv::StepReport> device = nv::device::Evolve(band, parameters, *launcher, nullptr);
  nv::BandValues phi;
  launcher->Download(phi);

  NV_CHECK(phi.size() == solver.GetPhi().size());
  NV_CHECK(device.size() == cpu.size());
  double largest = 0.0;
  for (std::size_t s = 0; s < phi.size() && s < solver.GetPhi().size(); ++s)
  {
    largest = std::max(largest, std::fabs(phi[s] - solver.GetPhi()[s]));
  }
  int sweepsCpu = 0, sweepsDevice = 0;
  for (std::size_t n = 0; n < cpu.size() && n < device.size(); ++n)
  {
    sweepsCpu += cpu[n].Sweeps;
    sweepsDevice += device[n].Sweeps;
    if (OnGpu)
    {
      NV_CHECK_NEAR(device[n].RelativeChange, cpu[n].RelativeChange, 1e-9);
    }
    else
    {
      NV_CHECK(device[n].RelativeChange == cpu[n].RelativeChange);
      NV_CHECK(device[n].Sweeps == cpu[n].Sweeps);
    }
  }
  std::printf("%s on %s: %lld band nodes, %zu steps, sweeps %d (CPU %d), max |phi - phi_CPU| %.3g\n", what,
    launcher->Name().c_str(), static_cast<long long>(band.Size()), device.size(), sweepsDevice, sweepsCpu, largest);
  NV_CHECK(largest <= (OnGpu ? 1e-9 : 0.0));
  CompareSurface(what, band, solver.GetPhi(), phi, parameters, *launcher);
}

void TestSphere()
{
  const double center[3] = { 0.3, -0.1, 0.2 };
  nv::Parameters p;
  p.OffsetDistance = 0.1;
  p.Spacing = 0.02;
  p.MaximumNumberOfIterations = 3;
  Compare("sphere, eq. (4), 3 steps", nvtest::SpherePoints(4000, 0.5, center), p);
  p.EdgeStoppingFunction = nv::EdgeStopping::Eq3;
  p.Domain = nv::Domain::WholeDomain;
  Compare("sphere, eq. (3), whole domain", nvtest::SpherePoints(4000, 0.5, center), p);
}

void TestTorus()
{
  nv::Parameters p;
  p.OffsetDistance = 0.08;
  p.Spacing = 0.02;
  // The paper's literal rule, within a cap.
  p.MaximumNumberOfIterations = 8;
  p.ConvergenceTolerance = 1e-5;
  Compare("torus, the literal stopping rule", TorusPoints(8000, 0.6, 0.25), p);
  p.ConvergenceTolerance = 0.02; // stops before the cap
  p.Relaxation = 1.0;            // plain Gauss-Seidel
  Compare("torus, tolerance 0.02, plain Gauss-Seidel", TorusPoints(8000, 0.6, 0.25), p);
}

template <typename T, typename A, typename B>
bool SameValues(const std::vector<T, A>& a, const std::vector<T, B>& b)
{
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin());
}

/// The largest distance from a vertex of `a` to the nearest vertex of `b`
/// (vertices hashed into cells of size h).
double LargestVertexDistance(const nv::SurfaceMesh& a, const nv::SurfaceMesh& b, double h)
{
  const auto key = [h](const double* x, int di, int dj, int dk) {
    const std::int64_t i = static_cast<std::int64_t>(std::floor(x[0] / h)) + di;
    const std::int64_t j = static_cast<std::int64_t>(std::floor(x[1] / h)) + dj;
    const std::int64_t k = static_cast<std::int64_t>(std::floor(x[2] / h)) + dk;
    return (i * 73856093) ^ (j * 19349663) ^ (k * 83492791);
  };
  std::unordered_multimap<std::int64_t, std::size_t> cells;
  for (std::size_t p = 0; p < b.Points.size(); p += 3)
  {
    cells.emplace(key(&b.Points[p], 0, 0, 0), p);
  }
  double largest = 0.0;
  for (std::size_t p = 0; p < a.Points.size(); p += 3)
  {
    double nearest = 1e300;
    for (int di = -1; di <= 1; ++di)
      for (int dj = -1; dj <= 1; ++dj)
        for (int dk = -1; dk <= 1; ++dk)
        {
          const auto range = cells.equal_range(key(&a.Points[p], di, dj, dk));
          for (auto it = range.first; it != range.second; ++it)
          {
            const double* q = &b.Points[it->second];
            nearest = std::min(nearest,
              std::sqrt((a.Points[p] - q[0]) * (a.Points[p] - q[0]) + (a.Points[p + 1] - q[1]) * (a.Points[p + 1] - q[1]) +
                (a.Points[p + 2] - q[2]) * (a.Points[p + 2] - q[2])));
          }
        }
    largest = std::max(largest, nearest);
  }
  return largest;
}

/// Whether every edge of the mesh joins exactly two triangles; `pieces`
/// gets the number of connected pieces.
bool Closed(const nv::SurfaceMesh& mesh, int& pieces)
{
  std::map<std::pair<nv::VertexId, nv::VertexId>, int> edges;
  std::vector<std::size_t> parent(mesh.Points.size() / 3);
  std::iota(parent.begin(), parent.end(), 0);
  const auto root = [&parent](std::size_t v) {
    while (parent[v] != v)
    {
      v = parent[v] = parent[parent[v]];
    }
    return v;
  };
  for (std::size_t t = 0; t + 2 < mesh.Triangles.size(); t += 3)
  {
    for (int e = 0; e < 3; ++e)
    {
      const nv::VertexId u = mesh.Triangles[t + e], v = mesh.Triangles[t + (e + 1) % 3];
      ++edges[std::make_pair(std::min(u, v), std::max(u, v))];
      parent[root(static_cast<std::size_t>(u))] = root(static_cast<std::size_t>(v));
    }
  }
  pieces = 0;
  for (std::size_t v = 0; v < parent.size(); ++v)
  {
    pieces += root(v) == v ? 1 : 0;
  }
  for (const auto& edge : edges)
  {
    if (edge.second != 2)
    {
      return false;
    }
  }
  return !edges.empty();
}

/// The launcher's cut bricks (CutBricks: CutMarkKernel's marks listed by
/// the point sort's kernels) against CutBricksOf's, made on one host thread
/// with a sort: the same ascending list, on the host and on a GPU.
void CompareCutBricks(const char* what, const nv::NarrowBand& band, nv::device::Launcher& launcher)
{
  nv::device::ContourArrays arrays;
  arrays.NumberOfBricks = static_cast<std::int64_t>(band.Bricks.size());
  arrays.Bricks = band.Bricks.data();
  arrays.RedStart = band.RedStart.data();
  arrays.BlackStart = band.BlackStart.data();
  arrays.Inside = band.Inside.data();
  nv::device::ContourConstants constants;
  const std::array<std::int64_t, 3> dims = nv::BrickDimensions(band.GridNodes);
  for (int a = 0; a < 3; ++a)
  {
    constants.GridDims[a] = band.GridNodes.Dims[a];
    constants.BrickDims[a] = dims[a];
  }
  std::vector<std::int64_t> device;
  launcher.CutBricks(arrays, constants, device);
  const std::vector<std::int64_t> host = nv::CutBricksOf(band);
  std::printf("%s, the cut bricks by the kernels on %s: %zu of the band's %zu bricks, CutBricksOf's list: %s\n", what,
    launcher.Name().c_str(), device.size(), band.Bricks.size(), device == host ? "yes" : "NO");
  NV_CHECK(!host.empty());
  NV_CHECK(device == host);
}

/// The device back end's surface (nvDeviceSurface.h: the surface kernels of
/// nvSurfaceKernels.h) from the device's phi against the CPU core's
/// (ContourBricks on BandField) from the CPU's: through the host launcher
/// the same vertices, normals and triangles bit for bit; on a GPU, the
/// vertices within 0.05 h of the CPU's; both sheets closed either way.
void CompareSurface(const char* what, const nv::NarrowBand& band, const nv::BandValues& cpuPhi,
  const nv::BandValues& devicePhi, const nv::Parameters& parameters, nv::device::Launcher& launcher)
{
  CompareCutBricks(what, band, launcher);
  nv::SurfaceMesh cpu, device;
  NV_CHECK(nv::ContourBricks(band.GridNodes, nv::BandField(band, cpuPhi, parameters), cpu));
  nv::ContourOnDevice(band.GridNodes, band, devicePhi, parameters, launcher, device);
  const bool same = SameValues(device.Points, cpu.Points) && SameValues(device.Normals, cpu.Normals) &&
    SameValues(device.Triangles, cpu.Triangles);
  const double h = band.GridNodes.Spacing;
  const double apart =
    std::max(LargestVertexDistance(device, cpu, h), LargestVertexDistance(cpu, device, h));
  int cpuPieces = 0, devicePieces = 0;
  const bool cpuClosed = Closed(cpu, cpuPieces);
  const bool deviceClosed = Closed(device, devicePieces);
  std::printf("%s, the surface on %s: %zu vertices, %zu triangles (CPU %zu, %zu), the CPU's bit for bit: %s, "
              "the farthest vertex %.3g h from the other's; closed %d and %d, pieces %d and %d\n",
    what, launcher.Name().c_str(), device.Points.size() / 3, device.Triangles.size() / 3, cpu.Points.size() / 3,
    cpu.Triangles.size() / 3, same ? "yes" : "no", apart / h, deviceClosed, cpuClosed, devicePieces, cpuPieces);
  NV_CHECK(!device.Triangles.empty());
  NV_CHECK(same || OnGpu);
  NV_CHECK(apart <= 0.05 * h);
  NV_CHECK(deviceClosed && cpuClosed);
  NV_CHECK(devicePieces == cpuPieces);
}

/// The grid of BandOf for the points.
nv::Grid GridOf(const std::vector<double>& xyz, const nv::Parameters& parameters)
{
  double bounds[6] = { 1e300, -1e300, 1e300, -1e300, 1e300, -1e300 };
  for (std::size_t p = 0; p < xyz.size(); p += 3)
  {
    for (int a = 0; a < 3; ++a)
    {
      bounds[2 * a] = std::min(bounds[2 * a], xyz[p + a]);
      bounds[2 * a + 1] = std::max(bounds[2 * a + 1], xyz[p + a]);
    }
  }
  return nv::MakeGrid(bounds, parameters.Spacing, nv::GridPadding(parameters.Reach(), parameters.Spacing));
}

/// The device back end's truncated distance (DistanceKernel, CoveredKernel)
/// against the CPU core's (ComputeBrick, BrickWithin) on every reached
/// brick: the same bits (the same tests and arithmetic, nvDeviceKernels.h);
/// and the band built from it, array for array the CPU's.
void CompareDistance(
  const char* what, const std::vector<double>& xyz, const nv::Parameters& parameters, bool someCovered)
{
  const nv::Grid grid = GridOf(xyz, parameters);
  const std::int64_t numberOfPoints = static_cast<std::int64_t>(xyz.size() / 3);
  const nv::TruncatedDistance distance(grid, xyz.data(), numberOfPoints, parameters.Reach());
  const nv::TruncatedDistance gridOnly(grid, parameters.Reach()); // the device sorts the points
  std::unique_ptr<nv::device::Launcher> launcher = Launcher();
  if (!launcher)
  {
    NV_CHECK(false);
    return;
  }
  const std::vector<std::int64_t> bricks = distance.ReachedBricks();
  const double lower = parameters.OffsetDistance - parameters.HalfBandWidth();
  std::int64_t nodes = 0, finite = 0, differ = 0, coveredBricks = 0, coverDiffer = 0;
  double largest = 0.0;
  {
    // 1000 bricks a batch: several batches, the last one short.
    nv::device::LauncherDistance device(gridOnly, xyz.data(), numberOfPoints, *launcher, 1000);
    // The points sorted on the device reach the CPU's bricks.
    NV_CHECK(device.ReachedBricks() && *device.ReachedBricks() == bricks);
    // Bricks deep inside the shell tested here (covered, their distances
    // not computed); every brick's distances, none skipped, in the band's
    // check with a visitor below.
    std::vector<double> d(bricks.size() * nv::BrickNodes);
    std::vector<std::uint8_t> covered(bricks.size());
    for (std::size_t done = 0; done < bricks.size(); done += 1000)
    {
      const std::int64_t count = std::min<std::int64_t>(1000, static_cast<std::int64_t>(bricks.size() - done));
      device.Compute(&bricks[done], count, lower, &d[done * nv::BrickNodes], &covered[done]);
    }
    double cpu[nv::BrickNodes];
    for (std::size_t a = 0; a < bricks.size(); ++a)
    {
      const bool within = distance.BrickWithin(bricks[a], lower);
      coverDiffer += (covered[a] != 0) != within ? 1 : 0;
      coveredBricks += within ? 1 : 0;
      if (within || covered[a])
      {
        continue;
      }
      distance.ComputeBrick(bricks[a], cpu);
      for (int n = 0; n < nv::BrickNodes; ++n)
      {
        const double gpu = d[a * nv::BrickNodes + n];
        ++nodes;
        finite += std::isfinite(cpu[n]) ? 1 : 0;
        if (!(gpu == cpu[n]))
        {
          ++differ;
          largest = std::max(largest, std::isfinite(cpu[n]) && std::isfinite(gpu) ? std::fabs(gpu - cpu[n]) : 1e300);
        }
      }
    }
  }
  std::printf("%s, the distance on %s: %zu bricks, %lld nodes (%lld within reach), %lld covered; %lld distances "
              "differ from the CPU's (the largest by %.3g), %lld covered flags differ\n",
    what, launcher->Name().c_str(), bricks.size(), static_cast<long long>(nodes), static_cast<long long>(finite),
    static_cast<long long>(coveredBricks), static_cast<long long>(differ), largest,
    static_cast<long long>(coverDiffer));
  NV_CHECK(finite > 1000);
  NV_CHECK((coveredBricks > 0) == someCovered);
  NV_CHECK(differ == 0);
  NV_CHECK(coverDiffer == 0);

  // The band built on the device (the collect, store and connect passes: BandCountKernel,
  // BandCompactKernel, StoreBand's joins, AdjacentBricksKernel,
  // NeighboursKernel; its distances and neighbour table brought back here),
  // and with a visitor (no brick skipped, each brick's distances handed
  // over, the band built on the host), against the CPU's.
  const nv::NarrowBand cpuBand = nv::BuildNarrowBand(distance, parameters);
  nv::NarrowBand deviceBand;
  {
    nv::device::LauncherDistance device(gridOnly, xyz.data(), numberOfPoints, *launcher, 777);
    deviceBand = nv::BuildNarrowBand(gridOnly, parameters, nullptr, nullptr, nullptr, nullptr, &device);
  }
  NV_CHECK(deviceBand.Distance.empty() && deviceBand.Neighbor.empty()); // held by the launcher
  nv::device::DownloadBand(*launcher, deviceBand);
  const bool same = deviceBand.Size() == cpuBand.Size() && deviceBand.RedCount == cpuBand.RedCount &&
    SameValues(deviceBand.Offset, cpuBand.Offset) && SameValues(deviceBand.Distance, cpuBand.Distance) &&
    SameValues(deviceBand.Neighbor, cpuBand.Neighbor) && SameValues(deviceBand.Bricks, cpuBand.Bricks) &&
    SameValues(deviceBand.RedStart, cpuBand.RedStart) && SameValues(deviceBand.BlackStart, cpuBand.BlackStart) &&
    SameValues(deviceBand.Inside, cpuBand.Inside);
  std::map<std::int64_t, std::vector<double>> cpuVisited, deviceVisited;
  std::mutex guard;
  const auto visitor = [&guard](std::map<std::int64_t, std::vector<double>>& into) {
    return [&guard, &into](std::int64_t brick, const double* d) {
      std::lock_guard<std::mutex> lock(guard);
      into[brick].assign(d, d + nv::BrickNodes);
    };
  };
  const nv::NarrowBand cpuVisitedBand =
    nv::BuildNarrowBand(distance, parameters, nullptr, nullptr, visitor(cpuVisited));
  nv::NarrowBand deviceVisitedBand;
  {
    nv::device::LauncherDistance device(gridOnly, xyz.data(), numberOfPoints, *launcher);
    deviceVisitedBand =
      nv::BuildNarrowBand(gridOnly, parameters, nullptr, nullptr, visitor(deviceVisited), nullptr, &device);
  }
  const bool sameVisited = cpuVisited == deviceVisited && !cpuVisited.empty() &&
    SameValues(deviceVisitedBand.Inside, cpuVisitedBand.Inside) &&
    SameValues(deviceVisitedBand.Distance, cpuVisitedBand.Distance);
  std::printf("%s, the band built on the device: %lld nodes, the CPU's array for array: %s; from the "
              "device's distances with a visitor (%zu bricks): %s\n",
    what, static_cast<long long>(deviceBand.Size()), same ? "yes" : "NO", deviceVisited.size(),
    sameVisited ? "yes" : "NO");
  NV_CHECK(deviceBand.Size() > 1000);
  NV_CHECK(same);
  NV_CHECK(sameVisited);
}

void TestDistance()
{
  const double center[3] = { 0.3, -0.1, 0.2 };
  nv::Parameters p;
  // A shell 2 l = 20 cells thick, as the Table 1 sphere's at h = 0.01 (l = 0.1),
  // on an eighth of its nodes: bricks deep inside the shell are covered.
  p.OffsetDistance = 0.2;
  p.Spacing = 0.02;
  CompareDistance("sphere (l = 10 h)", nvtest::SpherePoints(8000, 0.5, center), p, true);
  p.OffsetDistance = 0.08;
  p.Spacing = 0.02;
  CompareDistance("torus", TorusPoints(20000, 0.6, 0.25), p, false); // no brick inside the thin tube's shell
  p.Domain = nv::Domain::WholeDomain;
  CompareDistance("torus, whole domain", TorusPoints(8000, 0.6, 0.25), p, false);
}

/// The dense arrays of a run (Reconstruction::RequestVolume).
struct Dense
{
  std::vector<float> Phi, InitialPhi, Distance;
  std::vector<unsigned char> Band;
  /// Asks `run` to fill them on the whole grid.
  void Request(nv::Reconstruction& run)
  {
    run.RequestVolume(0, [this, &run](std::int64_t kBegin, std::int64_t kEnd) {
      const std::size_t n =
        static_cast<std::size_t>(run.GetGrid().Dims[0] * run.GetGrid().Dims[1] * (kEnd - kBegin));
      // Set to NaN first: a node the run leaves unset then differs.
      this->Phi.assign(n, std::nanf(""));
      this->InitialPhi.assign(n, std::nanf(""));
      this->Distance.assign(n, std::nanf(""));
      this->Band.assign(n, 7);
      nv::VolumeArrays arrays;
      arrays.Phi = this->Phi.data();
      arrays.InitialPhi = this->InitialPhi.data();
      arrays.Distance = this->Distance.data();
      arrays.Band = this->Band.data();
      return arrays;
    });
  }
};

/// The largest difference of two float arrays (+inf where their sizes differ or a value is NaN).
double LargestDifference(const std::vector<float>& a, const std::vector<float>& b)
{
  if (a.size() != b.size() || a.empty())
  {
    return 1e300;
  }
  double largest = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i)
  {
    const double d = std::fabs(static_cast<double>(a[i]) - b[i]);
    largest = std::isnan(d) ? 1e300 : std::max(largest, d);
  }
  return largest;
}

/// The whole run (nv::Reconstruction) with Device GPU against Device CPU;
/// with `volume`, the dense arrays too (the device's DenseBrickKernel and
/// DenseBandKernel against VolumeWriter).
void CompareRuns(const char* what, const std::vector<double>& xyz, nv::Settings settings, bool volume = false)
{
  settings.Device = nv::ComputeDevice::CPU;
  nv::Reconstruction cpu(settings, nullptr, nullptr);
  Dense cpuDense, gpuDense;
  if (volume)
  {
    cpuDense.Request(cpu);
  }
  NV_CHECK(cpu.Run(xyz));
  nv::SurfaceMesh cpuMesh;
  NV_CHECK(cpu.ExtractSurface(cpuMesh));
  NV_CHECK(cpu.DeviceUsed() == nv::DeviceKind::CPU && cpu.DeviceName() == "CPU");

  settings.Device = nv::ComputeDevice::GPU;
  nv::Reconstruction gpu(settings, nullptr, nullptr, OnGpu ? nv::GpuKernels::OnGpu : nv::GpuKernels::OnHost);
  if (volume)
  {
    gpuDense.Request(gpu);
  }
  const bool ran = gpu.Run(xyz);
  if (!ran)
  {
    std::printf("FAILED: %s: %s\n", what, gpu.Error().c_str());
    NV_CHECK(false);
    return;
  }
  nv::SurfaceMesh gpuMesh;
  NV_CHECK(gpu.ExtractSurface(gpuMesh));
  NV_CHECK(gpu.DeviceUsed() == nv::DeviceKind::GPU && gpu.DeviceName() == (OnGpu ? "GPU" : "GPU on the host"));
  NV_CHECK(gpu.RelativeChanges().size() == cpu.RelativeChanges().size());

  const double h = cpu.GetGrid().Spacing;
  const double apart = std::max(
    LargestVertexDistance(gpuMesh, cpuMesh, h), LargestVertexDistance(cpuMesh, gpuMesh, h));
  int cpuPieces = 0, gpuPieces = 0;
  const bool cpuClosed = Closed(cpuMesh, cpuPieces);
  const bool gpuClosed = Closed(gpuMesh, gpuPieces);
  std::printf("%s, Device GPU (%s) against CPU: %zu and %zu vertices, the farthest %.3g h from the other's; "
              "closed %d and %d, pieces %d and %d\n",
    what, gpu.DeviceName().c_str(), gpuMesh.Points.size() / 3, cpuMesh.Points.size() / 3, apart / h, gpuClosed,
    cpuClosed, gpuPieces, cpuPieces);
  // Through the host launcher, phi and the surface are the CPU's bit for bit.
  const bool same = SameValues(gpuMesh.Points, cpuMesh.Points) && SameValues(gpuMesh.Normals, cpuMesh.Normals) &&
    SameValues(gpuMesh.Triangles, cpuMesh.Triangles);
  std::printf("%s, the surface the CPU's bit for bit: %s\n", what, same ? "yes" : "no");
  NV_CHECK(same || OnGpu);
  NV_CHECK(!gpuMesh.Points.empty());
  NV_CHECK(apart <= 0.05 * h);
  NV_CHECK(gpuClosed && cpuClosed);
  NV_CHECK(gpuPieces == 2 && cpuPieces == 2); // the outer and the inner sheet
  if (volume)
  {
    // Through the host launcher the CPU's values bit for bit; on a GPU phi
    // within float's rounding of the last bits of the evolution's phi.
    const double phi = LargestDifference(gpuDense.Phi, cpuDense.Phi);
    const double phi0 = LargestDifference(gpuDense.InitialPhi, cpuDense.InitialPhi);
    const double d = LargestDifference(gpuDense.Distance, cpuDense.Distance);
    const bool band = !cpuDense.Band.empty() && SameValues(gpuDense.Band, cpuDense.Band);
    std::printf("%s, the dense volume filled on the device: %zu nodes; the largest difference from the CPU's: "
                "phi %.3g, phi0 %.3g, d %.3g; band flags the same: %s\n",
      what, gpuDense.Phi.size(), phi, phi0, d, band ? "yes" : "no");
    NV_CHECK(phi <= (OnGpu ? 1e-6 : 0.0));
    NV_CHECK(phi0 <= (OnGpu ? 1e-6 : 0.0));
    NV_CHECK(d == 0.0);
    NV_CHECK(band);
  }
}

void TestRuns()
{
  nv::Settings settings;
  settings.OffsetDistance = 0.1;
  settings.SampleSpacing = 0.02;
  settings.OutputVolume = false;
  const double center[3] = { 0.0, 0.0, 0.0 };
  CompareRuns("sphere (l = 5 h)", nvtest::SpherePoints(8000, 0.5, center), settings);
  settings.OffsetDistance = 0.08;
  settings.SampleSpacing = 0.02;
  CompareRuns("torus", TorusPoints(20000, 0.6, 0.25), settings);
  // The Volume output: a sphere whose shell is thick enough for bricks
  // inside it to be covered (BrickWithin), which the dense arrays must not
  // skip.
  settings.OutputVolume = true;
  settings.OffsetDistance = 0.3;
  CompareRuns("sphere (l = 0.3, h = 0.02), the Volume output", nvtest::SpherePoints(8000, 0.5, center), settings, true);
}

/// One sphere through every kernel, the checks above (`small`).
void TestSmall()
{
  const double center[3] = { 0.3, -0.1, 0.2 };
  nv::Parameters p;
  p.OffsetDistance = 0.1;
  p.Spacing = 0.02;
  p.MaximumNumberOfIterations = 3;
  Compare("sphere, eq. (4), 3 steps", nvtest::SpherePoints(4000, 0.5, center), p);
  p.OffsetDistance = 0.2;
  CompareDistance("sphere (l = 10 h)", nvtest::SpherePoints(8000, 0.5, center), p, true);
  nv::Settings settings;
  settings.OffsetDistance = 0.3;
  settings.SampleSpacing = 0.02;
  settings.OutputVolume = true;
  const double origin[3] = { 0.0, 0.0, 0.0 };
  CompareRuns("sphere (l = 0.3, h = 0.02), the Volume output", nvtest::SpherePoints(8000, 0.5, origin), settings, true);
}

/// Device GPU where the GPU is missing: an error that says what is missing.
void TestMissingGpu()
{
  if (OnGpu)
  {
    return;
  }
  nv::Settings settings;
  settings.Device = nv::ComputeDevice::GPU;
  const double center[3] = { 0.0, 0.0, 0.0 };
  nv::Reconstruction run(settings, nullptr, nullptr);
  NV_CHECK(!run.Run(nvtest::SpherePoints(2000, 0.5, center)));
  const std::string expected =
    nv::device::CudaCompiled() ? "no CUDA device was found" : "this build of NarrowVolume has no CUDA";
  std::printf("Device GPU here: %s\n", run.Error().c_str());
  NV_CHECK(run.Error().find("Device is GPU, but " + expected) == 0);
  // Automatic runs on the CPU.
  settings.Device = nv::ComputeDevice::Automatic;
  nv::Reconstruction automatic(settings, nullptr, nullptr);
  NV_CHECK(automatic.Run(nvtest::SpherePoints(2000, 0.5, center)));
  NV_CHECK(automatic.DeviceUsed() == nv::DeviceKind::CPU);
}

/// The one fallback rule (nvEngine.h): what Device GPU cannot do stops the
/// run with an error that says so and the way out; nothing falls back to
/// the CPU. PreserveOffset through a whole run (the host launcher would run
/// anything else), a distributed run by DeviceCannot (a run of several
/// processes needs MPI: the MPI test runs Device CPU).
void TestDeviceCannot()
{
  nv::Settings settings;
  settings.Device = nv::ComputeDevice::GPU;
  settings.PreserveOffset = true;
  const double center[3] = { 0.0, 0.0, 0.0 };
  nv::Reconstruction run(settings, nullptr, nullptr, nv::GpuKernels::OnHost);
  NV_CHECK(!run.Run(nvtest::SpherePoints(2000, 0.5, center)));
  std::printf("Device GPU with PreserveOffset: %s\n", run.Error().c_str());
  NV_CHECK(run.Error() == "Device GPU has no PreserveOffset yet: turn PreserveOffset off, or choose Device CPU.");
  NV_CHECK(run.RelativeChanges().empty()); // it stopped before the band
  NV_CHECK(nv::DeviceCannot(settings, true).find("Device GPU runs on one process only") == 0);
  settings.PreserveOffset = false;
  NV_CHECK(nv::DeviceCannot(settings, false).empty());
  settings.Device = nv::ComputeDevice::Automatic;
  settings.PreserveOffset = true;
  NV_CHECK(nv::DeviceCannot(settings, true).empty());
}

/// The host launcher, failing on purpose at one of its kernels (as a GPU
/// that runs out of memory would): the device's error must be the run's,
/// with the way out, and nothing made on the CPU instead.
class FailingLauncher : public nv::device::Launcher
{
public:
  explicit FailingLauncher(const std::string& where)
    : Host(nv::device::MakeHostLauncher())
    , Where(where)
  {
  }
  std::string Name() const override { return "failing host launcher"; }
  double DeviceBytes() const override { return this->Host->DeviceBytes(); }
  double HeldBytes() const override { return this->Host->HeldBytes(); }
  nv::CopyCounts Copies() const override { return this->Host->Copies(); }
  /// "evolution memory": 1 kB free once the band is stored, as a device
  /// that something else filled meanwhile; "surface memory": once the
  /// evolution is done.
  double FreeBytes() const override
  {
    const bool full = (this->Where == "evolution memory" && this->BandStored) ||
      (this->Where == "surface memory" && this->Evolved);
    return full ? 1e3 : this->Host->FreeBytes();
  }
  void Fail(const char* kernel) const
  {
    if (this->Where == kernel)
    {
      throw nv::device::DeviceError(std::string("The GPU failed (") + kernel + "): out of memory (a test)");
    }
  }
  void Upload(std::int64_t size, const std::uint32_t* neighbor, const double* distance, double inside,
    double outside) override
  {
    this->Host->Upload(size, neighbor, distance, inside, outside);
  }
  void InitialField(const nv::device::EvolutionConstants& c) override { this->Host->InitialField(c); }
  void Coefficients(const nv::device::EvolutionConstants& c) override { this->Host->Coefficients(c); }
  void KeepPrevious() override { this->Host->KeepPrevious(); }
  double Sweep(const std::int64_t red[2], const std::int64_t black[2], double omega) override
  {
    this->Fail("relax");
    return this->Host->Sweep(red, black, omega);
  }
  void React() override { this->Host->React(); }
  void StepSums(const std::int64_t red[2], const std::int64_t black[2], double sums[4]) override
  {
    this->Host->StepSums(red, black, sums);
  }
  void Download(nv::UninitializedVector<double>& phi) override { this->Host->Download(phi); }
  void ReleaseEvolution() override
  {
    this->Host->ReleaseEvolution();
    this->Evolved = true;
  }
  void SortPoints(const double* cloud, std::int64_t n, const nv::PointConstants& c,
    std::vector<std::int64_t>& reached) override
  {
    this->Host->SortPoints(cloud, n, c, reached);
  }
  void DistanceBricks(const std::int64_t* bricks, std::int64_t count, const nv::DistanceConstants& c, double* distance,
    std::uint8_t* covered) override
  {
    this->Host->DistanceBricks(bricks, count, c, distance, covered);
  }
  void BandNodes(std::int64_t count, const nv::device::BandNodeConstants& c, std::int32_t* red, std::int32_t* black,
    std::uint64_t* inside) override
  {
    this->Host->BandNodes(count, c, red, black, inside);
  }
  void StoreBand(std::int64_t redCount, std::int64_t size, std::uint16_t* offset) override
  {
    this->Host->StoreBand(redCount, size, offset);
    this->BandStored = true;
  }
  void ConnectBand(const std::int64_t* bricks, const std::int64_t* redStart, const std::int64_t* blackStart,
    std::int64_t numberOfBricks, const nv::device::NeighbourConstants& c) override
  {
    this->Host->ConnectBand(bricks, redStart, blackStart, numberOfBricks, c);
  }
  void DownloadBand(double* distance, std::uint32_t* neighbor) override { this->Host->DownloadBand(distance, neighbor); }
  void FreePoints() override { this->Host->FreePoints(); }
  void CutBricks(const nv::device::ContourArrays& band, const nv::device::ContourConstants& c,
    std::vector<std::int64_t>& cut) override
  {
    this->Host->CutBricks(band, c, cut);
  }
  void ContourCounts(const nv::device::ContourArrays& band, std::int64_t numberOfNodes,
    const nv::device::ContourConstants& c, std::int32_t* vertices, std::int32_t* triangles) override
  {
    this->Fail("contour");
    this->Host->ContourCounts(band, numberOfNodes, c, vertices, triangles);
  }
  void ContourGeometry(const std::int64_t* firstVertex, const std::int64_t* firstTriangle, std::int64_t vertices,
    std::int64_t triangles, double* points, float* normals, long long* ids) override
  {
    this->Host->ContourGeometry(firstVertex, firstTriangle, vertices, triangles, points, normals, ids);
  }
  void DenseBegin(const nv::device::DenseArrays& arrays, const nv::device::DenseConstants& c) override
  {
    this->Host->DenseBegin(arrays, c);
  }
  void DenseBricks(std::int64_t count) override { this->Host->DenseBricks(count); }
  void DenseBand(const nv::device::DenseBandArrays& band, std::int64_t bricks, std::int64_t nodes) override
  {
    this->Host->DenseBand(band, bricks, nodes);
  }
  void DenseDownload() override { this->Host->DenseDownload(); }

private:
  std::unique_ptr<nv::device::Launcher> Host;
  std::string Where;
  bool BandStored = false;
  bool Evolved = false;
};

/// A device that fails during the evolution, and one that fails making the
/// surface: the run stops with the device's words and the way out (the one
/// rule, nvEngine.h); the surface is not made on the CPU instead.
void TestDeviceFails()
{
  nv::Settings settings;
  settings.Device = nv::ComputeDevice::GPU;
  settings.OffsetDistance = 0.1;
  settings.SampleSpacing = 0.02;
  settings.OutputVolume = false;
  const double center[3] = { 0.0, 0.0, 0.0 };
  const std::vector<double> xyz = nvtest::SpherePoints(4000, 0.5, center);
  for (const char* where : { "relax", "contour" })
  {
    nv::Reconstruction run(settings, nullptr, nullptr,
      nv::MakeDeviceEngine(std::unique_ptr<nv::device::Launcher>(new FailingLauncher(where)), "GPU"));
    nv::SurfaceMesh surface;
    const nv::Outcome outcome = nv::Reconstruct(run, xyz, nullptr, surface, nv::VolumeRequest(), false);
    std::printf("Device GPU failing (%s): %s\n", where, outcome.Error.c_str());
    const std::string expected =
      std::string("The GPU failed (") + where + "): out of memory (a test)\nChoose Device CPU or Automatic.";
    NV_CHECK(!outcome.Done);
    NV_CHECK(outcome.Error == expected);
    NV_CHECK(run.DeviceUsed() == nv::DeviceKind::GPU);
  }
}

/// The device back end's stages in the engine's order (Run/nvDeviceEngine.cxx)
/// through `launcher`: the band built there (batches of 200 bricks), the
/// evolution, the surface. Throws DeviceError. phi stays with the
/// launcher; `phiBytes` (if given) gets its size once the band is known.
nv::SurfaceMesh DeviceStages(const std::vector<double>& xyz, const nv::Parameters& parameters,
  nv::device::Launcher& launcher, double* phiBytes = nullptr)
{
  const nv::Grid grid = GridOf(xyz, parameters);
  const nv::TruncatedDistance gridOnly(grid, parameters.Reach());
  nv::NarrowBand band;
  {
    nv::device::LauncherDistance device(
      gridOnly, xyz.data(), static_cast<std::int64_t>(xyz.size() / 3), launcher, 200);
    band = nv::BuildNarrowBand(gridOnly, parameters, nullptr, nullptr, nullptr, nullptr, &device);
  }
  if (phiBytes)
  {
    *phiBytes = 8.0 * static_cast<double>(band.Size() + 2);
  }
  nv::device::Evolve(band, parameters, launcher, nullptr);
  launcher.ReleaseEvolution();
  // phi stays with the launcher: the surface needs no copy on the host.
  const nv::BandValues none;
  nv::SurfaceMesh mesh;
  nv::ContourOnDevice(grid, band, none, parameters, launcher, mesh);
  return mesh;
}

/// The small case of the tests below: 4,000 points on a sphere of radius
/// 0.5, l = 0.1, h = 0.02, two time steps (`p` gets them).
std::vector<double> SmallSphere(nv::Parameters& p)
{
  const double center[3] = { 0.3, -0.1, 0.2 };
  p.OffsetDistance = 0.1;
  p.Spacing = 0.02;
  p.MaximumNumberOfIterations = 2;
  return nvtest::SpherePoints(4000, 0.5, center);
}

/// A failed allocation (the host launcher's limit on its bytes, as a full
/// GPU): the error names the array; nothing leaks (the bytes its allocator
/// holds come back to their value before once the launcher goes) and the
/// count does not drift (after the failure it is what the allocator holds,
/// 0 once the points and the evolution are let go where the surface had not
/// begun). Limits from 0 to the stages' peak make the band's construction
/// and the evolution fail at one array after another.
/// Then a whole run with the limit: the clear error, no result.
void TestFailedAllocation()
{
  if (OnGpu)
  {
    return;
  }
  nv::Parameters p;
  const std::vector<double> xyz = SmallSphere(p);
  const double before = nv::device::HostLauncherBytes();
  nv::SurfaceMesh whole;
  double peak = 0.0, phiBytes = 0.0;
  {
    std::unique_ptr<nv::device::Launcher> launcher = nv::device::MakeHostLauncher();
    whole = DeviceStages(xyz, p, *launcher, &phiBytes);
    peak = launcher->DeviceBytes();
    // Everything let go at the stages' ends but phi, held until the launcher goes.
    NV_CHECK(phiBytes > 0.0 && launcher->HeldBytes() == phiBytes);
    NV_CHECK(nv::device::HostLauncherBytes() - before == phiBytes);
  }
  NV_CHECK(nv::device::HostLauncherBytes() == before);
  NV_CHECK(peak > 0.0 && !whole.Triangles.empty());
  std::map<std::string, int> arrays; // the arrays whose allocation failed
  int drift = 0, leaks = 0, unclear = 0;
  for (int k = 0; k < 40; ++k)
  {
    nv::device::HostLauncherHooks hooks;
    hooks.AllocationLimit = peak * k / 40.0;
    bool surfaceBegun = false;
    {
      std::unique_ptr<nv::device::Launcher> launcher = nv::device::MakeHostLauncher(hooks);
      try
      {
        DeviceStages(xyz, p, *launcher);
        unclear += 1; // below the peak, something must fail
      }
      catch (const nv::device::DeviceError& error)
      {
        const std::string message = error.what();
        const std::string start = "The GPU failed (allocating ";
        const std::size_t comma = message.find(", ");
        if (message.compare(0, start.size(), start) != 0 || comma == std::string::npos ||
          message.find("): out of memory (the launcher's limit of ") == std::string::npos)
        {
          std::printf("FAILED: an unclear allocation error: %s\n", message.c_str());
          unclear += 1;
        }
        else
        {
          const std::string array = message.substr(start.size(), comma - start.size());
          arrays[array] += 1;
          surfaceBegun = array == "psi" || array == "the cut edges" || array == "the corners' signs";
        }
      }
      // What the launcher counts is what its allocator holds, then, the
      // points and the evolution let go, nothing but phi and the surface's
      // arrays.
      drift += launcher->HeldBytes() != nv::device::HostLauncherBytes() - before ? 1 : 0;
      launcher->FreePoints();
      launcher->ReleaseEvolution();
      drift += launcher->HeldBytes() != nv::device::HostLauncherBytes() - before ? 1 : 0;
      drift += !surfaceBegun && launcher->HeldBytes() != 0.0 && launcher->HeldBytes() != phiBytes ? 1 : 0;
    }
    leaks += nv::device::HostLauncherBytes() != before ? 1 : 0;
  }
  std::string failed;
  for (const auto& array : arrays)
  {
    failed += (failed.empty() ? "" : "; ") + array.first + " " + std::to_string(array.second);
  }
  std::printf("Allocations failing on purpose (40 limits below the host launcher's peak of %.3g MB): %s; the count "
              "drifted %d times, memory leaked %d times, %d unclear or missing errors\n",
    peak / 1e6, failed.c_str(), drift, leaks, unclear);
  // The failures spread over the band's construction and the evolution
  // (the surface needs less than the evolution held).
  NV_CHECK(arrays.size() >= 6);
  NV_CHECK(arrays.count("the points") == 1 && arrays.count("the neighbour table") == 1);
  NV_CHECK(arrays.count("the coupling") + arrays.count("phi^n") + arrays.count("the decay") > 0);
  NV_CHECK(drift == 0);
  NV_CHECK(leaks == 0);
  NV_CHECK(unclear == 0);

  // The whole run with a launcher that fails allocating: the device's error,
  // with the way out, no surface; the launcher's memory all given back.
  nv::Settings settings;
  settings.Device = nv::ComputeDevice::GPU;
  settings.OffsetDistance = 0.1;
  settings.SampleSpacing = 0.02;
  settings.OutputVolume = false;
  nv::device::HostLauncherHooks hooks;
  hooks.AllocationLimit = 0.5 * peak;
  {
    nv::Reconstruction run(
      settings, nullptr, nullptr, nv::MakeDeviceEngine(nv::device::MakeHostLauncher(hooks), "GPU"));
    nv::SurfaceMesh surface;
    const nv::Outcome outcome = nv::Reconstruct(run, xyz, nullptr, surface, nv::VolumeRequest(), false);
    std::printf("Device GPU failing to allocate: %s\n", outcome.Error.c_str());
    NV_CHECK(!outcome.Done);
    NV_CHECK(outcome.Error.find("The GPU failed (allocating ") == 0);
    NV_CHECK(outcome.Error.find("): out of memory (the launcher's limit of ") != std::string::npos);
    NV_CHECK(outcome.Error.find("\nChoose Device CPU or Automatic.") != std::string::npos);
    NV_CHECK(surface.Points.empty() && surface.Triangles.empty());
  }
  NV_CHECK(nv::device::HostLauncherBytes() == before);
}

/// The number of bytes in ByteWords' words at `from` ("12.3 MB", "4.56 GB"); -1 if none.
double BytesAt(const std::string& text, std::size_t from)
{
  double value = 0.0;
  char unit[3] = { 0, 0, 0 };
  if (from == std::string::npos || std::sscanf(text.c_str() + from, "%lf %2s", &value, unit) != 2)
  {
    return -1.0;
  }
  return std::string(unit) == "GB" ? value * 1e9 : std::string(unit) == "MB" ? value * 1e6 : -1.0;
}

/// The evolution's arrays other than phi come once the distances are let go
/// (InitialField): on a band built by the host launcher, the ledger's peak
/// through the evolution is the band's bytes (neighbours, distances, node
/// places: 34 a node) plus 18 bytes a node and eq. (5)'s two values, 52 a
/// node, not plus 26 (phi, phi^n, the coupling and the decay over the
/// distances: 60 a node), and EvolutionBytes says so. The outputs stay the
/// CPU's bit for bit (Compare, CompareRuns).
void TestEvolutionPeak()
{
  if (OnGpu)
  {
    return;
  }
  nv::Parameters p;
  const std::vector<double> xyz = SmallSphere(p);
  std::unique_ptr<nv::device::Launcher> launcher = nv::device::MakeHostLauncher();
  const nv::Grid grid = GridOf(xyz, p);
  const nv::TruncatedDistance gridOnly(grid, p.Reach());
  nv::NarrowBand band;
  {
    nv::device::LauncherDistance device(
      gridOnly, xyz.data(), static_cast<std::int64_t>(xyz.size() / 3), *launcher, 200);
    band = nv::BuildNarrowBand(gridOnly, p, nullptr, nullptr, nullptr, nullptr, &device);
  }
  const double n = static_cast<double>(band.Size());
  const double held = launcher->HeldBytes(), before = launcher->DeviceBytes();
  NV_CHECK(n > 0.0 && before < held + 18.0 * n); // the band's construction does not hide the evolution's peak
  nv::device::Evolve(band, p, *launcher, nullptr);
  launcher->ReleaseEvolution();
  const double peak = launcher->DeviceBytes();
  std::printf("evolution peak: %.2f bytes a node (the band's %.2f)\n", peak / n, held / n);
  NV_CHECK(peak == held + nv::device::EvolutionBytes(band.Size()));
  // After the evolution only phi (and its two slots) stays held, and it
  // comes to the host when asked, then still.
  NV_CHECK(launcher->HeldBytes() == 8.0 * (n + 2.0));
  nv::BandValues phi;
  launcher->Download(phi);
  NV_CHECK(phi.size() == band.Size() + 2);
  NV_CHECK(launcher->HeldBytes() == 8.0 * (n + 2.0));
}

/// The checks of the device's free memory (Run/nvDeviceEngine.cxx): before
/// the band (the host launcher reporting 0.1 MB free) and before the
/// evolution (1 kB free once the band is stored), a refusal with the bytes
/// needed and free and the way out, and no result; with enough memory
/// (1 TB reported free) the run is the CPU's bit for bit.
void TestMemoryChecks()
{
  if (OnGpu)
  {
    return;
  }
  nv::Settings settings;
  settings.Device = nv::ComputeDevice::GPU;
  settings.OffsetDistance = 0.1;
  settings.SampleSpacing = 0.02;
  settings.OutputVolume = false;
  const double center[3] = { 0.0, 0.0, 0.0 };
  const std::vector<double> xyz = nvtest::SpherePoints(4000, 0.5, center);
  const std::string advice =
    " is free. Choose a coarser grid (increase SampleSpacing or lower MaximumDimension), or choose Device CPU or "
    "Automatic.";
  const double before = nv::device::HostLauncherBytes();
  {
    nv::device::HostLauncherHooks hooks;
    hooks.FreeBytes = 1e5;
    nv::Reconstruction run(
      settings, nullptr, nullptr, nv::MakeDeviceEngine(nv::device::MakeHostLauncher(hooks), "GPU"));
    nv::SurfaceMesh surface;
    const nv::Outcome outcome = nv::Reconstruct(run, xyz, nullptr, surface, nv::VolumeRequest(), false);
    std::printf("Device GPU with 0.1 MB free: %s\n", outcome.Error.c_str());
    const std::string start = "The GPU has too little free memory to build the narrow band: it needs about ";
    const double needed = BytesAt(outcome.Error, outcome.Error.find(start) == 0 ? start.size() : std::string::npos);
    NV_CHECK(!outcome.Done && !outcome.Ran);
    NV_CHECK(needed > 1e5);
    NV_CHECK(outcome.Error.find(", and 0.1 MB" + advice) != std::string::npos);
    NV_CHECK(run.RelativeChanges().empty() && surface.Points.empty());
  }
  {
    nv::Reconstruction run(settings, nullptr, nullptr,
      nv::MakeDeviceEngine(std::unique_ptr<nv::device::Launcher>(new FailingLauncher("evolution memory")), "GPU"));
    nv::SurfaceMesh surface;
    const nv::Outcome outcome = nv::Reconstruct(run, xyz, nullptr, surface, nv::VolumeRequest(), false);
    std::printf("Device GPU with 1 kB free after the band: %s\n", outcome.Error.c_str());
    const std::string start = "The GPU has too little free memory for the evolution on the band's ";
    long long nodes = 0;
    const bool said = outcome.Error.find(start) == 0 &&
      std::sscanf(outcome.Error.c_str() + start.size(), "%lld nodes", &nodes) == 1;
    NV_CHECK(said && nodes > 1000);
    const std::string needed = "nodes: it needs about " + nv::device::ByteWords(nv::device::EvolutionBytes(nodes));
    NV_CHECK(outcome.Error.find(needed + ", and 0.001 MB" + advice) != std::string::npos);
    NV_CHECK(!outcome.Done && !outcome.Ran);
    NV_CHECK(run.RelativeChanges().empty() && surface.Points.empty());
  }
  {
    nv::Reconstruction run(settings, nullptr, nullptr,
      nv::MakeDeviceEngine(std::unique_ptr<nv::device::Launcher>(new FailingLauncher("surface memory")), "GPU"));
    nv::SurfaceMesh surface;
    const nv::Outcome outcome = nv::Reconstruct(run, xyz, nullptr, surface, nv::VolumeRequest(), false);
    std::printf("Device GPU with 1 kB free after the evolution: %s\n", outcome.Error.c_str());
    const std::string start = "The GPU has too little free memory for the surface's tables: it needs about ";
    const double needed = BytesAt(outcome.Error, outcome.Error.find(start) == 0 ? start.size() : std::string::npos);
    NV_CHECK(needed > 1e5); // psi alone: 2 kB for each of the band's hundreds of bricks
    NV_CHECK(outcome.Error.find(", and 0.001 MB" + advice) != std::string::npos);
    NV_CHECK(!outcome.Done && surface.Points.empty());
  }
  {
    // 1.6 MB free: enough for the band (in small batches), the evolution
    // and the surface's tables, not for its 2 MB of outputs.
    nv::device::HostLauncherHooks hooks;
    hooks.FreeBytes = 1.6e6;
    nv::Reconstruction run(
      settings, nullptr, nullptr, nv::MakeDeviceEngine(nv::device::MakeHostLauncher(hooks), "GPU"));
    nv::SurfaceMesh surface;
    const nv::Outcome outcome = nv::Reconstruct(run, xyz, nullptr, surface, nv::VolumeRequest(), false);
    std::printf("Device GPU with 1.6 MB free: %s\n", outcome.Error.c_str());
    const std::string start = "The GPU has too little free memory for the surface's ";
    long long vertices = 0, triangles = 0;
    const bool said = outcome.Error.find(start) == 0 &&
      std::sscanf(outcome.Error.c_str() + start.size(), "%lld vertices and %lld triangles", &vertices, &triangles) == 2;
    NV_CHECK(said && vertices > 1000 && triangles > 1000);
    const std::string needed = "triangles: it needs about " +
      nv::device::ByteWords(36.0 * static_cast<double>(vertices) + 24.0 * static_cast<double>(triangles));
    NV_CHECK(outcome.Error.find(needed + ", and 1.6 MB" + advice) != std::string::npos);
    NV_CHECK(!outcome.Done && surface.Points.empty());
  }
  {
    // 3 MB free: too little for the band's bricks in one batch, enough in
    // smaller ones, which the run takes (and for the surface's 2 MB of
    // outputs); the surface the CPU's bit for bit.
    nv::device::HostLauncherHooks hooks;
    hooks.FreeBytes = 3e6;
    nv::Reconstruction gpu(
      settings, nullptr, nullptr, nv::MakeDeviceEngine(nv::device::MakeHostLauncher(hooks), "GPU"));
    nv::SurfaceMesh gpuMesh, cpuMesh;
    const nv::Outcome outcome = nv::Reconstruct(gpu, xyz, nullptr, gpuMesh, nv::VolumeRequest(), false);
    const std::array<std::int64_t, 3> dims = nv::BrickDimensions(gpu.GetGrid());
    const std::int64_t bricks = dims[0] * dims[1] * dims[2];
    const double oneBatch = nv::device::BandBuildBytes(4000, bricks, bricks, 0.0);
    NV_CHECK(outcome.Done && outcome.Error.empty());
    NV_CHECK(bricks > nv::device::LauncherDistance::MinimumBatch && oneBatch > hooks.FreeBytes);
    nv::Settings onCpu = settings;
    onCpu.Device = nv::ComputeDevice::CPU;
    nv::Reconstruction cpu(onCpu, nullptr, nullptr);
    NV_CHECK(nv::Reconstruct(cpu, xyz, nullptr, cpuMesh, nv::VolumeRequest(), false).Done);
    const bool same = !cpuMesh.Triangles.empty() && SameValues(gpuMesh.Points, cpuMesh.Points) &&
      SameValues(gpuMesh.Triangles, cpuMesh.Triangles);
    std::printf("Device GPU with 3 MB free (%lld bricks in one batch would need %s): the band in smaller "
                "batches, the surface the CPU's bit for bit: %s\n",
      static_cast<long long>(bricks), nv::device::ByteWords(oneBatch).c_str(), same ? "yes" : "NO");
    NV_CHECK(same);
  }
  {
    // Enough memory: nothing changes.
    nv::device::HostLauncherHooks hooks;
    hooks.FreeBytes = 1e12;
    nv::Reconstruction gpu(
      settings, nullptr, nullptr, nv::MakeDeviceEngine(nv::device::MakeHostLauncher(hooks), "GPU"));
    nv::SurfaceMesh gpuMesh, cpuMesh;
    NV_CHECK(nv::Reconstruct(gpu, xyz, nullptr, gpuMesh, nv::VolumeRequest(), false).Done);
    settings.Device = nv::ComputeDevice::CPU;
    nv::Reconstruction cpu(settings, nullptr, nullptr);
    NV_CHECK(nv::Reconstruct(cpu, xyz, nullptr, cpuMesh, nv::VolumeRequest(), false).Done);
    const bool same = !cpuMesh.Triangles.empty() && SameValues(gpuMesh.Points, cpuMesh.Points) &&
      SameValues(gpuMesh.Normals, cpuMesh.Normals) && SameValues(gpuMesh.Triangles, cpuMesh.Triangles);
    std::printf("Device GPU with 1 TB free, the surface the CPU's bit for bit: %s\n", same ? "yes" : "NO");
    NV_CHECK(same);
  }
  NV_CHECK(nv::device::HostLauncherBytes() == before);
}

/// The surface's outputs slab by slab of cut bricks (the CUDA launcher
/// holds one slab at a time): the split, then a surface made in slabs of
/// at most 20 kB through the host launcher, the one-piece surface bit for bit.
void TestSurfaceSlabs()
{
  // The slabs' bounds (each one's Begin, then the last one's End), each
  // slab's first vertex and triangle and its counts checked on the way.
  const auto bounds = [](const std::int64_t* firstVertex, const std::int64_t* firstTriangle, std::int64_t count,
                        std::int64_t vertices, std::int64_t triangles, double bytes) {
    const auto vertexAt = [&](std::int64_t r) { return r < count ? firstVertex[r] : vertices; };
    const auto triangleAt = [&](std::int64_t r) { return r < count ? firstTriangle[r] : triangles; };
    std::vector<std::int64_t> at;
    for (const nv::device::SurfaceSlab& slab :
      nv::device::SurfaceSlabs(firstVertex, firstTriangle, count, vertices, triangles, bytes))
    {
      NV_CHECK(at.empty() || at.back() == slab.Begin);
      NV_CHECK(slab.FirstVertex == vertexAt(slab.Begin) && slab.FirstTriangle == triangleAt(slab.Begin));
      NV_CHECK(slab.Vertices == vertexAt(slab.End) - slab.FirstVertex &&
        slab.Triangles == triangleAt(slab.End) - slab.FirstTriangle);
      if (at.empty())
      {
        at.push_back(slab.Begin);
      }
      at.push_back(slab.End);
    }
    return at;
  };
  const std::int64_t firstVertex[4] = { 0, 10, 20, 30 }, firstTriangle[4] = { 0, 20, 40, 60 };
  // Each brick: 10 vertices and 20 triangles, 840 bytes.
  NV_CHECK((bounds(firstVertex, firstTriangle, 4, 40, 80, 1e9) ==
    std::vector<std::int64_t>{ 0, 4 }));
  NV_CHECK((bounds(firstVertex, firstTriangle, 4, 40, 80, 1700.0) ==
    std::vector<std::int64_t>{ 0, 2, 4 }));
  NV_CHECK((bounds(firstVertex, firstTriangle, 4, 40, 80, 2600.0) ==
    std::vector<std::int64_t>{ 0, 3, 4 }));
  NV_CHECK((bounds(firstVertex, firstTriangle, 4, 40, 80, 100.0) ==
    std::vector<std::int64_t>{ 0, 1, 2, 3, 4 }));
  NV_CHECK((bounds(nullptr, nullptr, 0, 0, 0, 100.0) == std::vector<std::int64_t>{ 0, 0 }));
  if (OnGpu)
  {
    return;
  }
  nv::Parameters p;
  const std::vector<double> xyz = SmallSphere(p);
  std::unique_ptr<nv::device::Launcher> whole = nv::device::MakeHostLauncher();
  nv::device::HostLauncherHooks hooks;
  hooks.SurfaceSlabBytes = 2e4;
  std::unique_ptr<nv::device::Launcher> sliced = nv::device::MakeHostLauncher(hooks);
  const nv::SurfaceMesh one = DeviceStages(xyz, p, *whole), slabs = DeviceStages(xyz, p, *sliced);
  const double bytes = 36.0 * static_cast<double>(one.Points.size() / 3) + 8.0 * static_cast<double>(one.Triangles.size());
  const bool same = !one.Triangles.empty() && SameValues(one.Points, slabs.Points) &&
    SameValues(one.Normals, slabs.Normals) && SameValues(one.Triangles, slabs.Triangles);
  std::printf("The surface (%.2f MB of outputs) in slabs of at most 20 kB, the one-piece surface bit for bit: %s\n",
    bytes / 1e6, same ? "yes" : "NO");
  NV_CHECK(bytes > 20 * hooks.SurfaceSlabBytes);
  NV_CHECK(same);
}

} // namespace

int main(int argc, char* argv[])
{
  OnGpu = argc > 1 && std::strcmp(argv[1], "cuda") == 0;
  if (argc > 2 && std::strcmp(argv[2], "small") == 0)
  {
    TestSmall();
    return nvtest::Result(NV_TEST_NAME);
  }
  TestSphere();
  TestTorus();
  TestDistance();
  TestRuns();
  TestMissingGpu();
  TestDeviceCannot();
  TestDeviceFails();
  TestFailedAllocation();
  TestEvolutionPeak();
  TestMemoryChecks();
  TestSurfaceSlabs();
  return nvtest::Result(NV_TEST_NAME);
}
