// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// Memory the core's stages free in many small blocks, handed back to the
// system before the next stage allocates its large arrays.
#ifndef nvMemory_h
#define nvMemory_h

#include <memory>
#include <new>
#include <utility>
#include <vector>

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

/// std::allocator, but resize() leaves new values unset instead of zeroing
/// them: the band's and the solver's arrays are first written by parallel
/// loops, so each thread touches (and the kernel places) its own pages, and
/// no single thread zeroes gigabytes first.
template <typename T>
struct UninitializedAllocator : std::allocator<T>
{
  template <typename U>
  struct rebind
  {
    using other = UninitializedAllocator<U>;
  };
  UninitializedAllocator() = default;
  template <typename U>
  UninitializedAllocator(const UninitializedAllocator<U>&) noexcept
  {
  }
  template <typename U>
  void construct(U* p) noexcept
  {
    ::new (static_cast<void*>(p)) U;
  }
  template <typename U, typename... Args>
  void construct(U* p, Args&&... args)
  {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};
/// A vector whose resize() leaves its new values unset (UninitializedAllocator).
template <typename T>
using UninitializedVector = std::vector<T, UninitializedAllocator<T>>;

/// Frees a vector's memory (clear() keeps it).
template <typename Vector>
void Free(Vector& v)
{
  Vector().swap(v);
}
} // namespace nv

#endif
