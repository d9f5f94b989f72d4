// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nvParallel.h"

#include "nvParallelBackend.h"

#include <algorithm>
#include <vector>

namespace nv
{
namespace
{
// Chunk size of the deterministic reductions: fixed, never derived from the thread count.
constexpr std::int64_t ReductionChunk = 8192;
// Below this many items a reduction (one Gauss-Seidel half sweep, say) costs
// less on the calling thread than shared out; above, each chunk is a task of
// its own (the threads take the next chunk from a counter, so 8192 items a
// task balance them at little cost). Measured on 2 cores with the pool of
// nvThreadPool.h (benchmarks/sweep_bandwidth --cells N --threads 1 2): half
// sweeps of 21,000 and 40,000 nodes run 1.2x to 1.4x slower on two threads
// than on one, of 81,000 from 0.97x slower to 1.36x faster, of 100,000 and
// up 1.3x to 2x faster. A sweep of a band that fits in the caches gains from
// a second thread once its halves are long enough to pay the wake-up.
constexpr std::int64_t SerialReduction = 1 << 16;

std::vector<double> ChunkValues(std::int64_t n, const RangeReduction& fn)
{
  const std::int64_t chunks = (n + ReductionChunk - 1) / ReductionChunk;
  std::vector<double> values(static_cast<std::size_t>(chunks), 0.0);
  ParallelFor(0, chunks, n < SerialReduction ? chunks : 1, [&](std::int64_t first, std::int64_t last) {
    for (std::int64_t c = first; c < last; ++c)
    {
      const std::int64_t begin = c * ReductionChunk;
      values[static_cast<std::size_t>(c)] = fn(begin, std::min(n, begin + ReductionChunk));
    }
  });
  return values;
}
} // namespace

void ParallelFor(std::int64_t begin, std::int64_t end, std::int64_t grain, const RangeFunction& fn)
{
  if (end <= begin)
  {
    return;
  }
  grain = std::max<std::int64_t>(grain, 1);
  // One chunk of work, or one thread: run here.
  if (end - begin <= grain || !backend::Concurrent())
  {
    for (std::int64_t first = begin; first < end; first += grain)
    {
      fn(first, std::min(end, first + grain));
    }
    return;
  }
  backend::For(begin, end, grain, fn);
}

void WithThreads(int threads, const std::function<void()>& body)
{
  backend::Scope(threads, body);
}

namespace
{
/// MonitoredFor and StoppableFor: rounds, reporting each round's end when `report`.
bool ForInRounds(std::int64_t begin, std::int64_t end, std::int64_t grain, Monitor* monitor, bool report,
  const RangeFunction& fn)
{
  constexpr std::int64_t Rounds = 16;
  const std::int64_t n = end - begin;
  const std::int64_t round = monitor ? std::max<std::int64_t>(grain, (n + Rounds - 1) / Rounds) : n;
  for (std::int64_t first = begin; first < end; first += round)
  {
    if (monitor && monitor->Aborted())
    {
      return false;
    }
    ParallelFor(first, std::min(end, first + round), grain, fn);
    if (monitor && report)
    {
      monitor->Progress(static_cast<double>(std::min(end, first + round) - begin) / n);
    }
  }
  return !(monitor && monitor->Aborted());
}
} // namespace

bool MonitoredFor(
  std::int64_t begin, std::int64_t end, std::int64_t grain, Monitor* monitor, const RangeFunction& fn)
{
  return ForInRounds(begin, end, grain, monitor, true, fn);
}

bool StoppableFor(
  std::int64_t begin, std::int64_t end, std::int64_t grain, Monitor* monitor, const RangeFunction& fn)
{
  return ForInRounds(begin, end, grain, monitor, false, fn);
}

bool StopAsked(Monitor* monitor)
{
  return monitor && monitor->Aborted();
}

double ParallelSum(std::int64_t n, const RangeReduction& fn)
{
  double sum = 0.0;
  for (double v : ChunkValues(n, fn))
  {
    sum += v;
  }
  return sum;
}

double ParallelMax(std::int64_t n, const RangeReduction& fn)
{
  double result = 0.0;
  for (double v : ChunkValues(n, fn))
  {
    result = std::max(result, v);
  }
  return result;
}

Monitor::~Monitor() = default;
void Monitor::Stage(double, double) {}
void Monitor::Progress(double) {}
bool Monitor::Aborted()
{
  return false;
}

//------------------------------------------------------------------------------
CallerMonitor::CallerMonitor()
  : Caller(std::this_thread::get_id())
{
}

void CallerMonitor::Stage(double begin, double width)
{
  this->Begin = begin;
  this->Width = width;
  this->Progress(0.0);
}

void CallerMonitor::Progress(double fraction)
{
  if (this->OnCallerThread())
  {
    // Monotone: a stage's parts may report out of order. A stage's start is
    // reported even when it adds nothing.
    const double progress = std::max(this->Last, this->Begin + this->Width * fraction);
    if (progress > this->Last || fraction == 0.0)
    {
      this->Last = progress;
      this->Reported = std::chrono::steady_clock::now();
      this->Report(progress);
    }
    this->Stop = this->Stop || this->Poll();
  }
}

bool CallerMonitor::Aborted()
{
  if (this->OnCallerThread())
  {
    // The caller hears a stop only when the run reports (a GUI's abort
    // button, Python's Ctrl-C run in its progress event): work that asks
    // between reports, a sort of millions, reports the same figure again,
    // at most every ReportAgain, so that the stop comes through.
    const auto now = std::chrono::steady_clock::now();
    if (!this->Stop && now - this->Reported >= ReportAgain)
    {
      this->Reported = now;
      this->Report(this->Last);
    }
    this->Stop = this->Stop || this->Poll();
  }
  return this->Stop;
}

} // namespace nv
