// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The core's loops on either thread backend (this test is built twice: with
// vtkSMPTools, and with the std::thread pool of the Python wheel): every
// index visited once for any grain and thread count, no more threads than
// asked for, loops inside loops and loops from two threads at once, an
// exception reaching the caller (the pool), reductions and the shipped run's phi
// bit-identical for any thread count, and (std::thread pool) a forked child
// that still runs parallel loops. The VTK build runs its loops on the same
// pool when vtkSMPTools' backend is Sequential or STDThread: there it is
// tested as the pool.
#include "nvParallel.h"
#include "nvPieces.h"
#include "nvReconstruct.h"
#include "nvReconstruction.h"
#include "nvSurface.h"
#include "nvTestUtilities.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstring>
#include <memory>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

#ifndef NV_TEST_POOL
#include <vtkSMPTools.h>
#include <string>
#endif

#ifndef _WIN32
#include <csignal>
#include <sys/wait.h>
#include <unistd.h>
#endif

namespace
{

/// Whether the core's loops run on the std::thread pool of nvThreadPool.h.
bool OnPool()
{
#ifdef NV_TEST_POOL
  return true;
#else
  const std::string backend = vtkSMPTools::GetBackend() ? vtkSMPTools::GetBackend() : "Sequential";
  return backend == "Sequential" || backend == "STDThread";
#endif
}

/// Every index of [begin, end) visited exactly once by ParallelFor.
bool VisitsOnce(std::int64_t begin, std::int64_t end, std::int64_t grain)
{
  std::unique_ptr<std::atomic<int>[]> visits(new std::atomic<int>[static_cast<std::size_t>(end - begin)]);
  for (std::int64_t i = 0; i < end - begin; ++i)
  {
    visits[i] = 0;
  }
  nv::ParallelFor(begin, end, grain, [&](std::int64_t first, std::int64_t last) {
    for (std::int64_t i = first; i < last; ++i)
    {
      ++visits[i - begin];
    }
  });
  for (std::int64_t i = 0; i < end - begin; ++i)
  {
    if (visits[i] != 1)
    {
      return false;
    }
  }
  return true;
}

void TestCoverage()
{
  for (int threads : { 1, 2, 3, 8 })
  {
    nv::WithThreads(threads, [&]() {
      for (std::int64_t grain : { 1, 7, 1000, 100000 })
      {
        NV_CHECK(VisitsOnce(0, 10000, grain));
        NV_CHECK(VisitsOnce(-35, 77, grain));
      }
      NV_CHECK(VisitsOnce(5, 5, 3)); // empty
    });
  }
}

/// The distinct threads that ran the chunks of a loop of slow chunks.
std::size_t ThreadsSeen(int threads)
{
  std::mutex lock;
  std::set<std::thread::id> seen;
  nv::WithThreads(threads, [&]() {
    nv::ParallelFor(0, 100, 1, [&](std::int64_t, std::int64_t) {
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
      std::lock_guard<std::mutex> guard(lock);
      seen.insert(std::this_thread::get_id());
    });
  });
  return seen.size();
}

void TestThreadCount()
{
  const std::size_t one = ThreadsSeen(1), three = ThreadsSeen(3);
  std::printf("threads seen: %zu with 1 asked for, %zu with 3\n", one, three);
  NV_CHECK(one == 1);
  NV_CHECK(three >= 2 && three <= 3);
}

void TestNestedAndConcurrent()
{
  nv::WithThreads(4, [&]() {
    // A loop inside a loop's chunk runs (on that chunk's thread).
    std::atomic<std::int64_t> inner{ 0 };
    nv::ParallelFor(0, 16, 1, [&](std::int64_t, std::int64_t) {
      nv::ParallelFor(0, 1000, 10, [&](std::int64_t first, std::int64_t last) { inner += last - first; });
    });
    NV_CHECK(inner == 16 * 1000);
  });
  // Two threads (two reconstructions at once, say) loop at the same time.
  std::atomic<int> good{ 0 };
  std::vector<std::thread> callers;
  for (int c = 0; c < 2; ++c)
  {
    callers.emplace_back([&]() {
      nv::WithThreads(3, [&]() {
        bool all = true;
        for (int repeat = 0; repeat < 50; ++repeat)
        {
          all = VisitsOnce(0, 20000, 100) && all;
        }
        good += all ? 1 : 0;
      });
    });
  }
  for (std::thread& caller : callers)
  {
    caller.join();
  }
  NV_CHECK(good == 2);
}

// The std::thread pool hands an exception to the caller (VTK 9.2's
// STDThread backend, which the pool replaces, would end the process).
void TestException()
{
  bool caught = false;
  nv::WithThreads(3, [&]() {
    try
    {
      nv::ParallelFor(0, 1000, 10, [&](std::int64_t first, std::int64_t) {
        if (first == 500)
        {
          throw std::runtime_error("chunk 500");
        }
      });
    }
    catch (const std::runtime_error& error)
    {
      caught = std::strcmp(error.what(), "chunk 500") == 0;
    }
    NV_CHECK(VisitsOnce(0, 1000, 10)); // the loops still run afterwards
  });
  NV_CHECK(caught);
}

void TestReductions()
{
  // Values whose sum depends on the order of the additions.
  const std::int64_t n = 1000003;
  std::vector<double> values(static_cast<std::size_t>(n));
  for (std::int64_t i = 0; i < n; ++i)
  {
    values[static_cast<std::size_t>(i)] = 1.0 / (1.0 + static_cast<double>((i * 7919) % 1000));
  }
  auto sum = [&](std::int64_t begin, std::int64_t end) {
    double s = 0.0;
    for (std::int64_t i = begin; i < end; ++i)
    {
      s += values[static_cast<std::size_t>(i)];
    }
    return s;
  };
  double sums[4], maxima[4];
  const int counts[4] = { 1, 2, 3, 7 };
  for (int t = 0; t < 4; ++t)
  {
    nv::WithThreads(counts[t], [&]() {
      sums[t] = nv::ParallelSum(n, sum);
      maxima[t] = nv::ParallelMax(n, sum);
    });
  }
  for (int t = 1; t < 4; ++t)
  {
    NV_CHECK(sums[t] == sums[0]);
    NV_CHECK(maxima[t] == maxima[0]);
  }
}

/// The shipped run on a sphere: phi bit-identical for 1, 2 and 5 threads.
void TestRunThreads()
{
  const double center[3] = { 0.3, -0.1, 0.2 };
  const std::vector<double> points = nvtest::SpherePoints(3000, 0.5, center);
  std::vector<double> phi[3];
  const int counts[3] = { 1, 2, 5 };
  for (int t = 0; t < 3; ++t)
  {
    nv::Settings settings;
    settings.OffsetDistance = 0.1;
    settings.SampleSpacing = 0.02;
    settings.NumberOfThreads = counts[t];
    nv::Reconstruction run(settings, nullptr, nullptr);
    NV_CHECK(run.Run(points));
    phi[t].assign(run.GetPhi().begin(), run.GetPhi().end());
  }
  NV_CHECK(!phi[0].empty());
  NV_CHECK(phi[1] == phi[0]);
  NV_CHECK(phi[2] == phi[0]);
}

/// The usage block of nvReconstruct.h (on a coarser grid): the entry point
/// makes the surface and the results in one thread scope; the triangles
/// are the same for 1 and 3 threads.
void TestEntryPoint()
{
  const double center[3] = { 0.3, -0.1, 0.2 };
  const std::vector<double> xyz = nvtest::SpherePoints(3000, 0.5, center);
  std::vector<nv::VertexId> triangles[2];
  const int counts[2] = { 1, 3 };
  for (int t = 0; t < 2; ++t)
  {
    nv::Settings settings;                       // the property table's defaults
    settings.OffsetDistance = 0.1;               // l; 0: from the cloud's spacing
    settings.OutputVolume = false;               // no dense phi (a VolumeRequest takes it)
    settings.NumberOfThreads = counts[t];
    nv::Reconstruction run(settings, nullptr, nullptr); // one process, no monitor
    nv::SurfaceMesh surface;                     // or a sink into the caller's arrays
    nv::Outcome outcome = nv::Reconstruct(run, xyz, nullptr, surface, nv::VolumeRequest(), false);
    NV_CHECK(outcome.Done && outcome.Error.empty());
    NV_CHECK(!surface.Triangles.empty());
    NV_CHECK(outcome.Chosen.OffsetDistanceUsed == 0.1);
    NV_CHECK(outcome.Chosen.SampleSpacingUsed == run.GetGrid().Spacing);
    NV_CHECK(outcome.Chosen.GridDimensionsUsed[2] == static_cast<int>(run.GetGrid().Dims[2]));
    NV_CHECK(outcome.Chosen.GridUsed == std::to_string(run.GetGrid().Dims[0]) + " x " +
        std::to_string(run.GetGrid().Dims[1]) + " x " + std::to_string(run.GetGrid().Dims[2]));
    triangles[t] = surface.Triangles;
  }
  NV_CHECK(triangles[1] == triangles[0]);
}

#ifndef _WIN32
/// A child made by fork() after the pool started runs parallel loops too
/// (it has none of its parent's threads).
void TestFork()
{
  nv::WithThreads(3, [&]() { NV_CHECK(VisitsOnce(0, 10000, 10)); });
  const pid_t child = fork();
  if (child == 0)
  {
    alarm(20); // a hang ends the child
    bool ok = true;
    nv::WithThreads(3, [&]() { ok = VisitsOnce(0, 10000, 10); });
    _exit(ok ? 0 : 1);
  }
  int status = 0;
  NV_CHECK(child > 0 && waitpid(child, &status, 0) == child);
  NV_CHECK(WIFEXITED(status) && WEXITSTATUS(status) == 0);
}
#endif

} // namespace

/// Small pieces removed from a surface of 400,000 tetrahedra (1.6 million
/// points, the parts' loops over many chunks), every third one too small
/// to stay: the kept points and triangles, in their order and renumbered,
/// the same as a plain serial compaction, for 1, 2 and 5 threads.
void TestSmallPiecesThreads()
{
  const std::int64_t tetrahedra = 400000;
  nv::SurfaceMesh mesh;
  std::vector<char> small(static_cast<std::size_t>(tetrahedra));
  // Points in an order that interleaves the pieces: point k of tetrahedron
  // i is point k * tetrahedra + i.
  mesh.Points.resize(3 * 4 * tetrahedra);
  mesh.Normals.resize(3 * 4 * tetrahedra);
  for (std::int64_t i = 0; i < tetrahedra; ++i)
  {
    small[i] = i % 3 == 1;
    const double size = small[i] ? 0.01 : 1.0; // volume 1/6 against SmallPieceVolume(0.1) = 0.034
    const double corner[4][3] = { { 0, 0, 0 }, { size, 0, 0 }, { 0, size, 0 }, { 0, 0, size } };
    for (int k = 0; k < 4; ++k)
    {
      const std::int64_t p = k * tetrahedra + i;
      for (int a = 0; a < 3; ++a)
      {
        mesh.Points[3 * p + a] = 10.0 * static_cast<double>(i) * (a == 0) + corner[k][a];
        mesh.Normals[3 * p + a] = static_cast<float>(p % 7 + a);
      }
    }
    // Faces outwards: the volume comes out positive (a piece).
    const int faces[4][3] = { { 0, 2, 1 }, { 0, 1, 3 }, { 0, 3, 2 }, { 1, 2, 3 } };
    for (const auto& face : faces)
    {
      for (int v = 0; v < 3; ++v)
      {
        mesh.Triangles.push_back(face[v] * tetrahedra + i);
      }
    }
  }
  // The serial compaction the result must equal.
  std::vector<double> points;
  std::vector<float> normals;
  std::vector<nv::VertexId> triangles;
  std::vector<std::int64_t> newId(4 * tetrahedra, -1);
  for (std::int64_t p = 0; p < 4 * tetrahedra; ++p)
  {
    if (!small[p % tetrahedra])
    {
      newId[p] = static_cast<std::int64_t>(points.size() / 3);
      points.insert(points.end(), &mesh.Points[3 * p], &mesh.Points[3 * p] + 3);
      normals.insert(normals.end(), &mesh.Normals[3 * p], &mesh.Normals[3 * p] + 3);
    }
  }
  for (std::size_t t = 0; t < mesh.Triangles.size(); t += 3)
  {
    if (!small[mesh.Triangles[t] % tetrahedra])
    {
      for (int v = 0; v < 3; ++v)
      {
        triangles.push_back(newId[mesh.Triangles[t + v]]);
      }
    }
  }
  const nv::Grid grid; // no phi: the grid is not read
  for (int threads : { 1, 2, 5 })
  {
    nv::SurfaceMesh copy = mesh;
    nv::RemovedPieces removed;
    nv::WithThreads(threads, [&]() { removed = nv::RemoveSmallPieces(copy, 0.1, grid, nullptr, 0, 0); });
    NV_CHECK(removed.Pieces == (tetrahedra + 1) / 3 && removed.KeptPieces == tetrahedra - (tetrahedra + 1) / 3);
    NV_CHECK(copy.Points == points && copy.Normals == normals && copy.Triangles == triangles);
  }
}

int main()
{
  TestCoverage();
  TestThreadCount();
  TestNestedAndConcurrent();
  if (OnPool())
  {
    TestException();
  }
  TestReductions();
  TestRunThreads();
  TestEntryPoint();
  TestSmallPiecesThreads();
#ifndef _WIN32
  if (OnPool())
  {
    TestFork();
  }
#endif
  return nvtest::Result(NV_TEST_NAME);
}
