// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nvControllerCommunicator.h"

#include "vtkCommunicator.h"
#include "vtkMultiProcessController.h"

namespace nv
{
namespace
{
constexpr int HaloTag = 61471; // messages of nvHalo, distinct from ParaView's own tags
}

ControllerCommunicator::ControllerCommunicator(vtkMultiProcessController* controller)
  : Controller(controller)
{
}

int ControllerCommunicator::Rank() const
{
  return this->Controller->GetLocalProcessId();
}

int ControllerCommunicator::Size() const
{
  return this->Controller->GetNumberOfProcesses();
}

void ControllerCommunicator::Send(int rank, const double* values, std::int64_t n)
{
  this->Controller->Send(values, static_cast<vtkIdType>(n), rank, HaloTag);
}

void ControllerCommunicator::Receive(int rank, double* values, std::int64_t n)
{
  this->Controller->Receive(values, static_cast<vtkIdType>(n), rank, HaloTag);
}

void ControllerCommunicator::MaxAll(double* values, int n)
{
  std::vector<double> in(values, values + n);
  this->Controller->AllReduce(in.data(), values, n, vtkCommunicator::MAX_OP);
}

void ControllerCommunicator::SumAll(double* values, int n)
{
  std::vector<double> in(values, values + n);
  this->Controller->AllReduce(in.data(), values, n, vtkCommunicator::SUM_OP);
}

std::vector<double> ExchangePoints(vtkMultiProcessController* controller, const std::vector<double>& xyz,
  const std::vector<std::array<double, 2>>& zRanges)
{
  const int size = controller->GetNumberOfProcesses();
  const int rank = controller->GetLocalProcessId();
  std::vector<double> mine;
  std::vector<double> send;
  for (int q = 0; q < size; ++q)
  {
    // One gather per destination: the points of every process that q needs.
    send.clear();
    for (std::size_t p = 0; p + 2 < xyz.size(); p += 3)
    {
      if (zRanges[q][0] <= xyz[p + 2] && xyz[p + 2] <= zRanges[q][1])
      {
        send.insert(send.end(), &xyz[p], &xyz[p] + 3);
      }
    }
    vtkIdType length = static_cast<vtkIdType>(send.size());
    std::vector<vtkIdType> lengths(static_cast<std::size_t>(size), 0);
    controller->Gather(&length, lengths.data(), 1, q);
    std::vector<vtkIdType> offsets(static_cast<std::size_t>(size), 0);
    vtkIdType total = 0;
    for (int r = 0; r < size; ++r)
    {
      offsets[r] = total;
      total += lengths[r];
    }
    if (rank == q)
    {
      mine.resize(static_cast<std::size_t>(total));
    }
    double empty = 0.0;
    controller->GatherV(send.empty() ? &empty : send.data(), mine.empty() ? &empty : mine.data(), length,
      lengths.data(), offsets.data(), q);
  }
  return mine;
}

} // namespace nv
