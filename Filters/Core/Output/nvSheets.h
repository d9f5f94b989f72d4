// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// Which sheets of the phi = 0 surface to keep. The region phi < 0 splits into
// the exterior (connected to the grid's boundary) and cavities (enclosed by
// the shell). The outer sheet faces the exterior, the inner sheets face the
// cavities: for a closed input surface they are its dilation and its erosion
// by the offset distance.
#ifndef nvSheets_h
#define nvSheets_h

#include "nvGrid.h"

namespace nv
{
class Monitor;


enum class Sheets
{
  Both = 0,
  Outer = 1,
  Inner = 2,
  Scan = 3 ///< no sheet: the surface on the scan (nvScanSurface.h)
};

/**
 * Rewrites phi (one value per grid node) so that contouring it at 0 gives
 * only the chosen sheets: cavities are filled (set to +1) to drop the inner
 * sheets, or the exterior is (to drop the outer sheet). Both: no change.
 * Returns the number of cavity nodes (phi < 0, not reachable from the
 * grid's boundary): 0 when the shell encloses nothing, as around an open
 * scan whose two sheets join at its rim; -1 for Both (and Scan, which is
 * no sheet: phi unchanged), or when the monitor
 * (may be null) asked to stop the search (phi is then unchanged).
 */
std::int64_t KeepSheets(const Grid& grid, float* phi, Sheets which, Monitor* monitor = nullptr);

} // namespace nv

#endif
