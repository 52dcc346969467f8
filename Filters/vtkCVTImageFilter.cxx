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
#include "vtkStringArray.h"
#include "vtkTable.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

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
  // vtkDelaunay2D walks from the last triangle to each new point: points fed in a serpentine
  // order of row bands keep the walks short (1000 sites: 21 -> 8 ms, 100,000: 19 -> 1.1 s).
  vtkPoints* points = sites->GetPoints();
  const vtkIdType n = points->GetNumberOfPoints();
  double bounds[6];
  points->GetBounds(bounds);
  const double bands = std::max(1.0, std::floor(std::sqrt(0.5 * n)));
  const double bandHeight = std::max(bounds[3] - bounds[2], 1e-300) / bands;
  std::vector<vtkIdType> order(n);
  std::vector<std::pair<double, double>> keys(n); // (band, x along the band's direction)
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    const double band = std::min(bands - 1.0, std::floor((p[1] - bounds[2]) / bandHeight));
    keys[i] = { band, std::fmod(band, 2.0) == 0.0 ? p[0] : -p[0] };
    order[i] = i;
  }
  std::sort(
    order.begin(), order.end(), [&keys](vtkIdType a, vtkIdType b) { return keys[a] < keys[b]; });
  vtkNew<vtkPoints> sorted;
  sorted->SetDataTypeToDouble();
  sorted->SetNumberOfPoints(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    sorted->SetPoint(i, points->GetPoint(order[i]));
  }
  vtkNew<vtkPolyData> input;
  input->SetPoints(sorted);
  vtkNew<vtkDelaunay2D> delaunay;
  delaunay->SetInputData(input);
  delaunay->Update();
  vtkIdType npts;
  const vtkIdType* sortedIds;
  vtkCellArray* polys = delaunay->GetOutput()->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(npts, sortedIds);)
  {
    if (npts != 3)
    {
      continue;
    }
    const vtkIdType ids[3] = { order[sortedIds[0]], order[sortedIds[1]], order[sortedIds[2]] };
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

/// The domain of a 2D image: each point the centre of a pixel. False with `error` saying what
/// to fix for an empty or 3D image, a non-positive spacing, or one too large for this machine.
bool ReadDomain(vtkImageData* image, cvt::Grid& grid, std::string& error)
{
  if (!image || image->GetNumberOfPoints() == 0)
  {
    error = "The input image is empty; give a 2D image with at least one pixel.";
    return false;
  }
  int dims[3];
  image->GetDimensions(dims);
  if (dims[2] != 1)
  {
    error = "The input image is 3D (" + std::to_string(dims[0]) + " x " + std::to_string(dims[1]) +
      " x " + std::to_string(dims[2]) + "); give a 2D image in the XY plane (one slice).";
    return false;
  }
  const double* spacing = image->GetSpacing();
  const double* origin = image->GetOrigin();
  if (!(spacing[0] > 0.0) || !(spacing[1] > 0.0))
  {
    std::ostringstream message;
    message << "The input image has a non-positive spacing (" << spacing[0] << ", " << spacing[1]
            << "); give positive spacings.";
    error = message.str();
    return false;
  }
  const int* extent = image->GetExtent();
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
    error = "The image is too large for this machine: " + memory + ".";
    return false;
  }
  return true;
}

/// The density per pixel from `array` (named `name`; nullptr: uniform): one component, or a
/// colour's luminance (ITU-R BT.601, as the CLI), inverted when asked. False with `error`.
bool ReadDensity(vtkDataArray* array, const char* name, bool invert, const cvt::Grid& grid,
  std::vector<float>& density, std::string& error)
{
  density.assign(static_cast<size_t>(grid.NumberOfPixels()), 1.0f);
  if (name && !array)
  {
    error = std::string("The density array '") + name +
      "' is not a point array of the input image; choose one of its point arrays.";
    return false;
  }
  if (array)
  {
    const int components = array->GetNumberOfComponents();
    if (components != 1 && components != 3 && components != 4)
    {
      error = std::string("The density array '") + name + "' has " + std::to_string(components) +
        " components; a density needs one (or three or four: a colour, whose luminance is "
        "taken).";
      return false;
    }
    if (array->GetNumberOfTuples() != grid.NumberOfPixels())
    {
      error = std::string("The density array '") + name + "' does not hold one value per pixel.";
      return false;
    }
    for (vtkIdType p = 0; p < array->GetNumberOfTuples(); ++p)
    {
      density[p] = static_cast<float>(components == 1 ? array->GetComponent(p, 0)
                                                      : 0.299 * array->GetComponent(p, 0) +
            0.587 * array->GetComponent(p, 1) + 0.114 * array->GetComponent(p, 2));
    }
    if (invert)
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
  const std::string problem = cvt::CheckDensity(grid, density);
  if (!problem.empty())
  {
    error = "Bad density: " + problem + ".";
    return false;
  }
  return true;
}
}

//------------------------------------------------------------------------------
vtkCVTImageFilter::vtkCVTImageFilter()
{
  this->SetNumberOfInputPorts(2);
  // What progress bars show (ParaView: the label the user knows, not the class name).
  this->SetProgressText("CVT Image");
}

//------------------------------------------------------------------------------
vtkCVTImageFilter::~vtkCVTImageFilter() = default;

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
vtkImageData* vtkCVTImageFilter::GetLabelsOutput()
{
  return vtkImageData::SafeDownCast(this->GetOutputDataObject(LabelsPort));
}

//------------------------------------------------------------------------------
vtkPolyData* vtkCVTImageFilter::GetDualOutput()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(DualPort));
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
bool vtkCVTImageFilter::Compute(
  vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkImageData* image = vtkImageData::GetData(inputVector[0], 0);
  cvt::Grid grid;
  std::vector<float> density;
  std::vector<double> sites;
  std::string error;
  const char* densityName = this->GetDensityArrayName();
  const bool densityChosen = densityName != nullptr;
  if (!ReadDomain(image, grid, error) ||
    !ReadDensity(densityChosen ? this->GetInputArrayToProcess(0, inputVector) : nullptr,
      densityName, this->InvertDensity, grid, density, error) ||
    !this->ReadInitialSites(vtkPointSet::GetData(inputVector[1], 0), grid,
      densityChosen ? density : std::vector<float>(), sites, error))
  {
    vtkErrorMacro("" << error);
    return false;
  }

  // --- The optimiser, on the engine chosen.
  const cvtvtk::EngineChoice choice = cvtvtk::ChooseEngine(this->Engine);
  cvt::ExactEngine cpu;
  vtkCVTOpenGLEngine* gpu =
    choice.UseOpenGL ? this->GetOpenGLEngine<vtkCVTOpenGLEngine>() : nullptr;
  cvt::Engine* engine = gpu ? static_cast<cvt::Engine*>(gpu) : &cpu;
  if (gpu)
  {
    gpu->SetSplitBoundaryPixels(this->SplitBoundaryPixels);
  }
  const bool ready = engine->SetDomain(grid, density);
  // Under MPI every rank runs the same optimisation and they share its integrals: on the CPU
  // each integrates its share of the cells, on OpenGL its band of rows.
  cvt::SharedCellSums* shared = gpu ? static_cast<cvt::SharedCellSums*>(gpu) : &cpu;
  const int ranks = this->ShareCellSumsAcrossRanks(shared, ready, outputVector);
  if (gpu)
  {
    this->ContextDescription = gpu->GetContextDescription();
  }
  cvt::PlaneProblem problem(*engine, grid);
  cvt::OptimizerResult result;
  std::vector<int> labels;
  const bool optimized = ready &&
    this->Optimize(
      problem, cvt::SiteState{ sites, {} }, this->GetOptimizerOptions(), result, error) &&
    engine->GetLabels(labels);
  if (!optimized)
  {
    vtkErrorMacro("The " << (choice.UseOpenGL ? "GPU" : "CPU") << " CVT failed: "
                         << (ready && !error.empty() ? error : engine->GetLastError()) << ".");
    return false;
  }

  // --- Outputs.
  vtkPolyData* sitesOut = vtkPolyData::GetData(outputVector, SitesPort);
  vtkSmartPointer<vtkPoints> points =
    cvtvtk::FillSites(sitesOut, result.Sites, 2, image->GetOrigin()[2], result.Sums);
  vtkFieldData* fields = sitesOut->GetFieldData();
  AddRunFields(fields, result, result.Sums.GradientNorm());
  this->AddQualityFields(fields, grid, result, densityChosen ? density : std::vector<float>());
  cvtvtk::AddFieldString(fields, "Engine", choice.Name);
  cvtvtk::AddFieldString(fields, "EngineReason", choice.Reason);
  cvtvtk::AddFieldValue(fields, "EngineRanks", ranks); // ranks sharing the cell sums

  vtkImageData* labelsOut = vtkImageData::GetData(outputVector, LabelsPort);
  labelsOut->SetExtent(image->GetExtent());
  labelsOut->SetSpacing(image->GetSpacing());
  labelsOut->SetOrigin(image->GetOrigin());
  labelsOut->GetPointData()->SetScalars(cvtvtk::SiteIdArray(labels));

  vtkPolyData* dualOut = vtkPolyData::GetData(outputVector, DualPort);
  dualOut->SetPoints(points);
  dualOut->SetPolys(DualTriangles(sitesOut, grid));
  vtkNew<vtkIntArray> dualIds;
  dualIds->DeepCopy(sitesOut->GetPointData()->GetArray("SiteId"));
  dualOut->GetPointData()->AddArray(dualIds);

  cvtvtk::FillHistoryTable(vtkTable::GetData(outputVector, HistoryPort), result.History);
  return true;
}

//------------------------------------------------------------------------------
const char* vtkCVTImageFilter::GetDensityArrayName()
{
  vtkInformation* info = this->GetInputArrayInformation(0);
  const char* name = info && info->Has(vtkDataObject::FIELD_NAME())
    ? info->Get(vtkDataObject::FIELD_NAME())
    : nullptr;
  return name && name[0] != '\0' && std::string(name) != UniformDensityName() ? name : nullptr;
}

//------------------------------------------------------------------------------
bool vtkCVTImageFilter::ReadInitialSites(vtkPointSet* initialSites, const cvt::Grid& grid,
  const std::vector<float>& density, std::vector<double>& sites, std::string& error)
{
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
  else if (this->NumberOfSites <= 0)
  {
    error =
      "NumberOfSites is " + std::to_string(this->NumberOfSites) + "; ask for at least one site.";
    return false;
  }
  else if (this->NumberOfSites > grid.NumberOfPixels())
  {
    error = "NumberOfSites (" + std::to_string(this->NumberOfSites) + ") exceeds the " +
      std::to_string(grid.NumberOfPixels()) +
      " pixels of the image; use fewer sites or a finer image.";
    return false;
  }
  else
  {
    sites = cvt::SampleSites(
      grid, density, this->NumberOfSites, static_cast<std::uint64_t>(this->RandomSeed));
  }
  const std::string problem = cvt::CheckSites(grid, sites);
  if (!problem.empty())
  {
    error = "Bad initial sites: " + problem + ".";
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkCVTImageFilter::AddQualityFields(vtkFieldData* fields, const cvt::Grid& grid,
  const cvt::OptimizerResult& result, const std::vector<float>& density)
{
  const cvt::QualityMeasures quality = cvt::MeasureQuality(grid, result.Sites);
  cvtvtk::AddFieldValue(fields, "HexagonalFraction", quality.HexagonalFraction);
  cvtvtk::AddFieldValue(fields, "RadiusStandardDeviation", quality.RadiusStandardDeviation);
  cvtvtk::AddFieldValue(
    fields, "NearestNeighborStandardDeviation", quality.NearestNeighborStandardDeviation);
  cvtvtk::AddFieldValue(fields, "AreaStandardDeviation", quality.AreaStandardDeviation);
  if (this->ComputeExactEnergy)
  {
    const double exact = cvt::ExactCellSums(grid, result.Sites, density).TotalEnergy();
    cvtvtk::AddFieldValue(fields, "ExactEnergy", exact);
    cvtvtk::AddFieldValue(
      fields, "EnergyRelativeDifference", (result.Sums.TotalEnergy() - exact) / exact);
  }
}

//------------------------------------------------------------------------------
void vtkCVTImageFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "InvertDensity: " << this->InvertDensity << "\n";
  os << indent << "ComputeExactEnergy: " << this->ComputeExactEnergy << "\n";
  os << indent << "SplitBoundaryPixels: " << this->SplitBoundaryPixels << "\n";
}
