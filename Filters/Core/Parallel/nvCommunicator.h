// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// What the scheme needs from the other processes of a distributed run:
// point-to-point messages for the ghost layers and global reductions for the
// stopping tests. The core only sees this interface; the VTK glue implements
// it with vtkMultiProcessController (MPI under ParaView).
#ifndef nvCommunicator_h
#define nvCommunicator_h

#include <cstdint>
#include <vector>

namespace nv
{

class Communicator
{
public:
  virtual ~Communicator();
  virtual int Rank() const = 0;
  virtual int Size() const = 0;
  /// Blocking send of n values to process `rank` (matched by its Receive).
  virtual void Send(int rank, const double* values, std::int64_t n) = 0;
  /// Blocking receive of n values from process `rank`.
  virtual void Receive(int rank, double* values, std::int64_t n) = 0;
  /// Element-wise maximum over all processes, in place.
  virtual void MaxAll(double* values, int n) = 0;
  /// Element-wise sum over all processes, in place.
  virtual void SumAll(double* values, int n) = 0;

  double MaxAll(double value)
  {
    this->MaxAll(&value, 1);
    return value;
  }

  /// Collective: process `root` gets every process's values, in rank order;
  /// the others get nothing. Built on Send and Receive (the root only
  /// receives, so blocking sends cannot deadlock).
  std::vector<double> Gather(const std::vector<double>& values, int root);
  /// Collective: every process sends outgoing[q] to process q (one entry per
  /// process); returns what reached this one, in rank order (one Gather per
  /// destination).
  std::vector<double> Exchange(const std::vector<std::vector<double>>& outgoing);
};

} // namespace nv

#endif
