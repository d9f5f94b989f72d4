// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The core's threads from vtkSMPTools (the VTK build), so that the filter and
// VTK's own filters in the same pipeline share one set of threads.
#include "nvParallelBackend.h"

#include <vtkSMPTools.h>

#include <string>

namespace nv
{
namespace backend
{

bool Concurrent()
{
  // A parallel region costs tens of microseconds in VTK 9.2's STDThread
  // backend, even with one thread: with one, the caller loops itself.
  return vtkSMPTools::GetEstimatedNumberOfThreads() > 1;
}

void For(std::int64_t begin, std::int64_t end, std::int64_t grain, const RangeFunction& fn)
{
  vtkSMPTools::For(begin, end, grain, [&fn](std::int64_t first, std::int64_t last) { fn(first, last); });
}

void Scope(int threads, const std::function<void()>& body)
{
  std::string name = vtkSMPTools::GetBackend() ? vtkSMPTools::GetBackend() : "Sequential";
  if (name == "Sequential")
  {
    name = "STDThread";
  }
  vtkSMPTools::LocalScope(vtkSMPTools::Config{ threads, name, false }, body);
}

} // namespace backend
} // namespace nv
