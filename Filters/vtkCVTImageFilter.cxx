#include "vtkCVTImageFilter.h"

#include "cvtExactEngine.h"
#include "cvtExactVoronoi.h"
#include "cvtMemory.h"
#include "cvtProblems.h"
#include "cvtQuality.h"
#include "cvtSampling.h"
#include "vtkCVTEngineChoice.h"
#include "vtkCVTOpenGLEngine.h"
#include "vtkCVTOutputHelpers.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkDelaunay2D.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkStringArray.h"
#include "vtkTable.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

vtkStandardNewMacro(vtkCVTImageFilter);

namespace
{
/// The Delaunay triangles whose three cells meet inside the domain: those whose circumcentre
/// (the shared Voronoi vertex) lies in it. Triangles come out counter-clockwise.
vtkSmartPointer<vtkCellArray> DualTriangles(vtkPolyData* sites, const cvt::Grid& grid)
{
  auto triangles = vtkSmartPointer<vtkCellArray>::New();
  if (sites->GetNumberOfPoints() < 3)
  {
    return triangles;
  }
  vtkNew<vtkDelaunay2D> delaunay;
  delaunay->SetInputData(sites);
  delaunay->Update();
  vtkPolyData* mesh = delaunay->GetOutput();
  vtkPoints* points = sites->GetPoints();
  vtkIdType npts;
  const vtkIdType* ids;
  vtkCellArray* polys = mesh->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(npts, ids);)
  {
    if (npts != 3)
    {
      continue;
    }
    double a[3], b[3], c[3];
    points->GetPoint(ids[0], a);
    points->GetPoint(ids[1], b);
    points->GetPoint(ids[2], c);
    const double bx = b[0] - a[0], by = b[1] - a[1], cx = c[0] - a[0], cy = c[1] - a[1];
    const double cross = bx * cy - by * cx;
    if (cross == 0.0)
    {
      continue; // degenerate (collinear) triangle
    }
    const double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
    const double ux = a[0] + (cy * b2 - by * c2) / (2.0 * cross);
    const double uy = a[1] + (bx * c2 - cx * b2) / (2.0 * cross);
    if (!grid.Contains(ux, uy))
    {
      continue;
    }
    const vtkIdType triangle[3] = { ids[0], cross > 0.0 ? ids[1] : ids[2],
      cross > 0.0 ? ids[2] : ids[1] };
    triangles->InsertNextCell(3, triangle);
  }
  return triangles;
}
}

//------------------------------------------------------------------------------
vtkCVTImageFilter::vtkCVTImageFilter()
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(4);
  // What progress bars show (ParaView: the label the user knows, not the class name).
  this->SetProgressText("CVT Image");
  // No density array by default: uniform density.
}

//------------------------------------------------------------------------------
vtkCVTImageFilter::~vtkCVTImageFilter() = default;

//------------------------------------------------------------------------------
void vtkCVTImageFilter::SetRenderWindow(vtkRenderWindow* window)
{
  if (window != this->RenderWindow)
  {
    this->RenderWindow = window;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkRenderWindow* vtkCVTImageFilter::GetRenderWindow() const
{
  return this->RenderWindow;
}

//------------------------------------------------------------------------------
void vtkCVTImageFilter::ReleaseGraphicsResources()
{
  this->OpenGLEngine = nullptr; // its GL objects, then its context
}

//------------------------------------------------------------------------------
void vtkCVTImageFilter::SetInitialSitesConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(1, output);
}

//------------------------------------------------------------------------------
void vtkCVTImageFilter::SetInitialSitesData(vtkDataObject* sites)
{
  this->SetInputData(1, sites);
}

//------------------------------------------------------------------------------
vtkPolyData* vtkCVTImageFilter::GetSitesOutput()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(SitesPort));
}
vtkImageData* vtkCVTImageFilter::GetLabelsOutput()
{
  return vtkImageData::SafeDownCast(this->GetOutputDataObject(LabelsPort));
}
vtkPolyData* vtkCVTImageFilter::GetDualOutput()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(DualPort));
}
vtkTable* vtkCVTImageFilter::GetHistoryOutput()
{
  return vtkTable::SafeDownCast(this->GetOutputDataObject(HistoryPort));
}

//------------------------------------------------------------------------------
int vtkCVTImageFilter::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 0)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  }
  else
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkCVTImageFilter::FillOutputPortInformation(int port, vtkInformation* info)
{
  switch (port)
  {
    case LabelsPort:
      info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkImageData");
      break;
    case HistoryPort:
      info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkTable");
      break;
    default:
      info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkPolyData");
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkCVTImageFilter::RequestInformation(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  cvtvtk::DescribeLabelsLikeInput(
    inputVector[0]->GetInformationObject(0), outputVector->GetInformationObject(LabelsPort));
  return 1;
}

//------------------------------------------------------------------------------
int vtkCVTImageFilter::RequestUpdateExtent(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  // The whole domain takes part in every cell, and every initial site counts.
  cvtvtk::RequestAllOfInput(inputVector[0]->GetInformationObject(0));
  cvtvtk::RequestAllOfInput(inputVector[1]->GetInformationObject(0));
  cvtvtk::ShareRequestedPiece(request, outputVector);
  return 1;
}

//------------------------------------------------------------------------------
int vtkCVTImageFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return cvtvtk::RunRequest(this, outputVector, this->FailPipelineOnError, this->LastFailure,
    this->LastRunFailed, [&] { return this->Compute(inputVector, outputVector); });
}

//------------------------------------------------------------------------------
bool vtkCVTImageFilter::Compute(
  vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkImageData* image = vtkImageData::GetData(inputVector[0], 0);
  vtkPointSet* initialSites = vtkPointSet::GetData(inputVector[1], 0);
  vtkPolyData* sitesOut = vtkPolyData::GetData(outputVector, SitesPort);
  vtkImageData* labelsOut = vtkImageData::GetData(outputVector, LabelsPort);
  vtkPolyData* dualOut = vtkPolyData::GetData(outputVector, DualPort);
  vtkTable* historyOut = vtkTable::GetData(outputVector, HistoryPort);
  sitesOut->Initialize();
  labelsOut->Initialize();
  dualOut->Initialize();
  historyOut->Initialize();
  this->ContextDescription.clear();

  // --- The domain.
  if (!image || image->GetNumberOfPoints() == 0)
  {
    vtkErrorMacro("The input image is empty; give a 2D image with at least one pixel.");
    return false;
  }
  int dims[3];
  image->GetDimensions(dims);
  if (dims[2] != 1)
  {
    vtkErrorMacro("The input image is 3D (" << dims[0] << " x " << dims[1] << " x " << dims[2]
                                            << "); give a 2D image in the XY plane (one slice).");
    return false;
  }
  double spacing[3], origin[3];
  image->GetSpacing(spacing);
  image->GetOrigin(origin);
  if (!(spacing[0] > 0.0) || !(spacing[1] > 0.0))
  {
    vtkErrorMacro("The input image has a non-positive spacing (" << spacing[0] << ", " << spacing[1]
                                                                 << "); give positive spacings.");
    return false;
  }
  const int* extent = image->GetExtent();
  cvt::Grid grid;
  grid.Width = dims[0];
  grid.Height = dims[1];
  grid.Spacing[0] = spacing[0];
  grid.Spacing[1] = spacing[1];
  grid.Origin[0] = origin[0] + (extent[0] - 0.5) * spacing[0];
  grid.Origin[1] = origin[1] + (extent[2] - 0.5) * spacing[1];

  // The filter's own arrays (the density and the labels output, 4 bytes per pixel each); the
  // engines check their own needs before they allocate.
  const std::string memory =
    cvt::CheckMemory(8.0 * static_cast<double>(grid.NumberOfPixels()), cvt::AvailableSystemMemory(),
      "an image of " + std::to_string(grid.Width) + " x " + std::to_string(grid.Height) + " pixels",
      "memory", "use a coarser image");
  if (!memory.empty())
  {
    vtkErrorMacro("The image is too large for this machine: " << memory << ".");
    return false;
  }

  // --- The density.
  std::vector<float> density(static_cast<size_t>(grid.NumberOfPixels()), 1.0f);
  vtkInformation* arrayInfo = this->GetInputArrayInformation(0);
  const bool densityChosen = arrayInfo && arrayInfo->Has(vtkDataObject::FIELD_NAME()) &&
    arrayInfo->Get(vtkDataObject::FIELD_NAME())[0] != '\0' &&
    std::string(arrayInfo->Get(vtkDataObject::FIELD_NAME())) != UniformDensityName();
  if (densityChosen)
  {
    vtkDataArray* array = this->GetInputArrayToProcess(0, inputVector);
    const char* name = arrayInfo->Get(vtkDataObject::FIELD_NAME());
    if (!array)
    {
      vtkErrorMacro("The density array '"
        << name << "' is not a point array of the input image; choose one of its point arrays.");
      return false;
    }
    const int components = array->GetNumberOfComponents();
    if (components != 1 && components != 3 && components != 4)
    {
      vtkErrorMacro("The density array '"
        << name << "' has " << components
        << " components; a density needs one (or three or four: a colour, whose luminance is "
           "taken).");
      return false;
    }
    if (array->GetNumberOfTuples() != grid.NumberOfPixels())
    {
      vtkErrorMacro("The density array '" << name << "' does not hold one value per pixel.");
      return false;
    }
    for (vtkIdType p = 0; p < array->GetNumberOfTuples(); ++p)
    {
      // Colours (RGB, RGBA pictures) give their luminance (ITU-R BT.601, as the CLI).
      density[p] = static_cast<float>(components == 1 ? array->GetComponent(p, 0)
                                                      : 0.299 * array->GetComponent(p, 0) +
            0.587 * array->GetComponent(p, 1) + 0.114 * array->GetComponent(p, 2));
    }
    if (this->InvertDensity)
    {
      // Dark = dense: from the type's largest value for integer arrays (255 for pictures),
      // else from the array's largest value.
      double top = *std::max_element(density.begin(), density.end());
      if (array->GetDataType() != VTK_FLOAT && array->GetDataType() != VTK_DOUBLE)
      {
        top = array->GetDataTypeMax();
      }
      for (float& value : density)
      {
        value = static_cast<float>(top - value);
      }
    }
  }
  const std::string densityError = cvt::CheckDensity(grid, density);
  if (!densityError.empty())
  {
    vtkErrorMacro("Bad density: " << densityError << ".");
    return false;
  }

  // --- The initial sites.
  std::vector<double> sites;
  if (initialSites)
  {
    const vtkIdType n = initialSites->GetNumberOfPoints();
    sites.resize(2 * static_cast<size_t>(n));
    for (vtkIdType i = 0; i < n; ++i)
    {
      double p[3];
      initialSites->GetPoint(i, p);
      sites[2 * i] = p[0];
      sites[2 * i + 1] = p[1];
    }
  }
  else
  {
    if (this->NumberOfSites <= 0)
    {
      vtkErrorMacro("NumberOfSites is " << this->NumberOfSites << "; ask for at least one site.");
      return false;
    }
    if (this->NumberOfSites > grid.NumberOfPixels())
    {
      vtkErrorMacro("NumberOfSites (" << this->NumberOfSites << ") exceeds the "
                                      << grid.NumberOfPixels()
                                      << " pixels of the image; use fewer sites or a finer image.");
      return false;
    }
    sites = cvt::SampleSites(grid, densityChosen ? density : std::vector<float>(),
      this->NumberOfSites, static_cast<std::uint64_t>(this->RandomSeed));
  }
  const std::string sitesError = cvt::CheckSites(grid, sites);
  if (!sitesError.empty())
  {
    vtkErrorMacro("Bad initial sites: " << sitesError << ".");
    return false;
  }

  // --- The optimiser, on the engine chosen.
  const cvtvtk::EngineChoice choice = cvtvtk::ChooseEngine(this->Engine);
  if (choice.UseOpenGL && !this->OpenGLEngine)
  {
    this->OpenGLEngine = vtkSmartPointer<vtkCVTOpenGLEngine>::New();
  }
  vtkCVTOpenGLEngine* gpu = this->OpenGLEngine;
  cvt::ExactEngine cpu;
  cvt::Engine& engine = choice.UseOpenGL ? static_cast<cvt::Engine&>(*gpu) : cpu;
  if (choice.UseOpenGL)
  {
    gpu->SetRenderWindow(this->RenderWindow);
    gpu->SetAdaptiveStep(this->AdaptiveJumpFlooding);
    gpu->SetSplitBoundaryPixels(this->SplitBoundaryPixels);
  }
  cvt::OptimizerOptions options;
  options.MaximumNumberOfIterations = this->MaximumNumberOfIterations;
  options.Tolerance = this->Tolerance;
  options.GradientTolerance = this->GradientTolerance;
  options.NumberOfCorrections = this->NumberOfCorrections;
  cvt::OptimizerResult result;
  std::string error;
  const auto progress = [this](double fraction)
  {
    this->UpdateProgress(fraction);
    return !this->GetAbortExecute();
  };
  const bool ok = engine.SetDomain(grid, density);
  if (choice.UseOpenGL)
  {
    this->ContextDescription = gpu->GetContextDescription();
  }
  cvt::PlaneProblem problem(engine, grid);
  const cvt::SiteState initial{ sites, {} };
  const bool optimized = ok &&
    (this->Method == LLOYD ? cvt::RunLloyd(problem, initial, options, progress, result, error)
                           : cvt::RunLBFGS(problem, initial, options, progress, result, error));
  const char* what = choice.UseOpenGL ? "The GPU CVT failed: " : "The CPU CVT failed: ";
  if (!optimized)
  {
    vtkErrorMacro("" << what << (ok ? error : engine.GetLastError()) << ".");
    return false;
  }
  std::vector<int> labels;
  if (!engine.GetLabels(labels))
  {
    vtkErrorMacro("" << what << engine.GetLastError() << ".");
    return false;
  }
  if (result.StopReason.rfind("no sufficient decrease", 0) == 0)
  {
    vtkWarningMacro("L-BFGS stopped after " << result.Iterations
                                            << " iterations: " << result.StopReason
                                            << "; the output holds its best sites.");
  }

  // --- Outputs.
  vtkSmartPointer<vtkPoints> points =
    cvtvtk::FillSites(sitesOut, result.Sites, 2, origin[2], result.Sums);
  vtkFieldData* fields = sitesOut->GetFieldData();
  cvtvtk::AddFieldValue(fields, "Energy", result.Sums.TotalEnergy());
  cvtvtk::AddFieldValue(fields, "GradientNorm", result.Sums.GradientNorm());
  cvtvtk::AddFieldValue(fields, "Iterations", result.Iterations);
  cvtvtk::AddFieldValue(fields, "Evaluations", result.Evaluations);
  const cvt::QualityMeasures quality = cvt::MeasureQuality(grid, result.Sites);
  cvtvtk::AddFieldValue(fields, "HexagonalFraction", quality.HexagonalFraction);
  cvtvtk::AddFieldValue(fields, "RadiusStandardDeviation", quality.RadiusStandardDeviation);
  cvtvtk::AddFieldValue(
    fields, "NearestNeighborStandardDeviation", quality.NearestNeighborStandardDeviation);
  cvtvtk::AddFieldValue(fields, "AreaStandardDeviation", quality.AreaStandardDeviation);
  if (this->ComputeExactEnergy)
  {
    const double exact =
      cvt::ExactCellSums(grid, result.Sites, densityChosen ? density : std::vector<float>())
        .TotalEnergy();
    cvtvtk::AddFieldValue(fields, "ExactEnergy", exact);
    cvtvtk::AddFieldValue(
      fields, "EnergyRelativeDifference", (result.Sums.TotalEnergy() - exact) / exact);
  }
  cvtvtk::AddFieldString(fields, "StopReason", result.StopReason);
  cvtvtk::AddFieldString(fields, "Engine", choice.Name);
  cvtvtk::AddFieldString(fields, "EngineReason", choice.Reason);

  labelsOut->SetExtent(image->GetExtent());
  labelsOut->SetSpacing(spacing);
  labelsOut->SetOrigin(origin);
  labelsOut->GetPointData()->SetScalars(cvtvtk::SiteIdArray(labels));

  dualOut->SetPoints(points);
  dualOut->SetPolys(DualTriangles(sitesOut, grid));
  vtkNew<vtkIntArray> dualIds;
  dualIds->DeepCopy(sitesOut->GetPointData()->GetArray("SiteId"));
  dualOut->GetPointData()->AddArray(dualIds);

  cvtvtk::FillHistoryTable(historyOut, result.History);
  return true;
}

//------------------------------------------------------------------------------
void vtkCVTImageFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FailPipelineOnError: " << this->FailPipelineOnError << "\n";
  os << indent << "Method: " << (this->Method == LLOYD ? "Lloyd" : "L-BFGS") << "\n";
  os << indent << "NumberOfCorrections: " << this->NumberOfCorrections << "\n";
  os << indent << "GradientTolerance: " << this->GradientTolerance << "\n";
  os << indent << "ComputeExactEnergy: " << this->ComputeExactEnergy << "\n";
  os << indent << "NumberOfSites: " << this->NumberOfSites << "\n";
  os << indent << "RandomSeed: " << this->RandomSeed << "\n";
  os << indent << "InvertDensity: " << this->InvertDensity << "\n";
  os << indent << "MaximumNumberOfIterations: " << this->MaximumNumberOfIterations << "\n";
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "AdaptiveJumpFlooding: " << this->AdaptiveJumpFlooding << "\n";
  os << indent << "SplitBoundaryPixels: " << this->SplitBoundaryPixels << "\n";
  os << indent << "Engine: " << cvtvtk::EngineKindName(this->Engine) << "\n";
  os << indent << "ContextDescription: "
     << (this->ContextDescription.empty() ? "(none)" : this->ContextDescription) << "\n";
  os << indent << "RenderWindow: " << this->RenderWindow.Get() << "\n";
  os << indent << "OpenGLEngine: " << (this->OpenGLEngine ? "kept" : "(none yet)") << "\n";
}
