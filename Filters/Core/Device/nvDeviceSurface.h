// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// Step 7 by the device back end: the phi = 0 surface of the band made by the
// surface kernels (Device/nvSurfaceKernels.h) through a launcher, on the GPU
// or, for the tests and machines without one, over the host's threads. The
// same surface as ContourBricks on the band's BandField (nvSurface.h): the
// host launcher gives its vertices, normals and triangles bit for bit
// (TestCoreDevice); on a GPU the vertices may differ in the last bits.
//
// What runs where: the list of cut bricks (the band's bricks where psi
// varies and the bricks just below them, marked and listed in ascending
// order), the per-brick and per-cell work (psi from phi, the corners'
// signs, the cut edges, the vertices and normals, the triangles) in the
// kernels; on the host, the sums of the chunks' marks while the cut bricks
// are listed, the sums of the counts (each cut brick's first vertex and
// triangle) between, and the sink's arrays after. Serial runs only, as the
// device back end.
#ifndef nvDeviceSurface_h
#define nvDeviceSurface_h

#include "nvDeviceLauncher.h"
#include "nvGrid.h"
#include "nvNarrowBand.h"
#include "nvParameters.h"
#include "nvSurface.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace nv
{

/// The cut bricks of a band, ascending: its bricks where the implied
/// distance varies (band nodes, or nodes on both sides of the shell) and
/// the bricks just below them on any axis, whose cells reach their first
/// nodes (nvSurface.cxx's CutBricks, over the whole grid at once; the
/// bricks where psi varies: UniformBandBrick, nvSurfaceField.h). On one
/// host thread with a sort: the list the launchers' CutBricks make with
/// kernels, which TestCoreDevice compares with it.
std::vector<std::int64_t> CutBricksOf(const NarrowBand& band);

/// Checks that `bytes` more fit on the device for `stage` (throws if not):
/// the device engine's free-memory check.
using MemoryCheck = std::function<void(double bytes, const std::string& stage)>;

/**
 * The surface of `band` with phi `phi` (L + 2 values; may be empty where
 * the launcher still holds the evolution's) into `sink`, by `launcher`'s
 * kernels: the vertices first (ids from 0, bricks in ascending order, each
 * brick's cut edges in order), then the triangles. With `check`, what the
 * tables and then the outputs need on the device (SurfaceTableBytes, the
 * largest slab's outputs) is checked before each is allocated. Throws
 * device::DeviceError when the device fails (the sink may then hold part of
 * the surface: the caller truncates it).
 */
void ContourOnDevice(const Grid& grid, const NarrowBand& band, const BandValues& phi, const Parameters& parameters,
  device::SurfaceLauncher& launcher, SurfaceSink& sink, const MemoryCheck& check = MemoryCheck());

} // namespace nv

#endif
