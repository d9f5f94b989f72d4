// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// What the user chooses: the filter's properties, as the core takes them.
//
// The fields, their types and defaults come from the property table,
// Python/_properties.py, through NV_SETTINGS (nvSettingsTable.h, which
// cmake/generate-properties.py writes; committed): one field per
// property, named as the property (OffsetDistance, Domain, Sheets, ...).
// The VTK filter and the Python filter of the wheel both keep their
// properties in one; a default-constructed one holds their defaults. The table
// says what each means; the code that uses a field says how.
#ifndef nvSettings_h
#define nvSettings_h

#include "nvParameters.h"    // Domain, EdgeStopping
#include "nvPrintSettings.h" // DrainAxis
#include "nvSettingsTable.h" // NV_SETTINGS, generated from the property table (committed)
#include "nvSheets.h"        // Sheets

#include <vector>

namespace nv
{

struct Settings
{
#define NV_SETTINGS_FIELD(Type, Name, Default) Type Name = Default;
  NV_SETTINGS(NV_SETTINGS_FIELD)
#undef NV_SETTINGS_FIELD

  /// Where the drain holes go (the VTK filter's DrainHolePositions, a list
  /// the panel edits as rows of x y z): x y z after one another, world
  /// units. Empty (the default): NumberOfDrainHoles at each cavity's lowest
  /// points. Not a row of the table, which holds single values.
  std::vector<double> DrainHolePositions;

  /// MemoryLimit in bytes (> 0).
  double MemoryLimitBytes() const;
  /// Bytes per node of the dense output piece: the arrays asked for and the
  /// isosurfacer's working memory; 0 with OutputVolume off.
  double OutputBytesPerNode() const;
};

} // namespace nv

#endif
