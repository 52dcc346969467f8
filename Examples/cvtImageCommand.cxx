// cvt image: a CVT of a 2D image domain, its density read from --input or uniform.
#include "cvtCommands.h"
#include "cvtErrors.h"
#include "cvtOutputs.h"
#include "cvtReaders.h"

#include "vtkCVTImageFilter.h"
#include "vtkCVTSceneRenderer.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkXMLImageDataWriter.h"
#include "vtkXMLPolyDataWriter.h"

#include <iomanip>
#include <iostream>

namespace cvtcli
{

int RunImage(const Options& options)
{
  OutputFolder(options); // before any work: a folder that cannot be written fails now
  vtkSmartPointer<vtkImageData> image = ReadDensityImage(options);
  vtkNew<vtkCVTImageFilter> cvt;
  cvt->SetInputData(image);
  if (image->GetPointData()->GetArray("density"))
  {
    cvt->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "density");
  }
  if (!options.InitialSites.empty())
  {
    cvt->SetInitialSitesData(ReadSitesCsv(options.InitialSites));
  }
  SetOptimizer(options, cvt.Get());
  cvt->SetComputeExactEnergy(options.Report);
  SetEngine(options, cvt.Get());
  RunOrFail(
    cvt, [](vtkAlgorithm* f) { return static_cast<vtkCVTImageFilter*>(f)->GetSitesOutput(); });

  OutputFiles files(OutputFolder(options));
  vtkPolyData* sites = cvt->GetSitesOutput();
  Write<vtkXMLPolyDataWriter>(sites, files, "sites.vtp");
  Write<vtkXMLImageDataWriter>(cvt->GetLabelsOutput(), files, "labels.vti");
  Write<vtkXMLPolyDataWriter>(cvt->GetDualOutput(), files, "dual.vtp");
  WriteCsv(sites, cvt->GetHistoryOutput(), 2, files);
  vtkNew<vtkCVTSceneRenderer> scene;
  const bool pictureWritten =
    WritePicture(scene->Render(cvt->GetLabelsOutput(), sites), scene->GetLastError(), files);
  files.Commit();

  if (options.Report)
  {
    std::cout << std::setprecision(6) << "report:\n"
              << "  method                      " << options.Method << "\n"
              << "  iterations / evaluations    " << Field(sites, "Iterations") << " / "
              << Field(sites, "Evaluations") << "\n"
              << "  energy F (engine)           " << Field(sites, "Energy") << "\n"
              << "  energy F (exact, CPU)       " << Field(sites, "ExactEnergy") << "\n"
              << "  relative difference         "
              << 100.0 * Field(sites, "EnergyRelativeDifference") << " %\n"
              << "  |grad F|                    " << Field(sites, "GradientNorm") << "\n"
              << "  hexagonal interior cells    " << 100.0 * Field(sites, "HexagonalFraction")
              << " %\n"
              << "  stdev cell radius r_i       " << Field(sites, "RadiusStandardDeviation") << "\n"
              << "  stdev nearest neighbour d_i "
              << Field(sites, "NearestNeighborStandardDeviation") << "\n"
              << "  stdev cell area a_i         " << Field(sites, "AreaStandardDeviation") << "\n";
  }
  PrintSummary(options, sites, cvt->GetContextDescription(),
    "sites.vtp sites.csv labels.vti dual.vtp history.csv cvt.png", pictureWritten);
  return 0;
}

} // namespace cvtcli
