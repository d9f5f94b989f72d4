// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nvSurfaceField.h"

#include "nvNarrowBand.h"

#include <algorithm>
#include <cmath>

namespace nv
{

ImpliedDistance::ImpliedDistance(const Parameters& parameters)
  : Scale(std::sqrt(2.0) * parameters.Xi())
  , Cap(parameters.HalfBandWidth())
{
}

std::array<std::int64_t, 3> BrickDimensions(const Grid& grid)
{
  std::array<std::int64_t, 3> dims;
  for (int a = 0; a < 3; ++a)
  {
    dims[a] = (grid.Dims[a] + BrickSize - 1) >> BrickShift;
  }
  return dims;
}

BrickField::~BrickField() = default;

//------------------------------------------------------------------------------
BandField::BandField(const NarrowBand& band, const BandValues& phi, const Parameters& parameters)
  : Band(band)
  , Phi(phi)
  , Psi(parameters)
  , BrickDims(BrickDimensions(band.GridNodes))
{
}

void BandField::Layer(std::int64_t layer, std::vector<float>& uniform, std::vector<std::int64_t>& varying) const
{
  // Bricks no point reaches are outside the shell; a reached brick without
  // band nodes lies on one side of it (inside and outside nodes are never
  // neighbours: their distances differ by eta > h).
  const std::int64_t perLayer = this->BrickDims[0] * this->BrickDims[1];
  uniform.assign(static_cast<std::size_t>(perLayer), this->Psi.Outside());
  varying.clear();
  std::int64_t first, last;
  BricksInLayers(this->Band.Bricks, perLayer, layer, layer + 1, first, last);
  for (std::int64_t a = first; a < last; ++a)
  {
    bool allInside;
    if (!UniformBandBrick(this->Band, a, allInside))
    {
      varying.push_back(this->Band.Bricks[a]);
    }
    else
    {
      uniform[this->Band.Bricks[a] - layer * perLayer] = allInside ? this->Psi.Inside() : this->Psi.Outside();
    }
  }
}

void BandField::Values(std::int64_t brick, float values[BrickNodes]) const
{
  const NarrowBand& band = this->Band;
  const std::int64_t a = IndexOf(band.Bricks.data(), 0, static_cast<std::int64_t>(band.Bricks.size()), brick);
  if (a < 0)
  {
    std::fill(values, values + BrickNodes, this->Psi.Outside()); // a brick no point reaches
    return;
  }
  // Nodes off the band: their side of the shell; band nodes: each at its
  // place in the brick.
  BandBrickPsi(&band.Inside[8 * a], band.RedStart[a], band.RedStart[a + 1], band.BlackStart[a],
    band.BlackStart[a + 1], band.Offset.data(), this->Phi.data(), this->Psi.GetScale(), this->Psi.GetCap(), values);
}

//------------------------------------------------------------------------------
DenseField::DenseField(
  const Grid& grid, const float* phi, std::int64_t kBegin, std::int64_t kEnd, const Parameters& parameters)
  : TheGrid(grid)
  , Phi(phi)
  , Begin(kBegin)
  , End(kEnd)
  , Psi(parameters)
  , BrickDims(BrickDimensions(grid))
{
}

void DenseField::Layer(std::int64_t layer, std::vector<float>& uniform, std::vector<std::int64_t>& varying) const
{
  const std::int64_t perLayer = this->BrickDims[0] * this->BrickDims[1];
  uniform.assign(static_cast<std::size_t>(perLayer), this->Psi.Outside());
  varying.clear();
  if ((layer + 1) * BrickSize > this->Begin && layer * BrickSize < this->End)
  {
    for (std::int64_t b = 0; b < perLayer; ++b)
    {
      varying.push_back(layer * perLayer + b);
    }
  }
}

void DenseField::Values(std::int64_t brick, float values[BrickNodes]) const
{
  const Grid& grid = this->TheGrid;
  const std::int64_t first[3] = { (brick % this->BrickDims[0]) << BrickShift,
    ((brick / this->BrickDims[0]) % this->BrickDims[1]) << BrickShift,
    (brick / (this->BrickDims[0] * this->BrickDims[1])) << BrickShift };
  for (int k = 0; k < BrickSize; ++k)
  {
    for (int j = 0; j < BrickSize; ++j)
    {
      for (int i = 0; i < BrickSize; ++i)
      {
        const std::int64_t x = first[0] + i, y = first[1] + j, z = first[2] + k;
        const bool present = x < grid.Dims[0] && y < grid.Dims[1] && z >= this->Begin && z < this->End;
        values[i + BrickSize * (j + BrickSize * k)] = present
          ? this->Psi(this->Phi[grid.Index(x, y, z) - this->Begin * grid.Dims[0] * grid.Dims[1]])
          : this->Psi.Outside();
      }
    }
  }
}

NodeField::NodeField(const Grid& grid, const std::vector<float>& values, float outside)
  : TheGrid(grid)
  , Nodes(values)
  , Outside(outside)
  , BrickDims(BrickDimensions(grid))
{
}

void NodeField::Layer(std::int64_t layer, std::vector<float>& uniform, std::vector<std::int64_t>& varying) const
{
  const std::int64_t perLayer = this->BrickDims[0] * this->BrickDims[1];
  uniform.assign(static_cast<std::size_t>(perLayer), this->Outside);
  varying.resize(static_cast<std::size_t>(perLayer));
  for (std::int64_t b = 0; b < perLayer; ++b)
  {
    varying[b] = layer * perLayer + b;
  }
}

void NodeField::Values(std::int64_t brick, float values[BrickNodes]) const
{
  const Grid& grid = this->TheGrid;
  const std::int64_t first[3] = { (brick % this->BrickDims[0]) * BrickSize,
    ((brick / this->BrickDims[0]) % this->BrickDims[1]) * BrickSize,
    (brick / (this->BrickDims[0] * this->BrickDims[1])) * BrickSize };
  for (int k = 0; k < BrickSize; ++k)
  {
    for (int j = 0; j < BrickSize; ++j)
    {
      for (int i = 0; i < BrickSize; ++i)
      {
        const std::int64_t x = first[0] + i, y = first[1] + j, z = first[2] + k;
        values[i + BrickSize * (j + BrickSize * k)] = x < grid.Dims[0] && y < grid.Dims[1] && z < grid.Dims[2]
          ? this->Nodes[grid.Index(x, y, z)]
          : this->Outside;
      }
    }
  }
}

} // namespace nv
