// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// NV_HD: a function the host and the GPU both run. Under nvcc it is
// __host__ __device__; for the host compiler, nothing. The kernels of the
// device back end (Device/nvDeviceKernels.h) and the points' sort
// (Band/nvPointSort.h), which the CPU core runs too, are written with it.
#ifndef nvHostDevice_h
#define nvHostDevice_h

#if defined(__CUDACC__)
#define NV_HD __host__ __device__
#else
#define NV_HD
#endif

#endif
