// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The device back end's kernels: one source for the host and the GPU.
//
// Each kernel is a small struct whose call operator is the work of one band
// node s, written once over plain arrays (EvolutionArrays). Under nvcc the
// call operators are __host__ __device__ (NV_HD): the CUDA launcher
// (nvCudaLauncher.cu) runs them on the GPU, one thread a node, and the host
// launcher (nvHostLauncher.cxx) runs the very same functions over the
// thread pool (nvParallel.h), so the whole device algorithm runs and is
// tested on every machine. The loops around them (the sweeps, the
// over-relaxation's estimate, the stopping rule) are host code shared by
// both launchers and the CPU's solver (nvDeviceEvolution.cxx on
// Scheme/nvTimeLoop.h); a launcher only allocates, copies and launches.
//
// The formulas are the CPU core's solver's own: both call the scheme's terms
// (Scheme/nvSchemeTerms.h), so that the host launcher gives the CPU core's
// phi bit for bit (TestCoreDevice checks it). On a GPU,
// nvcc contracts a * b + c into fused multiply-adds and the reductions sum
// in another order: phi then differs in the last bits, not more.
//
// The truncated distance of eq. (6) (DistanceKernel, CoveredKernel) and the
// band's collect and connect passes are here too, from the terms of Band/nvBandTerms.h
// that the CPU core (nvTruncatedDistance.cxx, nvNarrowBand.cxx) calls too,
// so that both launchers give its distances and band bit for bit.
//
// This header is plain C++ for the host compiler: it includes nothing of
// CUDA, and no STL beyond <cmath> and <cstdint>, whose math functions
// (::exp, ::sqrt, ::fabs, ::copysign, in double) CUDA provides on the device.
#ifndef nvDeviceKernels_h
#define nvDeviceKernels_h

#include "nvBandTerms.h"
#include "nvHostDevice.h"
#include "nvPointSort.h"
#include "nvSchemeTerms.h"

#include <cmath>
#include <cstdint>

namespace nv
{
namespace device
{

/**
 * The band as both sides hold it: a structure of arrays indexed by the band
 * node s = 0 .. Size - 1, red nodes first, then black ones (nvNarrowBand.h),
 * and the neighbour table. On the GPU these pointers are device memory, on
 * the host the band's own arrays or host copies. Precision, array by array:
 *
 * - Neighbor: uint32, 6 a node (-x, +x, -y, +y, -z, +z), the band's own
 *   table, unchanged: indices into Phi, Size and Size + 1 being the two
 *   Dirichlet slots of eq. (5). 32 bits address bands of up to 4.29e9 nodes
 *   (nvNarrowBand.h's MaximumBandSize), half the bytes of 64-bit indices.
 * - Distance: double, d of eq. (6), read once by InitialPhiKernel. Double as
 *   the CPU core's, so that phi0 is the same bits (float would move the
 *   sheets by up to 6e-8 of the box, but it would break the host launcher's
 *   bit-for-bit check against the CPU core).
 * - Phi: double, Size + 2 values. The Gauss-Seidel sweeps stop on changes of
 *   1e-6 (GaussSeidelTolerance) of values near 1, a tenth of float's
 *   resolution there (6e-8) only: in float the stopping test would measure
 *   rounding. Double also keeps the norms of the stopping rule exact enough
 *   for ConvergenceTolerance down to 1e-5 and below.
 * - Previous: double, phi^n (the right-hand side of eq. 10 and the stopping
 *   rule's reference): the same reasons as Phi.
 * - Coupling: double, w = c / (1 + 6 c), c = dt g / h^2 (eq. 10-11), read
 *   every sweep; double as the CPU core's, for the bit-for-bit check. (A
 *   float w would save 4 bytes of the 46 a node that a sweep reads; it is
 *   a candidate once the GPU's timings are measured.)
 * - Decay: float, exp(-2 g dt / eps^2) of eq. (12), read once a step, as
 *   the CPU core's (its rounding moves phi by at most 3e-8 a step).
 */
struct EvolutionArrays
{
  std::int64_t Size = 0;
  const std::uint32_t* Neighbor = nullptr;
  const double* Distance = nullptr;
  double* Phi = nullptr;
  double* Previous = nullptr;
  double* Coupling = nullptr;
  float* Decay = nullptr;
};

/// The scheme's constants (nvParameters.h), computed once on the host.
struct EvolutionConstants
{
  double Offset = 0.0;        ///< l
  double Xi = 0.0;            ///< xi of eq. (2)
  double TimeStep = 0.0;      ///< dt
  double Spacing = 0.0;       ///< h
  double Epsilon = 0.0;       ///< eps of eq. (12)
  bool EdgeStopEq4 = true;    ///< g of eq. (4), else of eq. (3)
};

/// phi^0 of eq. (2) at node s (d = +inf gives -1).
struct InitialPhiKernel
{
  EvolutionArrays A;
  EvolutionConstants C;
  NV_HD void operator()(std::int64_t s) const { A.Phi[s] = InitialPhi(A.Distance[s], C.Offset, C.Xi); }
};

/// The per-node coefficients of (10) and (12) from phi^0, and phi^n = phi^0.
struct CoefficientsKernel
{
  EvolutionArrays A;
  EvolutionConstants C;
  NV_HD void operator()(std::int64_t s) const
  {
    const double phi0 = A.Phi[s];
    const double g = EdgeStop(phi0, C.EdgeStopEq4);             // eq. (4) or (3)
    A.Coupling[s] = CouplingWeight(g, C.TimeStep, C.Spacing); // (10)-(11)
    A.Decay[s] = ReactionDecay(g, C.TimeStep, C.Epsilon);     // (12)
    A.Previous[s] = phi0;
  }
};

/// phi^n = phi at the start of a step.
struct KeepPreviousKernel
{
  EvolutionArrays A;
  NV_HD void operator()(std::int64_t s) const { A.Previous[s] = A.Phi[s]; }
};

/// One node of a red or black half sweep of (10)-(11), over-relaxed by
/// Omega; returns |change| (the sweeps' stopping test takes the max).
/// A red node reads only black neighbours and the reverse, so the nodes of
/// one colour are independent: any order, any number of threads, the same
/// result.
struct RelaxKernel
{
  EvolutionArrays A;
  double Omega = 1.0;
  NV_HD double operator()(std::int64_t s) const
  {
    const double step = RelaxationChange(A.Phi, A.Neighbor + 6 * s, s, A.Previous[s], A.Coupling[s], Omega);
    A.Phi[s] += step;
    return ::fabs(step);
  }
};

/// The reaction step (12) at node s, in place.
struct ReactKernel
{
  EvolutionArrays A;
  NV_HD void operator()(std::int64_t s) const { A.Phi[s] = ReactionStep(A.Phi[s], A.Decay[s]); }
};

/// The terms of the stopping rule's norms (section 4) at node s.
struct ChangeSquaredKernel
{
  EvolutionArrays A;
  NV_HD double operator()(std::int64_t s) const
  {
    return SquaredChange(A.Phi[s], A.Previous[s]);
  }
};
struct NormSquaredKernel
{
  EvolutionArrays A;
  NV_HD double operator()(std::int64_t s) const { return A.Previous[s] * A.Previous[s]; }
};

// ---------------------------------------------------------------------------
// The truncated distance of eq. (6), brick by brick (nvTruncatedDistance.h),
// from the terms of Band/nvBandTerms.h that the CPU core calls too (the
// constants, the brick's nodes and buckets, the box of eq. 7, the squared
// distance and its truncation, the covering test; MulRn, AddRn keep nvcc
// from fusing its products and sums).

/**
 * The points sorted into bricks and one batch of bricks, as both sides hold
 * them. Precision, array by array:
 *
 * - Points: double, 3 a point, relative to the grid's origin in cells, sorted
 *   by brick on the device (PointArrays' Points). Double as the CPU core's, so that the distances
 *   are the same bits; in float a point 4096 cells from the origin would move
 *   by up to 2.4e-4 cells (24 bits of 4096), and the band and phi0 with it.
 * - BucketStart: int64, one a brick of the grid and one more: the points of
 *   brick b are [BucketStart[b], BucketStart[b + 1]). 64 bits as the CPU
 *   core's, for clouds of more than 4.29e9 points.
 * - Bricks: int64, the batch's grid brick indices (NarrowBand::Bricks).
 * - Distance: double, BrickNodes a brick of the batch, node n = i + 8 (j + 8
 *   k) of batch brick a at BrickNodes a + n: d of eq. (6) in world units, as
 *   ComputeBrick's (band.Distance holds double; phi0 reads it).
 * - Covered: uint8, a brick of the batch: BrickWithin's answer (1: d <=
 *   l - eta/2 on the whole brick, its distances not computed).
 */
struct DistanceArrays
{
  const double* Points = nullptr;
  const std::int64_t* BucketStart = nullptr;
  const std::int64_t* Bricks = nullptr;
  double* Distance = nullptr;
  std::uint8_t* Covered = nullptr;
};

// DistanceConstants (the grid and the reach in cells, the covering radius):
// nvBandTerms.h's, made by DistanceConstantsOf as TruncatedDistance's.

/// BrickWithin(Bricks[a], radius) for batch brick a: nvBandTerms.h's
/// BrickCovered, which BrickWithin calls.
struct CoveredKernel
{
  DistanceArrays A;
  DistanceConstants C;
  NV_HD void operator()(std::int64_t a) const
  {
    A.Covered[a] = BrickCovered(C, A.Points, A.BucketStart, A.Bricks[a]) ? 1 : 0;
  }
};

/**
 * d of eq. (6) at node t of the batch (brick a = t / 512, node n = t % 512
 * in it): the least distance to the points of the bricks within Margin,
 * truncated at the reach. A gather (each node reads the points) where
 * ComputeBrick scatters (each point writes its box of nodes), with the
 * same terms (nvBandTerms.h), so the same bits: a point counts for node
 * (i, j, k) when the node lies in the point's box of eq. (7) (InBox), and
 * its squared distance is (dz^2 + dy^2) + dx^2 in that order (AddSquare);
 * the minimum of the same values in any order is the same value. One
 * thread a node: the threads of a block share one brick and read mostly
 * the same points.
 */
struct DistanceKernel
{
  DistanceArrays A;
  DistanceConstants C;
  NV_HD void operator()(std::int64_t t) const
  {
    const std::int64_t a = t >> (3 * BrickShift);
    const int n = static_cast<int>(t & (BrickNodes - 1));
    if (A.Covered[a])
    {
      return;
    }
    std::int64_t first[3], last[3];
    BrickNodeRange(C, A.Bricks[a], first, last);
    std::int64_t node[3];
    NodeAtPlace(first, n, node);
    const double at[3] = { static_cast<double>(node[0]), static_cast<double>(node[1]), static_cast<double>(node[2]) };
    double best = C.Infinity;
    if (node[0] <= last[0] && node[1] <= last[1] && node[2] <= last[2]) // else past the grid's end: +inf
    {
      // The bricks within Margin of this node (ComputeBrick takes those of
      // the whole brick: the points of the others fail the box test below,
      // those sorted into the grid's edge bricks included).
      std::int64_t lo[3], hi[3];
      BucketRange(C.BrickDims, node, node, C.Margin, lo, hi);
      for (std::int64_t bk = lo[2]; bk <= hi[2]; ++bk)
      {
        for (std::int64_t bj = lo[1]; bj <= hi[1]; ++bj)
        {
          for (std::int64_t bi = lo[0]; bi <= hi[0]; ++bi)
          {
            const std::int64_t bucket = BrickIndexOf(C.BrickDims, bi, bj, bk);
            for (std::int64_t p = A.BucketStart[bucket]; p < A.BucketStart[bucket + 1]; ++p)
            {
              const double* x = A.Points + 3 * p;
              // ComputeBrick's box BoxFirst(x) <= i <= BoxLast(x) (eq. 7).
              if (!(InBox(x[0], C.Reach, at[0]) && InBox(x[1], C.Reach, at[1]) && InBox(x[2], C.Reach, at[2])))
              {
                continue;
              }
              const double dyz2 = AddSquare(AxisSquare(at[2], x[2]), at[1], x[1]);
              if (BeyondReach(dyz2, C))
              {
                continue; // as ComputeBrick's row test; d2 >= Reach2 anyway
              }
              const double d2 = AddSquare(dyz2, at[0], x[0]);
              best = d2 < best ? d2 : best; // std::min(best, d2)
            }
          }
        }
      }
    }
    A.Distance[t] = TruncatedOf(best, C);
  }
};

// The points' sort into bricks and the bricks they reach: the kernels of
// Band/nvPointSort.h, which the CPU core runs too.

// ---------------------------------------------------------------------------
// The band's nodes of the collect pass (eq. 7), picked from a batch's distances on the
// device, so that only they come back to the host: nvBandTerms.h's
// ClassifyBrick, which nvNarrowBand.cxx's ClassifyBrickNodes calls.

/**
 * The band's nodes of one batch of bricks, as both sides hold them.
 * Precision, array by array:
 *
 * - Distance, Covered, Bricks: DistanceArrays' (read here).
 * - RedCount, BlackCount: int32, a brick: its band nodes of each colour
 *   (at most 512).
 * - RedFirst, BlackFirst: int64, a brick: where its red and its black
 *   nodes go in NodeOffset and NodeDistance, which hold the batch's red
 *   nodes first, brick after brick, then its black ones (the host's sums of
 *   the counts over the bricks before it), so that the store pass joins the batches
 *   by two copies each (StoreBand).
 * - NodeOffset: uint16, a band node: i + 8 (j + 8 k) in its brick, as
 *   NarrowBand::Offset.
 * - NodeDistance: double, a band node: its d, as NarrowBand::Distance.
 * - Inside: uint64, 8 a brick: NarrowBand::Inside's bits (the nodes off the
 *   band with d <= l - eta/2; all of a covered brick's).
 */
struct BandNodeArrays
{
  const std::int64_t* Bricks = nullptr;
  const double* Distance = nullptr;
  const std::uint8_t* Covered = nullptr;
  std::int32_t* RedCount = nullptr;
  std::int32_t* BlackCount = nullptr;
  const std::int64_t* RedFirst = nullptr;
  const std::int64_t* BlackFirst = nullptr;
  std::uint16_t* NodeOffset = nullptr;
  double* NodeDistance = nullptr;
  std::uint64_t* Inside = nullptr;
};

/// The grid and the band's bounds (nvNarrowBand.cxx's ClassifyBrickNodes).
struct BandNodeConstants
{
  DistanceConstants Grid; ///< GridDims and BrickDims are read
  BandBounds Bounds;      ///< l -/+ eta/2, or the whole domain
};

/// Counts batch brick c's band nodes of each colour and sets its Inside bits.
struct BandCountKernel
{
  BandNodeArrays A;
  BandNodeConstants C;
  NV_HD void operator()(std::int64_t c) const
  {
    std::int32_t red = 0, black = 0;
    std::uint64_t* inside = A.Inside + (BrickNodes / 64) * c;
    ResetInside(inside, A.Covered[c] != 0);
    if (!A.Covered[c])
    {
      std::int64_t first[3], last[3];
      BrickNodeRange(C.Grid, A.Bricks[c], first, last);
      ClassifyBrick(C.Grid.GridDims, first, A.Distance + BrickNodes * c, C.Bounds, inside,
        [&](int, bool isRed, double) {
          red += isRed ? 1 : 0;
          black += isRed ? 0 : 1;
        });
    }
    A.RedCount[c] = red;
    A.BlackCount[c] = black;
  }
};

/// Writes batch brick c's red band nodes from RedFirst[c] on and its black
/// ones from BlackFirst[c] on, each in ascending node order (as
/// CollectBandNodes' lists).
struct BandCompactKernel
{
  BandNodeArrays A;
  BandNodeConstants C;
  NV_HD void operator()(std::int64_t c) const
  {
    if (A.Covered[c])
    {
      return;
    }
    std::int64_t first[3], last[3];
    BrickNodeRange(C.Grid, A.Bricks[c], first, last);
    std::int64_t red = A.RedFirst[c], black = A.BlackFirst[c];
    ClassifyBrick(C.Grid.GridDims, first, A.Distance + BrickNodes * c, C.Bounds, nullptr, // Inside: counted
      [&](int n, bool isRed, double d) {
        const std::int64_t s = isRed ? red++ : black++;
        A.NodeOffset[s] = static_cast<std::uint16_t>(n);
        A.NodeDistance[s] = d;
      });
  }
};

// ---------------------------------------------------------------------------
// The band's neighbour table of the connect pass (nvNarrowBand.cxx's IndexBricks and
// ConnectNeighbours), built where the band's nodes are, so that neither it
// nor the distances cross to the host and back before the evolution. The
// brick across a face, a neighbour's place and the Dirichlet slot are
// nvBandTerms.h's, which the CPU core calls too; the lookups differ (a
// binary search here, the CPU's slot and rank tables there).

/**
 * The band after the store pass, as both sides hold it. Precision, array by array:
 *
 * - Bricks: int64, NumberOfBricks, ascending: NarrowBand::Bricks.
 * - RedStart, BlackStart: int64, NumberOfBricks + 1: NarrowBand's (a
 *   brick's red nodes are [RedStart[a], RedStart[a + 1]), the black ones
 *   likewise, the black ones after all the red ones).
 * - Offset: uint16, Size: NarrowBand::Offset, ascending within a brick's
 *   nodes of one colour.
 * - Distance: double, Size: NarrowBand::Distance (only its side of l is
 *   read here, for the Dirichlet slot).
 * - Adjacent: int32, 6 a brick: the slot in Bricks of the brick across each
 *   face (-x, +x, -y, +y, -z, +z), -1 for none (IndexBricks').
 * - Neighbor: uint32, 6 a node: NarrowBand::Neighbor, the same values.
 */
struct NeighbourArrays
{
  std::int64_t NumberOfBricks = 0;
  std::int64_t RedCount = 0;
  std::int64_t Size = 0;
  const std::int64_t* Bricks = nullptr;
  const std::int64_t* RedStart = nullptr;
  const std::int64_t* BlackStart = nullptr;
  const std::uint16_t* Offset = nullptr;
  const double* Distance = nullptr;
  std::int32_t* Adjacent = nullptr;
  std::uint32_t* Neighbor = nullptr;
};

struct NeighbourConstants
{
  std::int64_t BrickDims[3] = { 0, 0, 0 };
  double Offset = 0.0; ///< l: phi0 > 0 exactly when d < l (eq. 2)
};

/// Brick slot a's six adjacent slots, as IndexBricks (a brick off the band
/// or the grid: -1).
struct AdjacentBricksKernel
{
  NeighbourArrays A;
  NeighbourConstants C;
  NV_HD void operator()(std::int64_t a) const
  {
    std::int64_t at[3];
    BrickAt(C.BrickDims, A.Bricks[a], at);
    for (int direction = 0; direction < 6; ++direction)
    {
      const std::int64_t next = AdjacentBrick(C.BrickDims, at, direction);
      A.Adjacent[6 * a + direction] =
        next >= 0 ? static_cast<std::int32_t>(IndexOf(A.Bricks, 0, A.NumberOfBricks, next)) : -1;
    }
  }
};

/**
 * Band node s's six neighbours, as ConnectNeighbours: the neighbour at place
 * q of brick slot b (its own brick, or the one across the face it lies on;
 * NeighbourPlace) is the band node with that place among b's nodes of the
 * other colour, found by a binary search there (ConnectNeighbours reads a
 * rank table instead: the same node, so the same index); a neighbour off
 * the band is the Dirichlet slot of s's side (DirichletSlot, eq. 5). s's
 * brick is found by a binary search of its colour's starts.
 */
struct NeighboursKernel
{
  NeighbourArrays A;
  NeighbourConstants C;
  NV_HD void operator()(std::int64_t s) const
  {
    const bool red = s < A.RedCount;
    const std::int64_t* other = red ? A.BlackStart : A.RedStart;
    const std::int64_t a = LastAtOrBelow(red ? A.RedStart : A.BlackStart, A.NumberOfBricks, s);
    const int n = A.Offset[s];
    const std::uint32_t dirichlet = DirichletSlot(A.Distance[s], C.Offset, A.Size);
    for (int direction = 0; direction < 6; ++direction)
    {
      bool across = false;
      const int q = NeighbourPlace(n, direction, across);
      const std::int64_t b = across ? A.Adjacent[6 * a + direction] : a;
      const std::int64_t t = b >= 0 ? IndexOf(A.Offset, other[b], other[b + 1], static_cast<std::uint16_t>(q)) : -1;
      A.Neighbor[6 * s + direction] = t >= 0 ? static_cast<std::uint32_t>(t) : dirichlet;
    }
  }
};

} // namespace device
} // namespace nv

#endif
