// Defaults of the ParaView plugin that its server-manager XML cannot express, registered when
// ParaView loads the plugin library.
#include "vtkCallbackCommand.h"
#include "vtkNew.h"
#include "vtkPVDataInformation.h"
#include "vtkPVXMLElement.h"
#include "vtkSMOutputPort.h"
#include "vtkSMPropertyHelper.h"
#include "vtkSMProxyManager.h"
#include "vtkSMSettings.h"
#include "vtkSMSourceProxy.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace
{
// The colour map of SiteId arrays (the labelled image and mesh): many hues and no light
// colours, so that neighbouring cells (whose ids are in random order) stand apart and the
// white site dots show on every cell. A low priority: a SiteId colour map the user saved in
// their settings wins.
const char* const SiteIdColourMap = R"json({
  "array_lookup_tables": {
    "SiteId": {
      "PVLookupTable": {
        "ColorSpace": "RGB",
        "RGBPoints": [
          0.000, 0.27, 0.00, 0.33,
          0.125, 0.23, 0.32, 0.55,
          0.250, 0.13, 0.57, 0.55,
          0.375, 0.30, 0.70, 0.25,
          0.500, 0.80, 0.62, 0.05,
          0.625, 0.90, 0.40, 0.05,
          0.750, 0.80, 0.12, 0.15,
          0.875, 0.75, 0.30, 0.65,
          1.000, 0.20, 0.45, 0.80
        ]
      }
    }
  }
})json";

// The hint <CVTSiteDots port="P" spacing_fraction="F" shader="S"/> of a filter asks for the
// Point Gaussian dots of its port P to have a radius of F times the mean site spacing,
// sqrt(area / sites) over the data's two largest extents, drawn with shader preset S:
// ParaView's defaults (0.5% of the extent, shaded spheres) make 1000 sites three-pixel specks.
// Representations take no such default from XML, so it is set when Show() (GUI Apply or pvpython)
// registers a representation of that port; the user can change it.
struct SiteDots
{
  double Radius = 0.0;
  const char* Shader = nullptr;
  double Lift[3] = { 0.0, 0.0, 0.0 };
};

SiteDots SiteDotsOf(vtkSMProxy* representation)
{
  if (!representation->GetProperty("Input") || !representation->GetProperty("GaussianRadius"))
  {
    return {};
  }
  vtkSMPropertyHelper input(representation, "Input", /*quiet=*/true);
  auto* producer = vtkSMSourceProxy::SafeDownCast(input.GetAsProxy());
  vtkPVXMLElement* hints = producer ? producer->GetHints() : nullptr;
  if (!hints)
  {
    return {};
  }
  const int port = static_cast<int>(input.GetOutputPort());
  for (unsigned int i = 0; i < hints->GetNumberOfNestedElements(); ++i)
  {
    vtkPVXMLElement* hint = hints->GetNestedElement(i);
    int hintPort = 0;
    double fraction = 0.0;
    if (std::strcmp(hint->GetName(), "CVTSiteDots") != 0 ||
      !hint->GetScalarAttribute("port", &hintPort) || hintPort != port ||
      !hint->GetScalarAttribute("spacing_fraction", &fraction))
    {
      continue;
    }
    vtkPVDataInformation* info = producer->GetDataInformation(port);
    const vtkIdType sites = info ? info->GetNumberOfPoints() : 0;
    if (sites <= 0)
    {
      return {};
    }
    double bounds[6];
    info->GetBounds(bounds);
    double extents[3] = { bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4] };
    const int flattest = static_cast<int>(std::min_element(extents, extents + 3) - extents);
    std::sort(extents, extents + 3);
    const double area = extents[2] * extents[1];
    if (area <= 0.0)
    {
      return {};
    }
    SiteDots dots;
    dots.Radius = fraction * std::sqrt(area / static_cast<double>(sites));
    dots.Shader = hint->GetAttribute("shader");
    if (extents[0] == 0.0)
    {
      // Flat sites lie in the plane of the labelled image: lift the dots off it by their
      // radius (towards the default camera), or the image hides half of each.
      dots.Lift[flattest] = dots.Radius;
    }
    return dots;
  }
  return {};
}

void OnProxyRegistered(vtkObject*, unsigned long, void*, void* callData)
{
  auto* registered = static_cast<vtkSMProxyManager::RegisteredProxyInformation*>(callData);
  if (!registered || registered->Type != vtkSMProxyManager::RegisteredProxyInformation::PROXY ||
    !registered->Proxy || !registered->GroupName ||
    std::strcmp(registered->GroupName, "representations") != 0)
  {
    return;
  }
  const SiteDots dots = SiteDotsOf(registered->Proxy);
  if (dots.Radius > 0.0)
  {
    vtkSMPropertyHelper(registered->Proxy, "GaussianRadius").Set(dots.Radius);
    if (dots.Shader && registered->Proxy->GetProperty("ShaderPreset"))
    {
      vtkSMPropertyHelper(registered->Proxy, "ShaderPreset").Set(dots.Shader);
    }
    if (registered->Proxy->GetProperty("Position"))
    {
      vtkSMPropertyHelper(registered->Proxy, "Position").Set(dots.Lift, 3);
    }
    registered->Proxy->UpdateVTKObjects();
  }
}

struct RegisterDefaults
{
  RegisterDefaults()
  {
    vtkSMSettings::GetInstance()->AddCollectionFromString(SiteIdColourMap, -1.0);
    // Only where proxies are made (the client, pvpython, pvbatch), not on a pvserver.
    if (vtkSMProxyManager::IsInitialized())
    {
      vtkNew<vtkCallbackCommand> onRegister;
      onRegister->SetCallback(OnProxyRegistered);
      vtkSMProxyManager::GetProxyManager()->AddObserver(vtkCommand::RegisterEvent, onRegister);
    }
  }
};
const RegisterDefaults registerDefaults;
}
