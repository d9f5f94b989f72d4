// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// Small pieces of the shell: loose balls around lone points or small clumps
// of points (a point farther than 2 l from every other one gets a ball of its
// own, eq. 2), and tiny voids left inside a wall where the sampling is uneven.
// Neither is part of the narrow volume a user wants to print or measure, so by
// default both are removed:
//
// - a piece (a closed part of the phi = 0 surface around a region of phi > 0)
//   smaller than a ball of radius 2 l, that is, than about eight loose balls
//   together, becomes outside;
// - a void (a closed part around a region of phi < 0 enclosed by the shell)
//   smaller than a ball of radius l becomes inside.
//
// Larger regions stay: the shell itself, the cavity it encloses, and parts of
// the model that are separate but not small. The surface decides (its parts
// are what a user sees and prints); the volume's phi is then flipped in the
// same regions (FlipRegion), so that contouring it gives the same surface.
#ifndef nvPieces_h
#define nvPieces_h

#include "nvGrid.h"
#include "nvParallel.h"
#include "nvSurface.h"

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

namespace nv
{

/// Union-find over n items (a surface's points, or any others), joined from
/// any thread. A root is only ever linked under a smaller index, so each
/// part's root ends as its smallest index, whichever thread joined first.
class PointParts
{
public:
  explicit PointParts(std::int64_t n)
    : Parent(new std::atomic<std::int64_t>[static_cast<std::size_t>(n)])
  {
    ParallelFor(0, n, Grain, [&](std::int64_t first, std::int64_t last) {
      for (std::int64_t p = first; p < last; ++p)
      {
        this->Parent[p].store(p, std::memory_order_relaxed);
      }
    });
  }

  std::int64_t Root(std::int64_t p)
  {
    for (;;)
    {
      std::int64_t parent = this->Parent[p].load();
      if (parent == p)
      {
        return p;
      }
      // Path halving: p skips to its grandparent (still an ancestor, as links
      // are never undone).
      const std::int64_t grandparent = this->Parent[parent].load();
      if (grandparent != parent)
      {
        this->Parent[p].compare_exchange_weak(parent, grandparent);
      }
      p = grandparent;
    }
  }

  void Join(std::int64_t a, std::int64_t b)
  {
    for (;;)
    {
      a = this->Root(a);
      b = this->Root(b);
      if (a == b)
      {
        return;
      }
      if (a < b)
      {
        std::swap(a, b);
      }
      // a, the larger root, under b, unless another thread linked a first.
      std::int64_t expected = a;
      if (this->Parent[a].compare_exchange_strong(expected, b))
      {
        return;
      }
    }
  }

  /// Once every Join is done: each point's parent becomes its root.
  void Flatten(std::int64_t n)
  {
    ParallelFor(0, n, Grain, [&](std::int64_t first, std::int64_t last) {
      for (std::int64_t p = first; p < last; ++p)
      {
        this->Parent[p].store(this->Root(p), std::memory_order_relaxed);
      }
    });
  }

  std::unique_ptr<std::atomic<std::int64_t>[]> Parent;

private:
  static constexpr std::int64_t Grain = 1 << 15; ///< items per task
};
/// A surface's points joined by its triangles (PointParts, flattened).
void JoinTriangles(const SurfaceArrays& surface, PointParts& parts);

/// The connected parts of a surface: each point's part, named by its
/// smallest point index.
std::vector<std::int64_t> SurfaceParts(const SurfaceArrays& surface);

struct RemovedPieces
{
  std::int64_t Pieces = 0; ///< loose pieces made outside
  std::int64_t Voids = 0;  ///< tiny voids made inside
  std::int64_t Cavities = 0; ///< voids kept: the cavities the shell encloses
  double Volume = 0.0;       ///< the kept surface's enclosed volume (pieces less cavities)
  double CavityVolume = 0.0; ///< the kept cavities' volume
  double VoidLimit = 0.0;    ///< the volume below which a void went
  std::int64_t KeptPieces = 0; ///< pieces kept: the separate parts of the solid
};

/// The volumes below which a part goes: a piece (a region inside the
/// surface) below Piece, a void (a region outside it that it encloses) below
/// Void, or, with VoidShare > 0, below that share of the largest void.
struct PieceLimits
{
  double Piece = 0.0;
  double Void = 0.0;
  double VoidShare = 0.0;
  bool SpareLargest = true; ///< when every piece is small, the largest stays
  /// Where set: a piece with a vertex where it is true stays, whatever its
  /// volume (the printing part's material that holds scan points it had
  /// lost, nvPrintPart.h).
  std::function<bool(const double* x)> Supported;
};

/// The volume below which a piece is removed: a ball of radius 2 l.
double SmallPieceVolume(double offset);
/// The volume below which a void is removed: a ball of radius l.
double SmallVoidVolume(double offset);

/**
 * Flips the sign of phi over the region of nodes of one sign (inside: phi >
 * 0, else phi <= 0) that a closed part of the surface encloses, so that no
 * phi = 0 surface is left there. `vertices` are the part's points (indices
 * into `points`, 3 doubles each); the region is the 6-connected nodes reached
 * from each vertex's grid-edge end on the region's side (all vertices, as the
 * region's nodes may touch only across a cell's diagonal). phi holds the node
 * layers [kBegin, kBegin + layers) of the grid. A region larger than
 * maximumVolume (it joins a large one through a node the surface does not
 * see) is left as it is; returns whether the region was flipped.
 */
bool FlipRegion(const Grid& grid, float* phi, std::int64_t kBegin, std::int64_t layers, const double* points,
  const std::vector<std::int64_t>& vertices, bool inside, double maximumVolume);

/**
 * Removes the small pieces and voids from the surface, in place: each
 * connected part bounds a region whose signed volume (divergence theorem,
 * normals out of the shell) is positive for a piece and negative for a void;
 * pieces below SmallPieceVolume and voids below SmallVoidVolume go (when
 * every piece is small, the largest stays: a tiny cloud's shell is all there
 * is). The kept points and triangles move to the front of the arrays, in
 * their order, and the counts shrink. phi (may be null), the dense phi of the
 * node layers [kBegin, kBegin + layers), is flipped in the same regions
 * (FlipRegion), so that contouring it gives the same surface.
 */
RemovedPieces RemoveSmallPieces(SurfaceArrays& surface, double offset, const Grid& grid, float* phi,
  std::int64_t kBegin, std::int64_t layers);

/// The same on the surface a sink received, in its own arrays.
RemovedPieces RemoveSmallPieces(SurfaceSink& sink, double offset, const Grid& grid, float* phi,
  std::int64_t kBegin, std::int64_t layers);

/// The same with other limits (the printing part's cavities, nvPrintPart.h).
RemovedPieces RemoveSmallPieces(SurfaceArrays& surface, const PieceLimits& limits, const Grid& grid, float* phi,
  std::int64_t kBegin, std::int64_t layers);
RemovedPieces RemoveSmallPieces(SurfaceSink& sink, const PieceLimits& limits, const Grid& grid, float* phi,
  std::int64_t kBegin, std::int64_t layers);

} // namespace nv

#endif
