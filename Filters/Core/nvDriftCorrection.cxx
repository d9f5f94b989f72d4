// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
//
// Why and how (PreserveOffset)
// ----------------------------
// Eq. (1), d phi/dt = g (Lap phi - F'(phi) / eps^2), moves its phi = 0 set by
// mean-curvature motion. That motion smooths wrinkles and noise, whose
// curvature changes sign within a few cells, but it also moves every curved
// surface as a whole: both sheets of the Table 1 sphere move inwards, a little
// each step (the README's stopping-rule table). PreserveOffset keeps the first
// and removes the second with a Lagrange multiplier mu(x, t), a vector field,
// added to the bracket of (1):
//
//   d phi/dt = g (Lap phi - F'(phi) / eps^2 + mu . grad phi),             (1')
//
// mu chosen so that the sheets have no local mean translation: for every x,
//
//   integral K(x, y) (d phi/dt)(y) grad phi(y) dy = 0,                     (C)
//
// K a kernel about 16 cells wide. A translation of the sheets by a small v
// changes phi by -v . grad phi, so the v that best explains a change r over
// the kernel (least squares) solves (int K grad phi grad phi^T) v =
// -int K r grad phi: (C) sets it to zero. Where the curvature is about the same
// across the kernel (a sphere, the offset of a smooth scan), mean-curvature
// motion is such a translation and is cancelled; wrinkles and noise, shorter
// than the kernel, move as much out as in, have no mean translation and are
// smoothed as before. (With K = 1 and a scalar multiplier, (1') is the
// nonlocal Allen-Cahn equation of Rubinstein and Sternberg, which conserves
// the integral of phi. That is the wrong constraint for a shell: the inner and
// outer sheets of a sphere move the same way in space, opposite ways in
// volume, and a volume constraint would move the inner sheet more. Hence the
// local, vector form.)
//
// Discretely, with r_s = phi^{n+1}_s - phi^n_s the change of one step
// (10)-(12) at band node s and G_s = 2 h grad phi (central differences, the
// neighbours of eq. 11), the correction delta that is smallest in the norm
// sum delta_s^2 / g_s and satisfies sum_y K(x, y) (r + delta)_y G_y = 0 is
// delta_s = -g_s G_s . mu: the term g mu . grad phi of (1'). Taking mu along
// the kernel's mean normal (the sheets within a kernel are nearly parallel):
//
//   delta_s = -g_s G_s . S(s) / W(s),  S = sum K r G,  W = sum K g |G|^2.   (C')
//
// g_s vanishes where the paper's scheme holds a node still (phi0 = 0 with eq.
// 4): the correction holds it too, else it would pile up there.
//
// In time the multiplier is explicit, like an operator split: delta measured
// on step n is added to phi^n before the implicit step (10) of step n + 1.
// (10) then smooths the node-to-node pattern of delta (g differs between
// neighbours); added after (12) instead, that pattern would roughen the
// output. The first step has no correction, and the drift of the last step
// stays: one step's worth (10 steps end with a third of the drift of the
// 3-step default).
//
// delta is added as the exact solution of d phi/dt = a (1 - phi^2) over the
// step, a = delta / (1 - phi^2): phi <- (phi + t) / (1 + t phi), t = tanh(a),
// which is phi + delta to first order and a shift of the profile (atanh phi
// moves by a). It keeps |phi| < 1 for any delta, so the scheme stays
// unconditionally stable, as with (12).
//
// The kernel: per brick (8^3 nodes) the sums of r G and g |G|^2; per corner of
// the bricks, the sums of the 2 x 2 x 2 bricks around it; per node, the
// trilinear interpolation of its brick's 8 corners. Every sum runs in a fixed
// order (a brick's nodes in band order, a corner's bricks in grid order), and
// a process receives its ghost layer's brick sums from their owner: phi is
// bit-identical for any thread count and number of processes.
#include "nvDriftCorrection.h"

#include "nvHalo.h"
#include "nvNarrowBand.h"
#include "nvParallel.h"
#include "nvTruncatedDistance.h"

#include <algorithm>
#include <cmath>

namespace nv
{
namespace
{
/// Per brick and per corner: the sum of r G (3 values) and of g |G|^2.
constexpr int SumsPerBrick = 4;

/// q = n / d and n - q d for 0 <= n < 2^52 (no integer division: this runs per node).
inline std::int64_t Divide(std::int64_t n, std::int64_t d, double inverse, std::int64_t& remainder)
{
  std::int64_t q = static_cast<std::int64_t>(static_cast<double>(n) * inverse);
  remainder = n - q * d;
  if (remainder < 0)
  {
    --q;
    remainder += d;
  }
  else if (remainder >= d)
  {
    ++q;
    remainder -= d;
  }
  return q;
}

/// G = 2 h grad phi at a band node, from its six neighbours (eq. 11's).
inline void Gradient(const double* phi, const std::uint32_t* n, double gradient[3])
{
  gradient[0] = phi[n[1]] - phi[n[0]];
  gradient[1] = phi[n[3]] - phi[n[2]];
  gradient[2] = phi[n[5]] - phi[n[4]];
}

/// g_s up to a constant factor: c = dt g / h^2 from the solver's w = c / (1 + 6 c).
inline double Mobility(double w)
{
  return w / (1.0 - 6.0 * w);
}
} // namespace

DriftCorrection::DriftCorrection(const NarrowBand& band, Halo* halo)
  : Band(band)
  , Exchange(halo)
{
  for (int a = 0; a < 3; ++a)
  {
    this->BrickDims[a] = (band.GridNodes.Dims[a] + BrickSize - 1) >> BrickShift;
  }
  const LayerRange owned = band.OwnedLayers;
  this->Layers.Begin = std::max<std::int64_t>(0, owned.Begin - 1);
  this->Layers.End = std::min<std::int64_t>(this->BrickDims[2], owned.End + 1);
  this->CornerDims = { { this->BrickDims[0] + 1, this->BrickDims[1] + 1, owned.Empty() ? 0 : owned.End - owned.Begin + 1 } };
  if (!this->Applies())
  {
    return;
  }
  const std::int64_t bricks = this->BrickDims[0] * this->BrickDims[1] * (this->Layers.End - this->Layers.Begin);
  this->BrickSums.assign(static_cast<std::size_t>(SumsPerBrick * bricks), 0.0);
  this->CornerSums.assign(
    static_cast<std::size_t>(SumsPerBrick * this->CornerDims[0] * this->CornerDims[1] * this->CornerDims[2]), 0.0);
}

bool DriftCorrection::Applies() const
{
  return !this->Band.RedStart.empty() && !this->Band.OwnedLayers.Empty();
}

void DriftCorrection::OwnedBricks(std::int64_t& first, std::int64_t& last) const
{
  const std::vector<std::int64_t>& bricks = this->Band.Bricks; // ascending
  const std::int64_t perLayer = this->BrickDims[0] * this->BrickDims[1];
  first = std::lower_bound(bricks.begin(), bricks.end(), this->Band.OwnedLayers.Begin * perLayer) - bricks.begin();
  last = std::lower_bound(bricks.begin(), bricks.end(), this->Band.OwnedLayers.End * perLayer) - bricks.begin();
}

void DriftCorrection::Measure(const double* phi, const double* previous, const double* coupling)
{
  if (!this->Applies())
  {
    return;
  }
  const NarrowBand& band = this->Band;
  const std::int64_t perLayer = this->BrickDims[0] * this->BrickDims[1];
  std::fill(this->BrickSums.begin(), this->BrickSums.end(), 0.0);
  std::int64_t first, last;
  this->OwnedBricks(first, last);
  const std::uint32_t* neighbor = band.Neighbor.data();
  ParallelFor(first, last, 16, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t a = begin; a < end; ++a)
    {
      double sum[SumsPerBrick] = { 0.0, 0.0, 0.0, 0.0 };
      for (const std::vector<std::int64_t>* start : { &band.RedStart, &band.BlackStart })
      {
        for (std::int64_t s = (*start)[a]; s < (*start)[a + 1]; ++s)
        {
          double G[3];
          Gradient(phi, neighbor + 6 * s, G);
          const double r = phi[s] - previous[s];
          sum[0] += r * G[0];
          sum[1] += r * G[1];
          sum[2] += r * G[2];
          sum[3] += Mobility(coupling[s]) * (G[0] * G[0] + G[1] * G[1] + G[2] * G[2]);
        }
      }
      std::copy(sum, sum + SumsPerBrick,
        &this->BrickSums[SumsPerBrick * (band.Bricks[a] - this->Layers.Begin * perLayer)]);
    }
  });
  if (this->Exchange)
  {
    this->Exchange->ExchangeLayers(this->BrickSums.data(), SumsPerBrick * perLayer, this->Layers.Begin);
  }
  this->SumCorners();
  this->Measured = true;
}

void DriftCorrection::SumCorners()
{
  const std::int64_t nx = this->BrickDims[0], ny = this->BrickDims[1];
  const std::int64_t cx = this->CornerDims[0], cy = this->CornerDims[1];
  const std::int64_t firstLayer = this->Band.OwnedLayers.Begin;
  ParallelFor(0, cx * cy * this->CornerDims[2], 4096, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t c = begin; c < end; ++c)
    {
      // Corner (ci, cj, ck) touches the bricks ci - 1 and ci along x, etc.
      const std::int64_t ci = c % cx, cj = (c / cx) % cy, ck = firstLayer + c / (cx * cy);
      double sum[SumsPerBrick] = { 0.0, 0.0, 0.0, 0.0 };
      for (std::int64_t k = std::max(ck - 1, this->Layers.Begin); k <= ck && k < this->Layers.End; ++k)
      {
        for (std::int64_t j = std::max<std::int64_t>(cj - 1, 0); j <= cj && j < ny; ++j)
        {
          for (std::int64_t i = std::max<std::int64_t>(ci - 1, 0); i <= ci && i < nx; ++i)
          {
            const double* in = &this->BrickSums[SumsPerBrick * (i + nx * (j + ny * (k - this->Layers.Begin)))];
            for (int v = 0; v < SumsPerBrick; ++v)
            {
              sum[v] += in[v];
            }
          }
        }
      }
      std::copy(sum, sum + SumsPerBrick, &this->CornerSums[SumsPerBrick * c]);
    }
  });
}

void DriftCorrection::Correct(double* phi, const double* coupling)
{
  if (!this->Applies() || !this->Measured)
  {
    return;
  }
  const NarrowBand& band = this->Band;
  const Grid& grid = band.GridNodes;
  const std::int64_t perLayer = this->BrickDims[0] * this->BrickDims[1];
  const std::int64_t firstLayer = band.OwnedLayers.Begin;
  std::int64_t first, last;
  this->OwnedBricks(first, last);
  const std::uint32_t* neighbor = band.Neighbor.data();
  const std::int64_t cx = this->CornerDims[0], cy = this->CornerDims[1];
  const double inverseX = 1.0 / static_cast<double>(grid.Dims[0]);
  const double inverseY = 1.0 / static_cast<double>(grid.Dims[1]);
  // Red nodes read only black neighbours and vice versa (nvNarrowBand.h): each
  // colour's pass is order-independent.
  for (bool red : { true, false })
  {
    const std::vector<std::int64_t>& start = red ? band.RedStart : band.BlackStart;
    ParallelFor(first, last, 16, [&](std::int64_t begin, std::int64_t end) {
      for (std::int64_t a = begin; a < end; ++a)
      {
        const std::int64_t b = band.Bricks[a];
        const std::int64_t bi = b % this->BrickDims[0];
        const std::int64_t bj = (b / this->BrickDims[0]) % this->BrickDims[1];
        const std::int64_t bk = b / perLayer - firstLayer;
        const double* corner = &this->CornerSums[SumsPerBrick * (bi + cx * (bj + cy * bk))];
        const std::int64_t step[3] = { SumsPerBrick, SumsPerBrick * cx, SumsPerBrick * cx * cy };
        for (std::int64_t s = start[a]; s < start[a + 1]; ++s)
        {
          // The node's place in its brick: the weights of the brick's corners.
          std::int64_t i, j, k;
          k = Divide(Divide(band.Node[s], grid.Dims[0], inverseX, i), grid.Dims[1], inverseY, j);
          const double f[3] = { ((i & (BrickSize - 1)) + 0.5) / BrickSize,
            ((j & (BrickSize - 1)) + 0.5) / BrickSize, ((k & (BrickSize - 1)) + 0.5) / BrickSize };
          double sum[SumsPerBrick] = { 0.0, 0.0, 0.0, 0.0 };
          for (int o = 0; o < 8; ++o)
          {
            const int ox = o & 1, oy = (o >> 1) & 1, oz = o >> 2;
            const double w = (ox ? f[0] : 1.0 - f[0]) * (oy ? f[1] : 1.0 - f[1]) * (oz ? f[2] : 1.0 - f[2]);
            const double* in = corner + ox * step[0] + oy * step[1] + oz * step[2];
            for (int v = 0; v < SumsPerBrick; ++v)
            {
              sum[v] += w * in[v];
            }
          }
          const double p = phi[s];
          const double room = 1.0 - p * p;
          if (!(sum[3] > 0.0) || !(room > 0.0))
          {
            continue;
          }
          double G[3];
          Gradient(phi, neighbor + 6 * s, G);
          const double delta = -Mobility(coupling[s]) * (G[0] * sum[0] + G[1] * sum[1] + G[2] * sum[2]) / sum[3]; // (C')
          const double t = std::tanh(delta / room);
          phi[s] = (p + t) / (1.0 + t * p);
        }
      }
    });
    if (this->Exchange)
    {
      this->Exchange->Exchange(phi, red);
    }
  }
}

} // namespace nv
