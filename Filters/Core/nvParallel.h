// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// Parallel loops for the numerical core. The core states its loops as plain
// functions of an index range; this file runs them with vtkSMPTools. Sums and
// maxima are reduced over fixed-size chunks in a fixed order, so results are
// bit-identical for any number of threads.
#ifndef nvParallel_h
#define nvParallel_h

#include <cstdint>
#include <functional>

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

/// Sum of fn over fixed chunks of [0, n), added in chunk order (deterministic).
double ParallelSum(std::int64_t n, const RangeReduction& fn);

/// Maximum of fn over fixed chunks of [0, n) (0 for an empty range).
double ParallelMax(std::int64_t n, const RangeReduction& fn);

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

} // namespace nv

#endif
