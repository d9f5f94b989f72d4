// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The hole finder (nvHoleFinder.h): for each point of the thinned cloud,
// the largest empty circle through it in its tangent plane, and whether it
// is a hole (nvGapClosing.h).
#include "nvHoleFinder.h"

#include <limits>
#include <mutex>

namespace nv
{
namespace holes
{
namespace
{
/// Directions of the circles through each point, evenly around it (a
/// circle's centre lies on its direction).
constexpr int Directions = 32;
/// A circle is a hole when the points around it leave no direction gap of
/// this angle (as seen from its centre): they surround it.
constexpr double EnclosingGap = 2.0 * 3.14159265358979323846 / 3.0;
/// The rim of a hole lies around its centre near the tangent plane: the
/// mean squared sine of its points' elevation above that plane, seen from
/// the centre, is at most FlatRim (about 18 degrees).
constexpr double FlatRim = 0.1;

/// Eigenvectors of a symmetric 3x3 matrix (cyclic Jacobi rotations), as the
/// columns of `vectors`, sorted by ascending eigenvalue.
void SymmetricEigenvectors(double m[3][3], double vectors[3][3])
{
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      vectors[i][j] = i == j ? 1.0 : 0.0;
    }
  }
  for (int sweep = 0; sweep < 16; ++sweep)
  {
    const double off = m[0][1] * m[0][1] + m[0][2] * m[0][2] + m[1][2] * m[1][2];
    if (off <= 1e-30 * (m[0][0] * m[0][0] + m[1][1] * m[1][1] + m[2][2] * m[2][2]))
    {
      break;
    }
    for (int p = 0; p < 2; ++p)
    {
      for (int q = p + 1; q < 3; ++q)
      {
        if (m[p][q] == 0.0)
        {
          continue;
        }
        const double theta = (m[q][q] - m[p][p]) / (2.0 * m[p][q]);
        const double t = (theta >= 0.0 ? 1.0 : -1.0) / (std::fabs(theta) + std::sqrt(theta * theta + 1.0));
        const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
        for (int k = 0; k < 3; ++k) // m <- m J
        {
          const double a = m[k][p], b = m[k][q];
          m[k][p] = c * a - s * b;
          m[k][q] = s * a + c * b;
        }
        for (int k = 0; k < 3; ++k) // m <- J^T m
        {
          const double a = m[p][k], b = m[q][k];
          m[p][k] = c * a - s * b;
          m[q][k] = s * a + c * b;
        }
        for (int k = 0; k < 3; ++k)
        {
          const double a = vectors[k][p], b = vectors[k][q];
          vectors[k][p] = c * a - s * b;
          vectors[k][q] = s * a + c * b;
        }
      }
    }
  }
  // Sort the columns by eigenvalue.
  int order[3] = { 0, 1, 2 };
  std::sort(order, order + 3, [&](int a, int b) { return m[a][a] < m[b][b] || (m[a][a] == m[b][b] && a < b); });
  double sorted[3][3];
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      sorted[i][j] = vectors[i][order[j]];
    }
  }
  std::copy(&sorted[0][0], &sorted[0][0] + 9, &vectors[0][0]);
}

/// The neighbours of p within a radius, as offsets from p, in the cells'
/// order (the same whatever order the points came in).
void Neighbours(const PointCells& cells, const std::vector<double>& rel, std::int64_t p, double radius,
  double tiny, std::vector<std::array<double, 3>>& out)
{
  out.clear();
  const double* x = &rel[3 * p];
  cells.ForEachWithin(x, radius, [&](std::int64_t, const double* y) {
    const std::array<double, 3> v{ { y[0] - x[0], y[1] - x[1], y[2] - x[2] } };
    if (v[0] * v[0] + v[1] * v[1] + v[2] * v[2] > tiny) // not p, nor a copy of it
    {
      out.push_back(v);
    }
  });
}

/// What one point sees: the largest hole through it, if any.
struct Finding
{
  bool Suspect = false; ///< an empty circle wider than the threshold within 2 l
  bool Found = false;   ///< a hole of radius in (threshold, limit]
  bool Deferred = false; ///< needs every point (the finder had none): look again with them
  Hole Disc{};          ///< its centre (relative to the grid's origin) and radius
};

class HoleFinder
{
public:
  /// cells, rel: the points looked at (the thinned cloud); all, allRel:
  /// every point, for the empty balls (null: Examine defers the points that
  /// need them).
  HoleFinder(const PointCells& cells, const std::vector<double>& rel, const PointCells* all,
    const std::vector<double>& allRel, double offset)
    : Cells(cells)
    , Rel(rel)
    , All(all)
    , AllRel(allRel)
    , Offset(offset)
  {
    for (int k = 0; k < Directions; ++k)
    {
      const double angle = 2.0 * 3.14159265358979323846 * k / Directions;
      this->Cos[k] = std::cos(angle);
      this->Sin[k] = std::sin(angle);
    }
  }

  /**
   * The widest hole through point p: the largest circle in the plane with
   * threshold < radius <= limit that is a hole, whose empty ball (the
   * distance from its centre to the nearest point, which is less than the
   * circle's radius on a curved surface) is wider than the threshold; its
   * radius is the ball's.
   * With `prefilter`, first the cheap test on the neighbours within 2 l: an
   * empty circle through p whose radius is below 2 l / 2 = l is bounded by a
   * neighbour within 2 l, so p with no circle wider than the threshold
   * among those (threshold <= l) has none at all.
   */
  Finding Examine(std::int64_t p, double threshold, double limit, bool prefilter)
  {
    Finding finding;
    if (!this->FitPlane(p))
    {
      return finding; // a lone point or a pair: no surface to speak of
    }
    if (prefilter)
    {
      finding.Suspect = this->WiderThan(this->Near, threshold);
      if (!finding.Suspect)
      {
        return finding;
      }
    }
    finding.Suspect = true;
    this->ProjectNeighbours(p, limit);
    // The directions whose widest empty circle is a candidate, widest first.
    double radius[Directions];
    this->PlaneRadii(limit, radius);
    int candidates[Directions];
    int count = 0;
    for (int k = 0; k < Directions; ++k)
    {
      if (radius[k] > threshold && radius[k] <= limit)
      {
        candidates[count++] = k;
      }
    }
    std::sort(candidates, candidates + count,
      [&](int a, int b) { return radius[a] > radius[b] || (radius[a] == radius[b] && a < b); });
    for (int c = 0; c < count; ++c)
    {
      const int k = candidates[c];
      const double t = radius[k];
      const double center[2] = { t * this->Cos[k], t * this->Sin[k] };
      double height = 0.0;
      if (this->Enclosed(center, t, height) && this->IsHole(p, center, height, threshold, finding))
      {
        break;
      }
    }
    return finding;
  }

private:
  /// The tangent plane at p (Normal, Tangent): the principal directions of p
  /// and its neighbours within 2 l (Near). False with fewer than three.
  bool FitPlane(std::int64_t p)
  {
    const double l = this->Offset;
    Neighbours(this->Cells, this->Rel, p, 2.0 * l, 1e-24 * l * l, this->Near);
    if (this->Near.size() < 3)
    {
      return false;
    }
    double mean[3] = { 0.0, 0.0, 0.0 };
    for (const auto& v : this->Near)
    {
      for (int a = 0; a < 3; ++a)
      {
        mean[a] += v[a];
      }
    }
    const double n = static_cast<double>(this->Near.size() + 1);
    for (int a = 0; a < 3; ++a)
    {
      mean[a] /= n;
    }
    double covariance[3][3] = { { 0.0 } };
    auto add = [&](const double v[3]) {
      const double d[3] = { v[0] - mean[0], v[1] - mean[1], v[2] - mean[2] };
      for (int a = 0; a < 3; ++a)
      {
        for (int b = a; b < 3; ++b)
        {
          covariance[a][b] += d[a] * d[b];
        }
      }
    };
    const double origin[3] = { 0.0, 0.0, 0.0 };
    add(origin);
    for (const auto& v : this->Near)
    {
      add(v.data());
    }
    for (int a = 0; a < 3; ++a)
    {
      for (int b = 0; b < a; ++b)
      {
        covariance[a][b] = covariance[b][a]; // symmetric: each sum once
      }
    }
    double axes[3][3];
    SymmetricEigenvectors(covariance, axes);
    for (int a = 0; a < 3; ++a)
    {
      this->Normal[a] = axes[a][0];
      this->Tangent[0][a] = axes[a][2];
      this->Tangent[1][a] = axes[a][1];
    }
    return true;
  }

  /// The neighbours that a circle up to `limit` and its ring can reach
  /// (Wide), and those of them in the plane's reach (Plane: in-plane
  /// distance, u, w, height; nearest first, so that the searches stop
  /// early): not those far off the plane (the other side of a thin part),
  /// which would hide a hole on this side.
  void ProjectNeighbours(std::int64_t p, double limit)
  {
    const double l = this->Offset;
    Neighbours(this->Cells, this->Rel, p, 2.0 * limit + l, 1e-24 * l * l, this->Wide);
    this->Plane.clear();
    for (const auto& v : this->Wide)
    {
      const double u = v[0] * this->Tangent[0][0] + v[1] * this->Tangent[0][1] + v[2] * this->Tangent[0][2];
      const double w = v[0] * this->Tangent[1][0] + v[1] * this->Tangent[1][1] + v[2] * this->Tangent[1][2];
      const double h = v[0] * this->Normal[0] + v[1] * this->Normal[1] + v[2] * this->Normal[2];
      const double along = std::sqrt(u * u + w * w);
      if (std::fabs(h) <= std::max(l, 0.5 * along))
      {
        this->Plane.push_back({ { along, u, w, h } });
      }
    }
    std::sort(this->Plane.begin(), this->Plane.end());
  }

  /// Whether the enclosed circle at `center` (in the plane, `height` off it)
  /// ends the search: its disc's centre in space and the distance from there
  /// to the nearest point, the empty ball. The shell leaves a tunnel only if
  /// that exceeds the threshold (a circle in the plane may be covered by
  /// points off it, on a curved or thin part) and the disc is flat: then
  /// finding.Found and its Disc. Without every point (All) to check the
  /// ball against, finding.Deferred instead.
  bool IsHole(std::int64_t p, const double center[2], double height, double threshold, Finding& finding)
  {
    double offset[3];
    for (int a = 0; a < 3; ++a)
    {
      offset[a] = center[0] * this->Tangent[0][a] + center[1] * this->Tangent[1][a] + height * this->Normal[a];
    }
    double empty = offset[0] * offset[0] + offset[1] * offset[1] + offset[2] * offset[2]; // to p
    for (const auto& v : this->Wide)
    {
      const double dx = v[0] - offset[0], dy = v[1] - offset[1], dz = v[2] - offset[2];
      empty = std::min(empty, dx * dx + dy * dy + dz * dz);
    }
    empty = std::sqrt(empty);
    const double* x = &this->Rel[3 * p];
    const double centre[3] = { x[0] + offset[0], x[1] + offset[1], x[2] + offset[2] };
    if (empty > threshold)
    {
      if (!this->All)
      {
        finding.Deferred = true;
        return true;
      }
      // The points the thinning left out, within that ball.
      double nearest = empty * empty;
      this->All->ForEachWithin(centre, empty, [&](std::int64_t, const double* y) {
        const double dx = y[0] - centre[0], dy = y[1] - centre[1], dz = y[2] - centre[2];
        nearest = std::min(nearest, dx * dx + dy * dy + dz * dz);
      });
      empty = std::sqrt(nearest);
    }
    if (empty > threshold && this->Flat(offset, empty))
    {
      finding.Found = true;
      for (int a = 0; a < 3; ++a)
      {
        finding.Disc.Center[a] = centre[a];
      }
      finding.Disc.Radius = empty;
      finding.Disc.Normal = { { this->Normal[0], this->Normal[1], this->Normal[2] } };
      return true;
    }
    return false;
  }

  /// Per direction, the radius of the largest empty circle through p
  /// bounded by the neighbour at (u, w) in the plane: |v|^2 / (2 v.u).
  void Bound(double u, double w, double radius[Directions]) const
  {
    const double squared = u * u + w * w;
    for (int k = 0; k < Directions; ++k)
    {
      const double along = u * this->Cos[k] + w * this->Sin[k];
      if (along > 0.0)
      {
        radius[k] = std::min(radius[k], squared / (2.0 * along));
      }
    }
  }

  /// Whether, among the neighbours within 2 l, the largest empty circle
  /// through p in some direction is wider than the threshold: whether a
  /// direction is left that no neighbour bounds to the threshold or less
  /// (the bound of Bound, compared alike). Stops once every direction is
  /// bounded, which on a densely sampled surface takes a few neighbours.
  bool WiderThan(const std::vector<std::array<double, 3>>& points, double threshold) const
  {
    static_assert(Directions == 32, "one bit a direction");
    std::uint32_t open = ~std::uint32_t(0); // the directions not bounded yet
    // The neighbours within the threshold first: each bounds the directions
    // within 60 degrees of its own or more, so that a few of them bound all.
    const double near = threshold * threshold;
    // squared / (2 along) <= threshold, decided by products where they
    // are far from equal (1e-12 apart, many roundings), else by the quotient
    // itself: the same answer as the quotient, without a division each.
    const double below = threshold * (1.0 - 1e-12), above = threshold * (1.0 + 1e-12);
    for (const bool first : { true, false })
    {
      for (const auto& v : points)
      {
        if ((v[0] * v[0] + v[1] * v[1] + v[2] * v[2] <= near) != first)
        {
          continue;
        }
        const double u = v[0] * this->Tangent[0][0] + v[1] * this->Tangent[0][1] + v[2] * this->Tangent[0][2];
        const double w = v[0] * this->Tangent[1][0] + v[1] * this->Tangent[1][1] + v[2] * this->Tangent[1][2];
        const double squared = u * u + w * w;
        for (int k = 0; k < Directions; ++k)
        {
          const double along = u * this->Cos[k] + w * this->Sin[k];
          if (along > 0.0)
          {
            const double twice = 2.0 * along;
            const bool bounded = squared <= below * twice ||
              (squared <= above * twice && squared / twice <= threshold);
            if (bounded)
            {
              open &= ~(std::uint32_t(1) << k);
            }
          }
        }
        if (open == 0)
        {
          return false;
        }
      }
    }
    return true;
  }

  /// The same among the points in the plane, exact up to `limit` (a larger
  /// radius only says so): a neighbour at distance |v| bounds no circle
  /// below |v| / 2, so the nearest-first scan stops there.
  void PlaneRadii(double limit, double radius[Directions]) const
  {
    std::fill(radius, radius + Directions, std::numeric_limits<double>::infinity());
    double widest = limit;
    for (const auto& v : this->Plane)
    {
      if (0.5 * v[0] > widest)
      {
        break;
      }
      this->Bound(v[1], v[2], radius);
      widest = std::min(limit, *std::max_element(radius, radius + Directions));
    }
  }

  /// Whether the points around an empty ball (centre `center` relative to
  /// p, radius `empty`), those within empty + l of its centre, lie around it
  /// as a hole's rim in the surface does: in directions from the centre
  /// near p's tangent plane; not around a crevice between thin parts (toes,
  /// fingers), where they lie on all sides, nor between two facing sheets,
  /// where they lie above and below.
  bool Flat(const double center[3], double empty) const
  {
    const double reach = empty + this->Offset;
    double elevation = 0.0; // sum of sin^2 of the directions' elevation
    double count = 0.0;
    auto add = [&](const double w[3]) {
      const double d2 = w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
      if (d2 <= reach * reach && d2 > 0.0)
      {
        const double up = w[0] * this->Normal[0] + w[1] * this->Normal[1] + w[2] * this->Normal[2];
        elevation += up * up / d2;
        count += 1.0;
      }
    };
    const double toP[3] = { -center[0], -center[1], -center[2] };
    add(toP);
    for (const auto& v : this->Wide)
    {
      const double w[3] = { v[0] - center[0], v[1] - center[1], v[2] - center[2] };
      add(w);
    }
    return elevation <= FlatRim * count;
  }

  /// Whether the points within t + l of the centre surround it; `height`:
  /// the mean height above the plane of the rim (p and the points within
  /// t + l / 2 of the centre).
  bool Enclosed(const double center[2], double t, double& height)
  {
    const double ring = t + this->Offset;
    const double rim = t + 0.5 * this->Offset;
    this->Angles.clear();
    double sum = 0.0;
    int rimPoints = 1; // p itself, at height 0
    this->Angles.push_back(std::atan2(-center[1], -center[0]));
    for (const auto& v : this->Plane)
    {
      if (v[0] > t + ring) // beyond the ring, as all that follow
      {
        break;
      }
      const double du = v[1] - center[0], dw = v[2] - center[1];
      const double d = std::sqrt(du * du + dw * dw);
      if (d <= ring)
      {
        this->Angles.push_back(std::atan2(dw, du));
      }
      if (d <= rim)
      {
        sum += v[3];
        ++rimPoints;
      }
    }
    std::sort(this->Angles.begin(), this->Angles.end());
    double gap = this->Angles.front() + 2.0 * 3.14159265358979323846 - this->Angles.back();
    for (std::size_t i = 1; i < this->Angles.size(); ++i)
    {
      gap = std::max(gap, this->Angles[i] - this->Angles[i - 1]);
    }
    height = sum / rimPoints;
    return gap < EnclosingGap;
  }

  const PointCells& Cells;
  const std::vector<double>& Rel;
  const PointCells* All;
  const std::vector<double>& AllRel;
  double Offset;
  double Cos[Directions], Sin[Directions];
  double Normal[3], Tangent[2][3];
  std::vector<std::array<double, 3>> Near, Wide;
  std::vector<std::array<double, 4>> Plane; ///< distance in the plane, u, w, height
  std::vector<double> Angles;
};
} // namespace

/// One point per cube of side `size` anchored at the grid's origin (the
/// one with the lowest coordinates, whatever order the points came in): the
/// cloud the holes are looked for in. A dense cloud has thousands of points
/// within 2 l of each; one per l / 4 keeps the empty discs near l and wider
/// (no point lies farther than sqrt(3) l / 4 from the one kept in its cube).
std::vector<double> Thin(const Grid& grid, const std::vector<double>& rel, double size)
{
  std::int64_t dims[3];
  for (int a = 0; a < 3; ++a)
  {
    dims[a] = static_cast<std::int64_t>(static_cast<double>(grid.Dims[a]) * grid.Spacing / size) + 2;
  }
  const std::int64_t n = static_cast<std::int64_t>(rel.size() / 3);
  std::vector<std::pair<std::int64_t, std::int64_t>> keyed(static_cast<std::size_t>(n));
  ParallelFor(0, n, 4096, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t p = begin; p < end; ++p)
    {
      std::int64_t c[3];
      for (int a = 0; a < 3; ++a)
      {
        c[a] = std::min(dims[a] - 1, std::max<std::int64_t>(0, static_cast<std::int64_t>(rel[3 * p + a] / size)));
      }
      keyed[p] = { c[0] + dims[0] * (c[1] + dims[1] * c[2]), p };
    }
  });
  ParallelSort(keyed);
  // The cubes' kept points, in cube order: fixed chunks of the sorted pairs,
  // each taking the cubes whose first pair it holds, joined in chunk order.
  constexpr std::int64_t Chunks = 64;
  std::vector<std::vector<double>> kept(Chunks);
  ParallelFor(0, Chunks, 1, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t chunk = begin; chunk < end; ++chunk)
    {
      std::int64_t i = n * chunk / Chunks;
      const std::int64_t last = n * (chunk + 1) / Chunks;
      while (i > 0 && i < last && keyed[i].first == keyed[i - 1].first)
      {
        ++i; // the cube began in the chunk before
      }
      while (i < last)
      {
        // The cube's point with the lowest coordinates.
        const double* lowest = &rel[3 * keyed[i].second];
        std::int64_t j = i + 1;
        for (; j < n && keyed[j].first == keyed[i].first; ++j)
        {
          const double* other = &rel[3 * keyed[j].second];
          if (std::lexicographical_compare(other, other + 3, lowest, lowest + 3))
          {
            lowest = other;
          }
        }
        kept[chunk].insert(kept[chunk].end(), lowest, lowest + 3);
        i = j;
      }
    }
  });
  std::vector<double> thin;
  for (const auto& part : kept)
  {
    thin.insert(thin.end(), part.begin(), part.end());
  }
  return thin;
}

/// Looks at points [0, n) of rel (or only those marked in `look`) for holes
/// (HoleFinder::Examine); cells: rel's; all(): the cells of allRel (every
/// point), made only when a point needs them (a cloud without holes never
/// does). With `suspects`, first the cheap test of each point, whose outcome
/// it gets. False if the monitor stopped it.
bool FindHoles(const PointCells& cells, const std::vector<double>& rel, const std::function<const PointCells&()>& all,
  const std::vector<double>& allRel, double offset, double threshold, double limit, const std::vector<char>* look,
  std::vector<char>* suspects, Found& found, Monitor* monitor)
{
  const std::int64_t n = static_cast<std::int64_t>(rel.size() / 3);
  if (suspects)
  {
    suspects->assign(static_cast<std::size_t>(n), 0);
  }
  found.clear();
  std::vector<std::int64_t> deferred;
  std::mutex lock;
  const bool done = MonitoredFor(0, n, 256, monitor, [&](std::int64_t begin, std::int64_t end) {
    HoleFinder finder(cells, rel, nullptr, allRel, offset);
    Found mine;
    std::vector<std::int64_t> later;
    for (std::int64_t p = begin; p < end; ++p)
    {
      if (!look || (*look)[p])
      {
        const Finding finding = finder.Examine(p, threshold, limit, suspects != nullptr);
        if (suspects)
        {
          (*suspects)[p] = finding.Suspect;
        }
        if (finding.Deferred)
        {
          later.push_back(p);
        }
        else if (finding.Found)
        {
          mine.emplace_back(p, finding.Disc);
        }
      }
    }
    const std::lock_guard<std::mutex> guard(lock);
    found.insert(found.end(), mine.begin(), mine.end());
    deferred.insert(deferred.end(), later.begin(), later.end());
  });
  if (!done)
  {
    return false;
  }
  // The points whose discs need every point, with them (the same findings
  // as one pass with every point from the start).
  if (!deferred.empty())
  {
    const PointCells& every = all();
    const std::int64_t count = static_cast<std::int64_t>(deferred.size());
    const bool again = MonitoredFor(0, count, 64, monitor, [&](std::int64_t begin, std::int64_t end) {
      HoleFinder finder(cells, rel, &every, allRel, offset);
      Found mine;
      for (std::int64_t i = begin; i < end; ++i)
      {
        const Finding finding = finder.Examine(deferred[i], threshold, limit, suspects != nullptr);
        if (finding.Found)
        {
          mine.emplace_back(deferred[i], finding.Disc);
        }
      }
      const std::lock_guard<std::mutex> guard(lock);
      found.insert(found.end(), mine.begin(), mine.end());
    });
    if (!again)
    {
      return false;
    }
  }
  std::sort(found.begin(), found.end(),
    [](const Found::value_type& a, const Found::value_type& b) { return a.first < b.first; });
  return true;
}
} // namespace holes
} // namespace nv
