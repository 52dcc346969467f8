// Defaults of the ParaView plugin that its server-manager XML cannot express, registered when
// ParaView loads the plugin library.
#include "vtkSMSettings.h"

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

struct RegisterDefaults
{
  RegisterDefaults()
  {
    vtkSMSettings::GetInstance()->AddCollectionFromString(SiteIdColourMap, -1.0);
  }
};
const RegisterDefaults registerDefaults;
}
