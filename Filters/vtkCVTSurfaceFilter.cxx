#include "vtkCVTSurfaceFilter.h"

#include "cvtParameterization.h"
#include "cvtProblems.h"
#include "cvtQuality.h"
#include "cvtRemesh.h"
#include "cvtRestrictedVoronoi.h"
#include "cvtSampling.h"
#include "cvtSurface.h"
#include "cvtSurfaceMesh.h"
#include "vtkCVTEngineChoice.h"
#include "vtkCVTOutputHelpers.h"
#include "vtkCVTRemeshFilter.h"
#include "vtkCVTSurfaceEngine.h"

#include "vtkAbstractArray.h"
#include "vtkCallbackCommand.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkTable.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <string>

vtkStandardNewMacro(vtkCVTSurfaceFilter);

namespace
{
bool ReadFloats(vtkDataArray* array, int components, std::vector<float>& out)
{
  if (!array || array->GetNumberOfComponents() != components)
  {
    return false;
  }
  out.resize(static_cast<size_t>(array->GetNumberOfTuples()) * components);
  for (vtkIdType t = 0; t < array->GetNumberOfTuples(); ++t)
  {
    for (int c = 0; c < components; ++c)
    {
      out[static_cast<size_t>(t) * components + c] = static_cast<float>(array->GetComponent(t, c));
    }
  }
  return true;
}

/// The area weights of a geometry image's valid pixels: their range, sum and count.
struct AreaWeights
{
  double Minimum = VTK_DOUBLE_MAX, Maximum = 0.0, Total = 0.0;
  long long ValidPixels = 0;
};

AreaWeights MeasureAreaWeights(const cvt::GeometryImage& image)
{
  AreaWeights weights;
  for (long long p = 0; p < image.NumberOfPixels(); ++p)
  {
    if (image.IsValid(p))
    {
      weights.Minimum = std::min(weights.Minimum, static_cast<double>(image.AreaWeight[p]));
      weights.Maximum = std::max(weights.Maximum, static_cast<double>(image.AreaWeight[p]));
      weights.Total += image.AreaWeight[p];
      ++weights.ValidPixels;
    }
  }
  return weights;
}

/// The point arrays of the geometry image that describe the surface (a mesh's, carried by
/// vtkCVTMeshGeometryImage), at `pixels`, added to `points`: the image's own arrays (positions,
/// normals, weights, mask, charts, seams) are left out.
void CopySurfaceArrays(
  vtkPointData* image, const std::vector<long long>& pixels, vtkPointData* points)
{
  static const std::set<std::string> own = { "Position", "Normal", "AreaWeight", "Mask", "ChartId",
    "SeamPartner", "SurfaceBorder", "SiteId" };
  vtkNew<vtkIdList> ids;
  ids->SetNumberOfIds(static_cast<vtkIdType>(pixels.size()));
  for (size_t i = 0; i < pixels.size(); ++i)
  {
    ids->SetId(static_cast<vtkIdType>(i), pixels[i]);
  }
  for (int a = 0; a < image->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* array = image->GetAbstractArray(a);
    if (!array->GetName() || own.count(array->GetName()) || points->HasArray(array->GetName()))
    {
      continue;
    }
    vtkSmartPointer<vtkAbstractArray> values = vtk::TakeSmartPointer(array->NewInstance());
    values->SetName(array->GetName());
    values->SetNumberOfComponents(array->GetNumberOfComponents());
    values->SetNumberOfTuples(ids->GetNumberOfIds());
    array->GetTuples(ids, values);
    points->AddArray(values);
  }
}

/// The remesh output of an atlas: the dual across the seams of `labels` on `vertices` (the sites'
/// points on the surface, at `pixels`) made manifold (cvt::ManifoldRemesh: where three charts
/// meet, the dual can miss or double a triangle), with the image's surface arrays at its
/// vertices and their SiteId.
void FillAtlasRemesh(vtkPolyData* output, vtkImageData* input, const cvt::GeometryImage& image,
  const std::vector<int>& labels, const std::vector<double>& vertices,
  const std::vector<long long>& pixels)
{
  // Sites whose cells hold a pixel of the surface's own border (SurfaceBorder): their holes in
  // the dual are the surface's, not to be closed.
  std::vector<char> onBorder(vertices.size() / 3, 0);
  for (size_t p = 0; p < image.Border.size(); ++p)
  {
    if (image.Border[p] && labels[p] >= 0)
    {
      onBorder[static_cast<size_t>(labels[p])] = 1;
    }
  }
  const cvt::Remesh remesh =
    cvt::ManifoldRemesh(vertices, cvt::DualTriangles(image, labels, vertices), onBorder);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(remesh.SiteIds.size()));
  std::vector<long long> at(remesh.SiteIds.size());
  for (size_t v = 0; v < remesh.SiteIds.size(); ++v)
  {
    points->SetPoint(static_cast<vtkIdType>(v), &remesh.Points[3 * v]);
    at[v] = pixels[static_cast<size_t>(remesh.SiteIds[v])];
  }
  output->SetPoints(points);
  output->SetPolys(cvtvtk::TriangleCells(remesh.Triangles));
  cvtvtk::AddMeshQuality(output->GetFieldData(), cvt::MeasureMesh(remesh.Points, remesh.Triangles));
  cvtvtk::AddFieldValue(output->GetFieldData(), "RemovedTriangles", remesh.RemovedTriangles);
  cvtvtk::AddFieldValue(output->GetFieldData(), "FilledHoles", remesh.FilledHoles);
  output->GetPointData()->AddArray(cvtvtk::SiteIdArray(remesh.SiteIds));
  CopySurfaceArrays(input->GetPointData(), at, output->GetPointData());
}

/// Weighs each pixel's area by the density array `name` of the geometry image (one component;
/// cvt::CheckDensity's rules on the surface's pixels: finite, not negative, not all zero), so
/// that a pixel's mass is its area times the density there; else false with what to fix.
bool WeighByDensity(
  vtkImageData* input, const std::string& name, cvt::GeometryImage& image, std::string& error)
{
  vtkDataArray* array = input->GetPointData()->GetArray(name.c_str());
  if (!array || array->GetNumberOfComponents() != 1)
  {
    error = "The geometry image has no one-component point array '" + name +
      "' to use as density; name a point array (vtkCVTMeshGeometryImage carries the mesh's) or "
      "leave DensityArray empty.";
    return false;
  }
  std::vector<float> density(static_cast<size_t>(image.NumberOfPixels()), 0.0f);
  for (long long p = 0; p < image.NumberOfPixels(); ++p)
  {
    density[p] = image.IsValid(p) ? static_cast<float>(array->GetComponent(p, 0)) : 0.0f;
  }
  cvt::Grid pixels;
  pixels.Width = image.Width;
  pixels.Height = image.Height;
  const std::string problem = cvt::CheckDensity(pixels, density);
  if (!problem.empty())
  {
    error = "The density array '" + name + "' on the surface: " + problem + ".";
    return false;
  }
  for (long long p = 0; p < image.NumberOfPixels(); ++p)
  {
    image.AreaWeight[p] *= density[p];
  }
  return true;
}
}

//------------------------------------------------------------------------------
vtkCVTSurfaceFilter::vtkCVTSurfaceFilter()
{
  this->SetNumberOfInputPorts(1);
  // What progress bars show (ParaView: the label the user knows, not the class name).
  this->SetProgressText("CVT Surface");
}

//------------------------------------------------------------------------------
vtkCVTSurfaceFilter::~vtkCVTSurfaceFilter() = default;

//------------------------------------------------------------------------------
vtkImageData* vtkCVTSurfaceFilter::GetLabelsOutput()
{
  return vtkImageData::SafeDownCast(this->GetOutputDataObject(LabelsPort));
}

//------------------------------------------------------------------------------
vtkPolyData* vtkCVTSurfaceFilter::GetRemeshOutput()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(RemeshPort));
}

//------------------------------------------------------------------------------
int vtkCVTSurfaceFilter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  return 1;
}

//------------------------------------------------------------------------------
bool vtkCVTSurfaceFilter::ReadGeometryImage(
  vtkImageData* input, cvt::GeometryImage& image, std::string& error)
{
  if (!input || input->GetNumberOfPoints() == 0)
  {
    error = "The geometry image is empty; give a vtkImageData with a Position array.";
    return false;
  }
  int dims[3];
  input->GetDimensions(dims);
  if (dims[2] != 1)
  {
    error = "The geometry image is 3D (" + std::to_string(dims[0]) + " x " +
      std::to_string(dims[1]) + " x " + std::to_string(dims[2]) + "); it must be one 2D slice.";
    return false;
  }
  image = cvt::GeometryImage();
  image.Width = dims[0];
  image.Height = dims[1];
  vtkFieldData* inFields = input->GetFieldData();
  image.WrapU = inFields->GetArray("WrapU") && inFields->GetArray("WrapU")->GetTuple1(0) != 0.0;
  image.WrapV = inFields->GetArray("WrapV") && inFields->GetArray("WrapV")->GetTuple1(0) != 0.0;
  vtkPointData* pd = input->GetPointData();
  if (!ReadFloats(pd->GetArray("Position"), 3, image.Position))
  {
    error = "The input is not a geometry image (no 3-component point array 'Position'); make "
            "one with CVT Geometry Image or CVT Mesh Geometry Image (vtkCVTGeometryImageSource, "
            "vtkCVTMeshGeometryImage), or remesh a mesh with CVT Remesh (vtkCVTRemeshFilter).";
    return false;
  }
  if (!ReadFloats(pd->GetArray("Normal"), 3, image.Normal))
  {
    image.Normal = cvt::NormalsFromPositions(image);
  }
  if (vtkDataArray* mask = pd->GetArray("Mask"))
  {
    image.Mask.resize(static_cast<size_t>(mask->GetNumberOfTuples()));
    for (vtkIdType p = 0; p < mask->GetNumberOfTuples(); ++p)
    {
      image.Mask[p] = mask->GetComponent(p, 0) != 0.0 ? 1 : 0;
    }
  }
  if (vtkDataArray* seams = pd->GetArray("SeamPartner"))
  {
    image.SeamPartner.resize(static_cast<size_t>(seams->GetNumberOfTuples()));
    for (vtkIdType p = 0; p < seams->GetNumberOfTuples(); ++p)
    {
      image.SeamPartner[p] = static_cast<int>(seams->GetComponent(p, 0));
    }
  }
  if (vtkDataArray* border = pd->GetArray("SurfaceBorder"))
  {
    image.Border.resize(static_cast<size_t>(border->GetNumberOfTuples()));
    for (vtkIdType p = 0; p < border->GetNumberOfTuples(); ++p)
    {
      image.Border[p] = border->GetComponent(p, 0) != 0.0 ? 1 : 0;
    }
  }
  if (!ReadFloats(pd->GetArray("AreaWeight"), 1, image.AreaWeight))
  {
    image.AreaWeight = cvt::ComputeAreaWeights(image);
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkCVTSurfaceFilter::Compute(
  vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkImageData* input = vtkImageData::GetData(inputVector[0], 0);
  cvt::GeometryImage image;
  std::string error;
  if (!ReadGeometryImage(input, image, error))
  {
    vtkErrorMacro("" << error);
    return false;
  }
  error = cvt::CheckGeometryImage(image, this->NumberOfSites);
  if (!error.empty())
  {
    vtkErrorMacro("Bad geometry image: " << error << ".");
    return false;
  }
  const AreaWeights weights = MeasureAreaWeights(image);
  // The measures above stay areas; the weights become masses.
  const bool weighted = !this->DensityArray.empty() && this->DensityArray != UniformDensityName();
  if (weighted && !WeighByDensity(input, this->DensityArray, image, error))
  {
    vtkErrorMacro("" << error);
    return false;
  }
  // A cell should cover a good many pixels, even where pixels are largest.
  const double cellArea = weights.Total / this->NumberOfSites;
  if (weights.Maximum > cellArea / 8.0)
  {
    vtkWarningMacro("The geometry image is coarse for "
      << this->NumberOfSites << " sites: its largest pixels cover " << weights.Maximum / cellArea
      << " of a cell; use a finer resolution.");
  }

  const cvtvtk::EngineChoice choice = cvtvtk::ChooseEngine(this->Engine);
  const bool computed = choice.UseOpenGL
    ? this->RunOnGPU(input, image, choice.Reason, outputVector)
    : this->RunOnCPU(input, image, weights.ValidPixels, weighted, choice.Reason, outputVector);
  if (computed)
  {
    vtkFieldData* fields = vtkPolyData::GetData(outputVector, SitesPort)->GetFieldData();
    cvtvtk::AddFieldValue(fields, "MinimumAreaWeight", weights.Minimum);
    cvtvtk::AddFieldValue(fields, "MaximumAreaWeight", weights.Maximum);
    if (choice.UseOpenGL)
    {
      cvtvtk::AddFieldValue(fields, "SurfaceArea", weights.Total); // the CPU run adds its own
    }
  }
  return computed;
}

//------------------------------------------------------------------------------
bool vtkCVTSurfaceFilter::DrawSites(
  const cvt::GeometryImage& image, std::vector<double>& sites, std::vector<long long>& pixels)
{
  sites = cvt::SampleSurfaceSites(
    image, this->NumberOfSites, static_cast<std::uint64_t>(this->RandomSeed), pixels);
  if (static_cast<int>(pixels.size()) < this->NumberOfSites)
  {
    vtkErrorMacro("Only " << pixels.size() << " distinct pixels could hold the "
                          << this->NumberOfSites << " sites; use fewer sites or a finer image.");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkCVTSurfaceFilter::RunOnGPU(vtkImageData* input, const cvt::GeometryImage& image,
  const std::string& reason, vtkInformationVector* outputVector)
{
  std::vector<double> sites;
  std::vector<long long> pixels;
  if (!this->DrawSites(image, sites, pixels))
  {
    return false;
  }
  vtkCVTSurfaceEngine* engine = this->GetOpenGLEngine<vtkCVTSurfaceEngine>();
  const bool ready = engine->SetGeometryImage(image);
  this->ContextDescription = engine->GetContextDescription();
  // Under MPI the ranks share the reductions (each its band of the image's rows) if every rank
  // runs this engine.
  const int ranks = this->ShareCellSumsAcrossRanks(engine, ready, outputVector);
  cvt::GeometryImageProblem surface(*engine, image);
  cvt::OptimizerResult result;
  std::string error;
  std::vector<int> labels;
  const bool optimized = ready &&
    this->Optimize(
      surface, cvt::SiteState{ sites, pixels }, this->GetOptimizerOptions(), result, error) &&
    engine->GetLabels(labels);
  if (!optimized)
  {
    vtkErrorMacro("The GPU surface CVT failed: "
      << (ready && !error.empty() ? error : engine->GetLastError()) << ".");
    return false;
  }

  // --- Outputs.
  vtkPolyData* sitesOut = vtkPolyData::GetData(outputVector, SitesPort);
  vtkSmartPointer<vtkPoints> points =
    cvtvtk::FillSites(sitesOut, result.Sites, 3, 0.0, result.Sums);
  vtkFieldData* fields = sitesOut->GetFieldData();
  AddRunFields(fields, result, surface.GradientNorm(result.Sums));
  cvtvtk::AddFieldString(fields, "Engine", "OpenGL");
  cvtvtk::AddFieldString(fields, "EngineReason", reason);
  cvtvtk::AddFieldValue(fields, "EngineRanks", ranks); // ranks sharing the cell sums

  vtkImageData* labelsOut = vtkImageData::GetData(outputVector, LabelsPort);
  labelsOut->ShallowCopy(input);
  labelsOut->GetPointData()->AddArray(cvtvtk::SiteIdArray(labels));

  vtkPolyData* remeshOut = vtkPolyData::GetData(outputVector, RemeshPort);
  if (!image.SeamPartner.empty())
  {
    FillAtlasRemesh(remeshOut, input, image, labels, result.Sites, result.Pixels);
  }
  else
  {
    const std::vector<std::array<int, 3>> dual = cvt::DualTriangles(image, labels, result.Sites);
    remeshOut->SetPoints(points);
    remeshOut->SetPolys(cvtvtk::TriangleCells(dual));
    cvtvtk::AddMeshQuality(remeshOut->GetFieldData(), cvt::MeasureMesh(result.Sites, dual));
    vtkNew<vtkIntArray> remeshIds;
    remeshIds->DeepCopy(sitesOut->GetPointData()->GetArray("SiteId"));
    remeshOut->GetPointData()->AddArray(remeshIds);
    CopySurfaceArrays(input->GetPointData(), result.Pixels, remeshOut->GetPointData());
  }
  cvtvtk::FillHistoryTable(vtkTable::GetData(outputVector, HistoryPort), result.History);
  return true;
}

//------------------------------------------------------------------------------
bool vtkCVTSurfaceFilter::RunOnCPU(vtkImageData* input, const cvt::GeometryImage& image,
  long long valid, bool weighted, const std::string& reason, vtkInformationVector* outputVector)
{
  // About 20 triangles per site: the restricted cells are exact on the triangles, which differ
  // from the surface by their chords only (torus at 1000 sites: energy on a dense image -0.29%
  // from Geogram's, where 60 per site gave -0.14%, at two thirds of the time).
  const double wanted = std::max(20000.0, 20.0 * this->NumberOfSites);
  const int stride = std::max(1, static_cast<int>(std::floor(std::sqrt(2.0 * valid / wanted))));
  if (!image.SeamPartner.empty())
  {
    return this->RunAtlasOnCPU(input, image, stride, weighted, reason, outputVector);
  }
  std::vector<double> coordinates;
  std::vector<std::array<int, 3>> triangles;
  std::vector<long long> pixels;
  cvt::GeometryImageMesh(image, stride, coordinates, triangles, &pixels);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(coordinates.size() / 3));
  for (vtkIdType p = 0; p < points->GetNumberOfPoints(); ++p)
  {
    points->SetPoint(p, &coordinates[3 * p]);
  }
  vtkNew<vtkPolyData> mesh;
  mesh->SetPoints(points);
  mesh->SetPolys(cvtvtk::TriangleCells(triangles));
  // The surface's arrays at the points: the remesher takes its density from them and
  // interpolates them onto the remesh.
  CopySurfaceArrays(input->GetPointData(), pixels, mesh->GetPointData());
  vtkNew<vtkCVTRemeshFilter> remesher;
  if (weighted)
  {
    remesher->SetDensityArray(this->DensityArray.c_str());
  }

  remesher->SetInputData(mesh);
  remesher->CopyOptimizerSettings(this);
  remesher->SetCollapseForValence(this->CollapseForValence);
  // Under MPI the ranks share its clipping of the triangles; the outputs are split below.
  remesher->ShareRanksLike(outputVector->GetInformationObject(0));
  // Its errors become ours; its progress is ours, and our abort stops it.
  struct Relay
  {
    vtkCVTSurfaceFilter* Self;
    vtkCVTRemeshFilter* Inner;
    std::string Error;
  } relay{ this, remesher, std::string() };
  vtkNew<vtkCallbackCommand> onProgress, onError, onWarning;
  onProgress->SetClientData(&relay);
  onProgress->SetCallback(
    [](vtkObject*, unsigned long, void* client, void* data)
    {
      auto* r = static_cast<Relay*>(client);
      r->Self->UpdateProgress(*static_cast<double*>(data));
      if (r->Self->GetAbortExecute())
      {
        r->Inner->SetAbortExecute(1);
      }
    });
  onError->SetClientData(&relay);
  onError->SetCallback(
    [](vtkObject*, unsigned long, void* client, void* data)
    {
      const std::string text = static_cast<const char*>(data);
      const size_t header = text.find("): ");
      static_cast<Relay*>(client)->Error =
        header == std::string::npos ? text : text.substr(header + 3);
    });
  // Its warnings (the merged points of a sphere's poles) say nothing about the user's input.
  onWarning->SetCallback([](vtkObject*, unsigned long, void*, void*) {});
  remesher->AddObserver(vtkCommand::ProgressEvent, onProgress);
  remesher->AddObserver(vtkCommand::ErrorEvent, onError);
  remesher->AddObserver(vtkCommand::WarningEvent, onWarning);
  remesher->Update();
  if (remesher->GetSitesOutput()->GetNumberOfPoints() == 0)
  {
    vtkErrorMacro("The CPU surface CVT failed: " << relay.Error);
    return false;
  }
  vtkPolyData* sitesOut = vtkPolyData::GetData(outputVector, SitesPort);
  sitesOut->ShallowCopy(remesher->GetSitesOutput());
  vtkPolyData::GetData(outputVector, RemeshPort)->ShallowCopy(remesher->GetRemeshOutput());
  vtkTable::GetData(outputVector, HistoryPort)->ShallowCopy(remesher->GetHistoryOutput());
  std::ostringstream why;
  why << reason << "; the geometry image as " << triangles.size() << " triangles (every " << stride
      << " pixels), exact restricted Voronoi cells";
  vtkFieldData* fields = sitesOut->GetFieldData();
  fields->RemoveArray("EngineReason");
  cvtvtk::AddFieldString(fields, "EngineReason", why.str());

  vtkImageData* labelsOut = vtkImageData::GetData(outputVector, LabelsPort);
  labelsOut->ShallowCopy(input);
  std::vector<double> sites(3 * static_cast<size_t>(sitesOut->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < sitesOut->GetNumberOfPoints(); ++i)
  {
    sitesOut->GetPoint(i, &sites[3 * i]);
  }
  labelsOut->GetPointData()->AddArray(cvtvtk::SiteIdArray(cvt::NearestSiteLabels(image, sites)));
  return true;
}

//------------------------------------------------------------------------------
bool vtkCVTSurfaceFilter::RunAtlasOnCPU(vtkImageData* input, const cvt::GeometryImage& image,
  int stride, bool weighted, const std::string& reason, vtkInformationVector* outputVector)
{
  // The charts as one mesh of pieces, apart along the seams: the restricted Voronoi cells are
  // those of the 3D sites, so they reach across the seams whatever the mesh's pieces (the
  // sliver of a pixel or a stride between two charts is left out of their integrals).
  cvt::SurfaceMesh mesh;
  std::vector<long long> pointPixels;
  cvt::GeometryImageMesh(image, stride, mesh.Points, mesh.Triangles, &pointPixels);
  if (weighted)
  {
    vtkDataArray* density = input->GetPointData()->GetArray(this->DensityArray.c_str());
    for (long long p : pointPixels)
    {
      mesh.Density.push_back(density->GetTuple1(p)); // checked by WeighByDensity
    }
  }
  cvt::MeshRepairReport repairs;
  std::string error = cvt::RepairSurfaceMesh(mesh, repairs);
  if (!error.empty())
  {
    vtkErrorMacro("The charts of this atlas do not make a surface mesh: " << error << ".");
    return false;
  }
  std::vector<double> initial;
  std::vector<long long> pixels;
  if (!this->DrawSites(image, initial, pixels))
  {
    return false;
  }
  cvt::RestrictedVoronoi engine;
  const bool meshSet = engine.SetMesh(mesh);
  const int ranks = this->ShareCellSumsAcrossRanks(&engine, meshSet, outputVector);
  cvt::RestrictedProblem problem(engine);
  cvt::OptimizerOptions options = this->GetOptimizerOptions();
  options.LloydWarmUpIterations = std::min(5, this->MaximumNumberOfIterations); // as the mesh's
  cvt::OptimizerResult result;
  if (!meshSet || !this->Optimize(problem, cvt::SiteState{ initial, {} }, options, result, error))
  {
    vtkErrorMacro(
      "The CPU surface CVT failed: " << (error.empty() ? engine.GetLastError() : error) << ".");
    return false;
  }

  // --- Outputs: the sites as optimised (the centroids of their cells, slightly inside a curved
  // surface); the remesh's vertices the points of their cells nearest to them, on the surface.
  vtkPolyData* sitesOut = vtkPolyData::GetData(outputVector, SitesPort);
  cvtvtk::FillSites(sitesOut, result.Sites, 3, 0.0, result.Sums);
  vtkFieldData* fields = sitesOut->GetFieldData();
  AddRunFields(fields, result, result.Sums.GradientNorm());
  cvtvtk::AddFieldValue(fields, "SurfaceArea", cvt::SurfaceArea(mesh));
  cvtvtk::AddFieldString(fields, "Engine", "CPU");
  std::ostringstream why;
  why << reason << "; the atlas's charts as " << mesh.Triangles.size() << " triangles (every "
      << stride << " pixels), exact restricted Voronoi cells, the dual across the seams";
  cvtvtk::AddFieldString(fields, "EngineReason", why.str());
  cvtvtk::AddFieldValue(fields, "EngineRanks", ranks);

  const std::vector<int> labels = cvt::NearestSiteLabels(image, result.Sites);
  vtkImageData* labelsOut = vtkImageData::GetData(outputVector, LabelsPort);
  labelsOut->ShallowCopy(input);
  labelsOut->GetPointData()->AddArray(cvtvtk::SiteIdArray(labels));

  std::vector<double> vertices = initial;
  cvt::NearestPointsInCells(image, labels, result.Sites, vertices, pixels);
  FillAtlasRemesh(
    vtkPolyData::GetData(outputVector, RemeshPort), input, image, labels, vertices, pixels);

  cvtvtk::FillHistoryTable(vtkTable::GetData(outputVector, HistoryPort), result.History);
  return true;
}

//------------------------------------------------------------------------------
void vtkCVTSurfaceFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DensityArray: " << (this->DensityArray.empty() ? "(none)" : this->DensityArray)
     << "\n";
  os << indent << "CollapseForValence: " << (this->CollapseForValence ? "on" : "off") << "\n";
}
