// Seeded mutation fuzzing of the parsers and checks the project owns: the `cvt` command line,
// the --initial-sites CSV, OFF files (vtkCVTOFFReader), and the mesh path (checks, repairs,
// topology, restricted Voronoi diagram, remesh) in the core and through vtkCVTRemeshFilter with
// corrupt connectivity. Every case must end in a result that meets the documented invariants or in
// a clear error, never a crash or another exception; CI also runs this under AddressSanitizer and
// UBSan (tools/sanitize.sh). Fixed seeds and case counts keep it reproducible and bounded (144,000
// cases in about 3 s here). The outcome counts are printed.
#include "cvtCommandLine.h"
#include "cvtRemesh.h"
#include "cvtRestrictedVoronoi.h"
#include "cvtSurfaceMesh.h"
#include "vtkCVTOBJReader.h"
#include "vtkCVTOFFReader.h"
#include "vtkCVTRemeshFilter.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkDataArrayRange.h"
#include "vtkExecutive.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace
{
// Tokens that break parsers: numbers at and beyond the limits, non-numbers, empty strings.
const std::vector<std::string> NastyTokens = { "", "-", "--", "nan", "inf", "-inf", "1e999",
  "-1e999", "0x10", "1e-320", "9223372036854775808", "-9223372036854775809", "2147483648",
  "-2147483649", "0", "-1", "1.5", "65537", " 1", "1 ", "\t", "\xff\xfe", "1,2", "--sites",
  "--torus", "--domain", "--gi-resolution", "--input", "--help", "image", "surface", "lloyd",
  "lbfgs", "cpu", "opengl", "auto", std::string(5000, '9'), std::string("a\0b", 3) };

const std::vector<std::vector<std::string>> ValidCommandLines = {
  { "image", "--sites", "100", "--iterations", "5", "--method", "lloyd" },
  { "image", "--domain", "-1", "1", "-2", "2", "--resolution", "64", "--seed", "3" },
  { "image", "--input", "x.png", "--invert", "--array", "A", "--engine", "cpu", "--report" },
  { "image", "--initial-sites", "s.csv", "--tolerance", "1e-5", "--gradient-tolerance", "0.1" },
  { "surface", "--torus", "1", "0.4", "--gi-resolution", "64", "32", "--corrections", "5" },
  { "surface", "--input", "m.ply", "--array", "D", "--sites", "50", "--output", "o", "--quiet" },
  { "surface", "--input", "m.off", "--keep-every-site", "--engine", "cpu" },
};

// Invariants of a command line that parsed: every value in its documented range.
void ExpectValid(const cvtcli::Options& o)
{
  if (o.Help)
  {
    return;
  }
  EXPECT_TRUE(o.Command == "image" || o.Command == "surface");
  EXPECT_TRUE(o.Engine == "auto" || o.Engine == "cpu" || o.Engine == "opengl");
  EXPECT_TRUE(o.Method == "lloyd" || o.Method == "lbfgs");
  EXPECT_GE(o.Sites, 0);
  EXPECT_GE(o.Iterations, 0);
  EXPECT_TRUE(o.Resolution >= 1 && o.Resolution <= 65536);
  EXPECT_TRUE(o.Corrections >= 1 && o.Corrections <= 100);
  EXPECT_TRUE(o.Tolerance >= 0.0 && std::isfinite(o.Tolerance));
  EXPECT_TRUE(o.GradientTolerance >= 0.0 && o.GradientTolerance <= 1.0);
  EXPECT_TRUE(o.Domain[0] < o.Domain[1] && o.Domain[2] < o.Domain[3]);
  EXPECT_TRUE(std::isfinite(o.Domain[0]) && std::isfinite(o.Domain[3]));
  EXPECT_TRUE(o.Torus[1] > 0.0 && o.Torus[1] < o.Torus[0] && std::isfinite(o.Torus[0]));
  for (int r : o.GIResolution)
  {
    EXPECT_TRUE(r >= 2 && r <= 65536);
  }
}

std::string RandomBytes(std::mt19937_64& random, size_t count)
{
  std::string bytes(count, '\0');
  for (char& c : bytes)
  {
    c = static_cast<char>(random() & 0xff);
  }
  return bytes;
}
/// `text` with one to five mutations: flipped bits, a cut, nasty tokens or random bytes inserted.
std::string Mutated(std::string text, std::mt19937_64& random)
{
  const int mutations = 1 + static_cast<int>(random() % 5);
  for (int m = 0; m < mutations && !text.empty(); ++m)
  {
    const size_t at = random() % text.size();
    switch (random() % 4)
    {
      case 0:
        text[at] = static_cast<char>(text[at] ^ (1 << (random() % 8)));
        break;
      case 1:
        text.resize(at);
        break;
      case 2:
        text.insert(at, NastyTokens[random() % NastyTokens.size()]);
        break;
      default:
        text.insert(at, RandomBytes(random, random() % 16));
    }
  }
  return text;
}

} // namespace

TEST(Fuzz, CommandLine)
{
  std::mt19937_64 random(20261122);
  int parsed = 0, refused = 0;
  for (int n = 0; n < 100000; ++n)
  {
    std::vector<std::string> args = ValidCommandLines[random() % ValidCommandLines.size()];
    const int mutations = 1 + static_cast<int>(random() % 4);
    for (int m = 0; m < mutations; ++m)
    {
      const size_t at = args.empty() ? 0 : random() % args.size();
      switch (random() % 6)
      {
        case 0: // replace a token
          if (!args.empty())
            args[at] = NastyTokens[random() % NastyTokens.size()];
          break;
        case 1: // drop one
          if (!args.empty())
            args.erase(args.begin() + static_cast<long>(at));
          break;
        case 2: // insert one
          args.insert(
            args.begin() + static_cast<long>(at), NastyTokens[random() % NastyTokens.size()]);
          break;
        case 3: // cut the line short
          args.resize(at);
          break;
        case 4: // random bytes
          if (!args.empty())
            args[at] = RandomBytes(random, random() % 12);
          break;
        default: // swap two tokens
          if (!args.empty())
            std::swap(args[at], args[random() % args.size()]);
      }
    }
    try
    {
      ExpectValid(cvtcli::ParseArguments(args));
      ++parsed;
    }
    catch (const cvtcli::UsageError& error)
    {
      EXPECT_GT(std::string(error.what()).size(), 10u);
      ++refused;
    }
    if (HasFailure())
    {
      std::string line;
      for (const std::string& a : args)
        line += "'" + a + "' ";
      FAIL() << "case " << n << ": " << line;
    }
  }
  std::printf(
    "command lines: %d parsed, %d refused with a usage error, 0 crashes\n", parsed, refused);
  EXPECT_GT(parsed, 1000);
  EXPECT_GT(refused, 1000);
}

TEST(Fuzz, SitesCsv)
{
  std::mt19937_64 random(7);
  std::string valid = "x,y\n";
  for (int i = 0; i < 20; ++i)
  {
    valid += std::to_string(-0.9 + 0.09 * i) + "," + std::to_string(0.5 - 0.05 * i) + "\n";
  }
  int parsed = 0, refused = 0;
  for (int n = 0; n < 30000; ++n)
  {
    std::istringstream in(Mutated(valid, random));
    try
    {
      const std::vector<double> xy = cvtcli::ParseSitesCsv(in, "fuzz.csv");
      EXPECT_EQ(xy.size() % 2, 0u);
      for (double v : xy)
      {
        EXPECT_TRUE(std::isfinite(v));
      }
      ++parsed;
    }
    catch (const cvtcli::UsageError& error)
    {
      EXPECT_NE(std::string(error.what()).find("fuzz.csv"), std::string::npos);
      ++refused;
    }
    ASSERT_FALSE(HasFailure()) << "case " << n;
  }
  std::printf("sites files: %d parsed, %d refused naming the line, 0 crashes\n", parsed, refused);
  EXPECT_GT(parsed, 100);
  EXPECT_GT(refused, 100);
}

/// Mutations of `valid`, read by Reader: each is read to faces of at least 3 points of the mesh,
/// or refused with an empty output; never a crash. Returns "N read, M refused".
template<typename Reader>
std::string FuzzMeshReader(const std::string& valid, const std::string& extension, unsigned seed)
{
  std::mt19937_64 random(seed);
  const std::string path =
    testing::TempDir() + "cvt_fuzz_" + std::to_string(getpid()) + "." + extension;
  int read = 0, refused = 0;
  for (int n = 0; n < 3000; ++n)
  {
    std::ofstream(path, std::ios::binary) << Mutated(valid, random);
    vtkNew<Reader> reader;
    vtkNew<vtkCallbackCommand> quiet; // the refusals are counted, not printed
    reader->AddObserver(vtkCommand::ErrorEvent, quiet);
    reader->SetFileName(path.c_str());
    if (reader->GetExecutive()->Update())
    {
      vtkPolyData* mesh = reader->GetOutput();
      // Every face has at least 3 vertices, all of them points of the mesh.
      vtkCellArray* faces = mesh->GetPolys();
      EXPECT_TRUE(faces->IsValid());
      for (vtkIdType f = 0; f < faces->GetNumberOfCells(); ++f)
      {
        EXPECT_GE(faces->GetCellSize(f), 3);
      }
      const vtkIdType points = mesh->GetNumberOfPoints();
      faces->Visit(
        [points](auto& state)
        {
          for (const auto id : vtk::DataArrayValueRange<1>(state.GetConnectivity()))
          {
            EXPECT_TRUE(id >= 0 && id < points) << "face vertex " << id;
          }
        });
      ++read;
    }
    else
    {
      EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0);
      ++refused;
    }
    if (::testing::Test::HasFailure())
    {
      ADD_FAILURE() << "case " << n;
      break;
    }
  }
  std::remove(path.c_str());
  EXPECT_GT(read, 100);
  EXPECT_GT(refused, 100);
  return std::to_string(read) + " read, " + std::to_string(refused) + " refused";
}

TEST(Fuzz, OffFiles)
{
  const std::string valid = "OFF\n# pyramid\n5 5 8\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 0.5 0.7\n"
                            "4 0 1 2 3\n3 0 4 1 255 0 0\n3 1 4 2\n3 2 4 3\n3 3 4 0\n";
  const std::string counts = FuzzMeshReader<vtkCVTOFFReader>(valid, "off", 11);
  std::printf("OFF files: %s, 0 crashes\n", counts.c_str());
}

TEST(Fuzz, ObjFiles)
{
  const std::string valid = "# pyramid\nv 0 0 0\nv 1 0 0\nvt 0 0\nv 1 1 0\nv 0 1 0\nusemtl\n"
                            "f 1/1 2/ 3//1 4\nf 1 5 2\nv 0.5 0.5 0.7\nf -4 -1 -3\nf 3 \\\n5 4\n"
                            "f 4 5 1\nl 1 2\n";
  const std::string counts = FuzzMeshReader<vtkCVTOBJReader>(valid, "obj", 12);
  std::printf("OBJ files: %s, 0 crashes\n", counts.c_str());
}

namespace
{
// A closed octahedron: a small valid mesh to mutate.
cvt::SurfaceMesh Octahedron()
{
  cvt::SurfaceMesh mesh;
  mesh.Points = { 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1 };
  mesh.Triangles = { { 0, 2, 4 }, { 2, 1, 4 }, { 1, 3, 4 }, { 3, 0, 4 }, { 2, 0, 5 }, { 1, 2, 5 },
    { 3, 1, 5 }, { 0, 3, 5 } };
  return mesh;
}

// One of the damages real files carry: soups, repeats, sheets on one edge, pinches, flips,
// stray or coincident points, bad coordinates and densities.
void Damage(cvt::SurfaceMesh& mesh, std::mt19937_64& random)
{
  const int points = mesh.NumberOfPoints();
  auto anyPoint = [&] { return static_cast<int>(random() % static_cast<unsigned>(points)); };
  const size_t t = mesh.Triangles.empty() ? 0 : random() % mesh.Triangles.size();
  switch (random() % 10)
  {
    case 0: // a random triangle (often non-manifold)
      mesh.Triangles.push_back({ anyPoint(), anyPoint(), anyPoint() });
      break;
    case 1: // a repeated or reversed triangle
      if (!mesh.Triangles.empty())
      {
        auto copy = mesh.Triangles[t];
        if (random() % 2)
          std::swap(copy[0], copy[1]);
        mesh.Triangles.push_back(copy);
      }
      break;
    case 2: // a flipped triangle
      if (!mesh.Triangles.empty())
        std::swap(mesh.Triangles[t][1], mesh.Triangles[t][2]);
      break;
    case 3: // a dropped triangle (a hole)
      if (!mesh.Triangles.empty())
        mesh.Triangles.erase(mesh.Triangles.begin() + static_cast<long>(t));
      break;
    case 4: // a degenerate triangle
      if (!mesh.Triangles.empty())
        mesh.Triangles[t][random() % 3] = mesh.Triangles[t][random() % 3];
      break;
    case 5: // a point moved onto another (zero-length edges, zero-area triangles)
    {
      const int a = anyPoint(), b = anyPoint();
      for (int k = 0; k < 3; ++k)
        mesh.Points[3 * a + k] = mesh.Points[3 * b + k];
      break;
    }
    case 6: // a stray point, or a fan of new triangles around a new point
    {
      const int p = mesh.NumberOfPoints();
      for (int k = 0; k < 3; ++k)
        mesh.Points.push_back(std::uniform_real_distribution<double>(-2, 2)(random));
      if (!mesh.Density.empty())
        mesh.Density.push_back(1.0);
      if (random() % 2 && !mesh.Triangles.empty())
      {
        const auto base = mesh.Triangles[t];
        mesh.Triangles.push_back({ base[0], base[1], p });
        mesh.Triangles.push_back({ base[1], base[2], p });
      }
      break;
    }
    case 7: // a bad coordinate (rare: it ends every case)
      if (random() % 4 == 0)
      {
        const double bad[] = { std::nan(""), std::numeric_limits<double>::infinity(), 1e308 };
        mesh.Points[3 * static_cast<size_t>(anyPoint()) + random() % 3] = bad[random() % 3];
      }
      break;
    case 8: // a density, sometimes bad
    {
      mesh.Density.assign(static_cast<size_t>(mesh.NumberOfPoints()), 1.0);
      const double values[] = { 0.0, 2.0, -1.0, std::nan(""), 1e-300 };
      mesh.Density[static_cast<size_t>(anyPoint())] = values[random() % 5];
      break;
    }
    default: // a jittered point
      mesh.Points[3 * static_cast<size_t>(anyPoint()) + random() % 3] +=
        std::uniform_real_distribution<double>(-0.5, 0.5)(random);
  }
}
} // namespace

TEST(Fuzz, MeshChecksRepairsAndRemesh)
{
  std::mt19937_64 random(11);
  int refused = 0, remeshed = 0;
  for (int n = 0; n < 10000; ++n)
  {
    cvt::SurfaceMesh mesh = Octahedron();
    const int damages = 1 + static_cast<int>(random() % 8);
    for (int d = 0; d < damages; ++d)
    {
      Damage(mesh, random);
    }
    SCOPED_TRACE("case " + std::to_string(n));
    std::string error = cvt::CheckSurfaceMesh(mesh);
    cvt::MeshRepairReport report;
    if (error.empty())
    {
      error = cvt::RepairSurfaceMesh(mesh, report);
    }
    if (!error.empty())
    {
      ++refused;
      continue;
    }
    for (const auto& triangle : mesh.Triangles)
    {
      for (int v : triangle)
      {
        ASSERT_TRUE(v >= 0 && v < mesh.NumberOfPoints());
      }
    }
    const cvt::MeshTopology topology =
      cvt::ComputeMeshTopology(mesh.NumberOfPoints(), mesh.Triangles);
    const int count = 1 + static_cast<int>(random() % 24);
    const std::vector<double> sites = cvt::SampleMeshSites(mesh, count, n, &topology);
    cvt::RestrictedVoronoi engine;
    cvt::CellSums sums;
    cvt::RestrictedDual dual;
    ASSERT_TRUE(engine.SetMesh(mesh)) << engine.GetLastError();
    ASSERT_TRUE(engine.SetSites(sites)) << engine.GetLastError();
    ASSERT_TRUE(engine.ComputeCellSums(sums)) << engine.GetLastError();
    ASSERT_TRUE(std::isfinite(sums.TotalEnergy()));
    ASSERT_TRUE(engine.ComputeDual(dual)) << engine.GetLastError();
    const cvt::Remesh remesh = cvt::BuildRemesh(dual, static_cast<size_t>(topology.BoundaryLoops));
    const int vertices = static_cast<int>(remesh.Points.size() / 3);
    for (const auto& triangle : remesh.Triangles)
    {
      for (int v : triangle)
      {
        ASSERT_TRUE(v >= 0 && v < vertices);
      }
    }
    ++remeshed;
  }
  std::printf(
    "damaged meshes: %d remeshed, %d refused with a reason, 0 crashes\n", remeshed, refused);
  EXPECT_GT(remeshed, 500);
  EXPECT_GT(refused, 50);
}

TEST(Fuzz, RemeshFilterWithCorruptConnectivity)
{
  // Cell arrays as a corrupt file may leave them: ids out of range or negative, cells of 0 to
  // 5 points, lines and vertices among the polygons. The filter must refuse or remesh.
  std::mt19937_64 random(3);
  vtkNew<vtkCVTRemeshFilter> remesh;
  remesh->SetNumberOfSites(12);
  remesh->SetMaximumNumberOfIterations(3);
  remesh->GlobalWarningDisplayOff();
  int refused = 0, remeshed = 0;
  for (int n = 0; n < 1000; ++n)
  {
    const cvt::SurfaceMesh base = Octahedron();
    vtkNew<vtkPoints> points;
    for (int p = 0; p < base.NumberOfPoints(); ++p)
    {
      points->InsertNextPoint(base.Point(p));
    }
    vtkNew<vtkCellArray> polygons, lines;
    for (const auto& triangle : base.Triangles)
    {
      const vtkIdType ids[3] = { triangle[0], triangle[1], triangle[2] };
      polygons->InsertNextCell(3, ids);
    }
    const int extra = static_cast<int>(random() % 4);
    for (int e = 0; e < extra; ++e)
    {
      const int size = static_cast<int>(random() % 6);
      std::vector<vtkIdType> ids(static_cast<size_t>(size));
      for (vtkIdType& id : ids)
      {
        const vtkIdType choices[] = { static_cast<vtkIdType>(random() % 6), -1, 6, 1000000,
          std::numeric_limits<vtkIdType>::max() };
        id = choices[random() % 5];
      }
      (random() % 4 ? polygons : lines)->InsertNextCell(size, ids.data());
    }
    vtkNew<vtkPolyData> mesh;
    mesh->SetPoints(points);
    mesh->SetPolys(polygons);
    if (lines->GetNumberOfCells() > 0)
    {
      mesh->SetLines(lines);
    }
    remesh->SetInputData(mesh);
    remesh->SetRandomSeed(n);
    const int ok = remesh->GetExecutive()->Update();
    const vtkIdType out = remesh->GetRemeshOutput()->GetNumberOfPoints();
    if (ok)
    {
      ++remeshed;
      EXPECT_GT(out, 0) << "case " << n;
    }
    else
    {
      ++refused;
      EXPECT_EQ(out, 0) << "case " << n << ": a refused input leaves empty outputs";
    }
  }
  std::printf("corrupt cell arrays: %d remeshed, %d refused, 0 crashes\n", remeshed, refused);
  EXPECT_GT(remeshed, 20);
  EXPECT_GT(refused, 20);
}
