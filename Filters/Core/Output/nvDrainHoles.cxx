// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The drain holes (DrainHoles, nvPartSteps.h): from each cavity kept, by
// the shortest way out through the wall.
#include "nvPartSteps.h"

#include <tuple>

namespace nv
{
namespace part
{
namespace
{
/// A hole's way out of S from x (a point in a cavity) along the unit
/// vector d, for a hole of `radius`: marched in steps of h / 2, looking at
/// the hole's axis and 8 points around it on its rim. Length is the way's
/// length to where the whole cross-section has left S, Material what of it
/// has any of the cross-section in material, after the cavity that x is in
/// (a second cavity on the way counts as material: the hole would cut
/// through its wall too); infinite beyond `longest`. A hole that runs
/// beside a limb, cutting into it, runs long and is refused.
struct WayOut
{
  double Direction[3] = { 0.0, 0.0, 0.0 };
  double Length = 0.0;
  double Material = std::numeric_limits<double>::infinity();
};

template <typename Cavity>
WayOut WayAlong(const Grid& grid, const float* outer, const Cavity& cavity, const double x[3], const double d[3],
  double radius, double longest)
{
  const double h = grid.Spacing;
  WayOut way;
  std::copy(d, d + 3, way.Direction);
  // Two unit vectors across d.
  const int least = std::fabs(d[0]) <= std::fabs(d[1]) && std::fabs(d[0]) <= std::fabs(d[2]) ? 0
    : std::fabs(d[1]) <= std::fabs(d[2])                                                   ? 1
                                                                                            : 2;
  double e1[3] = { 0.0, 0.0, 0.0 }, e2[3];
  e1[least] = 1.0;
  const double along = e1[0] * d[0] + e1[1] * d[1] + e1[2] * d[2];
  double norm = 0.0;
  for (int a = 0; a < 3; ++a)
  {
    e1[a] -= along * d[a];
    norm += e1[a] * e1[a];
  }
  for (int a = 0; a < 3; ++a)
  {
    e1[a] /= std::sqrt(norm);
  }
  e2[0] = d[1] * e1[2] - d[2] * e1[1];
  e2[1] = d[2] * e1[0] - d[0] * e1[2];
  e2[2] = d[0] * e1[1] - d[1] * e1[0];
  // What lies at p: -1 outside S, 0 in a cavity, 1 in material.
  const auto at = [&](const double p[3]) {
    std::int64_t ijk[3];
    for (int a = 0; a < 3; ++a)
    {
      ijk[a] = static_cast<std::int64_t>(std::floor((p[a] - grid.Origin[a]) / h + 0.5));
      if (ijk[a] < 0 || ijk[a] >= grid.Dims[a])
      {
        return -1;
      }
    }
    const std::int64_t n = grid.Index(ijk[0], ijk[1], ijk[2]);
    return outer[n] <= 0.0f ? -1 : cavity(n) ? 0 : 1;
  };
  double t = 0.0, material = 0.0;
  bool leaving = true; // the axis still in x's cavity
  for (;; t += 0.5 * h)
  {
    int most = -1; // the most the cross-section meets: -1 outside S, 0 a cavity, 1 material
    for (int k = -1; k < 8 && most < 1; ++k)
    {
      const double angle = 2.0 * 3.14159265358979323846 * k / 8.0;
      const double r = k < 0 ? 0.0 : radius;
      double p[3];
      for (int a = 0; a < 3; ++a)
      {
        p[a] = x[a] + t * d[a] + r * (std::cos(angle) * e1[a] + std::sin(angle) * e2[a]);
      }
      const int here = at(p);
      leaving = leaving && !(k < 0 && here != 0);
      most = std::max(most, here);
    }
    if (most < 0)
    {
      break; // the whole cross-section out of S
    }
    material += leaving || most == 0 ? 0.0 : 0.5 * h;
    if (material > longest + h)
    {
      return way; // too long
    }
  }
  way.Length = t;
  way.Material = material;
  return way;
}

/// The shortest way out of S from x: among the directions within `angle`
/// (radians) of `down`, the one through the least material (WayAlong),
/// tried on rings of 0, 1/4, ... 4/4 of the angle, 12 directions on each
/// ring but the first; straight down first, so that it wins unless another
/// is shorter by more than a cell.
template <typename Cavity>
WayOut ShortestWayOut(const Grid& grid, const float* outer, const Cavity& cavity, const double x[3], DrainAxis down,
  double angle, double radius, double longest)
{
  const int axis = static_cast<int>(down) / 2;
  const double sign = static_cast<int>(down) % 2 == 0 ? -1.0 : 1.0;
  const int across[2] = { (axis + 1) % 3, (axis + 2) % 3 };
  WayOut best;
  const int rings = angle > 0.0 ? 4 : 0;
  for (int ring = 0; ring <= rings; ++ring)
  {
    const double tilt = rings > 0 ? angle * ring / rings : 0.0;
    for (int turn = 0; turn < (ring == 0 ? 1 : 12); ++turn)
    {
      const double around = 2.0 * 3.14159265358979323846 * turn / 12.0;
      double d[3];
      d[axis] = sign * std::cos(tilt);
      d[across[0]] = std::sin(tilt) * std::cos(around);
      d[across[1]] = std::sin(tilt) * std::sin(around);
      const WayOut way = WayAlong(grid, outer, cavity, x, d, radius, std::min(longest, best.Material));
      if (way.Material < best.Material - grid.Spacing) // shorter by more than a cell: not the grid's noise
      {
        best = way;
      }
    }
  }
  return best;
}
} // namespace

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
  double wall, double minimumVolume, double radius, const PartRequest& request, PrintReport& report)
{
  const double longest = 2.0 * (offset + wall) + 2.0 * grid.Spacing;
  const std::int64_t nodes = grid.NumberOfNodes();
  const double h = grid.Spacing;
  const DrainAxis down = request.Down;
  const double angle = request.DrainAngle * 3.14159265358979323846 / 180.0;
  const int axis = static_cast<int>(down) / 2;               // the axis down is along,
  const int sign = static_cast<int>(down) % 2 == 0 ? -1 : 1; // which way along it,
  const int across[2] = { (axis + 1) % 3, (axis + 2) % 3 };  // and the plane across it
  const std::size_t positions = request.DrainPositions.size() / 3;
  auto cavity = [&](std::int64_t n) { return outer[n] > 0.0f && inner(n) <= 0.0; };
  auto place = [&](std::int64_t n, double x[3]) {
    std::int64_t ijk[3];
    grid.Ijk(n, ijk);
    for (int a = 0; a < 3; ++a)
    {
      x[a] = grid.Origin[a] + static_cast<double>(ijk[a]) * h;
    }
  };
  std::vector<Drill> drills;
  std::vector<char> drilled; // per kept cavity: whether a hole leaves it
  // Drills a hole from x out of S, if its way is short enough: towards
  // `toward` where that is given and not x, else by the shortest way out.
  auto drill = [&](const double x[3], std::size_t cavityIndex, const double* toward) {
    double d[3] = { 0.0, 0.0, 0.0 }, length = 0.0;
    for (int a = 0; toward && a < 3; ++a)
    {
      d[a] = toward[a] - x[a];
      length += d[a] * d[a];
    }
    length = std::sqrt(length);
    for (int a = 0; a < 3; ++a)
    {
      d[a] = length > 0.5 * h ? d[a] / length : 0.0;
    }
    const WayOut way = length > 0.5 * h ? WayAlong(grid, outer, cavity, x, d, radius, longest)
                                        : ShortestWayOut(grid, outer, cavity, x, down, angle, radius, longest);
    if (way.Material > longest)
    {
      ++report.DrainHolesTooLong; // down a limb, or through a wall at a slant: not here
      return false;
    }
    Drill made;
    for (int a = 0; a < 3; ++a)
    {
      made.A[a] = x[a] - radius * way.Direction[a];
      made.B[a] = x[a] + (way.Length + 2.0 * h + radius) * way.Direction[a];
    }
    made.Radius = radius;
    drills.push_back(made);
    drilled[cavityIndex] = 1;
    return true;
  };
  // Per position: the nearest node of a kept cavity (squared distance, node, cavity).
  std::vector<std::tuple<double, std::int64_t, std::size_t>> nearest(
    positions, std::make_tuple(std::numeric_limits<double>::infinity(), std::int64_t(-1), std::size_t(0)));
  std::vector<std::int32_t> label(static_cast<std::size_t>(nodes), -1);
  std::vector<std::int64_t> region;
  std::int32_t next = 0;
  // Nodes in ascending order, z slowest: a region's first node is its lowest.
  for (std::int64_t start = 0; start < nodes; ++start)
  {
    if (label[start] >= 0 || !cavity(start))
    {
      continue;
    }
    region.assign(1, start);
    label[start] = next;
    for (std::size_t head = 0; head < region.size(); ++head)
    {
      std::int64_t ijk[3];
      grid.Ijk(region[head], ijk);
      for (int a = 0; a < 3; ++a)
      {
        for (int step : { -1, 1 })
        {
          std::int64_t to[3] = { ijk[0], ijk[1], ijk[2] };
          to[a] += step;
          if (to[a] < 0 || to[a] >= grid.Dims[a])
          {
            continue;
          }
          const std::int64_t m = grid.Index(to[0], to[1], to[2]);
          if (label[m] < 0 && cavity(m))
          {
            label[m] = next;
            region.push_back(m);
          }
        }
      }
    }
    ++next;
    if (static_cast<double>(region.size()) * h * h * h < minimumVolume)
    {
      continue; // merged into the wall
    }
    const std::size_t kept = drilled.size();
    drilled.push_back(0);
    if (positions > 0)
    {
      for (std::size_t p = 0; p < positions; ++p)
      {
        const double* at = &request.DrainPositions[3 * p];
        for (std::int64_t n : region)
        {
          double x[3], d2 = 0.0;
          place(n, x);
          for (int a = 0; a < 3; ++a)
          {
            d2 += (x[a] - at[a]) * (x[a] - at[a]);
          }
          if (d2 < std::get<0>(nearest[p]))
          {
            nearest[p] = std::make_tuple(d2, n, kept);
          }
        }
      }
      continue;
    }
    // The lowest points of the cavity's surface: below a node, about its
    // depth in the cavity (-inner) under it; the region sorted by that
    // height (then its node order).
    const auto height = [&](std::int64_t n) {
      std::int64_t ijk[3];
      grid.Ijk(n, ijk);
      return -sign * (grid.Origin[axis] + static_cast<double>(ijk[axis]) * h) + inner(n);
    };
    std::vector<std::pair<double, std::int64_t>> lowest; // (height, node), each height made once
    lowest.reserve(region.size());
    for (std::int64_t n : region)
    {
      lowest.emplace_back(height(n), n);
    }
    std::stable_sort(lowest.begin(), lowest.end(),
      [](const std::pair<double, std::int64_t>& u, const std::pair<double, std::int64_t>& v) { return u.first < v.first; });
    std::vector<std::array<double, 3>> tops; // the holes' tops and the places tried, which the next keep away from
    int made = 0;
    for (const auto& entry : lowest)
    {
      if (made == request.DrainHoles)
      {
        break;
      }
      std::array<double, 3> x;
      place(entry.second, x.data());
      bool apart = true;
      for (const auto& t : tops)
      {
        const double du = t[across[0]] - x[across[0]], dv = t[across[1]] - x[across[1]];
        apart = apart && du * du + dv * dv >= 36.0 * radius * radius;
      }
      if (!apart)
      {
        continue;
      }
      tops.push_back(x);
      made += drill(x.data(), kept, nullptr) ? 1 : 0;
    }
  }
  report.DrainHolesAsked =
    positions > 0 ? static_cast<std::int64_t>(positions) : request.DrainHoles * static_cast<std::int64_t>(drilled.size());
  for (std::size_t p = 0; p < positions; ++p)
  {
    const double* at = &request.DrainPositions[3 * p];
    if (std::get<1>(nearest[p]) < 0 || std::sqrt(std::get<0>(nearest[p])) > longest)
    {
      if (report.DrainPositionsAway++ == 0)
      {
        std::copy(at, at + 3, report.FirstPositionAway.begin());
      }
      continue;
    }
    double x[3];
    place(std::get<1>(nearest[p]), x);
    drill(x, std::get<2>(nearest[p]), at);
  }
  report.CavitiesWithoutHoles = static_cast<std::int64_t>(std::count(drilled.begin(), drilled.end(), 0));
  return drills;
}
} // namespace part
} // namespace nv
