// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The words a run and its callers use for the devices (nvEngine.h is the
// seam itself): which device ran, and where Device GPU's kernels run.
#ifndef nvDevices_h
#define nvDevices_h

namespace nv
{

/// The device that ran a job. The values are those of the field data
/// array DeviceUsed.
enum class DeviceKind
{
  CPU = 1,
  GPU = 2
};

/// Where Device GPU's kernels run: on the GPU (the CUDA launcher), or on
/// the host's threads through the host launcher (tests and benchmarks of
/// the device back end on machines without a GPU). Not a user setting.
enum class GpuKernels
{
  OnGpu,
  OnHost
};

} // namespace nv

#endif
