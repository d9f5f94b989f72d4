// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The nearest of a set of points to a place: the part to print's measures
// (its thinnest wall, nvPartChecks.cxx) and its check against the scan
// (the scan points it lost, the neighbours that join them), and the scan
// points' distances to the scan surface (nvScanSurface.cxx).
#ifndef nvNearestPoints_h
#define nvNearestPoints_h

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace nv
{

/// Points in a k-d tree (each range of the array split at its middle point
/// along its widest axis, in place), for the distance from a place to the
/// nearest.
class NearestPoints
{
public:
  /// numbered: keep each point's number in the caller's array (Nearest's id).
  NearestPoints(const double* points, std::int64_t n, bool numbered = false)
    : Points(static_cast<std::size_t>(n))
    , Axis(static_cast<std::size_t>(n), 0)
    , Ids(static_cast<std::size_t>(n))
  {
    for (std::int64_t p = 0; p < n; ++p)
    {
      std::copy(points + 3 * p, points + 3 * p + 3, this->Points[p].begin());
      this->Ids[p] = p;
    }
    // The tree is built on the numbers (the same comparisons, hence the same
    // order, as on the points themselves), then the points put in its order.
    this->Build(0, n);
    std::vector<std::array<double, 3>> ordered(static_cast<std::size_t>(n));
    for (std::int64_t p = 0; p < n; ++p)
    {
      ordered[p] = this->Points[this->Ids[p]];
    }
    this->Points.swap(ordered);
    if (!numbered)
    {
      std::vector<std::int64_t>().swap(this->Ids);
    }
  }

  /// The number (in the caller's array) of the point nearest to x, or -1
  /// when none is nearer than `cap`; `distance`: its distance. Needs a
  /// numbered tree.
  std::int64_t Nearest(const double x[3], double cap, double& distance) const
  {
    std::vector<std::pair<double, std::int64_t>> best;
    this->SearchK(x, 0, static_cast<std::int64_t>(this->Points.size()), 1, cap * cap, best);
    if (best.empty())
    {
      distance = cap;
      return -1;
    }
    distance = std::sqrt(best.front().first);
    return this->Ids[best.front().second];
  }

  /// The distance from x to the nearest point, or `cap` when none is nearer.
  double Distance(const double x[3], double cap) const
  {
    double best = cap * cap;
    this->Search(x, 0, static_cast<std::int64_t>(this->Points.size()), best);
    return std::sqrt(best);
  }

  /// The up to k points nearest to x within `cap` (nearest first), into `found`.
  void Nearest(const double x[3], int k, double cap, std::vector<std::array<double, 3>>& found) const
  {
    std::vector<std::pair<double, std::int64_t>> best; // a max-heap of (squared distance, point)
    this->SearchK(x, 0, static_cast<std::int64_t>(this->Points.size()), k, cap * cap, best);
    std::sort_heap(best.begin(), best.end());
    found.clear();
    for (const auto& entry : best)
    {
      found.push_back(this->Points[entry.second]);
    }
  }

private:
  static constexpr std::int64_t Leaf = 8;

  /// The range's points split at its middle along its widest axis (the
  /// lower ones before it), on the numbers: the points stay in place.
  void Build(std::int64_t begin, std::int64_t end)
  {
    if (end - begin <= Leaf)
    {
      return;
    }
    std::array<double, 3> low = this->Points[this->Ids[begin]], high = low;
    for (std::int64_t p = begin; p < end; ++p)
    {
      for (int a = 0; a < 3; ++a)
      {
        low[a] = std::min(low[a], this->Points[this->Ids[p]][a]);
        high[a] = std::max(high[a], this->Points[this->Ids[p]][a]);
      }
    }
    int axis = 0;
    for (int a = 1; a < 3; ++a)
    {
      axis = high[a] - low[a] > high[axis] - low[axis] ? a : axis;
    }
    const std::int64_t middle = begin + (end - begin) / 2;
    std::nth_element(this->Ids.begin() + begin, this->Ids.begin() + middle, this->Ids.begin() + end,
      [this, axis](std::int64_t u, std::int64_t v) { return this->Points[u][axis] < this->Points[v][axis]; });
    this->Axis[middle] = static_cast<char>(axis);
    this->Build(begin, middle);
    this->Build(middle + 1, end);
  }

  void Search(const double x[3], std::int64_t begin, std::int64_t end, double& best) const
  {
    if (end - begin <= Leaf)
    {
      for (std::int64_t p = begin; p < end; ++p)
      {
        best = std::min(best, this->Squared(x, p));
      }
      return;
    }
    const std::int64_t middle = begin + (end - begin) / 2;
    const int axis = this->Axis[middle];
    best = std::min(best, this->Squared(x, middle));
    const double side = x[axis] - this->Points[middle][axis];
    if (side < 0.0)
    {
      this->Search(x, begin, middle, best);
      if (side * side < best)
      {
        this->Search(x, middle + 1, end, best);
      }
    }
    else
    {
      this->Search(x, middle + 1, end, best);
      if (side * side < best)
      {
        this->Search(x, begin, middle, best);
      }
    }
  }

  void SearchK(const double x[3], std::int64_t begin, std::int64_t end, int k, double cap2,
    std::vector<std::pair<double, std::int64_t>>& best) const
  {
    const auto offer = [&](std::int64_t p) {
      const double d2 = this->Squared(x, p);
      const double worst = static_cast<int>(best.size()) < k ? cap2 : best.front().first;
      if (d2 < worst)
      {
        if (static_cast<int>(best.size()) == k)
        {
          std::pop_heap(best.begin(), best.end());
          best.pop_back();
        }
        best.emplace_back(d2, p);
        std::push_heap(best.begin(), best.end());
      }
    };
    if (end - begin <= Leaf)
    {
      for (std::int64_t p = begin; p < end; ++p)
      {
        offer(p);
      }
      return;
    }
    const std::int64_t middle = begin + (end - begin) / 2;
    const int axis = this->Axis[middle];
    offer(middle);
    const double side = x[axis] - this->Points[middle][axis];
    const std::int64_t nearBegin = side < 0.0 ? begin : middle + 1, nearEnd = side < 0.0 ? middle : end;
    const std::int64_t farBegin = side < 0.0 ? middle + 1 : begin, farEnd = side < 0.0 ? end : middle;
    this->SearchK(x, nearBegin, nearEnd, k, cap2, best);
    const double worst = static_cast<int>(best.size()) < k ? cap2 : best.front().first;
    if (side * side < worst)
    {
      this->SearchK(x, farBegin, farEnd, k, cap2, best);
    }
  }

  double Squared(const double x[3], std::int64_t p) const
  {
    const std::array<double, 3>& y = this->Points[p];
    const double dx = y[0] - x[0], dy = y[1] - x[1], dz = y[2] - x[2];
    return dx * dx + dy * dy + dz * dz;
  }

  std::vector<std::array<double, 3>> Points;
  std::vector<char> Axis; ///< the split axis of the range whose middle is this point
  std::vector<std::int64_t> Ids; ///< each point's number in the caller's array (numbered trees)
};

} // namespace nv

#endif
