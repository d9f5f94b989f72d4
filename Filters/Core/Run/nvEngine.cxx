// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nvEngine.h"

namespace nv
{
// The two engines (nvCpuEngine.cxx, nvDeviceEngine.cxx).
std::unique_ptr<Engine> MakeCpuEngine();
std::unique_ptr<Engine> MakeDeviceEngine(GpuKernels kernels, std::string& error);

Engine::~Engine() = default;

std::string DeviceCannot(const Settings& settings, bool distributed)
{
  if (settings.Device != ComputeDevice::GPU)
  {
    return std::string();
  }
  if (distributed)
  {
    return "Device GPU runs on one process only: choose Device CPU (or Automatic) for a distributed (MPI) run.";
  }
  if (settings.PreserveOffset)
  {
    return "Device GPU has no PreserveOffset yet: turn PreserveOffset off, or choose Device CPU.";
  }
  return std::string();
}

std::unique_ptr<Engine> MakeEngine(const Settings& settings, bool distributed, GpuKernels kernels, std::string& error)
{
  // Automatic is the CPU until the GPU's kernels pass scripts/test-gpu.sh on
  // a GPU (where they stand: doc/performance.md, "On a GPU").
  if (settings.Device != ComputeDevice::GPU)
  {
    return MakeCpuEngine();
  }
  error = DeviceCannot(settings, distributed);
  return error.empty() ? MakeDeviceEngine(kernels, error) : nullptr;
}

} // namespace nv
