// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The core's threads without VTK (the Python wheel): the pool of
// nvThreadPool.h, with WithThreads' count.
#include "nvParallelBackend.h"
#include "nvThreadPool.h"

#include <algorithm>
#include <thread>

namespace nv
{
namespace backend
{
namespace
{
thread_local int ScopeThreads = 0; // WithThreads' count on this thread; 0: all cores

int WantedThreads()
{
  const int all = static_cast<int>(std::thread::hardware_concurrency());
  return std::max(1, ScopeThreads > 0 ? ScopeThreads : all);
}
} // namespace

bool Concurrent()
{
  return !InPoolLoop() && WantedThreads() > 1;
}

void For(std::int64_t begin, std::int64_t end, std::int64_t grain, const RangeFunction& fn)
{
  PoolFor(begin, end, grain, WantedThreads(), fn);
}

void Scope(int threads, const std::function<void()>& body)
{
  const int outer = ScopeThreads;
  ScopeThreads = threads;
  try
  {
    body();
  }
  catch (...)
  {
    ScopeThreads = outer;
    throw;
  }
  ScopeThreads = outer;
}

} // namespace backend
} // namespace nv
