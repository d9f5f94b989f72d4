// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The distributed scheme without MPI: the slabs of nvPartition, and ranks
// simulated by threads that talk through an in-memory Communicator. Each
// rank builds the band on its slab and runs the solver with the ghost-layer
// exchange of nvHalo; its owned nodes must end with exactly the serial phi,
// and the pieces of the surface the ranks make must be the serial surface,
// also with PreserveOffset (whose brick sums cross the slabs' boundaries).
#include "nvAllenCahnSolver.h"
#include "nvCommunicator.h"
#include "nvGrid.h"
#include "nvHalo.h"
#include "nvNarrowBand.h"
#include "nvParallel.h"
#include "nvPartition.h"
#include "nvReconstruction.h"
#include "nvSampling.h"
#include "nvSurface.h"
#include "nvTestUtilities.h"
#include "nvTruncatedDistance.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <condition_variable>
#include <deque>
#include <map>
#include <random>
#include <mutex>
#include <string>
#include <thread>
#include <unordered_map>

namespace
{

/// Messages and reductions between threads of one process.
struct Hub
{
  explicit Hub(int size)
    : Size(size)
  {
  }
  int Size;
  std::mutex Mutex;
  std::condition_variable Changed;
  std::map<std::pair<int, int>, std::deque<std::vector<double>>> Mail; ///< (from, to)
  std::vector<double> Accumulator, Result;
  int Arrived = 0;
  int Generation = 0;
};

class ThreadCommunicator : public nv::Communicator
{
public:
  ThreadCommunicator(Hub& hub, int rank)
    : TheHub(hub)
    , MyRank(rank)
  {
  }
  int Rank() const override { return this->MyRank; }
  int Size() const override { return this->TheHub.Size; }
  void Send(int rank, const double* values, std::int64_t n) override
  {
    std::lock_guard<std::mutex> lock(this->TheHub.Mutex);
    this->TheHub.Mail[{ this->MyRank, rank }].emplace_back(values, values + n);
    this->TheHub.Changed.notify_all();
  }
  void Receive(int rank, double* values, std::int64_t n) override
  {
    std::unique_lock<std::mutex> lock(this->TheHub.Mutex);
    auto& box = this->TheHub.Mail[{ rank, this->MyRank }];
    this->TheHub.Changed.wait(lock, [&] { return !box.empty(); });
    NV_CHECK(static_cast<std::int64_t>(box.front().size()) == n);
    std::copy(box.front().begin(), box.front().begin() + std::min<std::size_t>(n, box.front().size()), values);
    box.pop_front();
  }
  void MaxAll(double* values, int n) override { this->Reduce(values, n, true); }
  void SumAll(double* values, int n) override { this->Reduce(values, n, false); }

private:
  void Reduce(double* values, int n, bool maximum)
  {
    std::unique_lock<std::mutex> lock(this->TheHub.Mutex);
    Hub& hub = this->TheHub;
    const int generation = hub.Generation;
    if (hub.Arrived == 0)
    {
      hub.Accumulator.assign(values, values + n);
    }
    else
    {
      for (int i = 0; i < n; ++i)
      {
        hub.Accumulator[i] = maximum ? std::max(hub.Accumulator[i], values[i]) : hub.Accumulator[i] + values[i];
      }
    }
    if (++hub.Arrived == hub.Size)
    {
      hub.Result = hub.Accumulator;
      hub.Arrived = 0;
      ++hub.Generation;
      hub.Changed.notify_all();
    }
    else
    {
      hub.Changed.wait(lock, [&] { return hub.Generation != generation; });
    }
    std::copy(hub.Result.begin(), hub.Result.end(), values);
  }
  Hub& TheHub;
  int MyRank;
};

void TestSplitLayers()
{
  // Equal weights: equal slabs; every layer in exactly one slab, in order.
  for (int layers : { 1, 3, 7, 40 })
  {
    for (int parts : { 1, 2, 3, 5 })
    {
      const std::vector<nv::LayerRange> slabs = nv::SplitLayers(std::vector<double>(layers, 1.0), parts);
      NV_CHECK(static_cast<int>(slabs.size()) == parts);
      std::int64_t next = 0;
      for (const nv::LayerRange& slab : slabs)
      {
        NV_CHECK(slab.Begin == next && slab.End >= slab.Begin);
        NV_CHECK(!slab.Empty() || layers < parts);
        next = slab.End;
      }
      NV_CHECK(next == layers);
    }
  }
  // All the weight in the last layers: the early slabs take one layer each.
  std::vector<double> weights(10, 0.0);
  weights[8] = weights[9] = 5.0;
  const std::vector<nv::LayerRange> slabs = nv::SplitLayers(weights, 3);
  NV_CHECK(slabs[0].Begin == 0 && slabs[2].End == 10 && !slabs[1].Empty() && !slabs[2].Empty());
  // Ghost layers stop at the grid's ends; an empty slab computes nothing.
  const nv::Subdomain first = nv::Subdomain::Around(nv::LayerRange{ 0, 3 }, 10);
  NV_CHECK(first.Computed.Begin == 0 && first.Computed.End == 4);
  const nv::Subdomain last = nv::Subdomain::Around(nv::LayerRange{ 7, 10 }, 10);
  NV_CHECK(last.Computed.Begin == 6 && last.Computed.End == 10);
  NV_CHECK(nv::Subdomain::Around(nv::LayerRange{ 4, 4 }, 10).Computed.Empty());
}

/// The serial phi by grid node.
std::unordered_map<std::int64_t, double> SerialPhi(
  const nv::TruncatedDistance& distance, const nv::Parameters& parameters)
{
  const nv::NarrowBand band = nv::BuildNarrowBand(distance, parameters);
  nv::AllenCahnSolver solver(band, parameters);
  solver.Run();
  std::unordered_map<std::int64_t, double> phi;
  for (std::int64_t s = 0; s < band.Size(); ++s)
  {
    phi[band.GridIndex(s)] = solver.GetPhi()[s];
  }
  return phi;
}

/// With preserve, PreserveOffset on (6 steps): its multiplier sums bricks
/// across the slabs' boundaries (the ghost layers' sums come from their owners).
void TestDistributedSolve(nv::Domain mode, int ranks, std::vector<double> weights, bool preserve = false)
{
  const double center[3] = { 0.0, 0.1, -0.05 };
  const std::vector<double> points = nvtest::SpherePoints(600, 0.5, center);
  nv::Parameters parameters;
  parameters.OffsetDistance = 0.08;
  parameters.Spacing = 0.02;
  parameters.MaximumNumberOfIterations = preserve ? 6 : 3;
  parameters.Domain = mode;
  parameters.PreserveOffset = preserve;
  const double bounds[6] = { -0.5, 0.5, -0.4, 0.6, -0.55, 0.45 };
  const nv::Grid grid = nv::MakeGrid(bounds, parameters.Spacing, nv::GridPadding(parameters.Reach(), parameters.Spacing));
  const nv::TruncatedDistance distance(grid, points.data(), 600, parameters.Reach());
  const std::unordered_map<std::int64_t, double> serial = SerialPhi(distance, parameters);
  if (preserve)
  {
    // The correction acts: phi is not the paper's scheme's.
    nv::Parameters paper = parameters;
    paper.PreserveOffset = false;
    const std::unordered_map<std::int64_t, double> plain = SerialPhi(distance, paper);
    int changed = 0;
    for (const auto& node : serial)
    {
      changed += plain.at(node.first) != node.second ? 1 : 0;
    }
    // (In the whole domain, the nodes far from the sheets have g = 0 and stay.)
    NV_CHECK(changed > static_cast<int>(serial.size()) / (mode == nv::Domain::WholeDomain ? 4 : 2));
  }

  const std::int64_t layers = distance.GetBrickDims()[2];
  weights.resize(static_cast<std::size_t>(layers), 1.0);
  const std::vector<nv::LayerRange> owners = nv::SplitLayers(weights, ranks);
  Hub hub(ranks);
  std::vector<std::int64_t> owned(static_cast<std::size_t>(ranks), 0);
  std::vector<int> mismatches(static_cast<std::size_t>(ranks), 0);
  std::vector<int> agreed(static_cast<std::size_t>(ranks), 0);
  std::vector<std::thread> threads;
  for (int rank = 0; rank < ranks; ++rank)
  {
    threads.emplace_back([&, rank]() {
      ThreadCommunicator communicator(hub, rank);
      const nv::Subdomain part = nv::Subdomain::Around(owners[rank], layers);
      const nv::NarrowBand band = nv::BuildNarrowBand(distance, parameters, nullptr, &part);
      nv::Halo halo(band, part, owners, communicator);
      agreed[rank] = halo.Agree();
      nv::AllenCahnSolver solver(band, parameters, &halo);
      solver.Run();
      for (bool red : { true, false })
      {
        std::int64_t begin, end;
        band.OwnedNodes(red, begin, end);
        owned[rank] += end - begin;
        for (std::int64_t s = begin; s < end; ++s)
        {
          const auto it = serial.find(band.GridIndex(s));
          mismatches[rank] += (it == serial.end() || it->second != solver.GetPhi()[s]) ? 1 : 0;
        }
      }
    });
  }
  for (std::thread& thread : threads)
  {
    thread.join();
  }
  std::int64_t total = 0;
  for (int rank = 0; rank < ranks; ++rank)
  {
    NV_CHECK(agreed[rank]);
    NV_CHECK(mismatches[rank] == 0);
    total += owned[rank];
  }
  // Every band node is owned by exactly one rank.
  NV_CHECK(total == static_cast<std::int64_t>(serial.size()));
}

/// A surface as its triangles, each the coordinates of its three vertices
/// (rotated to start at the smallest, which keeps the orientation), sorted;
/// and its vertices' normals by coordinates.
struct SurfaceByCoordinates
{
  std::vector<std::array<double, 9>> Triangles;
  std::map<std::array<double, 3>, std::array<float, 3>> Normals;
  void Add(const nv::SurfaceMesh& mesh)
  {
    auto vertex = [&mesh](nv::VertexId v) {
      return std::array<double, 3>{ { mesh.Points[3 * v], mesh.Points[3 * v + 1], mesh.Points[3 * v + 2] } };
    };
    for (std::size_t t = 0; t < mesh.Triangles.size(); t += 3)
    {
      std::array<std::array<double, 3>, 3> corners = { { vertex(mesh.Triangles[t]), vertex(mesh.Triangles[t + 1]),
        vertex(mesh.Triangles[t + 2]) } };
      std::rotate(corners.begin(), std::min_element(corners.begin(), corners.end()), corners.end());
      std::array<double, 9> triangle;
      for (int c = 0; c < 9; ++c)
      {
        triangle[c] = corners[c / 3][c % 3];
      }
      this->Triangles.push_back(triangle);
    }
    for (std::size_t v = 0; v < mesh.Points.size() / 3; ++v)
    {
      this->Normals[vertex(static_cast<nv::VertexId>(v))] = { { mesh.Normals[3 * v], mesh.Normals[3 * v + 1],
        mesh.Normals[3 * v + 2] } };
    }
  }
  /// Whether `part` holds only triangles and normals of this surface.
  bool Holds(const SurfaceByCoordinates& part) const
  {
    for (const auto& normal : part.Normals)
    {
      const auto it = this->Normals.find(normal.first);
      if (it == this->Normals.end() || it->second != normal.second)
      {
        return false;
      }
    }
    return true;
  }
};

/// The shipped run (nv::Reconstruction): each rank holds an uneven share of
/// the points, spread over the whole shape (one rank holds none); the run
/// weights the brick layers by the points, splits them, moves the points to
/// the ranks that need them and evolves the band. Every rank agrees on the
/// grid, and its owned nodes have exactly the serial phi. The ranks' pieces
/// of the surface together are the serial surface: the same triangles, with
/// the same vertices and normals to the bit (the shared planes' vertices made
/// on both sides from the same values). With `holes`, the sphere has holes
/// of radius 1.5 l to 4 l at several heights (across the slabs' faces): the
/// same points are added (nvGapClosing.h) and the same gaps left open.
void TestDistributedRun(int ranks, bool preserve = false, bool holes = false)
{
  const double center[3] = { 0.1, -0.2, 0.3 };
  std::vector<double> points = nvtest::SpherePoints(holes ? 4000 : 800, 0.5, center);
  if (holes)
  {
    // (direction, radius in units of l = 0.08 / 2)
    const double caps[][4] = { { 1, 0, 0, 1.5 }, { 0, 0, 1, 2.0 }, { 0, 0, -1, 3.0 }, { 0, 0.6, 0.8, 2.5 },
      { -0.8, 0, 0.6, 4.0 } };
    std::vector<double> kept;
    for (std::size_t p = 0; p < points.size(); p += 3)
    {
      bool keep = true;
      for (const auto& cap : caps)
      {
        double d2 = 0.0;
        for (int a = 0; a < 3; ++a)
        {
          const double d = points[p + a] - (center[a] + 0.5 * cap[a]);
          d2 += d * d;
        }
        keep = keep && std::sqrt(d2) > cap[3] * 0.04;
      }
      if (keep)
      {
        kept.insert(kept.end(), &points[p], &points[p] + 3);
      }
    }
    points = kept;
  }
  nv::Settings settings;
  settings.PreserveOffset = preserve;
  settings.MaximumNumberOfIterations = preserve ? 10 : settings.MaximumNumberOfIterations;
  settings.OffsetDistance = holes ? 0.04 : 0.08;
  settings.MaximumDimension = 60;
  settings.MemoryLimit = 1000.0;
  nv::Reconstruction serial(settings, nullptr, nullptr);
  NV_CHECK(serial.Run(points));
  nv::SurfaceMesh serialMesh;
  NV_CHECK(serial.ExtractSurface(serialMesh));
  SurfaceByCoordinates serialSurface;
  serialSurface.Add(serialMesh);
  std::sort(serialSurface.Triangles.begin(), serialSurface.Triangles.end());
  std::unordered_map<std::int64_t, double> serialPhi;
  for (std::int64_t s = 0; s < serial.GetBand().Size(); ++s)
  {
    serialPhi[serial.GetBand().GridIndex(s)] = serial.GetPhi()[s];
  }

  Hub hub(ranks);
  std::vector<std::int64_t> owned(static_cast<std::size_t>(ranks), 0);
  std::vector<int> mismatches(static_cast<std::size_t>(ranks), 0);
  std::vector<int> sameGrid(static_cast<std::size_t>(ranks), 0);
  std::vector<int> sameGaps(static_cast<std::size_t>(ranks), 0);
  std::vector<SurfaceByCoordinates> surfaces(static_cast<std::size_t>(ranks));
  std::vector<std::thread> threads;
  for (int rank = 0; rank < ranks; ++rank)
  {
    threads.emplace_back([&, rank]() {
      // Point p goes to rank (p mod (ranks + 1)), the last rank also taking
      // the extra share; rank 1 holds nothing when there are 3 or more.
      std::vector<double> mine;
      for (std::size_t p = 0; p < points.size() / 3; ++p)
      {
        int to = static_cast<int>(p % static_cast<std::size_t>(ranks + 1));
        to = to >= ranks ? ranks - 1 : to;
        if (ranks >= 3 && to == 1)
        {
          to = 0;
        }
        if (to == rank)
        {
          mine.insert(mine.end(), &points[3 * p], &points[3 * p] + 3);
        }
      }
      ThreadCommunicator communicator(hub, rank);
      nv::Reconstruction run(settings, &communicator, nullptr);
      if (!run.Run(mine))
      {
        mismatches[rank] = -1;
        return;
      }
      nv::SurfaceMesh mesh;
      NV_CHECK(run.ExtractSurface(mesh));
      surfaces[rank].Add(mesh);
      sameGrid[rank] = run.GetGrid().Dims == serial.GetGrid().Dims &&
        run.GetGrid().Origin == serial.GetGrid().Origin && run.GetGrid().Spacing == serial.GetGrid().Spacing &&
        run.NumberOfBandNodes() == serial.NumberOfBandNodes();
      const nv::GapReport& gaps = run.GetGaps();
      sameGaps[rank] = run.AddedPoints() == serial.AddedPoints() && gaps.Gaps == serial.GetGaps().Gaps &&
        gaps.GapPoints == serial.GetGaps().GapPoints && gaps.LargestGap == serial.GetGaps().LargestGap &&
        gaps.LargestGapCenter == serial.GetGaps().LargestGapCenter;
      for (bool red : { true, false })
      {
        std::int64_t begin, end;
        run.GetBand().OwnedNodes(red, begin, end);
        owned[rank] += end - begin;
        for (std::int64_t s = begin; s < end; ++s)
        {
          const auto it = serialPhi.find(run.GetBand().GridIndex(s));
          mismatches[rank] += (it == serialPhi.end() || it->second != run.GetPhi()[s]) ? 1 : 0;
        }
      }
    });
  }
  for (std::thread& thread : threads)
  {
    thread.join();
  }
  std::int64_t total = 0;
  for (int rank = 0; rank < ranks; ++rank)
  {
    NV_CHECK(sameGrid[rank]);
    NV_CHECK(sameGaps[rank]);
    NV_CHECK(mismatches[rank] == 0);
    total += owned[rank];
  }
  NV_CHECK(total == static_cast<std::int64_t>(serialPhi.size()));
  SurfaceByCoordinates pieces;
  for (const SurfaceByCoordinates& surface : surfaces)
  {
    NV_CHECK(serialSurface.Holds(surface));
    pieces.Triangles.insert(pieces.Triangles.end(), surface.Triangles.begin(), surface.Triangles.end());
  }
  std::sort(pieces.Triangles.begin(), pieces.Triangles.end());
  std::printf("%d ranks%s: %zu triangles in the pieces, %zu in the serial surface; %lld points added, %lld gaps "
              "left\n",
    ranks, holes ? " (sphere with holes)" : "", pieces.Triangles.size(), serialSurface.Triangles.size(),
    static_cast<long long>(serial.AddedPoints()), static_cast<long long>(serial.GetGaps().Gaps));
  if (holes)
  {
    NV_CHECK(serial.AddedPoints() > 0 && serial.GetGaps().Gaps == 1);
  }
  NV_CHECK(serialSurface.Triangles.size() > 1000);
  NV_CHECK(pieces.Triangles == serialSurface.Triangles);
}

/// The points' spacing measured by slabs (nvSampling.h): the serial figures
/// to the last bit, on clouds with outliers, duplicates, many points on one
/// z and a lone point; no process holds the whole cloud.
void TestDistributedSampling()
{
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  const double center[3] = { 0.0, 0.0, 0.0 };
  std::vector<std::pair<const char*, std::vector<double>>> clouds;
  clouds.emplace_back("sphere", nvtest::SpherePoints(4000, 0.5, center));
  std::vector<double> outliers = clouds.back().second;
  for (int p = 0; p < 60; ++p)
  {
    outliers.insert(outliers.end(), { uniform(random), uniform(random), uniform(random) });
  }
  clouds.emplace_back("sphere and outliers", outliers);
  std::vector<double> lattice; // many points on each z, and every one twice
  for (int i = 0; i < 9; ++i)
    for (int j = 0; j < 9; ++j)
      for (int k = 0; k < 9; ++k)
        for (int copy = 0; copy < 2; ++copy)
        {
          lattice.insert(lattice.end(), { 0.1 * i, 0.1 * j + (k == 4 ? 0.03 : 0.0), 0.1 * k });
        }
  clouds.emplace_back("lattice of duplicates", lattice);
  // A sparse square grid at z = 0 with a dense clump just above it, between
  // grid points: the clump's slab is tiny, and the grid points near the clump
  // find their nearest neighbour there, far outside that slab's box.
  std::vector<double> gridAndClump;
  for (int i = 0; i < 40; ++i)
    for (int j = 0; j < 40; ++j)
    {
      gridAndClump.insert(gridAndClump.end(), { 0.1 * i, 0.1 * j, 0.0 });
    }
  for (int p = 0; p < 1700; ++p)
  {
    gridAndClump.insert(gridAndClump.end(), { 2.05 + 1e-3 * uniform(random), 2.05 + 1e-3 * uniform(random), 1e-6 });
  }
  clouds.emplace_back("grid and clump", gridAndClump);
  clouds.emplace_back("three points", std::vector<double>{ 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 5.0, 0.0, 0.5 });
  clouds.emplace_back("one lone point", std::vector<double>{ 1.0, 2.0, 3.0, 1.0, 2.0, 3.0, 1.0, 2.0, 9.0 });
  for (const auto& cloud : clouds)
  {
    const std::vector<double>& points = cloud.second;
    const std::int64_t n = static_cast<std::int64_t>(points.size() / 3);
    nv::Sampling serial;
    serial.Measure(points, nullptr);
    for (int ranks : { 2, 3, 5, 8 })
    {
      Hub hub(ranks);
      std::vector<int> same(static_cast<std::size_t>(ranks), 1);
      std::vector<std::int64_t> held(static_cast<std::size_t>(ranks), 0);
      std::vector<std::thread> threads;
      for (int rank = 0; rank < ranks; ++rank)
      {
        threads.emplace_back([&, rank]() {
          // Points dealt round-robin, so every piece spans the whole cloud;
          // rank 1 holds nothing.
          std::vector<double> mine;
          for (std::int64_t p = 0; p < n; ++p)
          {
            int to = static_cast<int>(p % ranks);
            to = to == 1 ? 0 : to;
            if (to == rank)
            {
              mine.insert(mine.end(), &points[3 * p], &points[3 * p] + 3);
            }
          }
          ThreadCommunicator communicator(hub, rank);
          nv::Sampling sampling;
          sampling.Measure(mine, &communicator);
          const nv::SamplingStatistics& a = sampling.Statistics();
          const nv::SamplingStatistics& b = serial.Statistics();
          same[static_cast<std::size_t>(rank)] =
            a.Points == b.Points && a.MedianSpacing == b.MedianSpacing && a.WideSpacing == b.WideSpacing;
          held[static_cast<std::size_t>(rank)] = sampling.HeldPoints();
        });
      }
      for (std::thread& thread : threads)
      {
        thread.join();
      }
      const std::int64_t most = *std::max_element(held.begin(), held.end());
      std::printf("spacing of the %s by %d slabs: median %.6g, 99.9th percentile %.6g; at most %lld of %lld points "
                  "on one process\n",
        cloud.first, ranks, serial.Statistics().MedianSpacing, serial.Statistics().WideSpacing,
        static_cast<long long>(most), static_cast<long long>(n));
      for (int rank = 0; rank < ranks; ++rank)
      {
        NV_CHECK(same[static_cast<std::size_t>(rank)]);
      }
      if (std::string(cloud.first).rfind("sphere", 0) == 0)
      {
        // A slab's share and a thin layer: well under the whole cloud.
        NV_CHECK(most < 1.5 * n / ranks + 0.1 * n);
      }
    }
  }
}

/// Records the progress it gets; asks to stop once it has `StopAfter`
/// reports (never when negative).
struct RecordingMonitor : nv::Monitor
{
  int StopAfter = -1;
  std::vector<double> Reports;
  void Progress(double fraction) override { this->Reports.push_back(fraction); }
  bool Aborted() override { return this->StopAfter >= 0 && static_cast<int>(this->Reports.size()) >= this->StopAfter; }
};

/// The spacing measurement reports its progress and stops when asked: on
/// one process, on every process when one of them is asked, and a run that
/// measures for itself then stops as aborted, without an error.
void TestSamplingProgressAndStop()
{
  const double center[3] = { 0.0, 0.0, 0.0 };
  const std::vector<double> points = nvtest::SpherePoints(50000, 0.5, center);
  nv::Sampling plain;
  NV_CHECK(plain.Measure(points, nullptr));
  RecordingMonitor watch;
  nv::Sampling watched;
  NV_CHECK(watched.Measure(points, nullptr, &watch));
  NV_CHECK(watched.Statistics().MedianSpacing == plain.Statistics().MedianSpacing &&
    watched.Statistics().WideSpacing == plain.Statistics().WideSpacing);
  std::printf("spacing of %zu points: %zu progress reports\n", points.size() / 3, watch.Reports.size());
  NV_CHECK(watch.Reports.size() >= 8 && std::is_sorted(watch.Reports.begin(), watch.Reports.end()) &&
    watch.Reports.front() > 0.0 && watch.Reports.back() == 1.0);

  RecordingMonitor stop;
  stop.StopAfter = 2;
  nv::Sampling stopped;
  NV_CHECK(!stopped.Measure(points, nullptr, &stop));
  NV_CHECK(stop.Reports.size() == 2);

  // Three processes, the last one asked to stop: all three stop.
  Hub hub(3);
  std::vector<int> measured(3, -1);
  std::vector<std::thread> threads;
  for (int rank = 0; rank < 3; ++rank)
  {
    threads.emplace_back([&, rank]() {
      std::vector<double> mine(points.begin() + rank * (points.size() / 9) * 3,
        rank == 2 ? points.end() : points.begin() + (rank + 1) * (points.size() / 9) * 3);
      ThreadCommunicator communicator(hub, rank);
      RecordingMonitor asks;
      asks.StopAfter = rank == 2 ? 1 : -1;
      nv::Sampling sampling;
      measured[static_cast<std::size_t>(rank)] = sampling.Measure(mine, &communicator, &asks) ? 1 : 0;
    });
  }
  for (std::thread& thread : threads)
  {
    thread.join();
  }
  NV_CHECK(measured == std::vector<int>({ 0, 0, 0 }));

  RecordingMonitor stopRun;
  stopRun.StopAfter = 1;
  nv::Settings settings;
  nv::Reconstruction run(settings, nullptr, &stopRun);
  NV_CHECK(!run.Run(points) && run.Aborted() && run.Error().empty());
}

/// Errors are every rank's: no points anywhere, or a NaN on one rank.
void TestDistributedErrors()
{
  for (int bad : { 0, 1 })
  {
    Hub hub(3);
    std::vector<std::string> errors(3);
    std::vector<std::thread> threads;
    for (int rank = 0; rank < 3; ++rank)
    {
      threads.emplace_back([&, rank]() {
        std::vector<double> mine;
        if (bad && rank == 2)
        {
          mine = { 0.0, 0.0, 0.0, 1.0, std::nan(""), 0.0 };
        }
        nv::Settings settings;
        settings.MemoryLimit = 1000.0;
        ThreadCommunicator communicator(hub, rank);
        nv::Reconstruction run(settings, &communicator, nullptr);
        NV_CHECK(!run.Run(mine));
        errors[rank] = run.Error();
      });
    }
    for (std::thread& thread : threads)
    {
      thread.join();
    }
    for (const std::string& error : errors)
    {
      NV_CHECK(error.find(bad ? "non-finite" : "no points") != std::string::npos);
    }
  }
}

} // namespace

int main()
{
  TestSplitLayers();
  for (int ranks : { 1, 2, 3, 5 })
  {
    TestDistributedSolve(nv::Domain::NarrowBand, ranks, {});
  }
  TestDistributedSolve(nv::Domain::WholeDomain, 3, {});
  // Uneven slabs, and more ranks than brick layers (some ranks own nothing).
  TestDistributedSolve(nv::Domain::NarrowBand, 4, { 0.0, 0.0, 9.0, 1.0, 0.0 });
  TestDistributedSolve(nv::Domain::NarrowBand, 12, {});
  for (int ranks : { 1, 2, 3, 5 })
  {
    TestDistributedRun(ranks);
    TestDistributedRun(ranks, false, true);
  }
  // PreserveOffset: the same, serial phi on every rank.
  for (int ranks : { 2, 3, 5 })
  {
    TestDistributedSolve(nv::Domain::NarrowBand, ranks, {}, true);
    TestDistributedRun(ranks, true);
  }
  TestDistributedSolve(nv::Domain::NarrowBand, 4, { 0.0, 0.0, 9.0, 1.0, 0.0 }, true);
  TestDistributedSolve(nv::Domain::NarrowBand, 12, {}, true);
  TestDistributedSolve(nv::Domain::WholeDomain, 3, {}, true);
  TestDistributedErrors();
  TestDistributedSampling();
  TestSamplingProgressAndStop();
  return nvtest::Result("TestCorePartition");
}
