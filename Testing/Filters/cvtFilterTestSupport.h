// Helpers shared by the filter tests.
#ifndef cvtFilterTestSupport_h
#define cvtFilterTestSupport_h

#include "vtkCVTAlgorithm.h"
#include "vtkCVTGeometryImageSource.h"

#include "vtkAbstractArray.h"
#include "vtkCommand.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <string>

namespace cvttest
{

/// Collects an algorithm's error and warning messages (observe ErrorEvent and WarningEvent).
class Messages : public vtkCommand
{
public:
  static Messages* New() { return new Messages; }
  void Execute(vtkObject*, unsigned long event, void* data) override
  {
    (event == vtkCommand::ErrorEvent ? this->Errors : this->Warnings) +=
      static_cast<const char*>(data);
  }
  std::string Errors, Warnings;
};

/// The default torus (ring radius 1, tube radius 0.4) as a w x h geometry image.
inline vtkSmartPointer<vtkImageData> TorusImage(int w, int h)
{
  vtkNew<vtkCVTGeometryImageSource> source;
  source->SetResolution(w, h);
  source->Update();
  return source->GetOutput();
}

/// Why the filter's optimisation stopped (its sites' StopReason field).
inline std::string StopReason(vtkCVTAlgorithm* filter)
{
  return filter->GetSitesOutput()
    ->GetFieldData()
    ->GetAbstractArray("StopReason")
    ->GetVariantValue(0)
    .ToString();
}

} // namespace cvttest

#endif
