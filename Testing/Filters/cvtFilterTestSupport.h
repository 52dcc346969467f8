// Helpers shared by the filter tests.
#ifndef cvtFilterTestSupport_h
#define cvtFilterTestSupport_h

#include "vtkCVTGeometryImageSource.h"

#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkSmartPointer.h"

namespace cvttest
{

/// The default torus (ring radius 1, tube radius 0.4) as a w x h geometry image.
inline vtkSmartPointer<vtkImageData> TorusImage(int w, int h)
{
  vtkNew<vtkCVTGeometryImageSource> source;
  source->SetResolution(w, h);
  source->Update();
  return source->GetOutput();
}

} // namespace cvttest

#endif
