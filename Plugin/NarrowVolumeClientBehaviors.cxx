// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "NarrowVolumeClientBehaviors.h"

#include "vtkCommand.h"
#include "vtkNew.h"
#include "vtkPVDataInformation.h"
#include "vtkSMPropertyHelper.h"
#include "vtkSMProxyIterator.h"
#include "vtkSMProxyManager.h"
#include "vtkSMRenderViewProxy.h"
#include "vtkSMRepresentationProxy.h"
#include "vtkSMSessionProxyManager.h"
#include "vtkSMSourceProxy.h"
#include "vtkSmartPointer.h"

#include <cstring>
#include <set>

namespace
{
/// The producer of a representation (its Input), or null.
vtkSMProxy* ProducerOf(vtkSMProxy* representation)
{
  if (!representation || !representation->GetProperty("Input"))
  {
    return nullptr;
  }
  return vtkSMPropertyHelper(representation, "Input", /*quiet=*/true).GetAsProxy();
}

bool IsNarrowVolume(vtkSMProxy* proxy)
{
  return proxy && proxy->GetXMLName() && std::strcmp(proxy->GetXMLName(), "NarrowVolumeReconstruction") == 0;
}

/// Whether a representation puts something on the screen: visible, and its
/// data has cells (Point Gaussian draws points without cells too).
bool Draws(vtkSMProxy* proxy)
{
  auto* representation = vtkSMRepresentationProxy::SafeDownCast(proxy);
  if (!representation || vtkSMPropertyHelper(proxy, "Visibility", /*quiet=*/true).GetAsInt() == 0)
  {
    return false;
  }
  if (proxy->GetProperty("Representation"))
  {
    const char* type = vtkSMPropertyHelper(proxy, "Representation", /*quiet=*/true).GetAsString();
    if (type && std::strcmp(type, "Point Gaussian") == 0)
    {
      return true;
    }
  }
  vtkPVDataInformation* data = representation->GetRepresentedDataInformation();
  return data && data->GetNumberOfCells() > 0;
}

/// Watches the session proxy managers (for new filters and render views),
/// the filters' runs and every render view's Representations (for the
/// filter's outputs shown there).
class Watcher : public vtkCommand
{
public:
  static Watcher* New() { return new Watcher; }

  void Watch(vtkSMSessionProxyManager* proxies)
  {
    if (!proxies || this->WatchedManagers.count(proxies))
    {
      return;
    }
    this->WatchedManagers.insert(proxies);
    proxies->AddObserver(vtkCommand::RegisterEvent, this);
    vtkNew<vtkSMProxyIterator> views;
    views->SetSessionProxyManager(proxies);
    views->SetModeToOneGroup();
    for (views->Begin("views"); !views->IsAtEnd(); views->Next())
    {
      this->WatchView(views->GetProxy());
    }
    vtkNew<vtkSMProxyIterator> sources;
    sources->SetSessionProxyManager(proxies);
    sources->SetModeToOneGroup();
    for (sources->Begin("sources"); !sources->IsAtEnd(); sources->Next())
    {
      this->WatchFilter(sources->GetProxy());
    }
  }

  void Execute(vtkObject* caller, unsigned long event, void* data) override
  {
    if (event == vtkSMProxyManager::ActiveSessionChanged)
    {
      this->Watch(vtkSMProxyManager::GetProxyManager()->GetActiveSessionProxyManager());
    }
    else if (event == vtkCommand::RegisterEvent && data)
    {
      auto* info = static_cast<vtkSMProxyManager::RegisteredProxyInformation*>(data);
      if (info->Type == vtkSMProxyManager::RegisteredProxyInformation::PROXY && info->GroupName)
      {
        if (std::strcmp(info->GroupName, "views") == 0)
        {
          this->WatchView(info->Proxy);
        }
        else if (std::strcmp(info->GroupName, "sources") == 0)
        {
          this->WatchFilter(info->Proxy);
        }
      }
    }
    else if (event == vtkCommand::UpdateDataEvent && caller)
    {
      // The run's choices, for the panel and for Python.
      static_cast<vtkSMProxy*>(caller)->UpdatePropertyInformation();
    }
    else if (event == vtkCommand::PropertyModifiedEvent && data &&
      std::strcmp(static_cast<const char*>(data), "Representations") == 0)
    {
      this->RepresentationsChanged(vtkSMRenderViewProxy::SafeDownCast(caller));
    }
  }

private:
  void WatchFilter(vtkSMProxy* proxy)
  {
    if (IsNarrowVolume(proxy) && this->WatchedFilters.insert(proxy->GetGlobalID()).second)
    {
      proxy->AddObserver(vtkCommand::UpdateDataEvent, this);
    }
  }

  void WatchView(vtkSMProxy* proxy)
  {
    if (vtkSMRenderViewProxy::SafeDownCast(proxy) && this->WatchedViews.insert(proxy->GetGlobalID()).second)
    {
      proxy->AddObserver(vtkCommand::PropertyModifiedEvent, this);
    }
  }

  /// A representation was added to (or removed from) the view: when it is
  /// the view's first of the filter's outputs and nothing else draws,
  /// frame the camera on that output.
  void RepresentationsChanged(vtkSMRenderViewProxy* view)
  {
    if (!view)
    {
      return;
    }
    vtkSMPropertyHelper representations(view, "Representations");
    vtkSMProxy* shown = nullptr;
    bool somethingElseDraws = false;
    for (unsigned int i = 0; i < representations.GetNumberOfElements(); ++i)
    {
      vtkSMProxy* representation = representations.GetAsProxy(i);
      vtkSMProxy* producer = ProducerOf(representation);
      if (!IsNarrowVolume(producer))
      {
        somethingElseDraws = somethingElseDraws || Draws(representation);
      }
      else if (this->Framed.insert(representation->GetGlobalID()).second && !shown)
      {
        shown = producer;
      }
    }
    auto* source = vtkSMSourceProxy::SafeDownCast(shown);
    if (!source || somethingElseDraws || source->GetNumberOfOutputPorts() < 1)
    {
      return;
    }
    double bounds[6];
    source->GetDataInformation(0)->GetBounds(bounds);
    if (bounds[0] <= bounds[1] && bounds[2] <= bounds[3] && bounds[4] <= bounds[5])
    {
      view->ResetCamera(bounds);
    }
  }

  std::set<vtkSMSessionProxyManager*> WatchedManagers;
  std::set<vtkTypeUInt32> WatchedViews;
  std::set<vtkTypeUInt32> WatchedFilters;
  std::set<vtkTypeUInt32> Framed; // the representations already seen
};
} // namespace

void StartClientBehaviors()
{
  static bool started = false;
  if (started || !vtkSMProxyManager::IsInitialized())
  {
    return;
  }
  started = true;
  static vtkSmartPointer<Watcher> watcher = vtkSmartPointer<Watcher>::New();
  vtkSMProxyManager* manager = vtkSMProxyManager::GetProxyManager();
  manager->AddObserver(vtkSMProxyManager::ActiveSessionChanged, watcher);
  watcher->Watch(manager->GetActiveSessionProxyManager());
}
