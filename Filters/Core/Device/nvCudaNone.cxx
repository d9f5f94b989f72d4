// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// A build without CUDA (NARROWVOLUME_CUDA off, or no CUDA compiler found):
// no CUDA launcher; the host launcher still runs the device back end.
#include "nvDeviceLauncher.h"

namespace nv
{
namespace device
{

bool CudaCompiled()
{
  return false;
}

std::unique_ptr<Launcher> MakeCudaLauncher(std::string& why)
{
  why = "this build of NarrowVolume has no CUDA (it was built without a CUDA compiler: see NARROWVOLUME_CUDA)";
  return nullptr;
}

} // namespace device
} // namespace nv
