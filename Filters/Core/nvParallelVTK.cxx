// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The core's threads from vtkSMPTools (the VTK build), so that the filter and
// VTK's own filters in the same pipeline share one set of threads.
#include "nvParallelBackend.h"

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
}

bool Concurrent()
{
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
  vtkSMPTools::For(begin, end, grain, [&fn](std::int64_t first, std::int64_t last) { fn(first, last); });
}

void Scope(int threads, const std::function<void()>& body)
{
  std::string name = vtkSMPTools::GetBackend() ? vtkSMPTools::GetBackend() : "Sequential";
  if (name == "Sequential")
  {
    name = "STDThread";
  }
  struct Restore // the outer scope's request, also when body throws
  {
    int Outer = Requested;
    ~Restore() { Requested = this->Outer; }
  } restore;
  Requested = std::max(0, threads);
  vtkSMPTools::LocalScope(vtkSMPTools::Config{ threads, name, false }, body);
}

} // namespace backend
} // namespace nv
