// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "NarrowVolumeClientBehaviors.h"

#include "vtkCommand.h"
#include "vtkNew.h"
#include "vtkPVDataInformation.h"
#include "vtkSMPropertyHelper.h"
#include "vtkSMProxyIterator.h"
#include "vtkSMProxyManager.h"
#include "vtkSMSessionProxyManager.h"
#include "vtkSMSourceProxy.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <cmath>
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

/// The data a representation shows: its input's, at its output port (what
/// the server manager knows, without the views' module).
vtkPVDataInformation* DataOf(vtkSMProxy* representation)
{
  auto* producer = vtkSMSourceProxy::SafeDownCast(ProducerOf(representation));
  if (!producer)
  {
    return nullptr;
  }
  const unsigned int port = vtkSMPropertyHelper(representation, "Input", /*quiet=*/true).GetOutputPort();
  return port < producer->GetNumberOfOutputPorts() ? producer->GetDataInformation(port) : nullptr;
}

bool Visible(vtkSMProxy* representation)
{
  return representation->GetProperty("Visibility") &&
    vtkSMPropertyHelper(representation, "Visibility", /*quiet=*/true).GetAsInt() != 0;
}

/// Whether a representation puts something on the screen: visible, and its
/// data has cells (Point Gaussian draws points without cells too).
bool Draws(vtkSMProxy* representation)
{
  if (!representation || !Visible(representation))
  {
    return false;
  }
  if (representation->GetProperty("Representation"))
  {
    const char* type = vtkSMPropertyHelper(representation, "Representation", /*quiet=*/true).GetAsString();
    if (type && std::strcmp(type, "Point Gaussian") == 0)
    {
      return true;
    }
  }
  vtkPVDataInformation* data = DataOf(representation);
  return data && data->GetNumberOfCells() > 0;
}

/// Frames a render view's camera on `bounds` as ParaView's Reset Camera
/// does (vtkRenderer::ResetCamera): the same direction of view, the focal
/// point at the centre, the whole box in the view angle.
void FrameCamera(vtkSMProxy* view, const double bounds[6])
{
  double center[3], position[3], focal[3], direction[3];
  double radius = 0.0;
  for (int axis = 0; axis < 3; ++axis)
  {
    center[axis] = 0.5 * (bounds[2 * axis] + bounds[2 * axis + 1]);
    radius += 0.25 * (bounds[2 * axis + 1] - bounds[2 * axis]) * (bounds[2 * axis + 1] - bounds[2 * axis]);
  }
  radius = std::sqrt(radius);
  radius = radius > 0.0 ? radius : 0.5;
  vtkSMPropertyHelper(view, "CameraPosition").Get(position, 3);
  vtkSMPropertyHelper(view, "CameraFocalPoint").Get(focal, 3);
  double length = 0.0;
  for (int axis = 0; axis < 3; ++axis)
  {
    direction[axis] = position[axis] - focal[axis];
    length += direction[axis] * direction[axis];
  }
  length = std::sqrt(length);
  if (!(length > 0.0))
  {
    direction[0] = direction[1] = 0.0;
    direction[2] = length = 1.0;
  }
  const double pi = 3.14159265358979323846;
  const double angle = vtkSMPropertyHelper(view, "CameraViewAngle", /*quiet=*/true).GetAsDouble();
  const double distance = radius / std::sin(0.5 * (angle > 0.0 ? angle : 30.0) * pi / 180.0);
  for (int axis = 0; axis < 3; ++axis)
  {
    position[axis] = center[axis] + direction[axis] / length * distance;
  }
  vtkSMPropertyHelper(view, "CameraFocalPoint").Set(center, 3);
  vtkSMPropertyHelper(view, "CameraPosition").Set(position, 3);
  vtkSMPropertyHelper(view, "CameraParallelScale", /*quiet=*/true).Set(radius);
  vtkSMPropertyHelper(view, "CenterOfRotation", /*quiet=*/true).Set(center, 3);
  view->UpdateVTKObjects();
}

/// The filter's input, where the view shows it and it draws nothing (points
/// without cells), as Point Gaussian discs of a fifth of the offset used.
void ShowInputAsPoints(vtkSMProxy* view, vtkSMProxy* filter)
{
  vtkSMProxy* input = vtkSMPropertyHelper(filter, "Input", /*quiet=*/true).GetAsProxy();
  const double offset = vtkSMPropertyHelper(filter, "OffsetDistanceUsed", /*quiet=*/true).GetAsDouble();
  if (!input || !(offset > 0.0))
  {
    return;
  }
  vtkSMPropertyHelper representations(view, "Representations");
  for (unsigned int i = 0; i < representations.GetNumberOfElements(); ++i)
  {
    vtkSMProxy* representation = representations.GetAsProxy(i);
    if (!representation || ProducerOf(representation) != input || !representation->GetProperty("GaussianRadius") ||
      !Visible(representation) || Draws(representation))
    {
      continue;
    }
    vtkPVDataInformation* data = DataOf(representation);
    if (data && data->GetNumberOfPoints() > 0)
    {
      vtkSMPropertyHelper(representation, "Representation").Set("Point Gaussian");
      vtkSMPropertyHelper(representation, "GaussianRadius").Set(0.2 * offset);
      vtkSMPropertyHelper(representation, "ShaderPreset", /*quiet=*/true).Set("Plain circle");
      representation->UpdateVTKObjects();
    }
  }
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
    // The views and filters made before the plugin loaded.
    vtkNew<vtkSMProxyIterator> registered;
    registered->SetSessionProxyManager(proxies);
    registered->SetModeToOneGroup();
    for (registered->Begin("views"); !registered->IsAtEnd(); registered->Next())
    {
      this->WatchView(registered->GetProxy());
    }
    for (registered->Begin("sources"); !registered->IsAtEnd(); registered->Next())
    {
      this->WatchFilter(registered->GetProxy());
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
      this->RepresentationsChanged(vtkSMProxy::SafeDownCast(caller));
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
    // Render views: those with a camera (ParaView's RenderView and its kin).
    if (proxy && proxy->GetProperty("CameraPosition") && proxy->GetProperty("Representations") &&
      this->WatchedViews.insert(proxy->GetGlobalID()).second)
    {
      proxy->AddObserver(vtkCommand::PropertyModifiedEvent, this);
    }
  }

  /// A representation was added to (or removed from) the view: when it is
  /// the view's first of the filter's outputs and nothing else draws,
  /// frame the camera on that output.
  void RepresentationsChanged(vtkSMProxy* view)
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
    ShowInputAsPoints(view, source);
    double bounds[6];
    source->GetDataInformation(0)->GetBounds(bounds);
    if (bounds[0] <= bounds[1] && bounds[2] <= bounds[3] && bounds[4] <= bounds[5])
    {
      FrameCamera(view, bounds);
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
