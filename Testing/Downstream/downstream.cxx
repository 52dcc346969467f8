// Uses the installed CVT::Filters: a CVT of a small image, checked.
#include "vtkCVTImageFilter.h"

#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPolyData.h"

#include <iostream>

int main()
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(32, 32, 1);
  vtkNew<vtkCVTImageFilter> cvt;
  cvt->SetInputData(image);
  cvt->SetNumberOfSites(10);
  cvt->SetMaximumNumberOfIterations(10);
  cvt->Update();
  const vtkIdType sites = cvt->GetSitesOutput()->GetNumberOfPoints();
  std::cout << "downstream: " << sites << " sites\n";
  return sites == 10 ? 0 : 1;
}
