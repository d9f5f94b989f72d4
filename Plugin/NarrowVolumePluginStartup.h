// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// What the plugin does when ParaView loads it (paraview_add_plugin's
// INITIALIZERS), besides registering its XML.
#ifndef NarrowVolumePluginStartup_h
#define NarrowVolumePluginStartup_h

/// 1. Loads the Python readers shipped below the plugin (python/)
///    (NarrowVolumeScanReaders.py: LAZ through laspy, E57 through pye57), so
///    that one LoadPlugin, or one Auto Load, gives every reader.
/// 2. Makes the Point Cloud Text Reader the default reader for *.xyz files
///    opened from the GUI, where ParaView's PLOT3D and molecular XYZ readers
///    claim the extension too: ParaView 5.11 chooses among readers only by
///    its "Default reader details" setting (Settings > Miscellaneous), and
///    otherwise asks the user each time. The entry goes into a settings
///    collection of lower priority than the site's and the user's, so a
///    user's own choice of default readers wins; the Settings dialog shows
///    the entry, and saves it only if the user applies the dialog.
/// 3. Starts the client's behaviours (NarrowVolumeClientBehaviors.h): the
///    panel's values of the last run, the camera on the shell in views that
///    showed nothing before.
/// Runs once per process, however often the plugin is loaded.
void NarrowVolumePluginStartup();

#endif
