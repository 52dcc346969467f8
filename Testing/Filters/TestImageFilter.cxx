// vtkCVTImageFilter in a pipeline: outputs, determinism, progress, abort, bad input.
#include "cvtExactVoronoi.h"
#include "vtkCVTEngineChoice.h"
#include "vtkCVTImageFilter.h"
#include "vtkCVTOpenGLContext.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkGenericOpenGLRenderWindow.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkTable.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <sstream>

namespace
{
/// A W x H image over [x0, x0 + W*s] x [y0, y0 + H*s] (pixel centres half a spacing inside).
vtkSmartPointer<vtkImageData> MakeImage(
  int width, int height, double x0 = -1.0, double y0 = -1.0, double spacing = -1.0)
{
  if (spacing <= 0.0)
  {
    spacing = 2.0 / width;
  }
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(width, height, 1);
  image->SetSpacing(spacing, spacing, 1.0);
  image->SetOrigin(x0 + 0.5 * spacing, y0 + 0.5 * spacing, 0.0);
  return image;
}

void AddDensity(vtkImageData* image, const char* name, float value)
{
  vtkNew<vtkFloatArray> density;
  density->SetName(name);
  density->SetNumberOfValues(image->GetNumberOfPoints());
  density->Fill(value);
  image->GetPointData()->AddArray(density);
}

vtkSmartPointer<vtkPolyData> MakeSites(const std::vector<double>& xy)
{
  vtkNew<vtkPoints> points;
  for (size_t i = 0; i < xy.size(); i += 2)
  {
    points->InsertNextPoint(xy[i], xy[i + 1], 0.0);
  }
  auto sites = vtkSmartPointer<vtkPolyData>::New();
  sites->SetPoints(points);
  return sites;
}

/// Captures the filter's error messages instead of printing them.
class ErrorCatcher : public vtkCommand
{
public:
  static ErrorCatcher* New() { return new ErrorCatcher; }
  void Execute(vtkObject*, unsigned long, void* data) override
  {
    this->Messages.push_back(static_cast<const char*>(data));
  }
  std::vector<std::string> Messages;
};

/// Runs the filter expecting failure: returns the error message, and checks the outputs are empty.
std::string RunExpectingError(vtkCVTImageFilter* filter)
{
  vtkNew<ErrorCatcher> catcher;
  filter->AddObserver(vtkCommand::ErrorEvent, catcher);
  filter->Update();
  EXPECT_EQ(filter->GetSitesOutput()->GetNumberOfPoints(), 0);
  EXPECT_EQ(filter->GetLabelsOutput()->GetNumberOfPoints(), 0);
  EXPECT_EQ(filter->GetDualOutput()->GetNumberOfCells(), 0);
  EXPECT_EQ(filter->GetHistoryOutput()->GetNumberOfRows(), 0);
  std::string all;
  for (const std::string& m : catcher->Messages)
  {
    all += m;
  }
  EXPECT_FALSE(all.empty()) << "no error was reported";
  return all;
}

/// Four sites on `image` with the point array `density`, expecting failure: the error message.
std::string ErrorWithDensity(vtkImageData* image, const char* density)
{
  vtkNew<vtkCVTImageFilter> filter;
  filter->SetInputData(image);
  filter->SetNumberOfSites(4);
  filter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, density);
  return RunExpectingError(filter);
}

bool Contains(const std::string& text, const std::string& part)
{
  return text.find(part) != std::string::npos;
}
}

TEST(ImageFilter, ProducesAllOutputs)
{
  auto image = MakeImage(64, 48, 2.0, -3.0, 0.05);
  vtkNew<vtkCVTImageFilter> filter;
  filter->SetInputData(image);
  filter->SetNumberOfSites(40);
  filter->SetMaximumNumberOfIterations(15);
  filter->SetTolerance(0.0);
  filter->SetMethodToLloyd();
  int progressEvents = 0;
  vtkNew<vtkCallbackCommand> onProgress;
  onProgress->SetClientData(&progressEvents);
  onProgress->SetCallback(
    [](vtkObject*, unsigned long, void* clientData, void*) { ++*static_cast<int*>(clientData); });
  filter->AddObserver(vtkCommand::ProgressEvent, onProgress);
  filter->Update();

  vtkPolyData* sites = filter->GetSitesOutput();
  ASSERT_EQ(sites->GetNumberOfPoints(), 40);
  EXPECT_EQ(sites->GetNumberOfVerts(), 40);
  ASSERT_NE(sites->GetPointData()->GetArray("SiteId"), nullptr);
  ASSERT_NE(sites->GetPointData()->GetArray("Mass"), nullptr);
  ASSERT_NE(sites->GetPointData()->GetArray("Energy"), nullptr);
  EXPECT_EQ(sites->GetFieldData()->GetArray("Iterations")->GetTuple1(0), 15);
  // Masses add up to the domain area; energies to the reported total.
  double mass = 0.0, energy = 0.0;
  for (vtkIdType i = 0; i < 40; ++i)
  {
    mass += sites->GetPointData()->GetArray("Mass")->GetTuple1(i);
    energy += sites->GetPointData()->GetArray("Energy")->GetTuple1(i);
    double p[3];
    sites->GetPoint(i, p);
    EXPECT_GE(p[0], 2.0);
    EXPECT_LE(p[0], 2.0 + 64 * 0.05);
    EXPECT_GE(p[1], -3.0);
    EXPECT_LE(p[1], -3.0 + 48 * 0.05);
  }
  EXPECT_NEAR(mass, 64 * 48 * 0.05 * 0.05, 1e-3);
  EXPECT_NEAR(energy, sites->GetFieldData()->GetArray("Energy")->GetTuple1(0), 1e-9);

  // Labels: the input geometry, every pixel labelled, agreeing with brute force.
  vtkImageData* labels = filter->GetLabelsOutput();
  int dims[3];
  labels->GetDimensions(dims);
  EXPECT_EQ(dims[0], 64);
  EXPECT_EQ(dims[1], 48);
  EXPECT_DOUBLE_EQ(labels->GetOrigin()[0], image->GetOrigin()[0]);
  EXPECT_DOUBLE_EQ(labels->GetSpacing()[1], 0.05);
  vtkDataArray* ids = labels->GetPointData()->GetArray("SiteId");
  ASSERT_NE(ids, nullptr);
  EXPECT_TRUE(vtkIntArray::SafeDownCast(ids) != nullptr);
  cvt::Grid grid;
  grid.Width = 64;
  grid.Height = 48;
  grid.Origin[0] = 2.0;
  grid.Origin[1] = -3.0;
  grid.Spacing[0] = grid.Spacing[1] = 0.05;
  std::vector<double> xy;
  for (vtkIdType i = 0; i < 40; ++i)
  {
    double p[3];
    sites->GetPoint(i, p);
    xy.push_back(p[0]);
    xy.push_back(p[1]);
  }
  const std::vector<int> truth = cvt::BruteForceLabels(grid, xy);
  int wrong = 0;
  for (vtkIdType p = 0; p < ids->GetNumberOfTuples(); ++p)
  {
    wrong += static_cast<int>(ids->GetTuple1(p)) != truth[p];
  }
  EXPECT_LE(wrong, 3);

  // Dual: counter-clockwise triangles, no duplicates, joining Voronoi neighbours.
  vtkPolyData* dual = filter->GetDualOutput();
  EXPECT_GT(dual->GetNumberOfPolys(), 40);
  std::set<std::set<vtkIdType>> seen;
  std::map<std::pair<vtkIdType, vtkIdType>, int> directedEdges;
  vtkIdType npts;
  const vtkIdType* tri;
  for (dual->GetPolys()->InitTraversal(); dual->GetPolys()->GetNextCell(npts, tri);)
  {
    ASSERT_EQ(npts, 3);
    double a[3], b[3], c[3];
    dual->GetPoint(tri[0], a);
    dual->GetPoint(tri[1], b);
    dual->GetPoint(tri[2], c);
    EXPECT_GT((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]), 0.0);
    EXPECT_TRUE(seen.insert({ tri[0], tri[1], tri[2] }).second) << "duplicate triangle";
    for (int e = 0; e < 3; ++e)
    {
      const std::pair<vtkIdType, vtkIdType> edge(tri[e], tri[(e + 1) % 3]);
      EXPECT_EQ(++directedEdges[edge], 1) << "inconsistent orientation";
    }
  }

  // History: one row per iteration plus the initial state, energy going down.
  vtkTable* history = filter->GetHistoryOutput();
  ASSERT_EQ(history->GetNumberOfRows(), 16);
  for (const char* column : { "iteration", "evaluations", "energy", "gradient_norm", "seconds" })
  {
    EXPECT_NE(history->GetColumnByName(column), nullptr) << column;
  }
  EXPECT_LT(history->GetValueByName(15, "energy").ToDouble(),
    history->GetValueByName(0, "energy").ToDouble());
  EXPECT_GE(progressEvents, 15);
}

TEST(ImageFilter, SameSeedSameOutput)
{
  auto image = MakeImage(32, 32);
  vtkNew<vtkCVTImageFilter> a, b;
  for (vtkCVTImageFilter* f : { a.Get(), b.Get() })
  {
    f->SetInputData(image);
    f->SetNumberOfSites(12);
    f->SetRandomSeed(42);
    f->SetMaximumNumberOfIterations(5);
    f->Update();
  }
  ASSERT_EQ(a->GetSitesOutput()->GetNumberOfPoints(), 12);
  for (vtkIdType i = 0; i < 12; ++i)
  {
    double p[3], q[3];
    a->GetSitesOutput()->GetPoint(i, p);
    b->GetSitesOutput()->GetPoint(i, q);
    EXPECT_EQ(p[0], q[0]);
    EXPECT_EQ(p[1], q[1]);
  }
  b->SetRandomSeed(43);
  b->Update();
  double p[3], q[3];
  a->GetSitesOutput()->GetPoint(0, p);
  b->GetSitesOutput()->GetPoint(0, q);
  EXPECT_NE(p[0], q[0]);
}

TEST(ImageFilter, DensityPullsSitesAndInitialSitesAreUsed)
{
  // Density 1 on the left half, 0 on the right: every site stays on the left.
  auto image = MakeImage(32, 32);
  vtkNew<vtkUnsignedCharArray> density;
  density->SetName("rho");
  density->SetNumberOfValues(32 * 32);
  for (int j = 0; j < 32; ++j)
  {
    for (int i = 0; i < 32; ++i)
    {
      density->SetValue(j * 32 + i, i < 16 ? 200 : 0);
    }
  }
  image->GetPointData()->AddArray(density);
  vtkNew<vtkCVTImageFilter> filter;
  filter->SetInputData(image);
  filter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "rho");
  filter->SetInitialSitesData(MakeSites({ -0.5, -0.5, -0.5, 0.5, -0.2, 0.1 }));
  filter->SetMaximumNumberOfIterations(30);
  filter->Update();
  vtkPolyData* sites = filter->GetSitesOutput();
  ASSERT_EQ(sites->GetNumberOfPoints(), 3);
  for (vtkIdType i = 0; i < 3; ++i)
  {
    EXPECT_LT(sites->GetPoint(i)[0], 0.0);
  }
}

TEST(ImageFilter, AbortStopsIterations)
{
  auto image = MakeImage(32, 32);
  vtkNew<vtkCVTImageFilter> filter;
  filter->SetInputData(image);
  filter->SetNumberOfSites(10);
  filter->SetMaximumNumberOfIterations(1000);
  filter->SetTolerance(0.0);
  vtkNew<vtkCallbackCommand> abortSoon;
  abortSoon->SetCallback(
    [](vtkObject* caller, unsigned long, void*, void*)
    {
      auto* f = static_cast<vtkCVTImageFilter*>(caller);
      if (f->GetProgress() > 0.002)
      {
        f->AbortExecuteOn();
      }
    });
  filter->AddObserver(vtkCommand::ProgressEvent, abortSoon);
  filter->Update();
  EXPECT_LT(filter->GetHistoryOutput()->GetNumberOfRows(), 20);
}

TEST(ImageFilter, PrintSelfNamesTheParameters)
{
  vtkNew<vtkCVTImageFilter> filter;
  std::ostringstream out;
  filter->Print(out);
  EXPECT_TRUE(Contains(out.str(), "NumberOfSites: 1000"));
  EXPECT_TRUE(Contains(out.str(), "Tolerance"));
}

TEST(ImageFilter, LBFGSIsTheDefaultAndReportsExactEnergyAndQuality)
{
  auto image = MakeImage(128, 128);
  vtkNew<vtkCVTImageFilter> filter;
  EXPECT_EQ(filter->GetMethod(), vtkCVTImageFilter::LBFGS);
  filter->SetInputData(image);
  filter->SetNumberOfSites(60);
  filter->SetMaximumNumberOfIterations(40);
  filter->SetTolerance(0.0);
  filter->ComputeExactEnergyOn();
  filter->Update();
  vtkFieldData* fields = filter->GetSitesOutput()->GetFieldData();
  for (const char* name : { "Energy", "GradientNorm", "Iterations", "Evaluations",
         "HexagonalFraction", "RadiusStandardDeviation", "NearestNeighborStandardDeviation",
         "AreaStandardDeviation", "ExactEnergy", "EnergyRelativeDifference" })
  {
    ASSERT_NE(fields->GetArray(name), nullptr) << name;
  }
  const double energy = fields->GetArray("Energy")->GetTuple1(0);
  EXPECT_NEAR(fields->GetArray("ExactEnergy")->GetTuple1(0), energy, 1e-4 * energy);
  EXPECT_LT(std::abs(fields->GetArray("EnergyRelativeDifference")->GetTuple1(0)), 1e-4);
  EXPECT_GT(fields->GetArray("HexagonalFraction")->GetTuple1(0), 0.3);
  // L-BFGS evaluates at least once per iteration; the history counts both.
  vtkTable* history = filter->GetHistoryOutput();
  const vtkIdType last = history->GetNumberOfRows() - 1;
  EXPECT_GE(history->GetValueByName(last, "evaluations").ToInt(),
    history->GetValueByName(last, "iteration").ToInt() + 1);

  // The same sites relaxed by Lloyd for as many evaluations end with a higher energy.
  vtkNew<vtkCVTImageFilter> lloyd;
  lloyd->SetInputData(image);
  lloyd->SetNumberOfSites(60);
  lloyd->SetMethodToLloyd();
  lloyd->SetTolerance(0.0);
  lloyd->SetMaximumNumberOfIterations(
    static_cast<int>(fields->GetArray("Evaluations")->GetTuple1(0)) - 1);
  lloyd->Update();
  EXPECT_GT(lloyd->GetSitesOutput()->GetFieldData()->GetArray("Energy")->GetTuple1(0), energy);
}

TEST(ImageFilter, EngineAndSolverOptionsReachTheEngine)
{
  // Whole pixels (SplitBoundaryPixels off) give a staircase energy, off the exact one; the
  // adaptive flooding changes nothing in the result; fewer L-BFGS corrections change the path.
  auto image = MakeImage(64, 64);
  std::vector<int> lastSteps;
  const auto run = [&image, &lastSteps](bool split, bool adaptive, int corrections)
  {
    vtkNew<vtkCVTImageFilter> filter;
    filter->SetInputData(image);
    filter->SetNumberOfSites(30);
    filter->SetMaximumNumberOfIterations(15);
    filter->SetTolerance(0.0);
    filter->SetEngineToOpenGL(); // these are the GPU engine's options
    filter->SetSplitBoundaryPixels(split);
    filter->SetAdaptiveJumpFlooding(adaptive);
    filter->SetNumberOfCorrections(corrections);
    filter->ComputeExactEnergyOn();
    filter->Update();
    lastSteps.push_back(filter->GetLastJumpFloodingStep());
    vtkFieldData* fields = filter->GetSitesOutput()->GetFieldData();
    return std::make_pair(fields->GetArray("Energy")->GetTuple1(0),
      std::abs(fields->GetArray("EnergyRelativeDifference")->GetTuple1(0)));
  };
  const auto exact = run(true, true, 7);
  const auto whole = run(false, true, 7);
  const auto full = run(true, false, 7);
  const auto short_memory = run(true, true, 1);
  EXPECT_LT(exact.second, 1e-4);
  EXPECT_GT(whole.second, 10.0 * exact.second);
  EXPECT_NEAR(full.first, exact.first, 1e-6 * exact.first);
  EXPECT_NE(short_memory.first, exact.first);
  // The adaptive flooding starts from a shorter step than the full one (32 on 64 x 64).
  EXPECT_LT(lastSteps[0], 32);
  EXPECT_EQ(lastSteps[2], 32);
}

TEST(ImageFilter, GradientToleranceStops)
{
  vtkNew<vtkCVTImageFilter> filter;
  filter->SetInputData(MakeImage(64, 64));
  filter->SetNumberOfSites(20);
  filter->SetMaximumNumberOfIterations(500);
  filter->SetTolerance(0.0);
  filter->SetGradientTolerance(0.05);
  filter->Update();
  vtkFieldData* fields = filter->GetSitesOutput()->GetFieldData();
  EXPECT_LT(fields->GetArray("Iterations")->GetTuple1(0), 500);
  EXPECT_EQ(fields->GetAbstractArray("StopReason")->GetVariantValue(0).ToString(),
    "gradient tolerance reached");
}

// --- Bad input: a clear error, empty outputs, never a crash.

TEST(ImageFilterBadInput, EmptyImage)
{
  vtkNew<vtkImageData> image;
  vtkNew<vtkCVTImageFilter> filter;
  filter->SetInputData(image);
  EXPECT_TRUE(Contains(RunExpectingError(filter), "empty"));
}

TEST(ImageFilterBadInput, ThreeDimensionalImage)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(8, 8, 3);
  vtkNew<vtkCVTImageFilter> filter;
  filter->SetInputData(image);
  filter->SetNumberOfSites(4);
  EXPECT_TRUE(Contains(RunExpectingError(filter), "3D"));
}

TEST(ImageFilterBadInput, MoreSitesThanPixels)
{
  vtkNew<vtkCVTImageFilter> filter;
  filter->SetInputData(MakeImage(4, 4));
  filter->SetNumberOfSites(17);
  EXPECT_TRUE(Contains(RunExpectingError(filter), "exceeds the 16 pixels"));
}

TEST(ImageFilterBadInput, ZeroSites)
{
  vtkNew<vtkCVTImageFilter> filter;
  filter->SetInputData(MakeImage(4, 4));
  filter->SetNumberOfSites(0);
  EXPECT_TRUE(Contains(RunExpectingError(filter), "at least one site"));
}

TEST(ImageFilterBadInput, NaNDensity)
{
  auto image = MakeImage(8, 8);
  AddDensity(image, "rho", 1.0f);
  vtkFloatArray::SafeDownCast(image->GetPointData()->GetArray("rho"))
    ->SetValue(5, std::numeric_limits<float>::quiet_NaN());
  EXPECT_TRUE(Contains(ErrorWithDensity(image, "rho"), "not finite"));
}

TEST(ImageFilterBadInput, NegativeDensity)
{
  auto image = MakeImage(8, 8);
  AddDensity(image, "rho", 1.0f);
  vtkFloatArray::SafeDownCast(image->GetPointData()->GetArray("rho"))->SetValue(3, -1.0f);
  EXPECT_TRUE(Contains(ErrorWithDensity(image, "rho"), "negative"));
}

TEST(ImageFilterBadInput, AllZeroDensity)
{
  auto image = MakeImage(8, 8);
  AddDensity(image, "rho", 0.0f);
  EXPECT_TRUE(Contains(ErrorWithDensity(image, "rho"), "zero everywhere"));
}

TEST(ImageFilterBadInput, MissingDensityArray)
{
  vtkNew<vtkCVTImageFilter> filter;
  filter->SetInputData(MakeImage(8, 8));
  filter->SetNumberOfSites(4);
  filter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "nothere");
  EXPECT_TRUE(Contains(RunExpectingError(filter), "'nothere'"));
}

TEST(ImageFilter, UniformDensityNameMeansNoArray)
{
  vtkNew<vtkCVTImageFilter> filter;
  filter->SetInputData(MakeImage(16, 16));
  filter->SetNumberOfSites(4);
  filter->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkCVTImageFilter::UniformDensityName());
  filter->Update();
  EXPECT_EQ(filter->GetSitesOutput()->GetNumberOfPoints(), 4);
}

TEST(ImageFilterBadInput, TwoComponentDensity)
{
  auto image = MakeImage(8, 8);
  vtkNew<vtkUnsignedCharArray> pairs;
  pairs->SetName("pairs");
  pairs->SetNumberOfComponents(2);
  pairs->SetNumberOfTuples(64);
  pairs->Fill(10);
  image->GetPointData()->AddArray(pairs);
  EXPECT_TRUE(Contains(ErrorWithDensity(image, "pairs"), "2 components"));
}

TEST(ImageFilter, ColourDensityGivesLuminanceAndInvertMakesDarkDense)
{
  // An RGB picture: black on the left half, white on the right.
  auto image = MakeImage(32, 32);
  vtkNew<vtkUnsignedCharArray> rgb;
  rgb->SetName("rgb");
  rgb->SetNumberOfComponents(3);
  rgb->SetNumberOfTuples(32 * 32);
  for (int j = 0; j < 32; ++j)
  {
    for (int i = 0; i < 32; ++i)
    {
      const double grey = i < 16 ? 0.0 : 255.0;
      rgb->SetTuple3(j * 32 + i, grey, grey, grey);
    }
  }
  image->GetPointData()->AddArray(rgb);
  for (bool invert : { false, true })
  {
    vtkNew<vtkCVTImageFilter> filter;
    filter->SetInputData(image);
    filter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "rgb");
    filter->SetNumberOfSites(20);
    filter->SetMaximumNumberOfIterations(10);
    filter->SetInvertDensity(invert);
    filter->Update();
    vtkPolyData* sites = filter->GetSitesOutput();
    ASSERT_EQ(sites->GetNumberOfPoints(), 20);
    int left = 0;
    for (vtkIdType i = 0; i < 20; ++i)
    {
      left += sites->GetPoint(i)[0] < 0.0 ? 1 : 0;
    }
    // The density is zero on one half: every site is on the other.
    EXPECT_EQ(left, invert ? 20 : 0) << (invert ? "inverted" : "as is");
  }
}

TEST(ImageFilterBadInput, FailPipelineOnErrorOffStillEmptiesTheOutputs)
{
  // VTK's convention by default: the update fails; off (ParaView): it succeeds with the
  // outputs emptied, after a good run filled them.
  vtkNew<vtkCVTImageFilter> filter;
  filter->SetInputData(MakeImage(8, 8));
  filter->SetNumberOfSites(4);
  EXPECT_EQ(filter->GetExecutive()->Update(), 1);
  ASSERT_EQ(filter->GetSitesOutput()->GetNumberOfPoints(), 4);
  vtkNew<ErrorCatcher> catcher;
  filter->AddObserver(vtkCommand::ErrorEvent, catcher);
  filter->SetNumberOfSites(1000); // more sites than pixels
  EXPECT_EQ(filter->GetExecutive()->Update(), 0);
  filter->FailPipelineOnErrorOff();
  filter->SetNumberOfSites(4);
  EXPECT_EQ(filter->GetExecutive()->Update(), 1);
  filter->SetNumberOfSites(1000);
  EXPECT_EQ(filter->GetExecutive()->Update(), 1);
  // Every view updates its port: the failed run is not repeated.
  for (int port = 0; port < 4; ++port)
  {
    filter->UpdatePiece(0, 1, 0);
    filter->Update(port);
  }
  EXPECT_EQ(catcher->Messages.size(), 2u);
  EXPECT_EQ(filter->GetSitesOutput()->GetNumberOfPoints(), 0);
  EXPECT_EQ(filter->GetLabelsOutput()->GetNumberOfPoints(), 0);
  EXPECT_EQ(filter->GetHistoryOutput()->GetNumberOfRows(), 0);
}

TEST(ImageFilterBadInput, SitesOutsideTheDomain)
{
  vtkNew<vtkCVTImageFilter> filter;
  filter->SetInputData(MakeImage(8, 8));
  filter->SetInitialSitesData(MakeSites({ 0.0, 0.0, 1.5, 0.0 }));
  EXPECT_TRUE(Contains(RunExpectingError(filter), "outside the domain"));
}

TEST(ImageFilterBadInput, DuplicatedSites)
{
  vtkNew<vtkCVTImageFilter> filter;
  filter->SetInputData(MakeImage(8, 8));
  filter->SetInitialSitesData(MakeSites({ 0.25, 0.25, 0.5, 0.5, 0.25, 0.25 }));
  EXPECT_TRUE(Contains(RunExpectingError(filter), "duplicates"));
}

TEST(ImageFilterBadInput, EmptyInitialSites)
{
  vtkNew<vtkCVTImageFilter> filter;
  filter->SetInputData(MakeImage(8, 8));
  filter->SetInitialSitesData(MakeSites({}));
  EXPECT_TRUE(Contains(RunExpectingError(filter), "no sites"));
}

TEST(ImageFilterBadInput, GridBeyondTheLargestTexture)
{
  // 40000 x 1 pixels: wider than any GPU's largest texture (llvmpipe: 16384), yet tiny.
  vtkNew<vtkCVTImageFilter> filter;
  filter->SetInputData(MakeImage(40000, 1));
  filter->SetNumberOfSites(3);
  filter->SetEngineToOpenGL();
  EXPECT_TRUE(Contains(RunExpectingError(filter), "largest texture"));
}

TEST(ImageFilterBadInput, ImageBeyondThisMachinesMemory)
{
  // 200000 x 200000 pixels without arrays (uniform density): nothing allocated yet, but the
  // filter's arrays alone would take 320 GB. Refused before allocating, on either engine.
  for (int engine : { vtkCVTImageFilter::CPU, vtkCVTImageFilter::AUTO })
  {
    vtkNew<vtkCVTImageFilter> filter;
    filter->SetInputData(MakeImage(200000, 200000));
    filter->SetNumberOfSites(3);
    filter->SetEngine(engine);
    const std::string message = RunExpectingError(filter);
    EXPECT_TRUE(Contains(message, "too large for this machine")) << message;
    EXPECT_TRUE(Contains(message, "needs about 320 GB of memory")) << message;
  }
}

// What Auto does on a hardware GPU, run here on whatever OpenGL there is: both engines are timed
// on one job and the faster is taken, with the times in the reason. On a software renderer the
// CPU engine must win (llvmpipe is tens of times slower).
TEST(EngineChoice, CompareEnginesTakesTheFasterEngineAndSaysWhy)
{
  const cvtvtk::EngineChoice choice = cvtvtk::CompareEngines(nullptr, "the test's GPU");
  ASSERT_GT(choice.OpenGLMilliseconds, 0.0) << choice.Reason;
  ASSERT_GT(choice.CPUMilliseconds, 0.0) << choice.Reason;
  EXPECT_TRUE(choice.HardwareOpenGL);
  EXPECT_EQ(choice.UseOpenGL, choice.OpenGLMilliseconds < choice.CPUMilliseconds);
  EXPECT_EQ(choice.Name, choice.UseOpenGL ? "OpenGL" : "CPU");
  EXPECT_TRUE(Contains(choice.Reason, "the test's GPU")) << choice.Reason;
  EXPECT_TRUE(Contains(choice.Reason, "calibration Lloyd iteration")) << choice.Reason;
  vtkNew<vtkCVTOpenGLContext> context;
  if (context->Initialize() && context->IsSoftwareRenderer())
  {
    EXPECT_FALSE(choice.UseOpenGL) << choice.Reason;
    EXPECT_TRUE(Contains(choice.Reason, "the CPU engine is faster here")) << choice.Reason;
  }
}

TEST(ImageFilterBadInput, NoOpenGLContext)
{
  setenv("CVT_OPENGL_CONTEXT", "none", 1);
  vtkNew<vtkCVTImageFilter> filter;
  filter->SetInputData(MakeImage(8, 8));
  filter->SetNumberOfSites(3);
  filter->SetEngineToOpenGL(); // Auto would take the CPU (tested in cli-errors.sh)
  const std::string message = RunExpectingError(filter);
  unsetenv("CVT_OPENGL_CONTEXT");
  EXPECT_TRUE(Contains(message, "no OpenGL >= 4.0 context"));
}

TEST(ImageFilterBadInput, XServerThatRefusesTheConnection)
{
  // VTK's X window aborts the process when the server refuses it; the filter reports it.
  const char* display = std::getenv("DISPLAY");
  const std::string savedDisplay = display ? display : "";
  setenv("DISPLAY", ":4242", 1); // no server there
  setenv("CVT_OPENGL_CONTEXT", "window", 1);
  vtkNew<vtkCVTImageFilter> filter;
  filter->SetInputData(MakeImage(8, 8));
  filter->SetNumberOfSites(3);
  filter->SetEngineToOpenGL();
  const std::string message = RunExpectingError(filter);
  unsetenv("CVT_OPENGL_CONTEXT");
  if (display)
  {
    setenv("DISPLAY", savedDisplay.c_str(), 1);
  }
  else
  {
    unsetenv("DISPLAY");
  }
  EXPECT_TRUE(Contains(message, "cannot connect to the X server DISPLAY=:4242")) << message;
}

TEST(ImageFilterBadInput, OpenGLLostBetweenUpdates)
{
  // A result, then no new context can be made (a driver reset, a server losing its GPU:
  // simulated by forbidding every context). The filter keeps its engine and context, so the
  // next update still works; once its graphics resources are released it needs a new context
  // and fails cleanly with empty outputs; when OpenGL comes back it works again.
  vtkNew<vtkCVTImageFilter> filter;
  filter->SetInputData(MakeImage(16, 16));
  filter->SetNumberOfSites(4);
  filter->SetEngineToOpenGL();
  filter->Update();
  ASSERT_EQ(filter->GetSitesOutput()->GetNumberOfPoints(), 4);
  setenv("CVT_OPENGL_CONTEXT", "none", 1);
  filter->SetNumberOfSites(5);
  filter->Update();
  EXPECT_EQ(filter->GetSitesOutput()->GetNumberOfPoints(), 5);
  filter->ReleaseGraphicsResources();
  filter->SetNumberOfSites(6);
  const std::string message = RunExpectingError(filter);
  unsetenv("CVT_OPENGL_CONTEXT");
  EXPECT_TRUE(Contains(message, "no OpenGL >= 4.0 context")) << message;
  filter->SetNumberOfSites(7);
  filter->Update();
  EXPECT_EQ(filter->GetSitesOutput()->GetNumberOfPoints(), 7);
}

TEST(ImageFilterBadInput, HandedInWindowWithoutAContext)
{
  // A render window that has no OpenGL context (a generic window nobody made current): a clear
  // error and empty outputs; with the window taken back, the filter's own context works.
  vtkNew<vtkGenericOpenGLRenderWindow> window;
  vtkNew<vtkCVTImageFilter> filter;
  filter->SetInputData(MakeImage(16, 16));
  filter->SetNumberOfSites(4);
  filter->SetEngineToOpenGL();
  filter->SetRenderWindow(window);
  const std::string message = RunExpectingError(filter);
  EXPECT_TRUE(Contains(message,
    "the render window handed in (vtkGenericOpenGLRenderWindow) "
    "has no OpenGL >= 4.0 context"))
    << message;
  filter->SetRenderWindow(nullptr);
  filter->Update();
  EXPECT_EQ(filter->GetSitesOutput()->GetNumberOfPoints(), 4);
}

TEST(ImageFilterBadInput, ThenAGoodRunStillWorks)
{
  vtkNew<vtkCVTImageFilter> filter;
  filter->SetInputData(MakeImage(8, 8));
  filter->SetNumberOfSites(0);
  RunExpectingError(filter);
  filter->SetNumberOfSites(3);
  filter->Update();
  EXPECT_EQ(filter->GetSitesOutput()->GetNumberOfPoints(), 3);
}

TEST(ImageFilter, CPUAndOpenGLEnginesAgree)
{
  // Same job, same seed: Lloyd on a graded density. The GPU's discretisation (1+JFA labels,
  // split boundary pixels in float) makes the trajectories drift apart only slightly.
  auto image = MakeImage(128, 128);
  vtkNew<vtkFloatArray> density;
  density->SetName("density");
  for (vtkIdType p = 0; p < image->GetNumberOfPoints(); ++p)
  {
    density->InsertNextValue(static_cast<float>(1.0 + 3.0 * image->GetPoint(p)[0] / 128.0));
  }
  image->GetPointData()->AddArray(density);
  double energy[2] = { 0.0, 0.0 };
  std::string reason[2];
  for (int engine : { vtkCVTImageFilter::OPENGL, vtkCVTImageFilter::CPU })
  {
    vtkNew<vtkCVTImageFilter> filter;
    filter->SetInputData(image);
    filter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "density");
    filter->SetEngine(engine);
    filter->SetNumberOfSites(100);
    filter->SetMethodToLloyd();
    filter->SetMaximumNumberOfIterations(30);
    filter->SetTolerance(0.0);
    filter->ComputeExactEnergyOn();
    filter->Update();
    vtkFieldData* fields = filter->GetSitesOutput()->GetFieldData();
    const int k = engine == vtkCVTImageFilter::CPU;
    energy[k] = fields->GetArray("ExactEnergy")->GetTuple1(0);
    reason[k] = fields->GetAbstractArray("Engine")->GetVariantValue(0).ToString();
    if (k == 1)
    {
      // The CPU engine's energy is the exact one.
      EXPECT_NEAR(fields->GetArray("EnergyRelativeDifference")->GetTuple1(0), 0.0, 1e-12);
    }
  }
  EXPECT_EQ(reason[0], "OpenGL");
  EXPECT_EQ(reason[1], "CPU");
  EXPECT_NEAR(energy[1], energy[0], 2e-3 * energy[0]);

  // Auto names its choice and why: the CPU when OpenGL is a software renderer, or when a
  // hardware GPU's OpenGL engine was the slower on the calibration job.
  vtkNew<vtkCVTImageFilter> automatic;
  automatic->SetInputData(image);
  automatic->SetNumberOfSites(50);
  automatic->SetMaximumNumberOfIterations(3);
  automatic->Update();
  vtkFieldData* fields = automatic->GetSitesOutput()->GetFieldData();
  const std::string name = fields->GetAbstractArray("Engine")->GetVariantValue(0).ToString();
  const std::string why = fields->GetAbstractArray("EngineReason")->GetVariantValue(0).ToString();
  EXPECT_EQ(why.rfind("Auto: ", 0), 0u) << why;
  EXPECT_EQ(name == "CPU",
    why.find("software renderer") != std::string::npos ||
      why.find("no OpenGL") != std::string::npos ||
      why.find("the CPU engine is faster here") != std::string::npos)
    << name << ": " << why;
}
