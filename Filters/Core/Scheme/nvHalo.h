// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The exchange of ghost-layer values between neighbouring slabs (nvPartition.h).
//
// A red half sweep changes only red nodes, and red nodes read only black
// neighbours (nvNarrowBand.h). So after the red half sweep each process sends
// the red values of its first and last owned brick layers to the processes
// that keep those layers as ghosts, and receives the red values of its own
// ghost layers; the same follows the black half sweep. Every owned node then
// reads the values a serial run would give it, and the result is the serial
// one. Both sides list a layer's band nodes in the same order (brick order,
// then grid index), so the values travel as plain arrays.
#ifndef nvHalo_h
#define nvHalo_h

#include "nvPartition.h"

#include <cstdint>
#include <vector>

namespace nv
{
class Communicator;
struct NarrowBand;

class Halo
{
public:
  /**
   * band: built on `part.Computed` (BuildNarrowBand). owners: the owned
   * layers of every process, as SplitLayers gives them (the same on all).
   */
  Halo(const NarrowBand& band, const Subdomain& part, const std::vector<LayerRange>& owners,
    Communicator& communicator);

  /// Checks with the neighbours that both sides agree on the sizes of the
  /// exchanged layers. Collective; false on every process if any disagrees.
  bool Agree();

  /// Sends the owned boundary values of one colour and receives the ghosts'.
  void Exchange(double* phi, bool red);

  /**
   * The same exchange for values kept per brick layer (count values a layer,
   * layer L at values + (L - firstLayer) * count): sends those of the owned
   * boundary layers, receives those of the ghost layers.
   */
  void ExchangeLayers(double* values, std::int64_t count, std::int64_t firstLayer);

  Communicator& GetCommunicator() { return this->Comm; }

private:
  struct Link
  {
    int Rank = -1;                     ///< the neighbouring process
    std::int64_t SendLayer = 0;        ///< the owned brick layer it keeps as a ghost
    std::int64_t ReceiveLayer = 0;     ///< the ghost brick layer it owns
    std::int64_t SendBegin[2] = {};    ///< [colour]: red 0, black 1
    std::int64_t SendEnd[2] = {};
    std::int64_t ReceiveBegin[2] = {};
    std::int64_t ReceiveEnd[2] = {};
  };
  /// Sends send, receives receive, over one link; the lower process sends first.
  void Swap(const Link& link, const double* send, std::int64_t sendCount, double* receive,
    std::int64_t receiveCount);

  Communicator& Comm;
  std::vector<Link> Links; ///< in the order that cannot deadlock (see the .cxx)
};

} // namespace nv

#endif
