// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// What the client does for the filter beyond running it: the panel's
// values of the last run, and a camera on the shell.
#ifndef NarrowVolumeClientBehaviors_h
#define NarrowVolumeClientBehaviors_h

/// From this call on, in this process (the GUI client, pvpython, pvbatch):
/// 1. After each run of a NarrowVolumeReconstruction proxy, its read-only
///    properties (OffsetDistanceUsed, SampleSpacingUsed, ...: what the run
///    chose) are fetched, so the panel shows them after Apply and Python
///    reads them after UpdatePipeline().
/// 2. ParaView frames the camera when the first visible dataset is shown in
///    a view. A point cloud without cells (a PLY of points) is visible but
///    draws nothing, so the view keeps an empty framing, and after Apply the
///    shell shows as a sliver or not at all. So when a render view first
///    shows an output of the filter and none of its other visible
///    representations draws anything (no cells, and not Point Gaussian),
///    the camera is reset on the output's bounds, and the filter's input, if
///    it is one of those representations, is shown as Point Gaussian discs
///    (a fifth of the offset used) so that the cloud shows too. Views that
///    already show something keep their camera and representations.
/// Both watch the server manager, not the Qt client. Runs once per process.
void StartClientBehaviors();

#endif
