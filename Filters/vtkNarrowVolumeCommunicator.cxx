// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNarrowVolumeCommunicator.h"

#include "vtkCommunicator.h"
#include "vtkMultiProcessController.h"

#include <vector>

namespace
{
constexpr int HaloTag = 61471; // messages of the core, distinct from ParaView's own tags
}

vtkNarrowVolumeCommunicator::vtkNarrowVolumeCommunicator(vtkMultiProcessController* controller)
  : Controller(controller)
{
}

int vtkNarrowVolumeCommunicator::Rank() const
{
  return this->Controller->GetLocalProcessId();
}

int vtkNarrowVolumeCommunicator::Size() const
{
  return this->Controller->GetNumberOfProcesses();
}

void vtkNarrowVolumeCommunicator::Send(int rank, const double* values, std::int64_t n)
{
  this->Controller->Send(values, static_cast<vtkIdType>(n), rank, HaloTag);
}

void vtkNarrowVolumeCommunicator::Receive(int rank, double* values, std::int64_t n)
{
  this->Controller->Receive(values, static_cast<vtkIdType>(n), rank, HaloTag);
}

void vtkNarrowVolumeCommunicator::MaxAll(double* values, int n)
{
  std::vector<double> in(values, values + n);
  this->Controller->AllReduce(in.data(), values, n, vtkCommunicator::MAX_OP);
}

void vtkNarrowVolumeCommunicator::SumAll(double* values, int n)
{
  std::vector<double> in(values, values + n);
  this->Controller->AllReduce(in.data(), values, n, vtkCommunicator::SUM_OP);
}
