// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// How densely the cloud is sampled, and the automatic offset and spacing that
// follow from it.
//
// The shell is the set of nodes closer than l to some point (eq. 2, 6): the
// union of balls of radius l around the points. Where two neighbouring points
// are farther apart than l, the wall between them thins (its thickness at the
// midpoint of two points d apart is 2 sqrt(l^2 - d^2 / 4), and less between
// three or more) until the evolution opens it: a tunnel through the wall, or,
// beyond 2 l, a loose ball around a lone point. So the spacing statistic that
// matters is each point's distance to its nearest neighbour, d1:
//
// - the automatic offset is l = max(1.5 median(d1), the 99.9th percentile of
//   d1): the walls close wherever 999 in 1000 points have a neighbour within
//   l, and l stays near the sampling scale, so that detail survives;
// - the automatic spacing is the paper's h = l / 4 (section 4), unless the
//   grid's longest side would then exceed AutomaticMaximumDimension cells:
//   then h is that side over AutomaticMaximumDimension and l at least 4 h.
//
// The nearest-neighbour distance does not see a hole in the sampled surface
// (its rim's points have near neighbours along the rim): nvGapClosing.h
// measures and bridges those.
#ifndef nvSampling_h
#define nvSampling_h

#include <cstdint>
#include <vector>

namespace nv
{
class Communicator;
class Monitor;

/// The longest side, in cells, of a grid whose spacing is chosen automatically.
constexpr int AutomaticMaximumDimension = 320;

struct SamplingStatistics
{
  std::int64_t Points = 0;     ///< all points (all processes)
  double MedianSpacing = 0.0;  ///< median distance to the nearest other point
  double WideSpacing = 0.0;    ///< its 99.9th percentile
  bool Valid() const { return this->MedianSpacing > 0.0; }
};

/**
 * Nearest-neighbour distances of a cloud. In a distributed run each process
 * measures the points of one slab of z (with the few points of the slabs
 * next to it that some of its points need): every process gets the same
 * figures, equal to a serial run's, and none holds the whole cloud.
 */
class Sampling
{
public:
  /// Collective. Measures the distance from each point to its nearest other
  /// point (duplicates of a point do not count as neighbours). The monitor
  /// (may be null) gets the progress of the search, which takes most of the
  /// time, and may stop it: then false on every process, and the figures
  /// are not to be used.
  bool Measure(const std::vector<double>& xyz, Communicator* communicator, Monitor* monitor = nullptr);
  const SamplingStatistics& Statistics() const { return this->Stats; }
  /// The points this process held while measuring: all of them in a
  /// serial run (the caller's, not copied); in a distributed run, its slab's.
  /// None is kept after the measurement, only the figures.
  std::int64_t HeldPoints() const { return this->Held; }
  /// Wall-clock seconds the measurement took.
  double Seconds() const { return this->Time; }

private:
  bool MeasureHere(const std::vector<double>& xyz, Monitor* monitor);
  bool MeasureDistributed(const std::vector<double>& xyz, Communicator& communicator, Monitor* monitor);

  std::int64_t Held = 0;
  double Time = 0.0;
  SamplingStatistics Stats;
};

/// Bounds of xyz triples (empty: xmin > xmax). Returns the index of the first
/// point with a non-finite coordinate, or -1.
std::int64_t PointBounds(const std::vector<double>& xyz, double bounds[6]);

/// The bounds of all processes' points (in place), collective.
void GlobalBounds(Communicator& communicator, double bounds[6]);

} // namespace nv

#endif
