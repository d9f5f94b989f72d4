// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nvHalo.h"

#include "nvCommunicator.h"
#include "nvNarrowBand.h"

namespace nv
{

Halo::Halo(const NarrowBand& band, const Subdomain& part, const std::vector<LayerRange>& owners,
  Communicator& communicator)
  : Comm(communicator)
{
  const int rank = communicator.Rank();
  auto ownerOf = [&](std::int64_t layer) {
    for (std::size_t p = 0; p < owners.size(); ++p)
    {
      if (owners[p].Contains(layer))
      {
        return static_cast<int>(p);
      }
    }
    return -1;
  };
  auto makeLink = [&](int neighbour, std::int64_t ownLayer, std::int64_t ghostLayer) {
    Link link;
    link.Rank = neighbour;
    link.SendLayer = ownLayer;
    link.ReceiveLayer = ghostLayer;
    for (int colour = 0; colour < 2; ++colour)
    {
      band.NodesInLayers(LayerRange{ ownLayer, ownLayer + 1 }, colour == 0, link.SendBegin[colour],
        link.SendEnd[colour]);
      band.NodesInLayers(LayerRange{ ghostLayer, ghostLayer + 1 }, colour == 0, link.ReceiveBegin[colour],
        link.ReceiveEnd[colour]);
    }
    return link;
  };
  if (part.Owned.Empty())
  {
    return;
  }
  std::vector<Link> below, above;
  const int lower = ownerOf(part.Owned.Begin - 1);
  if (lower >= 0)
  {
    below.push_back(makeLink(lower, part.Owned.Begin, part.Owned.Begin - 1));
  }
  const int upper = ownerOf(part.Owned.End);
  if (upper >= 0)
  {
    above.push_back(makeLink(upper, part.Owned.End - 1, part.Owned.End));
  }
  // The slabs form a chain. Processes at even positions in it serve their
  // upper link first, those at odd positions their lower link first, so the
  // two ends of every link serve it at the same time: two rounds, no deadlock.
  int position = 0;
  for (int p = 0; p < rank && p < static_cast<int>(owners.size()); ++p)
  {
    position += owners[p].Empty() ? 0 : 1;
  }
  this->Links = position % 2 == 0 ? above : below;
  for (const Link& link : (position % 2 == 0 ? below : above))
  {
    this->Links.push_back(link);
  }
}

void Halo::Swap(const Link& link, const double* send, std::int64_t sendCount, double* receive,
  std::int64_t receiveCount)
{
  if (this->Comm.Rank() < link.Rank)
  {
    this->Comm.Send(link.Rank, send, sendCount);
    this->Comm.Receive(link.Rank, receive, receiveCount);
  }
  else
  {
    this->Comm.Receive(link.Rank, receive, receiveCount);
    this->Comm.Send(link.Rank, send, sendCount);
  }
}

bool Halo::Agree()
{
  bool agree = true;
  for (const Link& link : this->Links)
  {
    const double mine[4] = { double(link.SendEnd[0] - link.SendBegin[0]),
      double(link.SendEnd[1] - link.SendBegin[1]), double(link.ReceiveEnd[0] - link.ReceiveBegin[0]),
      double(link.ReceiveEnd[1] - link.ReceiveBegin[1]) };
    double theirs[4];
    this->Swap(link, mine, 4, theirs, 4);
    agree = agree && mine[0] == theirs[2] && mine[1] == theirs[3] && mine[2] == theirs[0] && mine[3] == theirs[1];
  }
  return this->Comm.MaxAll(agree ? 0.0 : 1.0) == 0.0;
}

void Halo::Exchange(double* phi, bool red)
{
  const int colour = red ? 0 : 1;
  for (const Link& link : this->Links)
  {
    this->Swap(link, phi + link.SendBegin[colour], link.SendEnd[colour] - link.SendBegin[colour],
      phi + link.ReceiveBegin[colour], link.ReceiveEnd[colour] - link.ReceiveBegin[colour]);
  }
}

void Halo::ExchangeLayers(double* values, std::int64_t count, std::int64_t firstLayer)
{
  for (const Link& link : this->Links)
  {
    this->Swap(link, values + (link.SendLayer - firstLayer) * count, count,
      values + (link.ReceiveLayer - firstLayer) * count, count);
  }
}

} // namespace nv
