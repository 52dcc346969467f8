#include "vtkCVTMeshGeometryImage.h"

#include "cvtAtlas.h"

#include "cvtParameterization.h"
#include "vtkCVTOutputHelpers.h"

#include "vtkCellArray.h"
#include "vtkCellLocator.h"
#include "vtkIdList.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTriangle.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

vtkStandardNewMacro(vtkCVTMeshGeometryImage);

namespace
{
/// The mesh's point arrays at the pixels: each pixel interpolates the points of the triangle it
/// samples (`triangles[sources.Triangle[p]]`, whose point ids `inputPoint` maps to the mesh's,
/// or keeps as they are when empty); pixels without a triangle get zeros. Names come out in
/// UTF-8 (MakeArrayNamesUtf8), for the XML writers.
void CarryPointData(vtkPolyData* mesh, const std::vector<std::array<int, 3>>& triangles,
  const std::vector<int>& inputPoint, const cvt::PixelSources& sources, vtkImageData* output)
{
  vtkPointData* in = mesh->GetPointData();
  vtkPointData* out = output->GetPointData();
  if (in->GetNumberOfArrays() == 0)
  {
    return;
  }
  const vtkIdType pixels = output->GetNumberOfPoints();
  vtkNew<vtkPointData> carried;
  carried->InterpolateAllocate(in, pixels);
  vtkNew<vtkIdList> corners;
  corners->SetNumberOfIds(3);
  for (vtkIdType p = 0; p < pixels; ++p)
  {
    const int t = sources.Triangle[p];
    if (t < 0)
    {
      carried->NullData(p);
      continue;
    }
    // Weights a rounding below 0 (a pixel on an edge) are clamped, so that values stay within
    // their corners' (a density of 0 and 1 never becomes -1e-9).
    double weights[3], sum = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      const int point = triangles[t][k];
      corners->SetId(k, inputPoint.empty() ? point : inputPoint[point]);
      weights[k] = std::max(0.0, static_cast<double>(sources.Barycentric[3 * p + k]));
      sum += weights[k];
    }
    for (double& w : weights)
    {
      w = sum > 0.0 ? w / sum : 1.0 / 3.0;
    }
    carried->InterpolatePoint(in, p, corners, weights);
  }
  cvtvtk::MakeArrayNamesUtf8(carried);
  for (int a = 0; a < carried->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* array = carried->GetAbstractArray(a);
    if (array->GetName() && !out->HasArray(array->GetName()))
    {
      out->AddArray(array);
    }
  }
}
} // namespace

//------------------------------------------------------------------------------
vtkCVTMeshGeometryImage::vtkCVTMeshGeometryImage()
{
  this->SetNumberOfInputPorts(1);
}

//------------------------------------------------------------------------------
int vtkCVTMeshGeometryImage::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

//------------------------------------------------------------------------------
int vtkCVTMeshGeometryImage::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  const int extent[6] = { 0, std::max(this->Resolution[0], 1) - 1, 0,
    std::max(this->Resolution[1], 1) - 1, 0, 0 };
  outputVector->GetInformationObject(0)->Set(
    vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  return 1;
}

//------------------------------------------------------------------------------
int vtkCVTMeshGeometryImage::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkImageData* output = vtkImageData::GetData(outputVector, 0);
  output->Initialize();
  if (!input || input->GetNumberOfPolys() == 0)
  {
    vtkErrorMacro("The mesh has no triangles; give a triangle mesh of disk topology.");
    return 0;
  }
  if (this->Resolution[0] < 2 || this->Resolution[1] < 2)
  {
    vtkErrorMacro("The resolution must be at least 2 x 2.");
    return 0;
  }
  const std::string memory =
    cvtvtk::GeometryImageMemoryError(this->Resolution[0], this->Resolution[1]);
  if (!memory.empty())
  {
    vtkErrorMacro("The geometry image is too large for this machine: " << memory << ".");
    return 0;
  }
  if (input->GetNumberOfVerts() + input->GetNumberOfLines() + input->GetNumberOfStrips() > 0)
  {
    vtkErrorMacro(
      "The mesh has vertices, lines or strips; give triangles only (vtkTriangleFilter).");
    return 0;
  }
  cvt::TriangleMesh mesh;
  mesh.Points.resize(3 * static_cast<size_t>(input->GetNumberOfPoints()));
  for (vtkIdType p = 0; p < input->GetNumberOfPoints(); ++p)
  {
    input->GetPoint(p, &mesh.Points[3 * p]);
  }
  vtkIdType npts;
  const vtkIdType* ids;
  vtkCellArray* polys = input->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(npts, ids);)
  {
    if (npts != 3)
    {
      vtkErrorMacro(
        "The mesh has a cell with " << npts << " points; give triangles only (vtkTriangleFilter).");
      return 0;
    }
    mesh.Triangles.push_back(
      { static_cast<int>(ids[0]), static_cast<int>(ids[1]), static_cast<int>(ids[2]) });
  }
  bool closed = false, manifold = false;
  const std::string problem = cvt::CheckMesh(mesh, closed, &manifold);
  if (!manifold)
  {
    vtkErrorMacro("Bad mesh: " << problem << ".");
    return 0;
  }
  // One chart where one suffices (a disk, a star-shaped genus-0 surface); an atlas for the rest
  // (several parts, genus, boundary loops, shapes not star-shaped) or when asked for.
  if (this->Parameterization == ATLAS || !problem.empty())
  {
    return this->BuildAtlas(input, mesh, output) ? 1 : 0;
  }
  cvt::PixelSources sources;
  if (closed)
  {
    cvt::GeometryImage image;
    std::string error;
    if (!this->SampleClosedMesh(input, image, sources, error))
    {
      return this->BuildAtlas(input, mesh, output) ? 1 : 0;
    }
    cvtvtk::WriteGeometryImage(image, output);
    CarryPointData(input, mesh.Triangles, {}, sources, output);
    return 1;
  }
  std::vector<double> uv;
  std::string error;
  if (!cvt::ParameterizeDisk(mesh, uv, error))
  {
    vtkErrorMacro("The mesh could not be parameterised: " << error << ".");
    return 0;
  }
  cvtvtk::WriteGeometryImage(
    cvt::ResampleMesh(mesh, uv, this->Resolution[0], this->Resolution[1], &sources), output);
  CarryPointData(input, mesh.Triangles, {}, sources, output);
  return 1;
}

//------------------------------------------------------------------------------
bool vtkCVTMeshGeometryImage::BuildAtlas(
  vtkPolyData* input, const cvt::TriangleMesh& triangles, vtkImageData* output)
{
  cvt::SurfaceMesh mesh;
  mesh.Points = triangles.Points;
  mesh.Triangles = triangles.Triangles;
  cvt::MeshRepairReport report;
  std::string error = cvt::RepairSurfaceMesh(mesh, report);
  if (!error.empty())
  {
    vtkErrorMacro("Cannot cut this mesh into charts: " << error << ".");
    return false;
  }
  if (report.Changed())
  {
    vtkWarningMacro("The mesh was repaired for its atlas: " << report.Summary() << ".");
  }
  cvt::AtlasOptions options;
  options.Width = this->Resolution[0];
  options.Height = this->Resolution[1];
  cvt::Atlas atlas;
  error = cvt::BuildAtlas(mesh, options, atlas);
  if (!error.empty())
  {
    vtkErrorMacro("The atlas failed: " << error << ".");
    return false;
  }
  cvtvtk::WriteGeometryImage(atlas.Image, output);
  output->GetPointData()->AddArray(cvtvtk::IntArray("ChartId", atlas.Chart));
  // The repairs may have copied points: SourceIds names each one's input point.
  CarryPointData(input, mesh.Triangles, mesh.SourceIds, atlas.Sources, output);
  vtkFieldData* fields = output->GetFieldData();
  cvtvtk::AddFieldValue(fields, "NumberOfCharts", atlas.NumberOfCharts);
  cvtvtk::AddFieldValue(fields, "SeamLength", atlas.SeamLength);
  cvtvtk::AddFieldValue(fields, "SeamPixels", static_cast<double>(atlas.SeamPixels));
  cvtvtk::AddFieldValue(fields, "MinimumAreaStretch", atlas.MinimumAreaStretch);
  cvtvtk::AddFieldValue(fields, "MaximumAreaStretch", atlas.MaximumAreaStretch);
  cvtvtk::AddFieldValue(fields, "MaximumAngleStretch", atlas.MaximumAngleStretch);
  return true;
}

//------------------------------------------------------------------------------
bool vtkCVTMeshGeometryImage::SampleClosedMesh(
  vtkPolyData* mesh, cvt::GeometryImage& image, cvt::PixelSources& sources, std::string& error)
{
  // The centre: the area-weighted centroid. Every triangle must face away from it (or every
  // one towards it): then each ray from the centre meets the surface once.
  double centre[3] = { 0.0, 0.0, 0.0 }, area = 0.0;
  vtkIdType npts;
  const vtkIdType* ids;
  vtkCellArray* polys = mesh->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(npts, ids);)
  {
    double a[3], b[3], c[3];
    mesh->GetPoint(ids[0], a);
    mesh->GetPoint(ids[1], b);
    mesh->GetPoint(ids[2], c);
    const double w = vtkTriangle::TriangleArea(a, b, c);
    for (int k = 0; k < 3; ++k)
    {
      centre[k] += w * (a[k] + b[k] + c[k]) / 3.0;
    }
    area += w;
  }
  for (double& c : centre)
  {
    c /= area;
  }
  int outward = 0, inward = 0;
  double radius = 0.0;
  for (polys->InitTraversal(); polys->GetNextCell(npts, ids);)
  {
    double a[3], b[3], c[3], normal[3];
    mesh->GetPoint(ids[0], a);
    mesh->GetPoint(ids[1], b);
    mesh->GetPoint(ids[2], c);
    vtkTriangle::ComputeNormal(a, b, c, normal);
    double toCentre[3];
    for (int k = 0; k < 3; ++k)
    {
      toCentre[k] = (a[k] + b[k] + c[k]) / 3.0 - centre[k];
      radius = std::max(radius, std::sqrt(vtkMath::Distance2BetweenPoints(a, centre)));
    }
    const double facing = vtkMath::Dot(normal, toCentre);
    outward += facing > 0.0 ? 1 : 0;
    inward += facing < 0.0 ? 1 : 0;
  }
  if (outward > 0 && inward > 0)
  {
    error = "it is not star-shaped about its centroid (some triangles face the centre, others "
            "away); the closed-surface parameterisation needs a star-shaped genus-0 mesh";
    return false;
  }
  // Cut open along a meridian and at the poles: columns around the axis (wrapped), rows from
  // pole to pole; each pixel is where the ray from the centre meets the surface.
  vtkNew<vtkCellLocator> locator;
  locator->SetDataSet(mesh);
  locator->BuildLocator();
  const int w = this->Resolution[0], h = this->Resolution[1];
  image = cvt::GeometryImage();
  image.Width = w;
  image.Height = h;
  image.WrapU = true;
  image.Position.resize(3 * static_cast<size_t>(w) * h);
  sources.Triangle.assign(static_cast<size_t>(w) * h, -1);
  sources.Barycentric.assign(3 * static_cast<size_t>(w) * h, 0.0f);
  const double pi = vtkMath::Pi();
  for (int j = 0; j < h; ++j)
  {
    const double polar = pi * j / (h - 1);
    for (int i = 0; i < w; ++i)
    {
      const double azimuth = 2.0 * pi * (i + 0.5) / w;
      const double direction[3] = { std::sin(polar) * std::cos(azimuth),
        std::sin(polar) * std::sin(azimuth), -std::cos(polar) };
      double end[3], hit[3], pcoords[3], t = 0.0;
      int subId = 0;
      vtkIdType cell = -1;
      for (int k = 0; k < 3; ++k)
      {
        end[k] = centre[k] + 2.0 * radius * direction[k];
      }
      if (!locator->IntersectWithLine(centre, end, 1e-9, t, hit, pcoords, subId, cell))
      {
        error = "a ray from the centroid missed the surface";
        return false;
      }
      const size_t p = static_cast<size_t>(j) * w + i;
      for (int k = 0; k < 3; ++k)
      {
        image.Position[3 * p + k] = static_cast<float>(hit[k]);
      }
      // A triangle's parametric coordinates (r, s) weigh its points 1 - r - s, r, s.
      sources.Triangle[p] = static_cast<int>(cell);
      sources.Barycentric[3 * p] = static_cast<float>(1.0 - pcoords[0] - pcoords[1]);
      sources.Barycentric[3 * p + 1] = static_cast<float>(pcoords[0]);
      sources.Barycentric[3 * p + 2] = static_cast<float>(pcoords[1]);
    }
  }
  image.Normal = cvt::NormalsFromPositions(image);
  image.AreaWeight = cvt::ComputeAreaWeights(image);
  return true;
}

//------------------------------------------------------------------------------
void vtkCVTMeshGeometryImage::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Resolution: " << this->Resolution[0] << " x " << this->Resolution[1] << "\n";
  os << indent << "Parameterization: " << (this->Parameterization == ATLAS ? "atlas" : "automatic")
     << "\n";
}
