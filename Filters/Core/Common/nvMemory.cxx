// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nvMemory.h"

#include <cstdlib> // defines __GLIBC__ with glibc
#ifdef __GLIBC__
#include <malloc.h>
#endif

namespace nv
{
void ReleaseFreedMemory()
{
#ifdef __GLIBC__
  malloc_trim(0);
#endif
}
} // namespace nv
