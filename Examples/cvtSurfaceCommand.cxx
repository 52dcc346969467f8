// cvt surface: a constrained CVT on a surface (a torus, or an --input mesh parameterised into a
// geometry image) on the OpenGL engine, or on an --input mesh itself on the CPU (the remesh).
#include "cvtCommands.h"
#include "cvtErrors.h"
#include "cvtOutputs.h"
#include "cvtReaders.h"

#include "vtkCVTGeometryImageSource.h"
#include "vtkCVTMeshGeometryImage.h"
#include "vtkCVTRemeshFilter.h"
#include "vtkCVTSceneRenderer.h"
#include "vtkCVTSurfaceFilter.h"
#include "vtkCleanPolyData.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkParametricTorus.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkXMLImageDataWriter.h"
#include "vtkXMLPolyDataWriter.h"

#include <chrono>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>

namespace cvtcli
{
namespace
{

/// The surface's geometry image: a torus, or a mesh read from --input and parameterised.
vtkSmartPointer<vtkAlgorithm> SurfaceGeometryImage(const Options& options)
{
  if (options.Input.empty())
  {
    vtkNew<vtkParametricTorus> torus;
    torus->SetRingRadius(options.Torus[0]);
    torus->SetCrossSectionRadius(options.Torus[1]);
    auto source = vtkSmartPointer<vtkCVTGeometryImageSource>::New();
    source->SetParametricFunction(torus);
    source->SetResolution(options.GIResolution[0], options.GIResolution[1]);
    return source;
  }
  vtkSmartPointer<vtkAlgorithm> reader = MeshReader(options);
  vtkNew<vtkCleanPolyData> merge;
  merge->SetInputConnection(reader->GetOutputPort());
  auto parameterise = vtkSmartPointer<vtkCVTMeshGeometryImage>::New();
  parameterise->SetInputConnection(merge->GetOutputPort());
  if (options.GIResolutionGiven)
  {
    parameterise->SetResolution(options.GIResolution[0], options.GIResolution[1]);
  }
  else
  {
    // An atlas fills about half its image: 800 pixels per site keep cells some 20 pixels wide.
    const int side =
      static_cast<int>(std::ceil(std::sqrt(std::max(512.0 * 512.0, 800.0 * options.Sites))));
    parameterise->SetResolution(side, side);
  }
  return parameterise;
}

/// The atlas lines of --report (chart count, distortion range, seam length), if an atlas.
std::string AtlasReport(vtkDataObject* image)
{
  vtkFieldData* fields = image ? image->GetFieldData() : nullptr;
  if (!fields || !fields->GetArray("NumberOfCharts"))
  {
    return "";
  }
  const auto value = [fields](const char* name) { return fields->GetArray(name)->GetTuple1(0); };
  int size[3] = { 0, 0, 0 };
  if (vtkImageData* pixels = vtkImageData::SafeDownCast(image))
  {
    pixels->GetDimensions(size);
  }
  std::ostringstream text;
  text << std::setprecision(6) << "  atlas: " << value("NumberOfCharts") << " charts in a "
       << size[0] << " x " << size[1] << " image, seam length " << value("SeamLength") << " ("
       << value("SeamPixels") << " seam pixels)\n"
       << "  atlas area stretch min / max " << value("MinimumAreaStretch") << " / "
       << value("MaximumAreaStretch") << ", angle stretch max " << value("MaximumAngleStretch")
       << "\n";
  return text.str();
}

/// The stages' clock, and the seconds since `from` (--report's per-stage times).
using Clock = std::chrono::steady_clock;
double SecondsSince(Clock::time_point from)
{
  return std::chrono::duration<double>(Clock::now() - from).count();
}

/// "N parts, genus G, L boundary loops" from the field data named with `prefix`.
std::string TopologyText(vtkDataObject* data, const std::string& prefix)
{
  std::ostringstream text;
  text << Field(data, (prefix + "Components").c_str()) << " parts, genus "
       << Field(data, (prefix + "Genus").c_str()) << ", "
       << Field(data, (prefix + "BoundaryLoops").c_str()) << " boundary loops";
  return text.str();
}

/// The report's line of how far input and remesh lie from each other (vtkCVTRemeshFilter's
/// remesh field data).
std::string DistanceText(vtkDataObject* remesh)
{
  std::ostringstream text;
  text << "  distance input -> remesh    " << 100.0 * Field(remesh, "InputToRemeshDistance")
       << " %, remesh -> input " << 100.0 * Field(remesh, "RemeshToInputDistance")
       << " % of the diagonal (at points 0.8% of it apart, 0.2% near 0.9%)\n";
  return text.str();
}

/// cvt surface --input MESH on the CPU engine: restricted Voronoi cells on the mesh itself.
int RunRemesh(const Options& options)
{
  const Clock::time_point start = Clock::now();
  OutputFolder(options); // before any work: a folder that cannot be written fails now
  vtkSmartPointer<vtkAlgorithm> reader = MeshReader(options);
  vtkNew<ErrorObserver> readErrors;
  reader->AddObserver(vtkCommand::ErrorEvent, readErrors);
  reader->Update();
  if (!readErrors->Message.empty())
  {
    Fail("cannot read --input '" + options.Input + "': " + readErrors->Message);
  }
  const double readSeconds = SecondsSince(start);
  vtkNew<vtkCVTRemeshFilter> cvt;
  cvt->SetInputConnection(reader->GetOutputPort());
  cvt->SetDensityArray(options.Array.c_str());
  cvt->SetCollapseForValence(!options.KeepEverySite);
  SetOptimizer(options, cvt.Get());
  if (options.IterationsGiven)
  {
    cvt->SetSiteIterationBudget(0); // the cap asked for, whatever the number of sites
  }
  const Clock::time_point optimise = Clock::now();
  RunOrFail(
    cvt, [](vtkAlgorithm* f) { return static_cast<vtkCVTRemeshFilter*>(f)->GetSitesOutput(); });
  const double cvtSeconds = SecondsSince(optimise);

  const Clock::time_point write = Clock::now();
  OutputFiles files(OutputFolder(options));
  vtkPolyData* sites = cvt->GetSitesOutput();
  vtkPolyData* remesh = cvt->GetRemeshOutput();
  Write<vtkXMLPolyDataWriter>(sites, files, "sites.vtp");
  Write<vtkXMLPolyDataWriter>(cvt->GetLabelsOutput(), files, "labels.vtp");
  Write<vtkXMLPolyDataWriter>(remesh, files, "remesh.vtp");
  WriteCsv(sites, cvt->GetHistoryOutput(), 3, files);
  const double writeSeconds = SecondsSince(write);
  vtkNew<vtkCVTSceneRenderer> scene;
  const bool pictureWritten = WritePicture(scene->RenderMesh(remesh), scene->GetLastError(), files);
  files.Commit();
  if (options.Report)
  {
    vtkFieldData* in = sites->GetFieldData();
    vtkFieldData* out = remesh->GetFieldData();
    std::cout << std::setprecision(6) << "report:\n"
              << "  engine                      CPU: "
              << in->GetAbstractArray("EngineReason")->GetVariantValue(0).ToString() << "\n"
              << "  method                      " << options.Method << "\n"
              << "  iterations / evaluations    " << Field(sites, "Iterations") << " / "
              << Field(sites, "Evaluations") << "\n"
              << "  energy F                    " << Field(sites, "Energy") << "\n"
              << "  normalised F n / A^2        "
              << Field(sites, "Energy") * sites->GetNumberOfPoints() /
        (Field(sites, "SurfaceArea") * Field(sites, "SurfaceArea"))
              << "\n"
              << "  |grad F|                    " << Field(sites, "GradientNorm") << "\n"
              << "  surface area                " << Field(sites, "SurfaceArea") << "\n"
              << "  input topology              " << TopologyText(sites, "Input") << "\n"
              << "  remesh topology             " << TopologyText(remesh, "") << "\n"
              << "  sites added for topology    "
              << Field(sites, "AddedSites") - Field(sites, "FarPointSites") -
        Field(sites, "AngleSites")
              << " (in " << Field(sites, "TopologyRounds") << " rounds"
              << (Field(sites, "TopologyCeilingReached") > 0
                     ? ", stopped at the ceiling of added sites"
                     : "")
              << (Field(sites, "AddedSitesSettled") > 0 ? ", settled under their cells' sizes" : "")
              << ")\n"
              << "  sites added far from remesh " << Field(sites, "FarPointSites") << " ("
              << Field(sites, "FarBorderSites")
              << " on the border; where input and remesh lie over 0.9% of the diagonal apart)\n"
              << "  sites added for angles      " << Field(sites, "AngleSites")
              << " (at triangles by the border with a corner under 25 degrees)\n"
              << "  remesh: " << remesh->GetNumberOfPoints() << " vertices, "
              << remesh->GetNumberOfPolys() << " triangles (" << Field(remesh, "RemovedTriangles")
              << " dropped as non-manifold, " << Field(remesh, "FilledHoles") << " holes closed, "
              << Field(remesh, "DroppedFragments") << " fragments dropped, "
              << Field(remesh, "OpenedHoles") << " holes opened, " << Field(remesh, "SplitVertices")
              << " pinched vertices split, " << Field(remesh, "SeparatedVertices")
              << " coincident vertices separated, " << Field(remesh, "FlippedEdges")
              << " edges flipped for angles, " << Field(remesh, "ValenceFlips") << " for valence, "
              << Field(remesh, "MovedVertices") << " vertices moved, "
              << Field(remesh, "CollapsedEdges") << " edges collapsed, "
              << Field(remesh, "ValenceCollapses") << " for valence, "
              << Field(remesh, "FittedVertices") << " vertices moved towards tips, "
              << Field(remesh, "BorderCorners") << " added on border corners, "
              << Field(remesh, "SlidBorderVertices") << " slid along the border, "
              << Field(remesh, "StraddlingVertices") << " moved to straddle the input)\n"
              << "  valence 6                   " << 100.0 * Field(remesh, "Valence6Fraction")
              << " % (off the border " << 100.0 * Field(remesh, "InteriorValence6Fraction")
              << " %)\n"
              << "  smallest / largest angle    " << Field(remesh, "MinimumAngle") << " / "
              << Field(remesh, "MaximumAngle") << " degrees\n"
              << DistanceText(remesh) << "  seconds: read " << readSeconds << ", prepare "
              << Field(sites, "PrepareSeconds") << ", optimise " << Field(sites, "OptimizeSeconds")
              << ", remesh " << Field(sites, "RemeshSeconds") << " (CVT filter " << cvtSeconds
              << "), write " << writeSeconds << "\n";
    (void)out;
  }
  PrintSummary(options, sites, "", "sites.vtp sites.csv labels.vtp remesh.vtp history.csv cvt.png",
    pictureWritten);
  return 0;
}

} // namespace

int RunSurface(const Options& options)
{
  if (!options.Input.empty() && options.Engine != "opengl")
  {
    return RunRemesh(options);
  }
  const Clock::time_point start = Clock::now();
  OutputFolder(options); // before any work: a folder that cannot be written fails now
  vtkSmartPointer<vtkAlgorithm> geometryImage = SurfaceGeometryImage(options);
  vtkNew<ErrorObserver> meshErrors;
  geometryImage->AddObserver(vtkCommand::ErrorEvent, meshErrors);
  geometryImage->Update();
  if (!meshErrors->Message.empty())
  {
    Fail(meshErrors->Message);
  }
  const double atlasSeconds = SecondsSince(start);
  vtkNew<vtkCVTSurfaceFilter> cvt;
  cvt->SetInputConnection(geometryImage->GetOutputPort());
  cvt->SetDensityArray(options.Array.c_str()); // the mesh's array, carried onto the pixels
  SetOptimizer(options, cvt.Get());
  SetEngine(options, cvt.Get());
  Clock::time_point stage = Clock::now();
  RunOrFail(
    cvt, [](vtkAlgorithm* f) { return static_cast<vtkCVTSurfaceFilter*>(f)->GetSitesOutput(); });
  const double optimiseSeconds = SecondsSince(stage);

  OutputFiles files(OutputFolder(options));
  vtkPolyData* sites = cvt->GetSitesOutput();
  vtkPolyData* remesh = cvt->GetRemeshOutput();
  // A mesh's remesh is the restricted Delaunay triangulation of the GPU's sites on the mesh
  // itself (exact, with the input's topology, shaped against the mesh), not the dual of the
  // geometry image's labels.
  vtkNew<vtkCVTRemeshFilter> exact;
  stage = Clock::now();
  if (!options.Input.empty())
  {
    exact->SetInputConnection(geometryImage->GetInputConnection(0, 0));
    exact->SetInitialSitesData(sites);
    exact->SetDensityArray(options.Array.c_str());
    exact->SetCollapseForValence(!options.KeepEverySite);
    exact->SetMaximumNumberOfIterations(0);
    RunOrFail(exact,
      [](vtkAlgorithm* f) { return static_cast<vtkCVTRemeshFilter*>(f)->GetRemeshOutput(); });
    remesh = exact->GetRemeshOutput();
  }
  const double remeshSeconds = SecondsSince(stage);
  Write<vtkXMLPolyDataWriter>(sites, files, "sites.vtp");
  Write<vtkXMLImageDataWriter>(cvt->GetLabelsOutput(), files, "labels.vti");
  Write<vtkXMLPolyDataWriter>(remesh, files, "remesh.vtp");
  WriteCsv(sites, cvt->GetHistoryOutput(), 3, files);
  vtkNew<vtkCVTSceneRenderer> scene;
  const bool pictureWritten = WritePicture(scene->RenderMesh(remesh), scene->GetLastError(), files);
  files.Commit();

  if (options.Report)
  {
    vtkFieldData* mesh = remesh->GetFieldData();
    std::cout << std::setprecision(6) << "report:\n"
              << "  method                      " << options.Method << "\n"
              << "  iterations / evaluations    " << Field(sites, "Iterations") << " / "
              << Field(sites, "Evaluations") << "\n"
              << "  energy F                    " << Field(sites, "Energy") << "\n"
              << "  |grad F| (tangential)       " << Field(sites, "GradientNorm") << "\n"
              << "  surface area                " << Field(sites, "SurfaceArea") << "\n"
              << "  area weights min / max      " << Field(sites, "MinimumAreaWeight") << " / "
              << Field(sites, "MaximumAreaWeight") << "\n"
              << AtlasReport(geometryImage->GetOutputDataObject(0));
    if (!options.Input.empty())
    {
      std::cout << "  input topology              " << TopologyText(remesh, "Input") << "\n"
                << "  remesh topology             " << TopologyText(remesh, "") << "\n"
                << "  remesh made as              the restricted Delaunay triangulation of the "
                   "sites on the mesh ("
                << Field(exact->GetSitesOutput(), "AddedSites")
                << " sites added for topology and fidelity)\n"
                << DistanceText(remesh);
    }
    std::cout << "  remesh: " << remesh->GetNumberOfPoints() << " vertices, "
              << remesh->GetNumberOfPolys() << " triangles\n"
              << "  valence 6                   " << 100.0 * Field(remesh, "Valence6Fraction")
              << " % (off the border " << 100.0 * Field(remesh, "InteriorValence6Fraction")
              << " %)\n"
              << "  smallest / largest angle    " << Field(remesh, "MinimumAngle") << " / "
              << Field(remesh, "MaximumAngle") << " degrees\n"
              << "  valence histogram          ";
    vtkDataArray* valence = mesh->GetArray("ValenceHistogram");
    for (vtkIdType v = 0; v < valence->GetNumberOfTuples(); ++v)
    {
      if (valence->GetTuple1(v) > 0)
      {
        std::cout << " " << v << ":" << valence->GetTuple1(v);
      }
    }
    std::cout << "\n  angle histogram (10 deg)   ";
    vtkDataArray* angles = mesh->GetArray("AngleHistogram");
    for (vtkIdType b = 0; b < angles->GetNumberOfTuples(); ++b)
    {
      if (angles->GetTuple1(b) > 0)
      {
        std::cout << " " << 10 * b << "-" << 10 * (b + 1) << ":" << angles->GetTuple1(b);
      }
    }
    std::cout << "\n  seconds: geometry image " << atlasSeconds << ", optimise " << optimiseSeconds
              << ", remesh " << remeshSeconds << "\n";
  }
  PrintSummary(options, sites, cvt->GetContextDescription(),
    "sites.vtp sites.csv labels.vti remesh.vtp history.csv cvt.png", pictureWritten);
  return 0;
}

} // namespace cvtcli
