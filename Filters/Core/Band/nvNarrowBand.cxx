// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nvNarrowBand.h"

#include "nvMemory.h"
#include "nvParallel.h"
#include "nvTruncatedDistance.h"

#include <algorithm>
#include <stdexcept>
#include <cmath>

namespace nv
{

namespace
{

/// Visits the band nodes of one brick whose distances `d` are known, in
/// ascending grid index: fn(n, red, d), n = i + 8 (j + 8 k) in the brick;
/// sets the bits of its other nodes inside the shell in `inside` (cleared
/// by the caller). nvBandTerms.h's ClassifyBrick, as the device's
/// BandCountKernel and BandCompactKernel.
template <typename Fn>
void ClassifyBrickNodes(const TruncatedDistance& distance, const Parameters& parameters, std::int64_t brick,
  const double d[BrickNodes], std::uint64_t inside[BrickNodes / 64], Fn&& fn)
{
  BandBounds bounds;
  bounds.Whole = parameters.Domain == Domain::WholeDomain;
  bounds.Lower = parameters.OffsetDistance - parameters.HalfBandWidth();
  bounds.Upper = distance.GetReach();
  std::int64_t first[3];
  distance.BrickFirstNode(brick, first);
  ClassifyBrick(distance.GetGrid().Dims.data(), first, d, bounds, inside, fn);
}

/// Whether the collect pass may skip the bricks that BrickWithin(brick, lower) finds
/// deep inside the shell (none is skipped in whole domain mode, nor when
/// the visitor wants every brick's distances).
bool SkipsCoveredBricks(const Parameters& parameters, const BrickVisitor& visitor)
{
  return parameters.Domain != Domain::WholeDomain && !visitor;
}

/// Visits the band nodes of one brick in ascending grid index (as
/// ClassifyBrickNodes), computing its distances here. Marks the brick's other nodes inside the shell in `inside`, and hands
/// its distances to `visitor`, if any.
template <typename Fn>
void ForEachBandNode(const TruncatedDistance& distance, const Parameters& parameters, std::int64_t brick,
  const BrickVisitor& visitor, double scratch[BrickNodes], std::uint64_t inside[BrickNodes / 64], Fn&& fn)
{
  const double lower = parameters.OffsetDistance - parameters.HalfBandWidth();
  const bool covered = SkipsCoveredBricks(parameters, visitor) && distance.BrickWithin(brick, lower);
  ResetInside(inside, covered);
  if (covered)
  {
    return; // d <= l - eta/2 on the whole brick (deep inside the shell): no band node
  }
  distance.ComputeBrick(brick, scratch);
  if (visitor)
  {
    visitor(brick, scratch);
  }
  ClassifyBrickNodes(distance, parameters, brick, scratch, inside, fn);
}

} // namespace

void NarrowBand::NodesInLayers(LayerRange layers, bool red, std::int64_t& begin, std::int64_t& end) const
{
  const std::int64_t bricksPerLayer = ((this->GridNodes.Dims[0] + BrickSize - 1) >> BrickShift) *
    ((this->GridNodes.Dims[1] + BrickSize - 1) >> BrickShift);
  std::int64_t first, last;
  BricksInLayers(this->Bricks, bricksPerLayer, layers.Begin, layers.End, first, last);
  const std::vector<std::int64_t>& start = red ? this->RedStart : this->BlackStart;
  begin = start[first];
  end = start[last];
}

void NarrowBand::BrickFirstNode(std::int64_t a, std::int64_t ijk[3]) const
{
  const std::int64_t brickDims[3] = { (this->GridNodes.Dims[0] + BrickSize - 1) >> BrickShift,
    (this->GridNodes.Dims[1] + BrickSize - 1) >> BrickShift, 0 }; // the layers' count is not read
  FirstNodeOf(brickDims, this->Bricks[a], ijk);
}

std::int64_t NarrowBand::GridIndex(std::int64_t s) const
{
  // The last brick whose range of s's colour starts at or before s.
  const std::vector<std::int64_t>& start = s < this->RedCount ? this->RedStart : this->BlackStart;
  const std::int64_t a = (std::upper_bound(start.begin(), start.end(), s) - start.begin()) - 1;
  std::int64_t first[3], ijk[3];
  this->BrickFirstNode(a, first);
  this->NodeIjk(first, s, ijk);
  return this->GridNodes.Index(ijk[0], ijk[1], ijk[2]);
}

void NarrowBand::OwnedNodes(bool red, std::int64_t& begin, std::int64_t& end) const
{
  if (this->RedStart.empty()) // a band without brick tables: all of it is owned
  {
    begin = red ? 0 : this->RedCount;
    end = red ? this->RedCount : this->Size();
    return;
  }
  this->NodesInLayers(this->OwnedLayers, red, begin, end);
}

namespace
{

/// One band node of a brick while the band is built: its place in the brick
/// and its distance.
struct BandEntry
{
  std::uint16_t Offset;
  double Distance;
};

/// The band nodes of one brick, red and black apart, in ascending grid index.
struct BrickBand
{
  std::vector<BandEntry> Red, Black;
};

/// The collect pass: the bricks to visit, in the computed layers: those the points
/// reach (as `source` found them, where it sorted the points, else as
/// `distance` finds them). Whole domain mode visits all of them.
std::vector<std::int64_t> BricksToVisit(const TruncatedDistance& distance, const Parameters& parameters,
  const Subdomain& part, const BrickDistanceSource* source)
{
  const std::int64_t bricksPerLayer = distance.GetBrickDims()[0] * distance.GetBrickDims()[1];
  std::vector<std::int64_t> bricks;
  if (parameters.Domain == Domain::WholeDomain)
  {
    for (std::int64_t b = part.Computed.Begin * bricksPerLayer; b < part.Computed.End * bricksPerLayer; ++b)
    {
      bricks.push_back(b);
    }
  }
  else
  {
    std::vector<std::int64_t> found;
    const std::vector<std::int64_t>* reached = source ? source->ReachedBricks() : nullptr;
    if (!reached)
    {
      found = distance.ReachedBricks();
      reached = &found;
    }
    for (std::int64_t b : *reached)
    {
      if (part.Computed.Contains(b / bricksPerLayer))
      {
        bricks.push_back(b);
      }
    }
  }
  return bricks;
}

/// The collect pass, continued: the distances brick by brick, band.Bricks' band nodes
/// into perBrick (a transient list that grows with the band) and the other
/// nodes inside the shell into band.Inside. False if the monitor stopped it.
bool CollectBandNodes(const TruncatedDistance& distance, const Parameters& parameters, Monitor* monitor,
  const BrickVisitor& visitor, NarrowBand& band, std::vector<BrickBand>& perBrick)
{
  const std::int64_t numberOfBricks = static_cast<std::int64_t>(band.Bricks.size());
  perBrick.resize(static_cast<std::size_t>(numberOfBricks));
  band.Inside.resize(static_cast<std::size_t>(numberOfBricks * BrickNodes / 64));
  return MonitoredFor(0, numberOfBricks, 16, monitor, [&](std::int64_t begin, std::int64_t end) {
    double scratch[BrickNodes];
    for (std::int64_t a = begin; a < end; ++a)
    {
      BrickBand& out = perBrick[a];
      ForEachBandNode(distance, parameters, band.Bricks[a], visitor, scratch, &band.Inside[a * BrickNodes / 64],
        [&](int n, bool red, double d) {
          (red ? out.Red : out.Black).push_back(BandEntry{ static_cast<std::uint16_t>(n), d });
        });
    }
  });
}

/// fn(done, count) for the batches [done, done + count) of `numberOfBricks`
/// bricks, `batch` at most each, with the monitor's progress after each;
/// false if the monitor stopped it.
template <typename Fn>
bool ForEachBatch(std::int64_t numberOfBricks, std::int64_t batch, Monitor* monitor, const Fn& fn)
{
  for (std::int64_t done = 0; done < numberOfBricks; done += batch)
  {
    if (monitor && monitor->Aborted())
    {
      return false;
    }
    const std::int64_t count = std::min(batch, numberOfBricks - done);
    fn(done, count);
    if (monitor)
    {
      monitor->Progress(static_cast<double>(done + count) / numberOfBricks);
    }
  }
  return !(monitor && monitor->Aborted());
}

/// The collect pass, continued, with the distances from `source` (the device back
/// end), batch by batch: the same band nodes and Inside bits as
/// CollectBandNodes when the source gives ComputeBrick's and BrickWithin's
/// results. False if the monitor stopped it.
bool CollectBandNodesFrom(BrickDistanceSource& source, const TruncatedDistance& distance,
  const Parameters& parameters, Monitor* monitor, const BrickVisitor& visitor, NarrowBand& band,
  std::vector<BrickBand>& perBrick)
{
  const std::int64_t numberOfBricks = static_cast<std::int64_t>(band.Bricks.size());
  perBrick.resize(static_cast<std::size_t>(numberOfBricks));
  band.Inside.resize(static_cast<std::size_t>(numberOfBricks * BrickNodes / 64));
  const double lower = parameters.OffsetDistance - parameters.HalfBandWidth();
  const double coverRadius = SkipsCoveredBricks(parameters, visitor) ? lower : 0.0;
  const std::int64_t batch = std::max<std::int64_t>(1, std::min(source.BatchSize(), numberOfBricks));
  UninitializedVector<double> d(static_cast<std::size_t>(batch * BrickNodes));
  std::vector<std::uint8_t> covered(static_cast<std::size_t>(batch));
  return ForEachBatch(numberOfBricks, batch, monitor, [&](std::int64_t done, std::int64_t count) {
    source.Compute(&band.Bricks[done], count, coverRadius, d.data(), covered.data());
    ParallelFor(0, count, 16, [&](std::int64_t begin, std::int64_t end) {
      for (std::int64_t c = begin; c < end; ++c)
      {
        const std::int64_t a = done + c;
        std::uint64_t* inside = &band.Inside[a * BrickNodes / 64];
        const double* brickDistance = &d[c * BrickNodes];
        ResetInside(inside, covered[c] != 0);
        if (covered[c])
        {
          continue; // d <= l - eta/2 on the whole brick, as ForEachBandNode
        }
        if (visitor)
        {
          visitor(band.Bricks[a], brickDistance);
        }
        BrickBand& out = perBrick[a];
        ClassifyBrickNodes(distance, parameters, band.Bricks[a], brickDistance, inside,
          [&](int n, bool red, double dn) {
            (red ? out.Red : out.Black).push_back(BandEntry{ static_cast<std::uint16_t>(n), dn });
          });
      }
    });
  });
}

/// The store pass's tables from each brick's counts of red and black band nodes
/// (red(a), black(a)): band.RedCount, band.RedStart and band.BlackStart,
/// the black nodes after all the red ones. Returns the band's size.
template <typename Red, typename Black>
std::int64_t SetStarts(std::int64_t numberOfBricks, const Red& red, const Black& black, NarrowBand& band)
{
  band.RedStart.assign(static_cast<std::size_t>(numberOfBricks + 1), 0);
  band.BlackStart.assign(static_cast<std::size_t>(numberOfBricks + 1), 0);
  for (std::int64_t a = 0; a < numberOfBricks; ++a)
  {
    band.RedStart[a + 1] = band.RedStart[a] + red(a);
    band.BlackStart[a + 1] = band.BlackStart[a] + black(a);
  }
  band.RedCount = band.RedStart[numberOfBricks];
  for (std::int64_t& start : band.BlackStart)
  {
    start += band.RedCount;
  }
  return band.BlackStart[numberOfBricks];
}

/// Whether a band of `size` nodes is over the limits (32-bit neighbour
/// indices, Parameters::MaximumBandNodes).
bool TooLarge(std::int64_t size, const Parameters& parameters)
{
  return size > MaximumBandSize || (parameters.MaximumBandNodes >= 0 && size > parameters.MaximumBandNodes);
}

/// The store pass: the band nodes stored compactly, red ones first, in brick order
/// (band.Offset, band.Distance, band.RedStart, band.BlackStart), perBrick
/// emptied. Returns 0; or, when the band is over the limit, its size, and
/// nothing is stored.
std::int64_t StoreBandNodes(std::vector<BrickBand>& perBrick, const Parameters& parameters, NarrowBand& band)
{
  const std::int64_t numberOfBricks = static_cast<std::int64_t>(perBrick.size());
  const std::int64_t size = SetStarts(
    numberOfBricks, [&](std::int64_t a) { return static_cast<std::int64_t>(perBrick[a].Red.size()); },
    [&](std::int64_t a) { return static_cast<std::int64_t>(perBrick[a].Black.size()); }, band);
  if (TooLarge(size, parameters))
  {
    return size;
  }
  const std::vector<std::int64_t>& redStart = band.RedStart;
  const std::vector<std::int64_t>& blackStart = band.BlackStart;
  band.Offset.resize(static_cast<std::size_t>(size));
  band.Distance.resize(static_cast<std::size_t>(size));
  ParallelFor(0, numberOfBricks, 64, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t a = begin; a < end; ++a)
    {
      std::int64_t s = redStart[a];
      for (const BandEntry& e : perBrick[a].Red)
      {
        band.Offset[s] = e.Offset;
        band.Distance[s++] = e.Distance;
      }
      s = blackStart[a];
      for (const BandEntry& e : perBrick[a].Black)
      {
        band.Offset[s] = e.Offset;
        band.Distance[s++] = e.Distance;
      }
    }
  });
  std::vector<BrickBand>().swap(perBrick);
  return 0;
}

/// What the connect pass knows of the band's bricks: for each, the bricks across its
/// six faces (slots in band.Bricks, -1 for none); for each brick holding band
/// nodes, a 512-bit mask of them and each one's rank among the brick's nodes
/// of its colour (a byte a place, at most 256 of a colour).
struct BrickIndex
{
  static constexpr int Words = BrickNodes / 64;
  std::vector<std::int32_t> Adjacent;  ///< 6 per brick
  std::vector<std::int32_t> BandBrick; ///< per brick: its number among those holding nodes, or -1
  UninitializedVector<std::uint64_t> Occupied; ///< Words per brick holding nodes
  UninitializedVector<std::uint8_t> Rank;      ///< BrickNodes per brick holding nodes (where Occupied)

  /// Whether node q of band brick b (a slot in band.Bricks, -1: none) is a band node.
  bool Holds(std::int64_t b, int q) const
  {
    const std::int32_t t = b >= 0 ? this->BandBrick[b] : -1;
    return t >= 0 && ((this->Occupied[static_cast<std::size_t>(t) * Words + q / 64] >> (q % 64)) & 1);
  }
};

BrickIndex IndexBricks(const TruncatedDistance& distance, const NarrowBand& band)
{
  const std::int64_t numberOfBricks = static_cast<std::int64_t>(band.Bricks.size());
  BrickIndex index;
  // Each grid brick's slot in band.Bricks (-1: none), written on all
  // threads (a 4096^3 grid has 134 million bricks).
  const std::int64_t gridBricks = distance.GetNumberOfBricks();
  UninitializedVector<std::int32_t> slotOfBrick(static_cast<std::size_t>(gridBricks));
  ParallelFor(0, gridBricks, 1 << 16, [&](std::int64_t begin, std::int64_t end) {
    std::fill(slotOfBrick.begin() + begin, slotOfBrick.begin() + end, -1);
  });
  ParallelFor(0, numberOfBricks, 1 << 12, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t a = begin; a < end; ++a)
    {
      slotOfBrick[band.Bricks[a]] = static_cast<std::int32_t>(a);
    }
  });
  index.BandBrick.resize(static_cast<std::size_t>(numberOfBricks));
  std::int32_t bandBricks = 0;
  for (std::int64_t a = 0; a < numberOfBricks; ++a)
  {
    const bool holdsNodes =
      band.RedStart[a + 1] > band.RedStart[a] || band.BlackStart[a + 1] > band.BlackStart[a];
    index.BandBrick[a] = holdsNodes ? bandBricks++ : -1;
  }
  index.Adjacent.resize(static_cast<std::size_t>(6 * numberOfBricks));
  // Cleared brick by brick below, on the threads that fill them.
  index.Occupied.resize(static_cast<std::size_t>(bandBricks) * BrickIndex::Words);
  index.Rank.resize(static_cast<std::size_t>(bandBricks) * BrickNodes);
  const auto& brickDims = distance.GetBrickDims();
  ParallelFor(0, numberOfBricks, 64, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t a = begin; a < end; ++a)
    {
      std::int64_t at[3];
      BrickAt(brickDims.data(), band.Bricks[a], at);
      for (int direction = 0; direction < 6; ++direction)
      {
        // The slot of the brick across the face (the device's
        // AdjacentBricksKernel finds it by a binary search of band.Bricks).
        const std::int64_t next = AdjacentBrick(brickDims.data(), at, direction);
        index.Adjacent[6 * a + direction] = next >= 0 ? slotOfBrick[next] : -1;
      }
      const std::int64_t t = index.BandBrick[a];
      if (t >= 0)
      {
        std::fill(index.Occupied.begin() + t * BrickIndex::Words, index.Occupied.begin() + (t + 1) * BrickIndex::Words,
          std::uint64_t(0));
      }
      for (const auto* start : { &band.RedStart, &band.BlackStart })
      {
        for (std::int64_t s = (*start)[a]; s < (*start)[a + 1]; ++s)
        {
          const int n = band.Offset[s];
          index.Occupied[t * BrickIndex::Words + n / 64] |= std::uint64_t(1) << (n % 64);
          index.Rank[t * BrickNodes + n] = static_cast<std::uint8_t>(s - (*start)[a]);
        }
      }
    }
  });
  return index;
}

/// The connect pass: each band node's six neighbours (band.Neighbor): a neighbour's
/// index is the start of its colour in its brick plus its rank, found within
/// the node's brick or the one across the face it lies on; a neighbour off
/// the band is the Dirichlet value of the node's side (eq. 5).
void ConnectNeighbours(const BrickIndex& index, const Parameters& parameters, NarrowBand& band)
{
  const std::int64_t numberOfBricks = static_cast<std::int64_t>(band.Bricks.size());
  band.Neighbor.resize(6 * band.Offset.size());
  const double offset = parameters.OffsetDistance;
  const std::int64_t size = band.Size();
  ParallelFor(0, numberOfBricks, 16, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t a = begin; a < end; ++a)
    {
      for (const bool red : { true, false })
      {
        // The neighbours have the other colour.
        const std::vector<std::int64_t>& own = red ? band.RedStart : band.BlackStart;
        const std::vector<std::int64_t>& other = red ? band.BlackStart : band.RedStart;
        for (std::int64_t s = own[a]; s < own[a + 1]; ++s)
        {
          const int n = band.Offset[s];
          // phi0 > 0 exactly when d < l (eq. 2): InsideSlot, else OutsideSlot.
          const std::uint32_t dirichlet = DirichletSlot(band.Distance[s], offset, size);
          for (int direction = 0; direction < 6; ++direction)
          {
            // Place n -/+ 1, 8 or 64 in this brick, or a side's length back
            // in the brick across the face the node lies on.
            bool across = false;
            const int q = NeighbourPlace(n, direction, across);
            const std::int64_t b = across ? index.Adjacent[6 * a + direction] : a;
            band.Neighbor[6 * s + direction] = index.Holds(b, q)
              ? static_cast<std::uint32_t>(
                  other[b] + index.Rank[static_cast<std::size_t>(index.BandBrick[b]) * BrickNodes + q])
              : dirichlet;
          }
        }
      }
    }
  });
}

/// The collect, store and connect passes where `source` builds the band (the device back end): the
/// collect pass's counts and Inside bits come back batch by batch, the store pass's tables are
/// made here from the counts and the source stores the nodes (band.Offset
/// comes back), the connect pass is the source's. band.Distance and band.Neighbor stay
/// empty. Returns false if the monitor stopped it; sets band.RefusedSize,
/// and stores nothing, when the band is over the limit.
bool BuildBandOnSource(BrickDistanceSource& source, const TruncatedDistance& distance,
  const Parameters& parameters, Monitor* monitor, StageTimes& times, NarrowBand& band)
{
  const std::int64_t numberOfBricks = static_cast<std::int64_t>(band.Bricks.size());
  band.Inside.resize(static_cast<std::size_t>(numberOfBricks * BrickNodes / 64));
  std::vector<std::int32_t> red(static_cast<std::size_t>(numberOfBricks));
  std::vector<std::int32_t> black(static_cast<std::size_t>(numberOfBricks));
  const double lower = parameters.OffsetDistance - parameters.HalfBandWidth();
  const bool whole = parameters.Domain == Domain::WholeDomain;
  const double coverRadius = SkipsCoveredBricks(parameters, nullptr) ? lower : 0.0;
  const std::int64_t batch = std::max<std::int64_t>(1, std::min(source.BatchSize(), numberOfBricks));
  // The collect pass: the distances and each brick's band nodes, counted.
  const bool collected = times.Time("band: collect", [&]() {
    return ForEachBatch(numberOfBricks, batch, monitor, [&](std::int64_t done, std::int64_t count) {
      source.CountNodes(&band.Bricks[done], count, coverRadius, lower, distance.GetReach(), whole, &red[done],
        &black[done], &band.Inside[done * BrickNodes / 64]);
    });
  });
  if (!collected)
  {
    return false;
  }
  // The store pass: stored compactly, unless the band is too large.
  const std::int64_t size = times.Time("band: store", [&]() {
    const std::int64_t nodes = SetStarts(
      numberOfBricks, [&](std::int64_t a) { return red[a]; }, [&](std::int64_t a) { return black[a]; }, band);
    if (!TooLarge(nodes, parameters))
    {
      band.Offset.resize(static_cast<std::size_t>(nodes));
      source.StoreNodes(band.RedCount, nodes, band.Offset.data());
    }
    return nodes;
  });
  if (TooLarge(size, parameters))
  {
    band.RefusedSize = size;
    return true;
  }
  // The connect pass: each node's six neighbours.
  times.Time("band: neighbours", [&]() { source.ConnectNeighbours(band, parameters.OffsetDistance); });
  return true;
}

/// The collect, store and connect passes on the host, from the distances computed here (or taken
/// from `source`, batch by batch). Returns false if the monitor stopped it;
/// sets band.RefusedSize, and stores nothing, when the band is over the
/// limit.
bool BuildBandOnHost(const TruncatedDistance& distance, const Parameters& parameters, Monitor* monitor,
  const BrickVisitor& visitor, BrickDistanceSource* source, StageTimes& times, NarrowBand& band)
{
  std::vector<BrickBand> perBrick;
  if (!times.Time("band: collect", [&]() {
        return source ? CollectBandNodesFrom(*source, distance, parameters, monitor, visitor, band, perBrick)
                      : CollectBandNodes(distance, parameters, monitor, visitor, band, perBrick);
      }))
  {
    return false;
  }
  // The store pass: stored compactly, unless the band is too large.
  band.RefusedSize = times.Time("band: store", [&]() { return StoreBandNodes(perBrick, parameters, band); });
  if (band.RefusedSize > 0)
  {
    return true;
  }
  ReleaseFreedMemory(); // before the neighbour indices, the band's largest array
  // The connect pass: each node's six neighbours.
  const BrickIndex index = times.Time("band: index bricks", [&]() { return IndexBricks(distance, band); });
  times.Time("band: neighbours", [&]() { ConnectNeighbours(index, parameters, band); });
  return true;
}

} // namespace

BrickDistanceSource::~BrickDistanceSource() = default;

void BrickDistanceSource::CountNodes(
  const std::int64_t*, std::int64_t, double, double, double, bool, std::int32_t*, std::int32_t*, std::uint64_t*)
{
  throw std::logic_error("BrickDistanceSource::CountNodes: this source does not build the band");
}

void BrickDistanceSource::StoreNodes(std::int64_t, std::int64_t, std::uint16_t*)
{
  throw std::logic_error("BrickDistanceSource::StoreNodes: this source does not build the band");
}

void BrickDistanceSource::ConnectNeighbours(const NarrowBand&, double)
{
  throw std::logic_error("BrickDistanceSource::ConnectNeighbours: this source does not build the band");
}

NarrowBand BuildNarrowBand(const TruncatedDistance& distance, const Parameters& parameters, Monitor* monitor,
  const Subdomain* part, const BrickVisitor& visitor, StageTimes* times, BrickDistanceSource* source)
{
  StageTimes untimed;
  times = times ? times : &untimed;
  NarrowBand band;
  band.GridNodes = distance.GetGrid();
  const Subdomain whole = Subdomain::Whole(distance.GetBrickDims()[2]);
  if (!part)
  {
    part = &whole;
  }
  // The collect pass: the bricks to visit; then their band nodes (collect, store, connect).
  band.Bricks = BricksToVisit(distance, parameters, *part, source);
  const bool built = source && source->BuildsBand() && !visitor
    ? BuildBandOnSource(*source, distance, parameters, monitor, *times, band)
    : BuildBandOnHost(distance, parameters, monitor, visitor, source, *times, band);
  if (!built)
  {
    return NarrowBand{};
  }
  if (band.RefusedSize > 0)
  {
    NarrowBand refused;
    refused.RefusedSize = band.RefusedSize;
    return refused;
  }
  band.OwnedLayers = part->Owned;
  if (monitor)
  {
    monitor->Progress(1.0);
  }
  return band;
}

} // namespace nv
