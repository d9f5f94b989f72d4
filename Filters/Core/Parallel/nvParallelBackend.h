// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// What nvParallel.cxx needs from a thread backend. Two implement it, one of
// which is compiled into the core: nvParallelVTK.cxx (vtkSMPTools) and
// nvParallelThreads.cxx (a pool of std::threads, no VTK).
#ifndef nvParallelBackend_h
#define nvParallelBackend_h

#include "nvParallel.h"

namespace nv
{
namespace backend
{
/// Whether a loop started on this thread now would run on more than one thread.
bool Concurrent();
/// Calls fn on the chunks [first, first + grain) of [begin, end) on the backend's threads.
void For(std::int64_t begin, std::int64_t end, std::int64_t grain, const RangeFunction& fn);
/// Runs body with loops on `threads` threads (0: all cores).
void Scope(int threads, const std::function<void()>& body);
} // namespace backend
} // namespace nv

#endif
