// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The truncated distance (eq. 6) and the narrow band with its neighbour
// indices (the paper's band construction: collect, store, connect) on a tiny grid, against values computed by
// hand and by brute force over every node.
#include "nvGrid.h"
#include "nvNarrowBand.h"
#include "nvParameters.h"
#include "nvTruncatedDistance.h"
#include "nvTestUtilities.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace
{

// Grid: origin 0, h = 1, 12^3 nodes (two bricks per axis, the second partial).
nv::Grid TinyGrid()
{
  nv::Grid grid;
  grid.Origin = { { 0.0, 0.0, 0.0 } };
  grid.Spacing = 1.0;
  grid.Dims = { { 12, 12, 12 } };
  return grid;
}

double BruteDistance(const std::vector<double>& points, double x, double y, double z)
{
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t p = 0; p < points.size(); p += 3)
  {
    best = std::min(best, std::hypot(x - points[p], y - points[p + 1], z - points[p + 2]));
  }
  return best;
}

void TestHandValues()
{
  // One point at (5.5, 4.6, 4.4), reach 3.
  const std::vector<double> points = { 5.5, 4.6, 4.4 };
  const nv::TruncatedDistance distance(TinyGrid(), points.data(), 1, 3.0);
  NV_CHECK(distance.GetBrickDims()[0] == 2);
  double d[nv::BrickNodes];
  distance.ComputeBrick(0, d); // nodes 0..7 on each axis
  auto at = [&](int i, int j, int k) { return d[i + 8 * (j + 8 * k)]; };
  NV_CHECK_NEAR(at(5, 5, 5), std::sqrt(0.25 + 0.16 + 0.36), 1e-14);
  NV_CHECK_NEAR(at(7, 5, 5), std::sqrt(2.25 + 0.16 + 0.36), 1e-14);
  NV_CHECK_NEAR(at(5, 7, 6), std::sqrt(0.25 + 5.76 + 2.56), 1e-14); // 2.93, just within reach
  NV_CHECK(std::isinf(at(5, 5, 1))); // 3.46 from the point: beyond reach
  NV_CHECK(std::isinf(at(0, 0, 0)));
  distance.ComputeBrick(1, d); // nodes i = 8..11, j, k = 0..7
  NV_CHECK_NEAR(at(0, 5, 5), std::sqrt(6.25 + 0.16 + 0.36), 1e-14); // node (8, 5, 5)
  NV_CHECK(std::isinf(at(1, 5, 5)));                                 // node (9, 5, 5): 3.57
  NV_CHECK(std::isinf(at(4, 5, 5)));      // node (12, 5, 5) is past the grid
  // Nodes within reach have i = 3..8, j, k = 2..7: bricks 0 and 1 only.
  const std::vector<std::int64_t> reached = distance.ReachedBricks();
  NV_CHECK(reached.size() == 2 && reached[0] == 0 && reached[1] == 1);
}

void TestAgainstBruteForce()
{
  // Three points; every node within reach must match the brute-force minimum.
  const std::vector<double> points = { 5.3, 5.1, 4.9, 3.2, 7.7, 6.4, 8.9, 2.2, 3.3 };
  const double reach = 3.0;
  const nv::Grid grid = TinyGrid();
  const nv::TruncatedDistance distance(grid, points.data(), 3, reach);
  int compared = 0;
  for (std::int64_t brick = 0; brick < distance.GetNumberOfBricks(); ++brick)
  {
    double d[nv::BrickNodes];
    distance.ComputeBrick(brick, d);
    std::int64_t first[3];
    distance.BrickFirstNode(brick, first);
    for (int k = 0; k < 8; ++k)
      for (int j = 0; j < 8; ++j)
        for (int i = 0; i < 8; ++i)
        {
          const double got = d[i + 8 * (j + 8 * k)];
          const std::int64_t x = first[0] + i, y = first[1] + j, z = first[2] + k;
          if (x >= 12 || y >= 12 || z >= 12)
          {
            NV_CHECK(std::isinf(got));
            continue;
          }
          const double expected = BruteDistance(points, x, y, z);
          if (expected < reach)
          {
            NV_CHECK_NEAR(got, expected, 1e-14);
            ++compared;
          }
          else
          {
            NV_CHECK(std::isinf(got));
          }
        }
  }
  NV_CHECK(compared > 100);
}

void TestBand(nv::Domain mode)
{
  // l = 2, h = 1, xi = eps_1: the band is 1 < d < 3 (eta/2 = m h = 1).
  const std::vector<double> points = { 5.3, 5.1, 4.9, 3.2, 7.7, 6.4 };
  nv::Parameters parameters;
  parameters.OffsetDistance = 2.0;
  parameters.Spacing = 1.0;
  parameters.XiCells = 1.0;
  parameters.Domain = mode;
  NV_CHECK_NEAR(parameters.HalfBandWidth(), 1.0, 1e-12);
  NV_CHECK_NEAR(parameters.Reach(), 3.0, 1e-12);
  const nv::Grid grid = TinyGrid();
  const nv::TruncatedDistance distance(grid, points.data(), 2, parameters.Reach());
  const nv::NarrowBand band = nv::BuildNarrowBand(distance, parameters);

  // Expected band, by brute force over all nodes.
  std::map<std::int64_t, double> expected;
  for (int z = 0; z < 12; ++z)
    for (int y = 0; y < 12; ++y)
      for (int x = 0; x < 12; ++x)
      {
        const double d = BruteDistance(points, x, y, z);
        if (mode == nv::Domain::WholeDomain || (1.0 < d && d < 3.0))
        {
          expected[grid.Index(x, y, z)] = d;
        }
      }
  NV_CHECK(band.Size() == static_cast<std::int64_t>(expected.size()));
  std::map<std::int64_t, std::int64_t> slot;
  for (std::int64_t s = 0; s < band.Size(); ++s)
  {
    slot[band.GridIndex(s)] = s;
    const auto it = expected.find(band.GridIndex(s));
    NV_CHECK(it != expected.end());
    if (it != expected.end() && it->second < 3.0)
    {
      NV_CHECK_NEAR(band.Distance[s], it->second, 1e-14);
    }
    std::int64_t ijk[3];
    grid.Ijk(band.GridIndex(s), ijk);
    // Red nodes (i + j + k even) come first.
    NV_CHECK((s < band.RedCount) == ((ijk[0] + ijk[1] + ijk[2]) % 2 == 0));
  }
  // Neighbours: the band index of a band neighbour, else the Dirichlet slot
  // chosen by the node's own phi0 sign (d < l: inside).
  for (std::int64_t s = 0; s < band.Size(); ++s)
  {
    std::int64_t ijk[3];
    grid.Ijk(band.GridIndex(s), ijk);
    const std::uint32_t dirichlet = band.Distance[s] < 2.0 ? band.InsideSlot() : band.OutsideSlot();
    for (int direction = 0; direction < 6; ++direction)
    {
      std::int64_t n[3] = { ijk[0], ijk[1], ijk[2] };
      n[direction / 2] += direction % 2 ? 1 : -1;
      std::uint32_t want = dirichlet;
      if (n[direction / 2] >= 0 && n[direction / 2] < 12)
      {
        const auto it = slot.find(grid.Index(n[0], n[1], n[2]));
        if (it != slot.end())
        {
          want = static_cast<std::uint32_t>(it->second);
        }
      }
      NV_CHECK(band.Neighbor[6 * s + direction] == want);
    }
  }
}

void TestGridHelpers()
{
  // A unit box, l = 0.1, h = 0.01, m = 2: padding l + 2h + 2h = 0.14, so
  // 1.28 / 0.01 = 128 cells and 129 nodes per axis.
  const double bounds[6] = { 0, 1, 0, 1, 0, 1 };
  const nv::Grid grid = nv::MakeGrid(bounds, 0.01, nv::GridPadding(0.12, 0.01));
  NV_CHECK(grid.Dims[0] == 129 && grid.Dims[1] == 129 && grid.Dims[2] == 129);
  NV_CHECK_NEAR(grid.Origin[0], -0.14, 1e-15);
  // MaximumDimension 100 for the same box: (1 + 0.2) / (100 - 8) cells.
  NV_CHECK_NEAR(nv::SpacingForMaximumDimension(bounds, 0.1, 2.0, 100), 1.2 / 92.0, 1e-15);
  NV_CHECK(nv::SpacingForMaximumDimension(bounds, 0.1, 2.0, 8) == 0.0);
  // eps_m = m h / (sqrt(2) atanh(0.99)): eps_6 at h = 0.01 is 0.016030...
  NV_CHECK_NEAR(nv::EpsilonFromCells(6, 0.01), 0.06 / (std::sqrt(2.0) * 2.6466524123622457), 1e-15);
}

} // namespace

int main()
{
  TestHandValues();
  TestAgainstBruteForce();
  TestBand(nv::Domain::NarrowBand);
  TestBand(nv::Domain::WholeDomain);
  TestGridHelpers();
  return nvtest::Result("TestCoreDistance");
}
