// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nvGapClosing.h"

#include "nvHoleFinder.h"
#include "nvParallel.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numeric>

namespace nv
{
using namespace holes; // the hole finder (nvHoleFinder.h)

GapClosing::GapClosing(const Grid& grid, double offset, double radius)
  : GridNodes(grid)
  , Offset(offset)
  , Radius(radius > offset ? radius : 0.0)
  , Measured(2.0 * (radius > offset ? radius : AutomaticClosingRadius * offset))
{
}

double GapClosing::Reach() const
{
  // Every pass decides a point's hole from the points within 2 M + l (M:
  // the measured radius), and a round places its point within M + l: per
  // round, 3 M + 2 l further; then the final measurement.
  const double l = this->Offset;
  const double rounds = this->Radius > 0.0 ? MaximumRounds * (3.0 * this->Measured + 2.0 * l) : 0.0;
  return rounds + 2.0 * this->Measured + l;
}

bool GapClosing::Run(std::vector<double>& xyz, const std::function<bool(const double*)>& owned, Monitor* monitor)
{
  const double l = this->Offset;
  const std::array<double, 3>& origin = this->GridNodes.Origin;
  std::vector<double> rel(xyz.size());
  ParallelFor(0, static_cast<std::int64_t>(xyz.size() / 3), 4096, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t p = begin; p < end; ++p)
    {
      for (int a = 0; a < 3; ++a)
      {
        rel[3 * p + a] = xyz[3 * p + a] - origin[a];
      }
    }
  });
  const std::int64_t given = static_cast<std::int64_t>(xyz.size() / 3);
  std::vector<double> thin = Thin(this->GridNodes, rel, ThinCells * l);
  // The searches' cells, made again only once points were added.
  std::unique_ptr<PointCells> thinCells, allCells;
  auto findHoles = [&](double threshold, const std::vector<char>* looked, std::vector<char>* suspects, Found& out) {
    if (!thinCells || thinCells->NumberOfPoints() != thin.size() / 3)
    {
      thinCells.reset(new PointCells(this->GridNodes, 2.0 * l, thin));
    }
    const auto every = [&]() -> const PointCells& {
      if (!allCells || allCells->NumberOfPoints() != rel.size() / 3)
      {
        allCells.reset(new PointCells(this->GridNodes, 0.5 * l, rel, false)); // for minima only
      }
      return *allCells;
    };
    return FindHoles(*thinCells, thin, every, rel, l, threshold, this->Measured, looked, suspects, out, monitor);
  };
  Found found;
  // Points that can border a hole: those with an empty circle wider than l
  // within 2 l (adding points only shrinks the circles), and the added ones.
  std::vector<char> look;
  for (int round = 0; this->Radius > 0.0 && round < MaximumRounds; ++round)
  {
    const bool first = round == 0;
    if (!findHoles(first ? l : BridgeTarget * l, first ? nullptr : &look, first ? &look : nullptr, found))
    {
      return false;
    }
    // One new point per cell of l / 2 (the rim's points find nearly the same
    // centre): the widest disc's, the lowest centre on ties.
    struct Proposal
    {
      std::array<std::int64_t, 3> Cell;
      double Radius;
      std::array<double, 3> Center;
      bool operator<(const Proposal& o) const
      {
        if (this->Cell != o.Cell)
        {
          return this->Cell < o.Cell;
        }
        if (this->Radius != o.Radius)
        {
          return this->Radius > o.Radius;
        }
        return this->Center < o.Center;
      }
    };
    std::vector<Proposal> proposals;
    for (const auto& f : found)
    {
      if (f.second.Radius <= this->Radius) // wider holes are left open
      {
        Proposal proposal{ {}, f.second.Radius, f.second.Center };
        for (int a = 0; a < 3; ++a)
        {
          proposal.Cell[a] = static_cast<std::int64_t>(std::floor(f.second.Center[a] / (0.5 * l)));
        }
        proposals.push_back(proposal);
      }
    }
    if (proposals.empty())
    {
      break;
    }
    std::sort(proposals.begin(), proposals.end());
    for (std::size_t i = 0; i < proposals.size(); ++i)
    {
      if (i == 0 || proposals[i].Cell != proposals[i - 1].Cell)
      {
        rel.insert(rel.end(), proposals[i].Center.begin(), proposals[i].Center.end());
        thin.insert(thin.end(), proposals[i].Center.begin(), proposals[i].Center.end());
        look.push_back(1);
      }
    }
  }

  // The holes left open: every disc wider than l up to the measured radius.
  const bool bridged = this->Radius > 0.0;
  if (!findHoles(l, bridged ? &look : nullptr, bridged ? nullptr : &look, found))
  {
    return false;
  }
  this->Open.clear();
  const std::int64_t all = static_cast<std::int64_t>(rel.size() / 3);
  for (const auto& f : found)
  {
    double x[3];
    for (int a = 0; a < 3; ++a)
    {
      x[a] = origin[a] + thin[3 * f.first + a];
    }
    if (!owned || owned(x))
    {
      Hole hole = f.second;
      for (int a = 0; a < 3; ++a)
      {
        hole.Center[a] += origin[a];
      }
      this->Open.push_back(hole);
    }
  }
  this->Added = all - given;
  for (std::size_t i = xyz.size(); i < rel.size(); ++i)
  {
    xyz.push_back(origin[i % 3] + rel[i]);
  }
  return true;
}

GapReport SummarizeHoles(std::vector<Hole> holes, double offset)
{
  // Group the circles whose centres lie within 2 l of each other (one hole,
  // seen from its rim's points): union-find over the pairs, found by sorting
  // the centres along x.
  GapReport report;
  std::sort(holes.begin(), holes.end(), [](const Hole& a, const Hole& b) {
    return a.Center < b.Center || (a.Center == b.Center && a.Radius < b.Radius);
  });
  const std::size_t n = holes.size();
  std::vector<std::size_t> parent(n);
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  auto root = [&](std::size_t i) {
    while (parent[i] != i)
    {
      i = parent[i] = parent[parent[i]];
    }
    return i;
  };
  const double reach = 2.0 * offset;
  for (std::size_t i = 0; i < n; ++i)
  {
    for (std::size_t j = i + 1; j < n && holes[j].Center[0] - holes[i].Center[0] <= reach; ++j)
    {
      double d2 = 0.0;
      for (int a = 0; a < 3; ++a)
      {
        const double d = holes[j].Center[a] - holes[i].Center[a];
        d2 += d * d;
      }
      if (d2 <= reach * reach)
      {
        parent[root(i)] = root(j);
      }
    }
  }
  std::vector<std::size_t> holeOf(n, n);
  for (std::size_t i = 0; i < n; ++i)
  {
    if (root(i) == i)
    {
      holeOf[i] = report.Holes.size();
      report.Holes.emplace_back();
    }
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    OpenHole& hole = report.Holes[holeOf[root(i)]];
    hole.Discs.push_back(holes[i]);
    if (holes[i].Radius > hole.Radius)
    {
      hole.Radius = holes[i].Radius;
      hole.Center = holes[i].Center;
    }
    if (holes[i].Radius > report.LargestGap)
    {
      report.LargestGap = holes[i].Radius;
      report.LargestGapCenter = holes[i].Center;
    }
  }
  // Widest first (the order of the centres on ties: the same on every process).
  std::stable_sort(report.Holes.begin(), report.Holes.end(),
    [](const OpenHole& a, const OpenHole& b) { return a.Radius > b.Radius; });
  report.Gaps = static_cast<std::int64_t>(report.Holes.size());
  report.GapPoints = static_cast<std::int64_t>(n);
  return report;
}

std::int64_t GapReport::PiercedGaps() const
{
  return std::count_if(
    this->Holes.begin(), this->Holes.end(), [](const OpenHole& hole) { return hole.Pierced; });
}

} // namespace nv
