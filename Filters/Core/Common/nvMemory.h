// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// Memory the core's stages free in many small blocks, handed back to the
// system before the next stage allocates its large arrays.
#ifndef nvMemory_h
#define nvMemory_h

namespace nv
{
/**
 * Hands memory freed on any thread back to the system (glibc: malloc_trim;
 * elsewhere nothing). glibc keeps blocks freed in the middle of its heaps,
 * the main thread's and each worker thread's, and a later large array is
 * mapped beside them instead of reusing them: measured on the VolumeOff
 * test's sphere (6 M band nodes, 2 threads), 110 MB; on the 1024^3 sphere
 * (26.9 M band nodes), 195 MB at the peak when the band's per-brick lists
 * were freed and its neighbour indices made without one.
 */
void ReleaseFreedMemory();
} // namespace nv

#endif
