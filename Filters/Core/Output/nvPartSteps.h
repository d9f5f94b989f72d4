// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The steps of the part to print (MakePart, nvPrintPart.h), each in a file
// of its own: the distance D to the outer sheet (nvSheetDistance.cxx), the
// field f and the material put back (nvPartField.cxx), the drain holes
// (nvDrainHoles.cxx), and the checks of the part, its thinnest wall and the
// scan's lost points (nvPartChecks.cxx). Internal to Output/.
#ifndef nvPartSteps_h
#define nvPartSteps_h

#include "nvNearestPoints.h"
#include "nvPrintPart.h"
#include "nvSurfaceField.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

namespace nv
{
namespace part
{
/// D on the nodes inside S (the outer phi > 0) up to `cap`, and outside S
/// near the sheet; `cap` elsewhere. Each vertex of the sheet gives the nodes
/// within two cells of it their distance to it; from those, the nearest
/// vertex moves inward node by node, to the 26 neighbours, nearest first (a
/// closest-point propagation: a node's nearest vertex is, but for rare
/// ties, one of its neighbours'). "Nearest first" by buckets h / 8 wide
/// (Dial's queue). The nodes of a bucket are swept in parallel, in rounds:
/// a round sweeps the nodes whose key is still the one they were queued
/// with when it begins, and lowers their neighbours' keys (an atomic least,
/// whose outcome no order changes); the nodes it lowered are the next
/// round's, in this bucket or a later one. So the result is the same on
/// every run and for any number of threads. Empty if the monitor (may be
/// null) asked to stop between rounds.
std::vector<float> SheetDistance(
  const Grid& grid, const float* outer, const std::vector<double>& sheet, double cap, Monitor* monitor);

/// A drain hole: the nodes within Radius of the segment from A (inside a
/// cavity) to B (outside the part) are no material.
struct Drill
{
  double A[3], B[3];
  double Radius;

  /// The distance from x to the hole's surface, negative inside the hole.
  double Signed(const double x[3]) const
  {
    double ab[3], ax[3], along = 0.0, length = 0.0;
    for (int a = 0; a < 3; ++a)
    {
      ab[a] = this->B[a] - this->A[a];
      ax[a] = x[a] - this->A[a];
      along += ab[a] * ax[a];
      length += ab[a] * ab[a];
    }
    const double t = length > 0.0 ? std::min(1.0, std::max(0.0, along / length)) : 0.0;
    double d2 = 0.0;
    for (int a = 0; a < 3; ++a)
    {
      const double r = ax[a] - t * ab[a];
      d2 += r * r;
    }
    return std::sqrt(d2) - this->Radius;
  }
};

/// Material put back around the scan points the part lost: a rod of
/// `radius` along the segment from each scan point within `reach` of a lost
/// one (itself included) to each of its nearest scan points within `reach`:
/// the rods join a lost limb's points to one another, and its ends to the
/// part. As a drain hole is a rod of no material. The rods are listed by the bricks they reach.
class Restoration
{
public:
  Restoration(const Grid& grid, const double* scan, std::int64_t scanPoints, const std::vector<std::int64_t>& lost,
    double radius, double reach);

  /// Whether a rod reaches brick b.
  bool Reaches(std::int64_t b) const
  {
    const auto found = std::lower_bound(this->ByBrick.begin(), this->ByBrick.end(), std::make_pair(b, std::int32_t(0)));
    return found != this->ByBrick.end() && found->first == b;
  }

  /// The material's f at x in brick b: the radius less the distance to the
  /// nearest rod (> 0 inside one).
  double Value(std::int64_t b, const double x[3]) const
  {
    double value = -std::numeric_limits<double>::infinity();
    for (auto r = std::lower_bound(this->ByBrick.begin(), this->ByBrick.end(), std::make_pair(b, std::int32_t(0)));
         r != this->ByBrick.end() && r->first == b; ++r)
    {
      value = std::max(value, -this->Rods[r->second].Signed(x));
    }
    return value;
  }

  /// Whether x lies within `reach` of a lost point.
  bool NearLost(const double* x, double reach) const { return this->LostPoints->Distance(x, reach) < reach; }

  double Radius;

private:
  std::unique_ptr<NearestPoints> LostPoints; ///< the lost points
  /// The nearest scan points a lost point is joined to (itself among them).
  static constexpr int NeighboursJoined = 16;
  std::array<std::int64_t, 3> BrickDims;
  std::vector<Drill> Rods;
  std::vector<std::pair<std::int64_t, std::int32_t>> ByBrick; ///< (brick, rod), ascending
};

/// A value at a place, trilinear between the nodes of its cell (the nearest
/// cell for a place beyond the grid), whose values node(i, j, k) gives.
template <class NodeValue>
double Trilinear(const Grid& grid, const double x[3], const NodeValue& node)
{
  std::int64_t c[3];
  double t[3];
  for (int a = 0; a < 3; ++a)
  {
    const double u = (x[a] - grid.Origin[a]) / grid.Spacing;
    c[a] = std::min(grid.Dims[a] - 2, std::max<std::int64_t>(0, static_cast<std::int64_t>(std::floor(u))));
    t[a] = std::min(1.0, std::max(0.0, u - static_cast<double>(c[a])));
  }
  double value = 0.0;
  for (int corner = 0; corner < 8; ++corner)
  {
    const int di = corner & 1, dj = (corner >> 1) & 1, dk = corner >> 2;
    const double weight = (di ? t[0] : 1.0 - t[0]) * (dj ? t[1] : 1.0 - t[1]) * (dk ? t[2] : 1.0 - t[2]);
    value += weight * node(c[0] + di, c[1] + dj, c[2] + dk);
  }
  return value;
}

/// The inner surface's field at a node inside S, positive in the wall:
/// l + w - D; or, with a closing distance c, the distance beyond c from the
/// cavity eroded by c (E: D > l + w + c), so that the cavity is E grown back
/// by c (an opening: its creases rounded with radius c, and the parts of it
/// narrower than 2 c gone). G: each node's distance to E's surface.
struct InnerField
{
  const std::vector<float>& D;
  const std::vector<float>* G; ///< null without a closing distance
  double Deep;                 ///< l + w
  double Closing;              ///< c

  double operator()(std::int64_t n) const
  {
    if (!this->G)
    {
      return this->Deep - this->D[n];
    }
    const double g = (*this->G)[n];
    return this->D[n] > this->Deep + this->Closing ? -(this->Closing + g) : g - this->Closing;
  }
};

/// f of the header, clamped to +-Clamp, brick by brick: a value per brick
/// where f is beyond +-Clamp on all of it, else its nodes' values.
class PartField : public BrickField
{
public:
  /// restored: material put back (f = max(f, its value)), before the
  /// holes are drilled.
  PartField(const Grid& grid, const float* outer, const std::vector<float>& distance, double offset,
    const InnerField& innerField, const std::vector<Drill>& drills = {}, const Restoration* restored = nullptr);

  void Layer(std::int64_t layer, std::vector<float>& uniform, std::vector<std::int64_t>& varying) const override
  {
    const std::int64_t perLayer = this->BrickDims[0] * this->BrickDims[1];
    uniform.assign(this->Uniform.begin() + layer * perLayer, this->Uniform.begin() + (layer + 1) * perLayer);
    const auto first = std::lower_bound(this->Varying.begin(), this->Varying.end(), layer * perLayer);
    const auto last = std::lower_bound(first, this->Varying.end(), (layer + 1) * perLayer);
    varying.assign(first, last);
  }

  void Values(std::int64_t brick, float values[BrickNodes]) const override
  {
    const auto found = std::lower_bound(this->Varying.begin(), this->Varying.end(), brick);
    if (found != this->Varying.end() && *found == brick)
    {
      const float* stored = &this->Stored[(found - this->Varying.begin()) * BrickNodes];
      std::copy(stored, stored + BrickNodes, values);
    }
    else
    {
      std::fill(values, values + BrickNodes, this->Uniform[brick]);
    }
  }

  /// f at a place, trilinear between the nodes of its cell (clamped to
  /// +-3 h as stored).
  double At(const Grid& grid, const double x[3]) const
  {
    return Trilinear(grid, x, [&](std::int64_t i, std::int64_t j, std::int64_t k) {
      const std::int64_t brick =
        (i >> BrickShift) + this->BrickDims[0] * ((j >> BrickShift) + this->BrickDims[1] * (k >> BrickShift));
      const auto found = std::lower_bound(this->Varying.begin(), this->Varying.end(), brick);
      if (found == this->Varying.end() || *found != brick)
      {
        return static_cast<double>(this->Uniform[brick]);
      }
      const std::int64_t within =
        (i & (BrickSize - 1)) + BrickSize * ((j & (BrickSize - 1)) + BrickSize * (k & (BrickSize - 1)));
      return static_cast<double>(this->Stored[(found - this->Varying.begin()) * BrickNodes + within]);
    });
  }

private:
  std::array<std::int64_t, 3> BrickDims;
  std::vector<float> Uniform;        ///< per brick: its value where it does not vary
  std::vector<std::int64_t> Varying; ///< the bricks where f is within +-3 h, ascending
  std::vector<float> Stored;         ///< their nodes' values, BrickNodes each
};

/// A node array's value at a place, trilinear between the nodes of its cell.
inline double ValueAt(const Grid& grid, const float* values, const double x[3])
{
  return Trilinear(grid, x, [&](std::int64_t i, std::int64_t j, std::int64_t k) {
    return static_cast<double>(values[grid.Index(i, j, k)]);
  });
}

/// The least distance from a vertex of the inner surface (D > l + w / 2)
/// to a vertex of the outer surface; 0 without an inner surface. Stops
/// early when the monitor (may be null) asks (the caller asks it again).
double MinimumWall(const Grid& grid, const SurfaceArrays& part, const std::vector<float>& distance, double offset,
  double wall, std::array<double, 3>& where, Monitor* monitor);

/// The drain holes (DrainHoles): the cavities are the regions of nodes
/// inside S where the inner field is not positive (6-connected) whose
/// volume is at least `minimumVolume` (the cavities kept). Each hole starts
/// at a point of a cavity: at the kept cavity's node nearest to each of
/// request.DrainPositions where those are given, else at each cavity's
/// lowest points along request.Down, request.DrainHoles of them at least
/// three diameters apart (from one another and from the places tried). A
/// position outside the cavities (on the scan, in the wall) gives the
/// hole's way: straight from that node through the position and on out of
/// S. Otherwise the hole leaves by the shortest way out of S within
/// request.DrainAngle of request.Down (ShortestWayOut). It runs to 2 h past
/// the outside, unless its way runs through more than 2 (l + w) + 2 h of
/// material (down a limb: within 60 degrees of the wall's normal the way
/// through the wall and the offset is shorter): those are not made. The report counts what was asked and why holes were
/// not made.
std::vector<Drill> DrainHoles(const Grid& grid, const float* outer, const InnerField& inner, double offset,
  double wall, double minimumVolume, double radius, const PartRequest& request, PrintReport& report);

/// The scan's lost points (PrintReport): those farther than
/// report.LostDistance outside the part beyond what the closing explains,
/// |D - l| for a point at D from the outer sheet (D = l on a surface smooth
/// at the offset's scale; a point in a concavity narrower than l is inside
/// the material, at D - l from its outer surface or less). The distance to
/// the part is to its nearest vertex. Points deeper than `cap` (D unknown),
/// and points where a drain hole was drilled, are not checked. Sets
/// report.FarthestLost; the points' indices, ascending.
std::vector<std::int64_t> LostPoints(const Grid& grid, const float* outer, const PartField& field,
  const SurfaceArrays& part, const std::vector<float>& distance, double offset, double cap, const PartRequest& request,
  const std::vector<Drill>& drills, PrintReport& report, Monitor* monitor);

/// The lost points in regions: points in cells of side `reach` that touch
/// (26 neighbours) are one region; the regions, the most points first.
std::vector<LostRegion> LostRegions(const double* scan, const std::vector<std::int64_t>& lost, double reach);
} // namespace part
} // namespace nv

#endif
