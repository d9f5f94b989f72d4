// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The discrete narrow band of section 3 and the paper's data structure box
// (collect, store, connect): the band nodes stored compactly, brick by brick, with their
// place in the brick, their distance and the indices of their six neighbours.
#ifndef nvNarrowBand_h
#define nvNarrowBand_h

#include "nvGrid.h"
#include "nvMemory.h"
#include "nvParameters.h"
#include "nvPartition.h"
#include "nvStageTimes.h"
#include "nvTruncatedDistance.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace nv
{
class Monitor;

/**
 * Band nodes s = 0 .. L-1. They are ordered for red-black Gauss-Seidel:
 * first the "red" nodes (i + j + k even), then the "black" ones, each colour
 * in brick order. A node's six neighbours all have the other colour.
 *
 * Neighbour indices point into a phi array of size L + 2: a neighbour that is
 * not a band node reads the Dirichlet value of eq. (5), slot L (1 - delta)
 * when the node's own phi0 > 0 and slot L + 1 (-1 + delta) otherwise, as in
 * the paper's band construction (its third step, our connect pass).
 */
struct NarrowBand
{
  Grid GridNodes;
  std::int64_t RedCount = 0;           ///< nodes [0, RedCount) are red
  /// Where band node s sits in its brick: i + 8 (j + 8 k) from the brick's
  /// first node (2 bytes a node; the brick gives the rest of the position).
  UninitializedVector<std::uint16_t> Offset;
  UninitializedVector<double> Distance;        ///< d of eq. (6) at band node s (+inf: beyond reach)
  UninitializedVector<std::uint32_t> Neighbor; ///< 6 per node: -x, +x, -y, +y, -z, +z

  /// The bricks visited (ascending brick index) and, per brick b, its red
  /// nodes [RedStart[b], RedStart[b+1]) and black ones [BlackStart[b], BlackStart[b+1]).
  std::vector<std::int64_t> Bricks;
  std::vector<std::int64_t> RedStart;
  std::vector<std::int64_t> BlackStart;

  /// Per brick of Bricks, BrickNodes / 64 words: bit i + 8 (j + 8 k) is set
  /// for a node off the band inside the shell (d <= l - eta/2, phi0 >= 1 -
  /// delta); every other node off the band is outside it. The side is all
  /// that the surface needs of those nodes (nvSurfaceField.h).
  std::vector<std::uint64_t> Inside;

  /// In a distributed run, the band covers this process's computed brick
  /// layers and it updates only the nodes of its owned ones (all of them in
  /// a serial run).
  LayerRange OwnedLayers;

  /// Set when the band would exceed Parameters::MaximumBandNodes: the band is
  /// then left empty, before its arrays are allocated.
  std::int64_t RefusedSize = 0;

  std::int64_t Size() const { return static_cast<std::int64_t>(this->Offset.size()); }
  std::uint32_t InsideSlot() const { return static_cast<std::uint32_t>(this->Size()); }
  std::uint32_t OutsideSlot() const { return static_cast<std::uint32_t>(this->Size() + 1); }

  /// The red band nodes [begin, end) (red = true) or black ones in the brick
  /// layers `layers`.
  void NodesInLayers(LayerRange layers, bool red, std::int64_t& begin, std::int64_t& end) const;
  /// The owned red nodes [begin, end) (red = true) or black ones (all of
  /// them in a band without brick tables).
  void OwnedNodes(bool red, std::int64_t& begin, std::int64_t& end) const;

  /// The first grid node (i, j, k) of brick Bricks[a].
  void BrickFirstNode(std::int64_t a, std::int64_t ijk[3]) const;
  /// The grid node (i, j, k) of band node s of the brick whose first node is `first`.
  void NodeIjk(const std::int64_t first[3], std::int64_t s, std::int64_t ijk[3]) const
  {
    NodeAtPlace(first, this->Offset[s], ijk);
  }
  /// The grid index of band node s, found by a search over the bricks (for
  /// checks and tests; passes over the band go brick by brick instead).
  std::int64_t GridIndex(std::int64_t s) const;
};

/// A value per band node (and the two Dirichlet slots), first written by
/// the parallel loop that computes it.
using BandValues = UninitializedVector<double>;

/// Largest band the 32-bit neighbour indices can address.
constexpr std::int64_t MaximumBandSize = 4294967295LL - 2;

/// Called with the distances of each brick computed (possibly from several
/// threads at once), for outputs that need them (nvVolume.h).
using BrickVisitor = std::function<void(std::int64_t brick, const double distance[BrickNodes])>;

/**
 * The distances of eq. (6) of batches of bricks, computed elsewhere than by
 * TruncatedDistance::ComputeBrick: by the device back end
 * (nvDeviceDistance.h), on the GPU or through its host launcher. A source
 * must give ComputeBrick's distances and BrickWithin's answers bit for bit,
 * so that the band is the one the CPU finds.
 */
class BrickDistanceSource
{
public:
  virtual ~BrickDistanceSource();
  /// The most bricks a call of Compute takes.
  virtual std::int64_t BatchSize() const = 0;
  /// Where the source sorted the points itself (the TruncatedDistance then
  /// has none): the bricks they reach, as TruncatedDistance::ReachedBricks.
  /// Null otherwise.
  virtual const std::vector<std::int64_t>* ReachedBricks() const { return nullptr; }
  /**
   * For the `count` bricks `bricks` (grid brick indices): covered[a] =
   * BrickWithin(bricks[a], coverRadius), or 0 for all when coverRadius is 0;
   * and for each brick not covered, distance[BrickNodes a + n] =
   * ComputeBrick(bricks[a])[n] (a covered brick's distances are left unset).
   */
  virtual void Compute(const std::int64_t* bricks, std::int64_t count, double coverRadius, double* distance,
    std::uint8_t* covered) = 0;

  /**
   * Whether the source builds the band's arrays itself, where its distances
   * are (CountNodes, StoreNodes, ConnectNeighbours: the collect, store and connect passes on the
   * device): only the counts, the Inside bits and Offset come to the band,
   * whose Distance and Neighbor then stay empty, held by the source's
   * device for the evolution (nvDeviceEvolution.h). Used where no visitor
   * wants the distances.
   */
  virtual bool BuildsBand() const { return false; }
  /**
   * The collect pass for the `count` bricks `bricks`, as CollectBandNodes does it from
   * Compute's distances, the band's nodes kept by the source: `red[a]`,
   * `black[a]`: brick a's band nodes of each colour; `inside`: 8 words a
   * brick, NarrowBand::Inside's. lower, upper: the band's bounds l -/+
   * eta/2; whole: every node of the grid is a band node
   * (Domain::WholeDomain).
   */
  virtual void CountNodes(const std::int64_t* bricks, std::int64_t count, double coverRadius, double lower,
    double upper, bool whole, std::int32_t* red, std::int32_t* black, std::uint64_t* inside);
  /// The store pass: the nodes CountNodes kept stored as NarrowBand's Offset and
  /// Distance (`size` nodes, the `redCount` red ones first); Offset into
  /// `offset` (size values).
  virtual void StoreNodes(std::int64_t redCount, std::int64_t size, std::uint16_t* offset);
  /// The connect pass: the band's neighbour table (as NarrowBand::Neighbor), from
  /// `band`'s Bricks, RedStart and BlackStart; l is `offsetDistance`.
  virtual void ConnectNeighbours(const NarrowBand& band, double offsetDistance);
};

/**
 * Finds the band nodes: in Domain::NarrowBand mode the nodes with
 * l - eta/2 < d < l + eta/2 (|phi0| < 1 - delta), in Domain::WholeDomain mode
 * every node of the grid. Returns an empty band if the monitor asks to stop.
 * part: in a distributed run, the layers this process computes and owns
 * (nvPartition.h); null for the whole grid. visitor: if set, also called
 * with the distances of every reached brick (none is skipped then). times:
 * if set, gets the seconds of steps 1 ("band: collect", the distances), 2
 * ("band: store"), and 3 ("band: index bricks", "band: neighbours"; by a
 * source that builds the band, "band: neighbours" only).
 * source: if set, the collect pass takes the distances from it, batch by batch,
 * instead of computing them on the host (the same band, bit for bit); and
 * where it builds the band (BuildsBand) and no visitor is set, the collect, store and connect passes
 * run there: the band's Distance and Neighbor are then the source's, not
 * the returned band's.
 */
NarrowBand BuildNarrowBand(const TruncatedDistance& distance, const Parameters& parameters,
  Monitor* monitor = nullptr, const Subdomain* part = nullptr, const BrickVisitor& visitor = nullptr,
  StageTimes* times = nullptr, BrickDistanceSource* source = nullptr);

} // namespace nv

#endif
