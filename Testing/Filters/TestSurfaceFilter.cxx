// The surface filters: geometry images (area weights, meshes parameterised and resampled), the
// constrained CVT on a torus, remeshing of a torus and a sphere, both engines, bad input.
#include "cvtFilterTestSupport.h"
#include "cvtSurface.h"
#include "vtkCVTGeometryImageSource.h"
#include "vtkCVTMeshGeometryImage.h"
#include "vtkCVTRemeshFilter.h"
#include "vtkCVTSurfaceFilter.h"

#include "vtkCallbackCommand.h"
#include "vtkCell.h"
#include "vtkCellArray.h"
#include "vtkCleanPolyData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkParametricEllipsoid.h"
#include "vtkParametricTorus.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkStaticCellLocator.h"
#include "vtkTable.h"
#include "vtkTriangle.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <sstream>

using cvttest::TorusImage;

namespace
{
class ErrorCatcher : public vtkCommand
{
public:
  static ErrorCatcher* New() { return new ErrorCatcher; }
  void Execute(vtkObject*, unsigned long, void* data) override
  {
    this->Message += static_cast<const char*>(data);
  }
  std::string Message;
};

struct MeshCheck
{
  long long Vertices = 0, Edges = 0, Faces = 0;
  int NonManifoldEdges = 0, MisorientedEdges = 0, DuplicateFaces = 0;
  int BorderEdges = 0; // of NonManifoldEdges, those of one triangle
  int BorderLoops = 0; // the connected sets of their points
  long long Euler() const { return this->Vertices - this->Edges + this->Faces; }
};

MeshCheck CheckMesh(vtkPolyData* mesh)
{
  MeshCheck check;
  std::map<std::pair<vtkIdType, vtkIdType>, int> undirected, directed;
  std::set<std::set<vtkIdType>> faces;
  vtkIdType npts;
  const vtkIdType* ids;
  for (mesh->GetPolys()->InitTraversal(); mesh->GetPolys()->GetNextCell(npts, ids);)
  {
    ++check.Faces;
    check.DuplicateFaces += faces.insert({ ids[0], ids[1], ids[2] }).second ? 0 : 1;
    for (int e = 0; e < 3; ++e)
    {
      const vtkIdType a = ids[e], b = ids[(e + 1) % 3];
      ++undirected[{ std::min(a, b), std::max(a, b) }];
      ++directed[{ a, b }];
    }
  }
  check.Vertices = mesh->GetNumberOfPoints();
  check.Edges = static_cast<long long>(undirected.size());
  std::map<vtkIdType, vtkIdType> group; // union-find over the border edges' points
  const auto root = [&group](vtkIdType v)
  {
    while (group[v] != v)
    {
      v = group[v] = group[group[v]];
    }
    return v;
  };
  for (const auto& e : undirected)
  {
    check.NonManifoldEdges += e.second != 2 ? 1 : 0;
    if (e.second == 1)
    {
      ++check.BorderEdges;
      for (vtkIdType v : { e.first.first, e.first.second })
      {
        group.emplace(v, v);
      }
      group[root(e.first.first)] = root(e.first.second);
    }
  }
  for (const auto& [v, parent] : group)
  {
    check.BorderLoops += root(v) == v ? 1 : 0;
  }
  for (const auto& e : directed)
  {
    check.MisorientedEdges += e.second != 1 ? 1 : 0;
  }
  return check;
}
}

TEST(GeometryImage, TorusAreaWeightsSumToTheArea)
{
  auto image = TorusImage(256, 128);
  const double area = 4.0 * M_PI * M_PI * 1.0 * 0.4;
  const double total = image->GetFieldData()->GetArray("TotalArea")->GetTuple1(0);
  std::cout << "[ measured ] torus area " << total << " (exact " << area << ")\n";
  EXPECT_NEAR(total, area, 0.005 * area);
  EXPECT_EQ(image->GetFieldData()->GetArray("WrapU")->GetTuple1(0), 1.0);
  EXPECT_EQ(image->GetFieldData()->GetArray("WrapV")->GetTuple1(0), 1.0);
  // The inner ring's pixels are smaller than the outer ring's: (R - r) / (R + r).
  const double ratio = image->GetFieldData()->GetArray("MinimumAreaWeight")->GetTuple1(0) /
    image->GetFieldData()->GetArray("MaximumAreaWeight")->GetTuple1(0);
  EXPECT_NEAR(ratio, 0.6 / 1.4, 0.01);
}

TEST(SurfaceFilter, TorusWith600SitesAndItsRemesh)
{
  vtkNew<vtkCVTGeometryImageSource> source;
  source->SetResolution(256, 128);
  vtkNew<vtkCVTSurfaceFilter> cvt;
  cvt->SetInputConnection(source->GetOutputPort());
  cvt->SetNumberOfSites(600);
  cvt->SetMaximumNumberOfIterations(60);
  cvt->SetTolerance(0.0);
  int progress = 0;
  vtkNew<vtkCallbackCommand> onProgress;
  onProgress->SetClientData(&progress);
  onProgress->SetCallback(
    [](vtkObject*, unsigned long, void* data, void*) { ++*static_cast<int*>(data); });
  cvt->AddObserver(vtkCommand::ProgressEvent, onProgress);
  cvt->Update();
  vtkTable* history = cvt->GetHistoryOutput();
  ASSERT_GT(history->GetNumberOfRows(), 10);
  const double first = history->GetValueByName(0, "energy").ToDouble();
  const double last = cvt->GetSitesOutput()->GetFieldData()->GetArray("Energy")->GetTuple1(0);
  const double firstGradient = history->GetValueByName(0, "gradient_norm").ToDouble();
  const double lastGradient =
    cvt->GetSitesOutput()->GetFieldData()->GetArray("GradientNorm")->GetTuple1(0);
  std::cout << "[ measured ] torus, 600 sites: energy " << first << " -> " << last << ", |grad F| "
            << firstGradient << " -> " << lastGradient << "\n";
  // Random sites have energy A^2 / (pi n), a hexagonal CVT 0.1604 A^2 / n: at most a 49.6% fall.
  EXPECT_LT(last, 0.55 * first);
  EXPECT_LT(lastGradient, 0.2 * firstGradient);
  EXPECT_GT(progress, 10);

  vtkPolyData* sites = cvt->GetSitesOutput();
  ASSERT_EQ(sites->GetNumberOfPoints(), 600);
  for (vtkIdType i = 0; i < 600; ++i)
  {
    // On the torus: distance to the ring circle is r.
    double p[3];
    sites->GetPoint(i, p);
    const double ring = std::hypot(p[0], p[1]) - 1.0;
    EXPECT_NEAR(std::hypot(ring, p[2]), 0.4, 0.01);
  }
  const MeshCheck mesh = CheckMesh(cvt->GetRemeshOutput());
  EXPECT_EQ(mesh.Vertices, 600);
  EXPECT_EQ(mesh.NonManifoldEdges, 0);
  EXPECT_EQ(mesh.MisorientedEdges, 0);
  EXPECT_EQ(mesh.DuplicateFaces, 0);
  EXPECT_EQ(mesh.Euler(), 0);
  EXPECT_EQ(
    cvt->GetLabelsOutput()->GetPointData()->GetArray("SiteId")->GetNumberOfTuples(), 256 * 128);
}

// On the CPU engine the remesh is vtkCVTRemeshFilter's of the triangulated image: a vertex per
// site by default, as on the OpenGL engine; CollapseForValence on lets it collapse edges where
// that brings valences closer to 6, a vertex fewer each, with the same sites.
TEST(SurfaceFilter, CollapseForValenceReachesTheCpuRemesh)
{
  vtkNew<vtkCVTGeometryImageSource> source;
  source->SetResolution(256, 128);
  const auto run = [&source](bool collapse)
  {
    vtkSmartPointer<vtkCVTSurfaceFilter> cvt = vtkSmartPointer<vtkCVTSurfaceFilter>::New();
    cvt->SetInputConnection(source->GetOutputPort());
    cvt->SetEngineToCPU();
    cvt->SetNumberOfSites(600);
    cvt->SetMaximumNumberOfIterations(30);
    cvt->SetCollapseForValence(collapse);
    cvt->Update();
    return cvt;
  };
  const auto field = [](vtkPolyData* data, const char* name)
  {
    vtkDataArray* array = data->GetFieldData()->GetArray(name);
    return array ? array->GetTuple1(0) : std::numeric_limits<double>::quiet_NaN();
  };
  vtkSmartPointer<vtkCVTSurfaceFilter> keeping = run(false), collapsing = run(true);
  EXPECT_FALSE(vtkNew<vtkCVTSurfaceFilter>()->GetCollapseForValence()); // the default
  std::ostringstream printed;
  collapsing->Print(printed);
  EXPECT_NE(printed.str().find("CollapseForValence: on"), std::string::npos);
  vtkPolyData* kept = keeping->GetRemeshOutput();
  vtkPolyData* collapsed = collapsing->GetRemeshOutput();
  EXPECT_EQ(kept->GetNumberOfPoints(), 600);
  EXPECT_EQ(field(kept, "ValenceCollapses"), 0);
  const double collapses = field(collapsed, "ValenceCollapses");
  EXPECT_GT(collapses, 0);
  EXPECT_EQ(collapsed->GetNumberOfPoints() + collapses, 600);
  EXPECT_GT(field(collapsed, "InteriorValence6Fraction"), field(kept, "InteriorValence6Fraction"));
  EXPECT_EQ(
    field(keeping->GetSitesOutput(), "Energy"), field(collapsing->GetSitesOutput(), "Energy"));
  const MeshCheck mesh = CheckMesh(collapsed);
  EXPECT_EQ(mesh.NonManifoldEdges, 0);
  EXPECT_EQ(mesh.Euler(), 0);
  std::cout << "[ measured ] torus, 600 sites on the CPU engine: valence 6 "
            << field(kept, "InteriorValence6Fraction") << " -> "
            << field(collapsed, "InteriorValence6Fraction") << " with " << collapses
            << " collapses\n";
}

TEST(SurfaceFilter, WarnsWhenTheGeometryImageIsTooCoarse)
{
  vtkNew<vtkCVTGeometryImageSource> source;
  source->SetResolution(32, 16); // 512 pixels for 200 sites
  vtkNew<vtkCVTSurfaceFilter> cvt;
  cvt->SetInputConnection(source->GetOutputPort());
  cvt->SetNumberOfSites(200);
  cvt->SetMaximumNumberOfIterations(2);
  vtkNew<ErrorCatcher> warnings;
  cvt->AddObserver(vtkCommand::WarningEvent, warnings);
  cvt->Update();
  EXPECT_NE(warnings->Message.find("coarse"), std::string::npos) << warnings->Message;
  EXPECT_EQ(cvt->GetSitesOutput()->GetNumberOfPoints(), 200); // a warning, not an error
  vtkFieldData* fields = cvt->GetSitesOutput()->GetFieldData();
  EXPECT_GT(fields->GetArray("MaximumAreaWeight")->GetTuple1(0),
    fields->GetArray("MinimumAreaWeight")->GetTuple1(0));
}

TEST(SurfaceFilter, SeedToleranceAndCorrectionsTakeEffect)
{
  vtkNew<vtkCVTGeometryImageSource> source;
  source->SetResolution(128, 64);
  const auto run = [&source](int seed, double tolerance, double gradientTolerance, int corrections)
  {
    auto cvt = vtkSmartPointer<vtkCVTSurfaceFilter>::New();
    cvt->SetInputConnection(source->GetOutputPort());
    cvt->SetNumberOfSites(80);
    cvt->SetRandomSeed(seed);
    cvt->SetMaximumNumberOfIterations(200);
    cvt->SetTolerance(tolerance);
    cvt->SetGradientTolerance(gradientTolerance);
    cvt->SetNumberOfCorrections(corrections);
    cvt->Update();
    return cvt;
  };
  auto a = run(3, 1e-3, 0.0, 7), b = run(3, 1e-3, 0.0, 7), c = run(4, 1e-3, 0.0, 7);
  double pa[3], pb[3], pc[3];
  a->GetSitesOutput()->GetPoint(0, pa);
  b->GetSitesOutput()->GetPoint(0, pb);
  c->GetSitesOutput()->GetPoint(0, pc);
  EXPECT_EQ(pa[0], pb[0]); // the same seed gives the same sites
  EXPECT_NE(pa[0], pc[0]);
  EXPECT_LT(a->GetHistoryOutput()->GetNumberOfRows(), 200);
  EXPECT_EQ(cvttest::StopReason(a), "relative energy decrease below tolerance");
  auto g = run(3, 0.0, 0.3, 7);
  EXPECT_EQ(cvttest::StopReason(g), "gradient tolerance reached");
  // One correction takes another path than seven once the memory fills (on the CPU engine
  // after its five Lloyd steps).
  auto seven = run(3, 0.0, 0.02, 7), one = run(3, 0.0, 0.02, 1);
  vtkTable* h7 = seven->GetHistoryOutput();
  vtkTable* h1 = one->GetHistoryOutput();
  ASSERT_GT(std::min(h7->GetNumberOfRows(), h1->GetNumberOfRows()), 10);
  EXPECT_NE(
    h7->GetValueByName(10, "energy").ToDouble(), h1->GetValueByName(10, "energy").ToDouble());
}

TEST(SurfaceFilter, AdaptiveJumpFloodingReachesTheOpenGLEngine)
{
  // On: once the sites are spread the labelling starts from a shorter step than the full one
  // (64 on 128 x 64); off: always the full step. On the CPU engine there is no flooding (0).
  vtkNew<vtkCVTGeometryImageSource> source;
  source->SetResolution(128, 64);
  const auto lastStep = [&source](int engine, bool adaptive)
  {
    vtkNew<vtkCVTSurfaceFilter> cvt;
    cvt->SetInputConnection(source->GetOutputPort());
    cvt->SetNumberOfSites(150);
    cvt->SetMaximumNumberOfIterations(10);
    cvt->SetEngine(engine);
    cvt->SetAdaptiveJumpFlooding(adaptive);
    cvt->Update();
    EXPECT_EQ(cvt->GetSitesOutput()->GetNumberOfPoints(), 150);
    return cvt->GetLastJumpFloodingStep();
  };
  EXPECT_EQ(lastStep(vtkCVTSurfaceFilter::OPENGL, false), 64);
  EXPECT_LT(lastStep(vtkCVTSurfaceFilter::OPENGL, true), 64);
  EXPECT_EQ(lastStep(vtkCVTSurfaceFilter::CPU, true), 0);
}

TEST(SurfaceFilter, AbortStopsTheIterations)
{
  vtkNew<vtkCVTGeometryImageSource> source;
  source->SetResolution(64, 32);
  vtkNew<vtkCVTSurfaceFilter> cvt;
  cvt->SetInputConnection(source->GetOutputPort());
  cvt->SetNumberOfSites(50);
  cvt->SetMaximumNumberOfIterations(1000);
  cvt->SetTolerance(0.0);
  vtkNew<vtkCallbackCommand> abortSoon;
  abortSoon->SetCallback(
    [](vtkObject* caller, unsigned long, void*, void*)
    {
      auto* filter = static_cast<vtkCVTSurfaceFilter*>(caller);
      if (filter->GetProgress() > 0.002)
      {
        filter->AbortExecuteOn();
      }
    });
  cvt->AddObserver(vtkCommand::ProgressEvent, abortSoon);
  cvt->Update();
  EXPECT_LT(cvt->GetHistoryOutput()->GetNumberOfRows(), 20);
}

TEST(SurfaceFilter, SphereRemeshIsClosedWithEulerCharacteristicTwo)
{
  vtkNew<vtkCVTGeometryImageSource> source;
  vtkNew<vtkParametricEllipsoid> sphere; // cut open along a meridian, poles at two rows
  source->SetParametricFunction(sphere);
  source->SetResolution(128, 64);
  vtkNew<vtkCVTSurfaceFilter> cvt;
  cvt->SetInputConnection(source->GetOutputPort());
  cvt->SetNumberOfSites(150);
  cvt->SetMaximumNumberOfIterations(40);
  cvt->SetMethodToLloyd();
  cvt->Update();
  const MeshCheck mesh = CheckMesh(cvt->GetRemeshOutput());
  // Every site is a vertex, but where the CPU path collapsed an edge of a thin triangle (the
  // OpenGL path, taken on a hardware GPU, collapses none and has no such field).
  vtkDataArray* collapsedEdges = cvt->GetRemeshOutput()->GetFieldData()->GetArray("CollapsedEdges");
  const double collapsed = collapsedEdges ? collapsedEdges->GetTuple1(0) : 0.0;
  EXPECT_LE(collapsed, 3.0);
  EXPECT_EQ(mesh.Vertices + collapsed, 150);
  EXPECT_EQ(mesh.NonManifoldEdges, 0);
  EXPECT_EQ(mesh.MisorientedEdges, 0);
  EXPECT_EQ(mesh.Euler(), 2);
}

namespace
{
std::string FailWith(vtkImageData* image, int sites = 10)
{
  vtkNew<vtkCVTSurfaceFilter> cvt;
  vtkNew<ErrorCatcher> catcher;
  cvt->AddObserver(vtkCommand::ErrorEvent, catcher);
  cvt->SetInputData(image);
  cvt->SetNumberOfSites(sites);
  cvt->Update();
  EXPECT_EQ(cvt->GetSitesOutput()->GetNumberOfPoints(), 0);
  EXPECT_EQ(cvt->GetRemeshOutput()->GetNumberOfCells(), 0);
  EXPECT_EQ(cvt->GetHistoryOutput()->GetNumberOfRows(), 0);
  EXPECT_FALSE(catcher->Message.empty());
  return catcher->Message;
}
}

TEST(SurfaceFilterBadInput, EveryBadGeometryImageSaysWhatToFix)
{
  vtkNew<vtkImageData> empty;
  EXPECT_NE(FailWith(empty).find("empty"), std::string::npos);

  vtkNew<vtkImageData> noPositions;
  noPositions->SetDimensions(8, 8, 1);
  EXPECT_NE(FailWith(noPositions).find("'Position'"), std::string::npos);

  auto nan = TorusImage(16, 8);
  vtkFloatArray::SafeDownCast(nan->GetPointData()->GetArray("Position"))
    ->SetComponent(5, 1, std::numeric_limits<float>::quiet_NaN());
  EXPECT_NE(FailWith(nan).find("not finite"), std::string::npos);

  auto masked = TorusImage(16, 8);
  vtkUnsignedCharArray* mask =
    vtkUnsignedCharArray::SafeDownCast(masked->GetPointData()->GetArray("Mask"));
  for (vtkIdType p = 5; p < mask->GetNumberOfTuples(); ++p)
  {
    mask->SetValue(p, 0);
  }
  EXPECT_NE(FailWith(masked).find("mask leaves 5 pixels"), std::string::npos);

  EXPECT_NE(FailWith(TorusImage(16, 8), 0).find("at least one"), std::string::npos);

  vtkNew<vtkImageData> volume;
  volume->SetDimensions(4, 4, 4);
  EXPECT_NE(FailWith(volume).find("3D"), std::string::npos);
}

namespace
{
vtkSmartPointer<vtkPolyData> Hemisphere()
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(0.5);
  sphere->SetThetaResolution(48);
  sphere->SetPhiResolution(24);
  sphere->SetEndPhi(90.0); // the upper half: a disk bounded by the equator
  vtkNew<vtkCleanPolyData> clean;
  clean->SetInputConnection(sphere->GetOutputPort());
  clean->Update();
  return clean->GetOutput();
}

double MeshArea(vtkPolyData* mesh)
{
  double area = 0.0;
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    double a[3], b[3], d[3];
    vtkCell* cell = mesh->GetCell(c);
    mesh->GetPoint(cell->GetPointId(0), a);
    mesh->GetPoint(cell->GetPointId(1), b);
    mesh->GetPoint(cell->GetPointId(2), d);
    area += vtkTriangle::TriangleArea(a, b, d);
  }
  return area;
}

/// The CVT energy of `sites` (their points) on `mesh`: exact restricted Voronoi cells
/// (vtkCVTRemeshFilter with the sites as given and no iterations).
double EnergyOnMesh(vtkPolyData* mesh, vtkPolyData* sites)
{
  vtkNew<vtkCVTRemeshFilter> exact;
  exact->SetInputData(mesh);
  exact->SetInitialSitesData(sites);
  exact->SetMaximumNumberOfIterations(0);
  exact->Update();
  vtkDataArray* energy = exact->GetSitesOutput()->GetFieldData()->GetArray("Energy");
  return energy ? energy->GetTuple1(0) : std::nan("");
}

std::string MeshError(vtkPolyData* mesh)
{
  vtkNew<vtkCVTMeshGeometryImage> gi;
  vtkNew<ErrorCatcher> catcher;
  gi->AddObserver(vtkCommand::ErrorEvent, catcher);
  gi->SetInputData(mesh);
  gi->SetResolution(32, 32);
  gi->Update();
  EXPECT_EQ(gi->GetOutput()->GetNumberOfPoints(), 0);
  return catcher->Message;
}
}

TEST(GeometryImageSource, BeyondThisMachinesMemoryIsRefusedBeforeAllocating)
{
  vtkNew<vtkCVTGeometryImageSource> source;
  vtkNew<ErrorCatcher> catcher;
  source->AddObserver(vtkCommand::ErrorEvent, catcher);
  source->SetResolution(200000, 200000); // 2.3 TB
  source->Update();
  EXPECT_EQ(source->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_NE(catcher->Message.find("too large for this machine"), std::string::npos)
    << catcher->Message;
}

TEST(MeshGeometryImage, DiskMeshIsParameterisedResampledAndRemeshed)
{
  auto mesh = Hemisphere();
  vtkNew<vtkCVTMeshGeometryImage> gi;
  gi->SetInputData(mesh);
  gi->SetResolution(128, 128);
  gi->Update();
  const double area = MeshArea(mesh);
  const double total = gi->GetOutput()->GetFieldData()->GetArray("TotalArea")->GetTuple1(0);
  std::cout << "[ measured ] hemisphere mesh area " << area << ", geometry image " << total
            << ", distortion max/min "
            << gi->GetOutput()->GetFieldData()->GetArray("MaximumAreaWeight")->GetTuple1(0) /
      gi->GetOutput()->GetFieldData()->GetArray("MinimumAreaWeight")->GetTuple1(0)
            << "\n";
  EXPECT_NEAR(total, area, 0.02 * area);

  vtkNew<vtkCVTSurfaceFilter> cvt;
  cvt->SetInputConnection(gi->GetOutputPort());
  cvt->SetNumberOfSites(120);
  cvt->SetMaximumNumberOfIterations(30);
  cvt->SetMethodToLloyd();
  cvt->Update();
  ASSERT_EQ(cvt->GetSitesOutput()->GetNumberOfPoints(), 120);
  for (vtkIdType i = 0; i < 120; ++i)
  {
    double p[3];
    cvt->GetSitesOutput()->GetPoint(i, p);
    EXPECT_NEAR(std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]), 0.5, 0.01);
  }
  const MeshCheck remesh = CheckMesh(cvt->GetRemeshOutput());
  EXPECT_EQ(remesh.MisorientedEdges, 0);
  EXPECT_EQ(remesh.DuplicateFaces, 0);
  EXPECT_EQ(remesh.Euler(), 1); // a disk
}

TEST(MeshGeometryImageBadInput, EveryBadMeshSaysWhatToFix)
{
  vtkNew<vtkPlaneSource> quads; // quadrilaterals, not triangles
  quads->Update();
  EXPECT_NE(MeshError(quads->GetOutput()).find("triangles only"), std::string::npos);

  const auto make = [](const std::vector<std::array<double, 3>>& points,
                      const std::vector<std::array<vtkIdType, 3>>& triangles)
  {
    auto mesh = vtkSmartPointer<vtkPolyData>::New();
    vtkNew<vtkPoints> p;
    for (const auto& x : points)
    {
      p->InsertNextPoint(x.data());
    }
    vtkNew<vtkCellArray> cells;
    for (const auto& t : triangles)
    {
      cells->InsertNextCell(3, t.data());
    }
    mesh->SetPoints(p);
    mesh->SetPolys(cells);
    return mesh;
  };
  // Three triangles on one edge.
  EXPECT_NE(MeshError(make({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 }, { 0, 0, 1 } },
                        { { 0, 1, 2 }, { 1, 0, 3 }, { 0, 1, 4 } }))
              .find("not manifold"),
    std::string::npos);
  // A zero-area triangle.
  EXPECT_NE(
    MeshError(make({ { 0, 0, 0 }, { 1, 0, 0 }, { 2, 0, 0 } }, { { 0, 1, 2 } })).find("zero area"),
    std::string::npos);
  // NaN coordinates.
  EXPECT_NE(MeshError(make({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, std::nan(""), 0 } }, { { 0, 1, 2 } }))
              .find("not finite"),
    std::string::npos);
}

TEST(MeshGeometryImage, ClosedGenus0MeshIsCutOpenAndRemeshedClosed)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(0.5);
  sphere->SetThetaResolution(40);
  sphere->SetPhiResolution(20);
  sphere->Update();
  vtkNew<vtkCVTMeshGeometryImage> gi;
  gi->SetInputConnection(sphere->GetOutputPort());
  gi->SetResolution(128, 64);
  gi->Update();
  const double area = MeshArea(sphere->GetOutput());
  const double total = gi->GetOutput()->GetFieldData()->GetArray("TotalArea")->GetTuple1(0);
  std::cout << "[ measured ] sphere mesh area " << area << ", geometry image " << total << "\n";
  EXPECT_NEAR(total, area, 0.02 * area);
  EXPECT_EQ(gi->GetOutput()->GetFieldData()->GetArray("WrapU")->GetTuple1(0), 1.0);

  vtkNew<vtkCVTSurfaceFilter> cvt;
  cvt->SetInputConnection(gi->GetOutputPort());
  cvt->SetNumberOfSites(150);
  cvt->SetMaximumNumberOfIterations(30);
  cvt->SetMethodToLloyd();
  cvt->Update();
  const MeshCheck remesh = CheckMesh(cvt->GetRemeshOutput());
  EXPECT_EQ(remesh.Vertices, 150);
  EXPECT_EQ(remesh.NonManifoldEdges, 0);
  EXPECT_EQ(remesh.MisorientedEdges, 0);
  EXPECT_EQ(remesh.Euler(), 2);
}

namespace
{
/// The energy of sites on a dense torus geometry image: area weight times the squared distance
/// to the nearest site (brute force), summed over the pixels.
double DenseTorusEnergy(vtkPolyData* sites)
{
  vtkNew<vtkCVTGeometryImageSource> dense;
  dense->SetResolution(512, 256);
  dense->Update();
  cvt::GeometryImage image;
  std::string error;
  vtkCVTSurfaceFilter::ReadGeometryImage(dense->GetOutput(), image, error);
  double energy = 0.0;
  for (long long p = 0; p < image.NumberOfPixels(); ++p)
  {
    double best = 1e300;
    for (vtkIdType i = 0; i < sites->GetNumberOfPoints(); ++i)
    {
      const double* s = sites->GetPoint(i);
      const double d2 = std::pow(image.Position[3 * p] - s[0], 2) +
        std::pow(image.Position[3 * p + 1] - s[1], 2) +
        std::pow(image.Position[3 * p + 2] - s[2], 2);
      best = std::min(best, d2);
    }
    energy += image.AreaWeight[p] * best;
  }
  return energy;
}
}

TEST(SurfaceFilter, CPUAndOpenGLEnginesAgreeOnTheTorus)
{
  // The same torus job on both engines: energies (on the same dense geometry image) within the
  // GPU's discretisation, both remeshes closed tori.
  vtkNew<vtkCVTGeometryImageSource> source;
  source->SetResolution(512, 256);
  double energy[2];
  for (int engine : { vtkCVTSurfaceFilter::OPENGL, vtkCVTSurfaceFilter::CPU })
  {
    vtkNew<vtkCVTSurfaceFilter> cvt;
    cvt->SetInputConnection(source->GetOutputPort());
    cvt->SetEngine(engine);
    cvt->SetNumberOfSites(300);
    cvt->SetMaximumNumberOfIterations(60);
    cvt->Update();
    vtkPolyData* sites = cvt->GetSitesOutput();
    ASSERT_EQ(sites->GetNumberOfPoints(), 300);
    EXPECT_EQ(sites->GetFieldData()->GetAbstractArray("Engine")->GetVariantValue(0).ToString(),
      engine == vtkCVTSurfaceFilter::CPU ? "CPU" : "OpenGL");
    vtkPolyData* remesh = cvt->GetRemeshOutput();
    EXPECT_EQ(
      remesh->GetNumberOfPoints() - 3 * remesh->GetNumberOfPolys() / 2 + remesh->GetNumberOfPolys(),
      0); // V - E + F of a closed triangle mesh: the torus's 0
    // Labels: every pixel labelled with an existing site.
    vtkDataArray* labels = cvt->GetLabelsOutput()->GetPointData()->GetArray("SiteId");
    ASSERT_NE(labels, nullptr);
    EXPECT_GE(labels->GetRange()[0], 0.0);
    EXPECT_LT(labels->GetRange()[1], 300.0);
    // The energy of these sites on a dense image, by nearest sites (brute force).
    energy[engine == vtkCVTSurfaceFilter::CPU] = DenseTorusEnergy(sites);
  }
  EXPECT_NEAR(energy[1], energy[0], 0.01 * energy[0]);
}

TEST(MeshGeometryImage, AnyMeshBecomesAnAtlasAndRemeshesWithItsTopologyOnEitherEngine)
{
  // A sphere (atlas asked for), a sphere with its cap pushed in (not star-shaped: an atlas by
  // itself), a torus mesh (genus 1) and a sphere with two holes: the CVT on the atlas crosses its
  // seams on both engines (the GPU's jump flooding follows them; the CPU's restricted cells are
  // 3D, on the charts as a mesh), and the dual, made manifold where three charts meet, is
  // oriented, with the mesh's Euler characteristic and border loops. The engines' energies on the
  // mesh agree, and on the CPU every pixel's label is its nearest site.
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(48);
  sphere->SetPhiResolution(24);
  sphere->Update();
  vtkNew<vtkSphereSource> dented;
  dented->SetThetaResolution(48);
  dented->SetPhiResolution(24);
  dented->Update();
  vtkPoints* points = dented->GetOutput()->GetPoints();
  for (vtkIdType p = 0; p < points->GetNumberOfPoints(); ++p)
  {
    double x[3];
    points->GetPoint(p, x);
    if (x[2] > 0.2)
    {
      x[2] = 0.2 - 1.5 * (x[2] - 0.2);
      points->SetPoint(p, x);
    }
  }
  vtkNew<vtkCVTGeometryImageSource> torusImage;
  torusImage->SetResolution(128, 64);
  vtkNew<vtkCVTSurfaceFilter> torusMesher;
  torusMesher->SetInputConnection(torusImage->GetOutputPort());
  torusMesher->SetEngineToCPU();
  torusMesher->SetNumberOfSites(800);
  torusMesher->SetMaximumNumberOfIterations(5);
  torusMesher->Update();
  vtkNew<vtkPolyData> holed; // the sphere less the triangles near (+-0.5, 0, 0)
  holed->SetPoints(sphere->GetOutput()->GetPoints());
  vtkNew<vtkCellArray> kept;
  for (vtkIdType cell = 0; cell < sphere->GetOutput()->GetNumberOfCells(); ++cell)
  {
    vtkCell* triangle = sphere->GetOutput()->GetCell(cell);
    double centroid[3] = { 0.0, 0.0, 0.0 };
    for (int k = 0; k < 3; ++k)
    {
      for (int d = 0; d < 3; ++d)
      {
        centroid[d] += triangle->GetPoints()->GetPoint(k)[d] / 3.0;
      }
    }
    if (std::hypot(std::abs(centroid[0]) - 0.5, centroid[1], centroid[2]) > 0.15)
    {
      kept->InsertNextCell(triangle->GetPointIds());
    }
  }
  holed->SetPolys(kept);
  const struct
  {
    const char* Name;
    vtkPolyData* Mesh;
    bool AskForAtlas;
    long long Euler;
    int Loops;
  } cases[] = { { "sphere", sphere->GetOutput(), true, 2, 0 },
    { "dented sphere", dented->GetOutput(), false, 2, 0 },
    { "torus", torusMesher->GetRemeshOutput(), false, 0, 0 },
    { "sphere with two holes", holed, true, 0, 2 } };
  for (const auto& c : cases)
  {
    SCOPED_TRACE(c.Name);
    vtkNew<vtkCVTMeshGeometryImage> gi;
    gi->SetInputData(c.Mesh);
    gi->SetResolution(256, 256);
    if (c.AskForAtlas)
    {
      gi->SetParameterizationToAtlas();
    }
    gi->Update();
    vtkFieldData* fields = gi->GetOutput()->GetFieldData();
    ASSERT_NE(fields->GetArray("NumberOfCharts"), nullptr);
    EXPECT_GT(fields->GetArray("NumberOfCharts")->GetTuple1(0), 1);
    EXPECT_NEAR(
      fields->GetArray("TotalArea")->GetTuple1(0), MeshArea(c.Mesh), 1e-3 * MeshArea(c.Mesh));
    ASSERT_NE(gi->GetOutput()->GetPointData()->GetArray("SeamPartner"), nullptr);
    // Pixels by the surface's own border are marked, on open meshes only.
    vtkDataArray* border = gi->GetOutput()->GetPointData()->GetArray("SurfaceBorder");
    ASSERT_NE(border, nullptr);
    EXPECT_EQ(border->GetRange()[1] > 0.0, c.Loops > 0);

    double energy[2] = { 0.0, 0.0 };
    for (int engine : { vtkCVTSurfaceFilter::OPENGL, vtkCVTSurfaceFilter::CPU })
    {
      const bool onCpu = engine == vtkCVTSurfaceFilter::CPU;
      SCOPED_TRACE(onCpu ? "CPU" : "OpenGL");
      vtkNew<vtkCVTSurfaceFilter> cvt;
      cvt->SetInputConnection(gi->GetOutputPort());
      cvt->SetEngine(engine);
      cvt->SetNumberOfSites(150);
      cvt->SetMaximumNumberOfIterations(30);
      cvt->SetMethodToLloyd();
      cvt->Update();
      vtkPolyData* sites = cvt->GetSitesOutput();
      ASSERT_EQ(sites->GetNumberOfPoints(), 150);
      const MeshCheck remesh = CheckMesh(cvt->GetRemeshOutput());
      std::cout << "[ measured ] " << c.Name << " atlas of "
                << fields->GetArray("NumberOfCharts")->GetTuple1(0) << " charts, "
                << (onCpu ? "CPU" : "OpenGL") << ": remesh of " << remesh.Faces
                << " triangles, Euler " << remesh.Euler() << ", " << remesh.NonManifoldEdges
                << " edges not on two triangles, " << remesh.MisorientedEdges
                << " misoriented; energy on the mesh "
                << EnergyOnMesh(c.Mesh, cvt->GetRemeshOutput()) << "\n";
      // Where three charts meet the dual across the seams missed or doubled a triangle, before
      // it was made manifold (150 sites on the GPU: dented sphere 5 bad edges of ~450, torus 13).
      EXPECT_EQ(remesh.DuplicateFaces, 0);
      EXPECT_EQ(remesh.NonManifoldEdges, remesh.BorderEdges);
      EXPECT_EQ(remesh.MisorientedEdges, 0);
      EXPECT_EQ(remesh.Euler(), c.Euler);
      EXPECT_EQ(remesh.BorderLoops, c.Loops);
      // On the surface: the remesh's vertices (the sites, or on the CPU their cells' points
      // nearest to them).
      energy[onCpu ? 1 : 0] = EnergyOnMesh(c.Mesh, cvt->GetRemeshOutput());
      if (onCpu)
      {
        // Every valid pixel's label is its nearest site (brute force over all sites).
        vtkImageData* labelled = cvt->GetLabelsOutput();
        vtkDataArray* ids = labelled->GetPointData()->GetArray("SiteId");
        vtkDataArray* positions = labelled->GetPointData()->GetArray("Position");
        vtkDataArray* mask = labelled->GetPointData()->GetArray("Mask");
        ASSERT_NE(ids, nullptr);
        long long wrong = 0, labelledPixels = 0;
        for (vtkIdType p = 0; p < labelled->GetNumberOfPoints(); ++p)
        {
          if (mask && mask->GetTuple1(p) == 0)
          {
            EXPECT_EQ(ids->GetTuple1(p), -1);
            continue;
          }
          double x[3], site[3];
          positions->GetTuple(p, x);
          double best = VTK_DOUBLE_MAX;
          for (vtkIdType i = 0; i < sites->GetNumberOfPoints(); ++i)
          {
            sites->GetPoint(i, site);
            best = std::min(best, vtkMath::Distance2BetweenPoints(x, site));
          }
          sites->GetPoint(static_cast<vtkIdType>(ids->GetTuple1(p)), site);
          wrong += vtkMath::Distance2BetweenPoints(x, site) > best ? 1 : 0;
          ++labelledPixels;
        }
        EXPECT_EQ(wrong, 0) << "of " << labelledPixels << " pixels";
      }
    }
    // Pixel sums against exact integrals on the charts' triangles, 30 Lloyd steps each.
    EXPECT_NEAR(energy[1], energy[0], 0.02 * energy[0]);
  }
}

namespace
{
/// A sphere mesh (the sphere source's normals dropped) with point arrays: "linear", x + 2y + 3z
/// (which barycentric interpolation reproduces exactly), "rho", 10 where x > 0, else 1, and
/// "step", 1 where x > 0, else 0.
vtkSmartPointer<vtkPolyData> SphereWithArrays(double endPhi = 180.0)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(0.5);
  sphere->SetThetaResolution(40);
  sphere->SetPhiResolution(20);
  sphere->SetEndPhi(endPhi);
  vtkNew<vtkCleanPolyData> clean;
  clean->SetInputConnection(sphere->GetOutputPort());
  clean->Update();
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->ShallowCopy(clean->GetOutput());
  mesh->GetPointData()->Initialize();
  vtkNew<vtkFloatArray> linear, rho, step, normal;
  linear->SetName("linear");
  rho->SetName("rho");
  step->SetName("step");
  normal->SetName("Normal"); // named like the geometry image's own: not carried
  for (vtkIdType p = 0; p < mesh->GetNumberOfPoints(); ++p)
  {
    double x[3];
    mesh->GetPoint(p, x);
    linear->InsertNextValue(static_cast<float>(x[0] + 2.0 * x[1] + 3.0 * x[2]));
    rho->InsertNextValue(x[0] > 0.0 ? 10.0f : 1.0f);
    step->InsertNextValue(x[0] > 0.0 ? 1.0f : 0.0f);
    normal->InsertNextValue(-7.0f);
  }
  mesh->GetPointData()->AddArray(linear);
  mesh->GetPointData()->AddArray(rho);
  mesh->GetPointData()->AddArray(step);
  mesh->GetPointData()->AddArray(normal);
  return mesh;
}

/// The sites with x > 0, of all sites.
double ShareWherePositive(vtkPolyData* sites)
{
  int positive = 0;
  for (vtkIdType i = 0; i < sites->GetNumberOfPoints(); ++i)
  {
    positive += sites->GetPoint(i)[0] > 0.0 ? 1 : 0;
  }
  return static_cast<double>(positive) / std::max<vtkIdType>(1, sites->GetNumberOfPoints());
}
}

// Every way a mesh becomes a geometry image (a disk's map, a closed star-shaped mesh's rays, an
// atlas) carries the mesh's point arrays onto the pixels: a linear field is reproduced exactly.
TEST(MeshGeometryImage, PointArraysAreCarriedOntoThePixels)
{
  struct Case
  {
    const char* Name;
    double EndPhi;
    int Parameterization;
  };
  for (const Case& c : { Case{ "disk", 90.0, vtkCVTMeshGeometryImage::AUTOMATIC },
         Case{ "star-shaped sphere", 180.0, vtkCVTMeshGeometryImage::AUTOMATIC },
         Case{ "atlas", 180.0, vtkCVTMeshGeometryImage::ATLAS } })
  {
    SCOPED_TRACE(c.Name);
    vtkNew<vtkCVTMeshGeometryImage> gi;
    gi->SetInputData(SphereWithArrays(c.EndPhi));
    gi->SetParameterization(c.Parameterization);
    gi->SetResolution(96, 96);
    gi->Update();
    vtkPointData* pd = gi->GetOutput()->GetPointData();
    vtkDataArray* linear = pd->GetArray("linear");
    vtkDataArray* rho = pd->GetArray("rho");
    vtkDataArray* step = pd->GetArray("step");
    ASSERT_NE(linear, nullptr);
    ASSERT_NE(rho, nullptr);
    ASSERT_NE(step, nullptr);
    vtkDataArray* position = pd->GetArray("Position");
    vtkDataArray* mask = pd->GetArray("Mask");
    double worst = 0.0;
    int valid = 0, masked = 0;
    for (vtkIdType p = 0; p < position->GetNumberOfTuples(); ++p)
    {
      if (mask && mask->GetTuple1(p) == 0.0)
      {
        masked += linear->GetTuple1(p) == 0.0 && rho->GetTuple1(p) == 0.0;
        continue;
      }
      const double* x = position->GetTuple3(p);
      worst = std::max(worst, std::abs(linear->GetTuple1(p) - (x[0] + 2.0 * x[1] + 3.0 * x[2])));
      ++valid;
      ASSERT_GE(rho->GetTuple1(p), 1.0 - 1e-5);
      ASSERT_LE(rho->GetTuple1(p), 10.0 + 1e-4);
      // Within the corners' values: a density of 0 and 1 never becomes slightly negative.
      ASSERT_GE(step->GetTuple1(p), 0.0) << "pixel " << p;
    }
    std::cout << "[ measured ] " << c.Name << ": " << valid
              << " pixels, largest error of the carried linear field " << worst << "\n";
    EXPECT_GT(valid, 1000);
    EXPECT_LT(worst, 1e-5);
    if (mask)
    {
      EXPECT_EQ(masked, position->GetNumberOfTuples() - valid); // zeros off the surface
    }
    // The image's own Normal is kept: unit vectors, not the mesh's array of that name.
    ASSERT_EQ(pd->GetArray("Normal")->GetNumberOfComponents(), 3);
  }
}

// A point array named in Latin-1 (as VTK's OBJ reader names texture coordinates after an OBJ's
// materials) reaches the pixels under its UTF-8 name, as on the CPU engine's outputs: an XML
// name is UTF-8, and the image written as it was could not be read back.
TEST(MeshGeometryImage, ArrayNamesReachThePixelsInUtf8)
{
  vtkSmartPointer<vtkPolyData> mesh = SphereWithArrays(90.0);
  mesh->GetPointData()->GetArray("step")->SetName("Terraind\xe6k");
  vtkNew<vtkCVTMeshGeometryImage> gi;
  gi->SetInputData(mesh);
  gi->SetResolution(64, 64);
  gi->Update();
  vtkPointData* pd = gi->GetOutput()->GetPointData();
  EXPECT_NE(pd->GetArray("Terraind\xc3\xa6k"), nullptr);
  EXPECT_EQ(pd->GetArray("Terraind\xe6k"), nullptr);
  EXPECT_NE(mesh->GetPointData()->GetArray("Terraind\xe6k"), nullptr); // the input keeps its own
}

// A density carried from the mesh draws the sites where it is larger, on both engines, on the
// sphere's star-shaped map and on an atlas of it (sites per area go as the square root of the
// density: about 3/4 of them where it is 10 times larger).
TEST(SurfaceFilter, DensityArrayDrawsTheSitesWhereItIsLarger)
{
  for (const auto& [atlas, engine] : { std::pair{ false, int(vtkCVTSurfaceFilter::CPU) },
         { false, int(vtkCVTSurfaceFilter::OPENGL) }, { true, int(vtkCVTSurfaceFilter::CPU) },
         { true, int(vtkCVTSurfaceFilter::OPENGL) } })
  {
    SCOPED_TRACE(std::string(engine == vtkCVTSurfaceFilter::CPU ? "CPU" : "OpenGL") +
      (atlas ? ", atlas" : ""));
    vtkNew<vtkCVTMeshGeometryImage> gi;
    gi->SetInputData(SphereWithArrays());
    gi->SetResolution(128, atlas ? 128 : 64);
    gi->SetParameterization(
      atlas ? vtkCVTMeshGeometryImage::ATLAS : vtkCVTMeshGeometryImage::AUTOMATIC);
    vtkNew<vtkCVTSurfaceFilter> cvt;
    cvt->SetInputConnection(gi->GetOutputPort());
    cvt->SetEngine(engine);
    cvt->SetNumberOfSites(120);
    cvt->SetMaximumNumberOfIterations(20);
    cvt->Update();
    const double uniform = ShareWherePositive(cvt->GetSitesOutput());
    cvt->SetDensityArray("rho");
    cvt->Update();
    ASSERT_EQ(cvt->GetSitesOutput()->GetNumberOfPoints(), 120);
    const double dense = ShareWherePositive(cvt->GetSitesOutput());
    // The mesh's arrays reach the remesh's vertices: the linear field at the input's points
    // nearest to them (on the CPU interpolated on the triangulated image, on the GPU and on an
    // atlas the value of the site's pixel). A vertex that straddles the input (moved off it along
    // its normal where the remesh lay far from it) has its value from the point it moved from:
    // within three times its distance to the input of the nearest point, the field's gradient times
    // that more.
    vtkPolyData* remesh = cvt->GetRemeshOutput();
    vtkDataArray* linear = remesh->GetPointData()->GetArray("linear");
    ASSERT_NE(linear, nullptr);
    ASSERT_NE(remesh->GetPointData()->GetArray("rho"), nullptr);
    vtkNew<vtkStaticCellLocator> input;
    input->SetDataSet(SphereWithArrays());
    input->BuildLocator();
    double worst = 0.0;
    for (vtkIdType v = 0; v < remesh->GetNumberOfPoints(); ++v)
    {
      double x[3], distance2 = 0.0;
      vtkIdType cell = -1;
      int subId = 0;
      input->FindClosestPoint(remesh->GetPoint(v), x, cell, subId, distance2);
      const double moved = 3.0 * std::sqrt(14.0) * std::sqrt(distance2);
      worst =
        std::max(worst, std::abs(linear->GetTuple1(v) - (x[0] + 2.0 * x[1] + 3.0 * x[2])) - moved);
    }
    std::cout << "[ measured ] sites where x > 0: uniform " << uniform << ", density " << dense
              << "; the linear field at the remesh's vertices off by " << worst
              << " beyond what straddling allows\n";
    EXPECT_NEAR(uniform, 0.5, 0.08);
    EXPECT_GT(dense, 0.68);
    EXPECT_LT(worst, engine == vtkCVTSurfaceFilter::CPU && !atlas ? 1e-4 : 0.1);
  }
}

TEST(SurfaceFilterBadInput, EveryBadDensitySaysWhatToFix)
{
  vtkNew<vtkCVTMeshGeometryImage> gi;
  gi->SetInputData(SphereWithArrays());
  gi->SetResolution(64, 32);
  gi->Update();
  const auto fail = [&gi](const char* name, float value)
  {
    vtkNew<vtkImageData> image;
    image->DeepCopy(gi->GetOutput());
    if (value != 1.0f)
    {
      vtkDataArray* rho = image->GetPointData()->GetArray("rho");
      for (vtkIdType p = 0; p < rho->GetNumberOfTuples(); ++p)
      {
        rho->SetTuple1(p, value == 0.0f ? 0.0 : (p == 700 ? value : 1.0));
      }
    }
    vtkNew<vtkCVTSurfaceFilter> cvt;
    vtkNew<ErrorCatcher> catcher;
    cvt->AddObserver(vtkCommand::ErrorEvent, catcher);
    cvt->SetInputData(image);
    cvt->SetNumberOfSites(10);
    cvt->SetEngine(vtkCVTSurfaceFilter::CPU);
    cvt->SetDensityArray(name);
    cvt->Update();
    EXPECT_EQ(cvt->GetSitesOutput()->GetNumberOfPoints(), 0);
    EXPECT_EQ(cvt->GetRemeshOutput()->GetNumberOfCells(), 0);
    return catcher->Message;
  };
  EXPECT_NE(
    fail("nothing", 1.0f).find("no one-component point array 'nothing'"), std::string::npos);
  EXPECT_NE(fail("Position", 1.0f).find("no one-component"), std::string::npos);
  EXPECT_NE(fail("rho", std::numeric_limits<float>::quiet_NaN()).find("NaN"), std::string::npos);
  EXPECT_NE(fail("rho", -2.0f).find("negative"), std::string::npos);
  EXPECT_NE(fail("rho", 0.0f).find("zero everywhere"), std::string::npos);
}
