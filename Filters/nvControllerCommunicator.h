// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The core's Communicator (Core/nvCommunicator.h) on a vtkMultiProcessController,
// and the redistribution of the points between processes, for the distributed
// run of vtkNarrowVolumeReconstruction under MPI.
#ifndef nvControllerCommunicator_h
#define nvControllerCommunicator_h

#include "nvCommunicator.h"

#include <array>
#include <vector>

class vtkMultiProcessController;

namespace nv
{

class ControllerCommunicator : public Communicator
{
public:
  explicit ControllerCommunicator(vtkMultiProcessController* controller);
  int Rank() const override;
  int Size() const override;
  void Send(int rank, const double* values, std::int64_t n) override;
  void Receive(int rank, double* values, std::int64_t n) override;
  void MaxAll(double* values, int n) override;
  void SumAll(double* values, int n) override;
  using Communicator::MaxAll;

private:
  vtkMultiProcessController* Controller;
};

/**
 * Every process gets the points (xyz triples) of all processes whose z lies
 * in its interval zRanges[rank] = {zmin, zmax}; returns this process's.
 * Collective.
 */
std::vector<double> ExchangePoints(vtkMultiProcessController* controller, const std::vector<double>& xyz,
  const std::vector<std::array<double, 2>>& zRanges);

} // namespace nv

#endif
