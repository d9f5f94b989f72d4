// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// A process-wide pool of std::threads that share a loop's chunks with the
// calling thread. The core's loops run on it in the Python wheel
// (nvParallelThreads.cxx), and in the VTK build where vtkSMPTools' STDThread
// backend would otherwise start new threads for every loop
// (nvParallelVTK.cxx).
#ifndef nvThreadPool_h
#define nvThreadPool_h

#include "nvParallel.h"

namespace nv
{
/**
 * Calls fn on the chunks [first, first + grain) of [begin, end) on `threads`
 * threads: the caller and threads - 1 workers of the pool (started when a
 * loop first needs them, kept for the life of the process). A loop started
 * while another thread's loop holds the pool, or from inside a loop, runs on
 * the calling thread alone. Exceptions thrown by fn reach the caller.
 */
void PoolFor(std::int64_t begin, std::int64_t end, std::int64_t grain, int threads, const RangeFunction& fn);

/// Whether the calling thread is computing a chunk of a PoolFor loop.
bool InPoolLoop();
} // namespace nv

#endif
