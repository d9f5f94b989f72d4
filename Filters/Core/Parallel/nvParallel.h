// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// Parallel loops for the numerical core. The core states its loops as plain
// functions of an index range; this file runs them on threads. Sums and
// maxima are reduced over fixed-size chunks in a fixed order, so results are
// bit-identical for any number of threads and for either backend.
//
// The threads come from one of two backends, chosen when the core is built
// (CMake option NARROWVOLUME_CORE_THREADS): vtkSMPTools in the VTK build
// (nvParallelVTK.cxx), so that the filter shares VTK's threads; or a small
// pool of std::threads (nvParallelThreads.cxx) in the Python wheel, which is
// built without VTK.
#ifndef nvParallel_h
#define nvParallel_h

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <thread>
#include <vector>

namespace nv
{

using RangeFunction = std::function<void(std::int64_t begin, std::int64_t end)>;
using RangeReduction = std::function<double(std::int64_t begin, std::int64_t end)>;

/// Calls fn on disjoint sub-ranges covering [begin, end), possibly concurrently.
void ParallelFor(
  std::int64_t begin, std::int64_t end, std::int64_t grain, const RangeFunction& fn);

class Monitor;

/**
 * ParallelFor in about 16 rounds: after each round, on the calling thread,
 * reports the fraction done to the monitor and stops early if it asks to.
 * (Worker threads cannot report: a GUI takes progress from its own thread.)
 * Returns false if it stopped early. monitor may be null.
 */
bool MonitoredFor(
  std::int64_t begin, std::int64_t end, std::int64_t grain, Monitor* monitor, const RangeFunction& fn);

/// ParallelFor in about 16 rounds, asking the monitor (may be null) to stop
/// between them, on the calling thread, without reports of progress (a
/// loop inside a step whose progress is reported as a whole). Returns false
/// if it stopped early.
bool StoppableFor(
  std::int64_t begin, std::int64_t end, std::int64_t grain, Monitor* monitor, const RangeFunction& fn);

/// Whether the monitor (may be null) asks to stop: for work between two
/// reports of progress, asked on the calling thread (Monitor::Aborted).
bool StopAsked(Monitor* monitor);

/// Sorts v: fixed chunks sorted in parallel, then merged pairwise, in
/// parallel while there are several pairs (the result is the sorted
/// sequence, whatever the threads). With a monitor, asks it to stop after
/// every four chunks and every round of merges (a sort of millions takes
/// seconds): false, and v unsorted, if it did.
template <typename T, typename Allocator>
bool ParallelSort(std::vector<T, Allocator>& v, Monitor* monitor = nullptr)
{
  constexpr std::int64_t Chunks = 32;
  constexpr std::int64_t ChunksPerRound = 4;
  const std::int64_t n = static_cast<std::int64_t>(v.size());
  auto bound = [&](std::int64_t c) { return v.begin() + static_cast<std::ptrdiff_t>(n * c / Chunks); };
  for (std::int64_t first = 0; first < Chunks; first += ChunksPerRound)
  {
    if (StopAsked(monitor))
    {
      return false;
    }
    ParallelFor(first, first + ChunksPerRound, 1, [&](std::int64_t begin, std::int64_t end) {
      for (std::int64_t c = begin; c < end; ++c)
      {
        std::sort(bound(c), bound(c + 1));
      }
    });
  }
  for (std::int64_t width = 1; width < Chunks; width *= 2)
  {
    if (StopAsked(monitor))
    {
      return false;
    }
    ParallelFor(0, Chunks / (2 * width), 1, [&](std::int64_t begin, std::int64_t end) {
      for (std::int64_t m = begin; m < end; ++m)
      {
        const std::int64_t first = 2 * width * m;
        std::inplace_merge(bound(first), bound(first + width), bound(first + 2 * width));
      }
    });
  }
  return !StopAsked(monitor);
}

/// Sum of fn over fixed chunks of [0, n), added in chunk order (deterministic).
double ParallelSum(std::int64_t n, const RangeReduction& fn);

/// Maximum of fn over fixed chunks of [0, n) (0 for an empty range).
double ParallelMax(std::int64_t n, const RangeReduction& fn);

/**
 * Runs body with `threads` threads for the loops above (0: all cores). With
 * vtkSMPTools, a process whose backend is Sequential (the default of
 * Debian's ParaView) gets the STDThread backend for the scope, so that VTK
 * filters run inside body use threads too; the core's own loops then run on
 * the pool of nvThreadPool.h.
 */
void WithThreads(int threads, const std::function<void()>& body);

/// Receives progress and answers whether the caller wants the work stopped.
class Monitor
{
public:
  virtual ~Monitor();
  /// A stage of the run begins; it covers [begin, begin + width) of the whole
  /// run's progress (fractions in [0, 1]).
  virtual void Stage(double begin, double width);
  /// fraction in [0, 1] of the current stage
  virtual void Progress(double fraction);
  virtual bool Aborted();
};

/**
 * A monitor that passes another's stages on within a share of its progress,
 * [Begin, Begin + Width): a run's stages, which say where they lie in the
 * run, when the run is a share of a longer job.
 */
class ShareMonitor : public Monitor
{
public:
  ShareMonitor(Monitor& whole, double begin, double width)
    : Whole(whole)
    , Begin(begin)
    , Width(width)
  {
  }
  void Stage(double begin, double width) override
  {
    this->Whole.Stage(this->Begin + this->Width * begin, this->Width * width);
  }
  void Progress(double fraction) override { this->Whole.Progress(fraction); }
  bool Aborted() override { return this->Whole.Aborted(); }

private:
  Monitor& Whole;
  double Begin;
  double Width;
};

/**
 * A monitor for a caller that takes progress and answers "stop?" only on
 * its own thread (a GUI's event loop, Python's interpreter): the whole run's
 * progress as one fraction that never goes back, reported from the thread
 * that created the monitor; worker threads get the caller's last answer.
 * The VTK filter and the Python binding both derive from it.
 */
class CallerMonitor : public Monitor
{
public:
  CallerMonitor();
  void Stage(double begin, double width) override;
  void Progress(double fraction) override;
  bool Aborted() override;

protected:
  /// The run's progress in [0, 1], on the caller's thread, never below the last report.
  virtual void Report(double progress) = 0;
  /// Whether the caller wants the run stopped, asked on the caller's thread
  /// (not again once it said yes).
  virtual bool Poll() = 0;

private:
  bool OnCallerThread() const { return std::this_thread::get_id() == this->Caller; }

  /// The longest the caller goes without a report while the run asks
  /// whether to stop.
  static constexpr std::chrono::milliseconds ReportAgain{ 100 };

  std::thread::id Caller;
  std::chrono::steady_clock::time_point Reported = std::chrono::steady_clock::now();
  double Begin = 0.0;
  double Width = 1.0;
  double Last = 0.0;
  std::atomic<bool> Stop{ false };
};

} // namespace nv

#endif
