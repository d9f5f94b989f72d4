// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// Whether a hole of the sampling that the gap closing left open
// (nvGapClosing.h) pierces the evolved shell, read on the grid.
//
// The gap closing measures holes in the points; whether the shell has a
// tunnel there is decided by the evolution (eq. 10-12): the balls of the
// rim's points may cover a hole off its plane, a hole may leave only a
// sealed pocket inside the wall, and a disc between two parts of the model
// (a crevice) opens to one side only. So after the evolution, for each disc
// of a hole (its centre lies on the sampled surface, with the normal of the
// tangent plane there): the hole pierces the wall when the field is
// negative (outside the shell) at the centre and that outside region,
// within the box of half-width R + 2 l + h around it (R the hole's radius),
// reaches past the wall on both sides of the surface: nodes farther than
// l + h from the tangent plane, above it and below it. There the outer and
// inner sheets join.
#ifndef nvHoleProbe_h
#define nvHoleProbe_h

#include "nvGapClosing.h"
#include "nvGrid.h"

#include <array>

namespace nv
{
class BrickField;

/// Whether the outside region of `field` (values < 0) at the centre of
/// `disc` (world coordinates) reaches farther than `wall` from its tangent
/// plane on both sides, within the box of half-width `reach` around it.
bool TunnelThrough(const BrickField& field, const Grid& grid, const Hole& disc, double wall, double reach);

/// Whether `hole` pierces the shell of `field` at one of its discs' centres
/// for which `probed(disc)` is true (a distributed run probes its own).
template <typename Probed>
bool Pierces(const BrickField& field, const Grid& grid, const OpenHole& hole, double offset, Probed&& probed)
{
  const double reach = hole.Radius + 2.0 * offset + grid.Spacing;
  for (const Hole& disc : hole.Discs)
  {
    if (probed(disc) && TunnelThrough(field, grid, disc, offset + grid.Spacing, reach))
    {
      return true;
    }
  }
  return false;
}

} // namespace nv

#endif
