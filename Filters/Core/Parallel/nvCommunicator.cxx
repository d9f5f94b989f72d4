// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nvCommunicator.h"

namespace nv
{

Communicator::~Communicator() = default;

std::vector<double> Communicator::Gather(const std::vector<double>& values, int root)
{
  if (this->Rank() != root)
  {
    const double length = static_cast<double>(values.size());
    this->Send(root, &length, 1);
    if (!values.empty())
    {
      this->Send(root, values.data(), static_cast<std::int64_t>(values.size()));
    }
    return {};
  }
  std::vector<double> all;
  for (int rank = 0; rank < this->Size(); ++rank)
  {
    if (rank == root)
    {
      all.insert(all.end(), values.begin(), values.end());
      continue;
    }
    double length = 0.0;
    this->Receive(rank, &length, 1);
    const std::size_t offset = all.size();
    all.resize(offset + static_cast<std::size_t>(length));
    if (length > 0.0)
    {
      this->Receive(rank, all.data() + offset, static_cast<std::int64_t>(length));
    }
  }
  return all;
}

std::vector<double> Communicator::Exchange(const std::vector<std::vector<double>>& outgoing)
{
  std::vector<double> mine;
  for (int q = 0; q < this->Size(); ++q)
  {
    std::vector<double> gathered = this->Gather(outgoing[static_cast<std::size_t>(q)], q);
    if (q == this->Rank())
    {
      mine.swap(gathered);
    }
  }
  return mine;
}

} // namespace nv
