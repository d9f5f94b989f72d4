// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The core's threads in the VTK build: vtkSMPTools' TBB or OpenMP threads, so
// that the filter and VTK's own filters share one set of threads; where the
// backend is STDThread (or Sequential, which the filter lifts to STDThread),
// the pool of nvThreadPool.h. VTK 9.2's STDThread backend starts new threads
// for every loop and hands each chunk over through a mutex-guarded queue:
// tens of microseconds a loop, and the Gauss-Seidel sweeps make two loops a
// sweep (the sphere of Fig. 5: 0.13 s a run against 0.11 s on the pool, and
// its half sweeps then gain from a second thread; see nvParallel.cxx).
#include "nvParallelBackend.h"
#include "nvThreadPool.h"

#include <vtkSMPTools.h>

#include <algorithm>
#include <string>
#include <thread>

namespace nv
{
namespace backend
{

namespace
{
/// Threads asked for by the innermost Scope open on this thread (0: all
/// cores); -1 outside any.
thread_local int Requested = -1;
/// Threads of the pool in the innermost Scope open on this thread; 0 when
/// its loops go to vtkSMPTools (or outside any Scope).
thread_local int PoolThreads = 0;
}

bool Concurrent()
{
  if (PoolThreads > 0)
  {
    return PoolThreads > 1 && !InPoolLoop();
  }
  // A parallel region costs tens of microseconds in VTK 9.2's STDThread
  // backend, even with one thread: with one, the caller loops itself. Inside
  // a Scope the answer comes from what it asked for: VTK 9.6's TBB backend
  // goes on reporting the thread count of an earlier, finished one-thread
  // scope as its estimate (while its loops do use every thread).
  if (Requested == 0)
  {
    return std::thread::hardware_concurrency() > 1;
  }
  return Requested > 1 || (Requested < 0 && vtkSMPTools::GetEstimatedNumberOfThreads() > 1);
}

void For(std::int64_t begin, std::int64_t end, std::int64_t grain, const RangeFunction& fn)
{
  if (PoolThreads > 0)
  {
    PoolFor(begin, end, grain, PoolThreads, fn);
    return;
  }
  vtkSMPTools::For(begin, end, grain, [&fn](std::int64_t first, std::int64_t last) { fn(first, last); });
}

void Scope(int threads, const std::function<void()>& body)
{
  std::string name = vtkSMPTools::GetBackend() ? vtkSMPTools::GetBackend() : "Sequential";
  const bool pool = name == "Sequential" || name == "STDThread";
  if (pool)
  {
    name = "STDThread"; // for VTK filters run inside body
  }
  struct Restore // the outer scope's settings, also when body throws
  {
    int Outer = Requested;
    int OuterPool = PoolThreads;
    ~Restore()
    {
      Requested = this->Outer;
      PoolThreads = this->OuterPool;
    }
  } restore;
  Requested = std::max(0, threads);
  vtkSMPTools::LocalScope(vtkSMPTools::Config{ threads, name, false }, [&]() {
    // Within the scope, STDThread's estimate is `threads`, or its default
    // (all cores, or what vtkSMPTools::Initialize or VTK_SMP_MAX_THREADS set).
    PoolThreads = pool ? std::max(1, vtkSMPTools::GetEstimatedNumberOfThreads()) : 0;
    body();
  });
}

} // namespace backend
} // namespace nv
