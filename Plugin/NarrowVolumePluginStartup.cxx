// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "NarrowVolumePluginStartup.h"

#include "NarrowVolumeClientBehaviors.h"

#include "vtkNew.h"
#include "vtkPVPluginLoader.h"
#include "vtkPVVersion.h"
#include "vtkSMPropertyHelper.h"
#include "vtkSMProxy.h"
#include "vtkSMProxyManager.h"
#include "vtkSMSessionProxyManager.h"
#include "vtkSMSettings.h"

#if NARROWVOLUME_WITH_PYTHON && (PARAVIEW_VERSION_MAJOR < 5 || (PARAVIEW_VERSION_MAJOR == 5 && PARAVIEW_VERSION_MINOR < 12))
#include "vtkPythonInterpreter.h"
#define NARROWVOLUME_GETARGSPEC_SHIM 1
#endif

// The "Default reader details" setting belongs to the settings proxy
// RepresentedArrayListSettings in ParaView 5.11 and to IOSettings from 5.12
// on, where ParaView's File > Open looks it up.
#if PARAVIEW_VERSION_MAJOR < 5 || (PARAVIEW_VERSION_MAJOR == 5 && PARAVIEW_VERSION_MINOR < 12)
#define NARROWVOLUME_READER_SETTINGS "RepresentedArrayListSettings"
#else
#define NARROWVOLUME_READER_SETTINGS "IOSettings"
#endif

#include <vtksys/SystemTools.hxx>

#include <dlfcn.h>
#include <string>

namespace
{
/// The priority of the plugin's settings: below the site settings (1.0) and
/// the user's (VTK_DOUBLE_MAX), which ParaView loads at start-up.
constexpr double SettingsPriority = 0.5;

// The entries of the "Default reader details" setting, three strings each:
// file patterns, the description of the file type, the reader's proxy name.
// .xyz: ParaView's PLOT3D and XYZ readers claim it too; .ply: ParaView's PLY
// reader, which the plugin's replaces (it checks the file first).
const char* const DefaultReaders[6] = { "*.xyz", "Point Cloud Text Files (x y z)", "ASCIIPointCloudReader",
  "*.ply", "PLY Files (checked)", "PLYPointCloudReader" };
const char* const DefaultReadersSetting = R"json({
  "settings": {
    ")json" NARROWVOLUME_READER_SETTINGS R"json(": {
      "ReaderDetails": ["*.xyz", "Point Cloud Text Files (x y z)", "ASCIIPointCloudReader",
                        "*.ply", "PLY Files (checked)", "PLYPointCloudReader"]
    }
  }
})json";

/// The settings proxy that the Settings dialog edits, if this process has
/// one already (a client whose session exists).
vtkSMProxy* ReaderSettingsProxy()
{
  if (!vtkSMProxyManager::IsInitialized())
  {
    return nullptr;
  }
  vtkSMSessionProxyManager* proxies = vtkSMProxyManager::GetProxyManager()->GetActiveSessionProxyManager();
  return proxies ? proxies->GetProxy("settings", NARROWVOLUME_READER_SETTINGS) : nullptr;
}

/// The folder of the shared library this function is in: the plugin's.
std::string PluginFolder()
{
  Dl_info info;
  if (dladdr(reinterpret_cast<void*>(&NarrowVolumePluginStartup), &info) == 0 || !info.dli_fname)
  {
    return std::string();
  }
  return vtksys::SystemTools::GetFilenamePath(vtksys::SystemTools::CollapseFullPath(info.dli_fname));
}
} // namespace

void NarrowVolumePluginStartup()
{
  static bool started = false;
  if (started)
  {
    return;
  }
  started = true;
  StartClientBehaviors();

  const std::string readers = PluginFolder() + "/python/NarrowVolumeScanReaders.py";
  if (vtksys::SystemTools::FileExists(readers, true))
  {
#ifdef NARROWVOLUME_GETARGSPEC_SHIM
    // ParaView 5.11's paraview.detail.pythonalgorithm, which every Python
    // plugin goes through, imports inspect.getargspec, which Python 3.11
    // removed (Debian 12 pairs the two): without this no Python plugin
    // loads there. getfullargspec's result has the .args it uses.
    // ParaView 5.12 stopped using getargspec.
    vtkPythonInterpreter::RunSimpleString("import inspect\n"
                                          "if not hasattr(inspect, 'getargspec'):\n"
                                          "    inspect.getargspec = inspect.getfullargspec\n");
#endif
    // Through ParaView's own loader: the Python readers become a plugin of
    // their own (NarrowVolumeScanReaders) in the plugin manager. Without
    // Python in this ParaView it fails quietly and only they are missing.
    vtkNew<vtkPVPluginLoader> loader;
    loader->LoadPluginSilently(readers.c_str());
  }

  vtkSMSettings::GetInstance()->AddCollectionFromString(DefaultReadersSetting, SettingsPriority);
  // A settings proxy created before this reads its values from the settings
  // then, without the entry; ParaView writes the proxy's values back over the
  // user's settings whenever the Settings dialog is applied, and an empty list
  // there would hide the entry for good. So the proxy shows the entry too,
  // and applying the dialog keeps it (saving it with the user's settings).
  // Only the server-manager property is set: pushing it to the VTK object
  // would make ParaView save the settings at once.
  if (vtkSMProxy* proxy = ReaderSettingsProxy())
  {
    vtkSMPropertyHelper details(proxy, "ReaderDetails", /*quiet=*/true);
    if (details.GetNumberOfElements() == 0)
    {
      for (unsigned int k = 0; k < 6; ++k)
      {
        details.Set(k, DefaultReaders[k]);
      }
    }
  }
}
