// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// Bridging the holes of the sampling before the distance is computed: an
// addition to the paper's method, which takes the points as they come.
//
// The shell is the union of balls of radius l around the points (eq. 2, 6).
// Over an empty disc of radius rho on the sampled surface (no point within
// rho of its centre) the wall's half-thickness is sqrt(l^2 - rho^2): a disc
// wider than l pierces the wall, and one such tunnel joins the outer and the
// inner sheet, so the shell has no cavity. The nearest-neighbour spacing
// (nvSampling.h) does not see these discs: the points along a hole's rim
// have near neighbours along the rim.
//
// The measure, per point p of a thinned copy of the cloud (one point per
// cube of side l / 2: a dense cloud has thousands of points within 2 l of
// each, and the holes that matter are wider than l):
//  - the tangent plane at p: the principal directions of p's neighbours
//    within 2 l;
//  - in that plane, the largest empty circle through p in each of
//    `Directions` directions u: the circle of centre p + t u is empty while
//    t <= |v|^2 / (2 v.u) for every neighbour projected to v with v.u > 0;
//  - such a circle is a hole when the points around it (within t + l of its
//    centre) surround the centre (their directions from it leave no gap of
//    2 pi / 3 or more), when, lifted to the mean height of its rim, its
//    centre is farther than l from every point of the whole cloud (the
//    shell is pierced there: on a curved or thin part points off the plane
//    may cover it), and when
//    the points around that empty ball lie in directions near the tangent
//    plane (a hole's rim in the surface, not a crevice between toes or two
//    facing sheets, which the shell fills as it should); an open circle
//    belongs to an edge of the surface (a scan's border, the mouth of a cup)
//    and is left alone. Its radius is the empty ball's.
//
// Bridging: the centre of each hole of radius in (l, ClosingRadius] becomes a
// new point (on a curved surface too, lifted to its rim), and the rims are
// measured again with the target 3/4 l, at most three times (each round
// about halves the discs left). Where a hole is bridged, no
// empty disc is wider than 3/4 l: the wall over it is at least
// sqrt(1 - 0.75^2) l = 0.66 l on each side of the surface, against l where
// the sampling is dense. Holes wider than ClosingRadius are left open and
// reported (GapReport), with their rim's points and centre. Concavities are
// not filled, unlike a morphological closing of the shell: the points are
// only added inside holes of the sampled surface.
//
// Every result for a point depends only on the points within Reach() of it,
// so that a process holding the points within that distance of its region
// computes there exactly what a serial run does (nvReconstruction.cxx).
#ifndef nvGapClosing_h
#define nvGapClosing_h

#include "nvGrid.h"

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

namespace nv
{
class Monitor;

/// One empty disc seen from one rim point: centre (x, y, z), radius, and
/// the normal of the surface's tangent plane there.
struct Hole
{
  std::array<double, 3> Center;
  double Radius;
  std::array<double, 3> Normal{ { 0.0, 0.0, 0.0 } };
};

/// One hole left open: the empty discs its rim's points see, grouped.
struct OpenHole
{
  double Radius = 0.0;                                    ///< the widest disc's radius (world units)
  std::array<double, 3> Center{ { 0.0, 0.0, 0.0 } };      ///< the widest disc's centre
  std::vector<Hole> Discs;                                ///< every disc, where the wall is probed
  /// Set after the evolution (Reconstruction::ProbeHoles): whether the
  /// shell's wall has a tunnel there, so that its outer and inner sheets
  /// join (nvHoleProbe.h). A hole the evolved wall covers is measured but
  /// harmless.
  bool Pierced = false;
};

/// The holes the shell cannot bridge, measured after the gap closing.
struct GapReport
{
  std::int64_t Gaps = 0;      ///< holes left open (groups of circles whose centres lie within 2 l)
  std::int64_t GapPoints = 0; ///< rim points of those holes
  double LargestGap = 0.0;    ///< radius of the largest empty disc left open (world units)
  std::array<double, 3> LargestGapCenter{ { 0.0, 0.0, 0.0 } }; ///< its centre
  std::vector<OpenHole> Holes; ///< the Gaps holes, widest first

  /// The holes that pierce the evolved shell.
  std::int64_t PiercedGaps() const;
};

/// The automatic closing radius, in offsets: holes of radius up to 3 l.
constexpr double AutomaticClosingRadius = 3.0;
/// After a hole is found, the rims are measured again down to this share of
/// l: the wall over a bridged hole keeps sqrt(1 - 0.75^2) = 0.66 of its
/// half-thickness. An offset of R / BridgeTarget covers a hole of radius R
/// with the same margin.
constexpr double BridgeTarget = 0.75;

class GapClosing
{
public:
  /**
   * grid: the run's grid (its origin anchors every computation, so that all
   * processes compute alike). offset: l. radius: the largest hole radius
   * that is bridged (world units); 0 or less: none, holes are only measured.
   */
  GapClosing(const Grid& grid, double offset, double radius);

  /// Holes are looked for up to this radius (twice the closing radius, or
  /// 2 AutomaticClosingRadius l when nothing is bridged); wider openings
  /// belong to the surface (an open scan, the base of a statue).
  double MeasuredRadius() const { return this->Measured; }
  /// The distance within which the points decide the points added at a
  /// place and the holes reported there.
  double Reach() const;

  /**
   * Adds the bridging points to xyz (world coordinates, appended) and
   * measures the holes left open. The holes seen from the points for which
   * owned(point) is true are kept (OpenHoles); null: all. Returns false if
   * the monitor stopped it (xyz is then unchanged).
   */
  bool Run(std::vector<double>& xyz, const std::function<bool(const double*)>& owned, Monitor* monitor);

  std::int64_t AddedPoints() const { return this->Added; }
  /// One entry per rim point of a hole left open, in ascending point order.
  const std::vector<Hole>& OpenHoles() const { return this->Open; }

private:
  Grid GridNodes;
  double Offset;
  double Radius;
  double Measured;
  std::int64_t Added = 0;
  std::vector<Hole> Open;
};

/// The report of the holes left open, from the holes seen by every process
/// (the same, in any order, for any number of processes).
GapReport SummarizeHoles(std::vector<Hole> holes, double offset);

} // namespace nv

#endif
