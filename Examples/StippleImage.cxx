// A C++ VTK pipeline: picture -> darkness as density -> GPU CVT -> offscreen render -> PNG.
//   StippleImage INPUT.png OUTPUT.png [SITES]
#include "vtkCVTImageFilter.h"
#include "vtkCVTSceneRenderer.h"

#include "vtkImageData.h"
#include "vtkImageShiftScale.h"
#include "vtkNew.h"
#include "vtkPNGReader.h"
#include "vtkPNGWriter.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <cstdlib>
#include <iostream>

int main(int argc, char* argv[])
{
  if (argc < 3)
  {
    std::cerr << "usage: " << argv[0] << " INPUT.png OUTPUT.png [SITES]\n";
    return 2;
  }
  const int sites = argc > 3 ? std::atoi(argv[3]) : 2000;

  vtkNew<vtkPNGReader> reader; // a grey picture: one component, 0..255
  reader->SetFileName(argv[1]);
  vtkNew<vtkImageShiftScale> darkness; // density = 255 - grey: dark is dense
  darkness->SetInputConnection(reader->GetOutputPort());
  darkness->SetShift(-255.0);
  darkness->SetScale(-1.0);
  darkness->SetOutputScalarTypeToFloat();

  vtkNew<vtkCVTImageFilter> cvt;
  cvt->SetInputConnection(darkness->GetOutputPort());
  cvt->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "PNGImage");
  cvt->SetNumberOfSites(sites);
  cvt->SetMaximumNumberOfIterations(50);
  cvt->Update();
  if (cvt->GetSitesOutput()->GetNumberOfPoints() == 0)
  {
    std::cerr << "the CVT failed (see the error above)\n";
    return 1;
  }

  vtkNew<vtkCVTSceneRenderer> scene;
  scene->ShowCellsOff(); // stippling: dots only
  scene->SetPointSize(3.0);
  vtkSmartPointer<vtkImageData> picture =
    scene->Render(cvt->GetLabelsOutput(), cvt->GetSitesOutput());
  if (!picture)
  {
    std::cerr << "cannot render: " << scene->GetLastError() << "\n";
    return 1;
  }
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(picture);
  writer->SetFileName(argv[2]);
  writer->Write();
  std::cout << "wrote " << argv[2] << " (" << sites << " dots)\n";
  return 0;
}
