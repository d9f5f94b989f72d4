// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The core's Communicator (Core/nvCommunicator.h) on a vtkMultiProcessController,
// for the distributed run of vtkNarrowVolumeReconstruction under MPI.
#ifndef vtkNarrowVolumeCommunicator_h
#define vtkNarrowVolumeCommunicator_h

#include "nvCommunicator.h"

class vtkMultiProcessController;

class vtkNarrowVolumeCommunicator : public nv::Communicator
{
public:
  explicit vtkNarrowVolumeCommunicator(vtkMultiProcessController* controller);
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

#endif
