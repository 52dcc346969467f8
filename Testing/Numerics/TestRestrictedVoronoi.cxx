// The exact CPU surface engine (restricted Voronoi cells on a triangle mesh), its dual and the
// mesh repairs, against independent computations: exact 2D Voronoi polygons for a flat mesh,
// brute-force nearest sites on a fine quadrature for a curved one.
#include "cvtEdgeTable.h"
#include "cvtExactVoronoi.h"
#include "cvtGeometry.h"
#include "cvtProblems.h"
#include "cvtQuality.h"
#include "cvtRemesh.h"
#include "cvtRestrictedVoronoi.h"
#include "cvtSampling.h"
#include "cvtSurfaceMesh.h"
#include "cvtSurfaceProjector.h"
#include "cvtTestMeshes.h"
#include "cvtTwoRanks.h"

#include "vtkSMPTools.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <random>
#include <set>
#include <thread>
#include <utility>

namespace
{
using cvttest::FlatSquare;
using cvttest::Sphere;
using cvttest::Tube;
using cvttest::TwoParts;

/// The smallest corner of a remesh's triangles, in degrees.
double SmallestAngle(const cvt::Remesh& remesh)
{
  return cvt::MeasureMesh(remesh.Points, remesh.Triangles).MinimumAngle;
}

/// The squared distance from p to the nearest of `triangles` (corners in `points`), by brute force.
double BruteForceNearest2(const double* p, const std::vector<double>& points,
  const std::vector<std::array<int, 3>>& triangles)
{
  double nearest = 1e300;
  for (const auto& t : triangles)
  {
    double q[3], w[3];
    cvt::ClosestPointOnTriangle(p, &points[3 * t[0]], &points[3 * t[1]], &points[3 * t[2]], q, w);
    nearest = std::min(nearest, cvt::Distance2(p, q));
  }
  return nearest;
}

/// Brute force: every triangle cut into m^2 similar pieces, each given by its centroid to the
/// nearest site (density interpolated linearly at the centroid).
cvt::CellSums BruteForceSums(const cvt::SurfaceMesh& mesh, const std::vector<double>& sites, int m)
{
  cvt::CellSums sums;
  const size_t n = sites.size() / 3;
  sums.Resize(n, true);
  for (const auto& t : mesh.Triangles)
  {
    const double* a = mesh.Point(t[0]);
    const double* b = mesh.Point(t[1]);
    const double* c = mesh.Point(t[2]);
    const double e1[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
    const double e2[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
    const double cross[3] = { e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
      e1[0] * e2[1] - e1[1] * e2[0] };
    const double piece =
      0.5 * std::sqrt(cross[0] * cross[0] + cross[1] * cross[1] + cross[2] * cross[2]) / (m * m);
    for (int i = 0; i < m; ++i)
    {
      for (int j = 0; i + j < m; ++j)
      {
        for (int flip = 0; flip < (i + j + 1 < m ? 2 : 1); ++flip)
        {
          const double u = flip ? (i + 2.0 / 3.0) / m : (i + 1.0 / 3.0) / m;
          const double v = flip ? (j + 2.0 / 3.0) / m : (j + 1.0 / 3.0) / m;
          const double x[3] = { a[0] + u * e1[0] + v * e2[0], a[1] + u * e1[1] + v * e2[1],
            a[2] + u * e1[2] + v * e2[2] };
          const double rho = mesh.Density.empty()
            ? 1.0
            : (1 - u - v) * mesh.Density[t[0]] + u * mesh.Density[t[1]] + v * mesh.Density[t[2]];
          size_t best = 0;
          double best2 = 1e300;
          for (size_t s = 0; s < n; ++s)
          {
            const double d2 = std::pow(x[0] - sites[3 * s], 2) +
              std::pow(x[1] - sites[3 * s + 1], 2) + std::pow(x[2] - sites[3 * s + 2], 2);
            if (d2 < best2)
            {
              best2 = d2;
              best = s;
            }
          }
          sums.Mass[best] += rho * piece;
          sums.MomentX[best] += rho * piece * (x[0] - sites[3 * best]);
          sums.MomentY[best] += rho * piece * (x[1] - sites[3 * best + 1]);
          sums.MomentZ[best] += rho * piece * (x[2] - sites[3 * best + 2]);
          sums.Energy[best] += rho * piece * best2;
        }
      }
    }
  }
  return sums;
}

/// Random sites near the unit sphere, some off it (the restricted CVT's sites are free).
std::vector<double> SitesNearSphere(int count, unsigned seed)
{
  std::mt19937_64 rng(seed);
  std::vector<double> sites;
  while (static_cast<int>(sites.size()) < 3 * count)
  {
    double p[3], length = 0.0;
    for (double& c : p)
    {
      c = 2.0 * cvt::Uniform01(rng) - 1.0;
      length += c * c;
    }
    if (length < 1e-3 || length > 1.0)
    {
      continue;
    }
    const double radius = 0.9 + 0.2 * cvt::Uniform01(rng);
    for (double c : p)
    {
      sites.push_back(radius * c / std::sqrt(length));
    }
  }
  return sites;
}

/// A dual whose vertex v is site v at `points[v]` (its own surface and border point), on the
/// border or not, pinned where `pinned` says; the triangles are left to the caller.
cvt::RestrictedDual DualAt(const std::vector<std::array<double, 3>>& points, bool onBoundary,
  const std::vector<char>& pinned)
{
  cvt::RestrictedDual dual;
  for (size_t v = 0; v < points.size(); ++v)
  {
    dual.Sites.push_back(static_cast<int>(v));
    dual.SurfacePoints.insert(dual.SurfacePoints.end(), points[v].begin(), points[v].end());
    dual.SurfaceTriangles.push_back(0);
    dual.SurfaceBarycentric.insert(dual.SurfaceBarycentric.end(), { 1.0, 0.0, 0.0 });
    dual.OnBoundary.push_back(onBoundary ? 1 : 0);
    dual.Pinned.push_back(pinned.empty() ? 0 : pinned[v]);
    dual.BoundaryPoints.insert(dual.BoundaryPoints.end(), points[v].begin(), points[v].end());
    dual.BoundaryTriangles.push_back(0);
    dual.BoundaryBarycentric.insert(dual.BoundaryBarycentric.end(), { 1.0, 0.0, 0.0 });
  }
  return dual;
}

/// The triangles of a 5 x 5 grid of dual vertices (vertex 5 j + i at (i, j)), two per square;
/// with `doubled`, that vertex stands for vertex 2 as the lower-left corner of square (2, 0)
/// (the middle of the bottom side doubled), and their needle triangle with vertex 7 is added.
void AddGridTriangles(cvt::RestrictedDual& dual, int doubled = -1)
{
  for (int j = 0; j < 4; ++j)
  {
    for (int i = 0; i < 4; ++i)
    {
      const int a = 5 * j + i;
      const int lowerLeft = (doubled >= 0 && i == 2 && j == 0) ? doubled : a;
      dual.Triangles.push_back({ lowerLeft, a + 1, a + 6 });
      dual.Triangles.push_back({ lowerLeft, a + 6, a + 5 });
    }
  }
  if (doubled >= 0)
  {
    dual.Triangles.push_back({ 2, doubled, 7 }); // the needle
  }
}

/// A 5 x 5 grid (vertex 5 j + i) with its border pinned at (i, j) and its nine inner points
/// jittered: one of the random grids where moves to the neighbours' mean stop at a 25-degree
/// corner and no collapse helps.
void JitteredGrid(std::vector<std::array<double, 3>>& points, std::vector<char>& pinned)
{
  const double inner[9][2] = { { 1.26, 1.05 }, { 2.17, 0.87 }, { 3.26, 0.73 }, { 1.07, 2.29 },
    { 1.90, 1.86 }, { 3.19, 1.76 }, { 0.75, 2.85 }, { 1.88, 3.05 }, { 3.17, 3.29 } };
  for (int j = 0, k = 0; j < 5; ++j)
  {
    for (int i = 0; i < 5; ++i)
    {
      const bool border = i == 0 || i == 4 || j == 0 || j == 4;
      points.push_back({ border ? i : inner[k][0], border ? j : inner[k][1], 0.0 });
      k += border ? 0 : 1;
      pinned.push_back(border);
    }
  }
}

/// The remesh of a dual on the 5 x 5 grids above without the input surface, and with it (the
/// plane z = 0, reaching past the grid): the triangles before and after the moves along it.
std::pair<cvt::Remesh, cvt::Remesh> GridRemeshBeforeAndAfterMoves(const cvt::RestrictedDual& dual)
{
  const cvt::SurfaceMesh plane = FlatSquare(1, -3.0, 7.0);
  return { cvt::BuildRemesh(dual, 1), cvt::BuildRemesh(dual, 1, 8, &plane) };
}

/// 2D sites (x, y) as 3D points at z = 0.
std::vector<double> AtZeroHeight(const std::vector<double>& xy)
{
  std::vector<double> xyz;
  for (size_t i = 0; i < xy.size() / 2; ++i)
  {
    xyz.insert(xyz.end(), { xy[2 * i], xy[2 * i + 1], 0.0 });
  }
  return xyz;
}
}

TEST(RestrictedVoronoi, FlatMeshMatchesExactVoronoiPolygons)
{
  // On a flat mesh the restricted cells are the 2D Voronoi cells clipped to the square: the
  // exact 2D reference integrates them as polygons, independently of any triangle.
  const cvt::SurfaceMesh mesh = FlatSquare(7, -1.0, 1.0);
  const cvt::Grid grid = cvt::Grid::Square(64, -1.0, 1.0);
  const std::vector<double> sites2D = cvt::SampleSites(grid, {}, 60, 3);
  const std::vector<double> sites = AtZeroHeight(sites2D);
  cvt::RestrictedVoronoi engine;
  ASSERT_TRUE(engine.SetMesh(mesh));
  ASSERT_TRUE(engine.SetSites(sites));
  cvt::CellSums sums;
  ASSERT_TRUE(engine.ComputeCellSums(sums));
  const cvt::CellSums exact = cvt::ExactCellSums(grid, sites2D, {});
  for (size_t i = 0; i < exact.Size(); ++i)
  {
    EXPECT_NEAR(sums.Mass[i], exact.Mass[i], 1e-12) << "site " << i;
    EXPECT_NEAR(sums.MomentX[i], exact.MomentX[i], 1e-12);
    EXPECT_NEAR(sums.MomentY[i], exact.MomentY[i], 1e-12);
    EXPECT_NEAR(sums.MomentZ[i], 0.0, 1e-14);
    EXPECT_NEAR(sums.Energy[i], exact.Energy[i], 1e-12);
  }
}

TEST(RestrictedVoronoi, LargeTrianglesMeetManyCells)
{
  // Two triangles for the whole square (CAD models have such faces), 400 sites: each triangle
  // meets hundreds of cells, and still the integrals are the exact 2D ones.
  const cvt::SurfaceMesh mesh = FlatSquare(1, -1.0, 1.0);
  const cvt::Grid grid = cvt::Grid::Square(64, -1.0, 1.0);
  const std::vector<double> sites2D = cvt::SampleSites(grid, {}, 400, 8);
  const std::vector<double> sites = AtZeroHeight(sites2D);
  cvt::RestrictedVoronoi engine;
  cvt::CellSums sums;
  ASSERT_TRUE(engine.SetMesh(mesh) && engine.SetSites(sites) && engine.ComputeCellSums(sums));
  const cvt::CellSums exact = cvt::ExactCellSums(grid, sites2D, {});
  for (size_t i = 0; i < exact.Size(); ++i)
  {
    ASSERT_NEAR(sums.Mass[i], exact.Mass[i], 1e-12) << "site " << i;
    ASSERT_NEAR(sums.Energy[i], exact.Energy[i], 1e-12) << "site " << i;
  }
  cvt::RestrictedDual dual;
  ASSERT_TRUE(engine.ComputeDual(dual));
  const cvt::Remesh remesh = cvt::BuildRemesh(dual, 1);
  const cvt::MeshTopology topology =
    cvt::ComputeMeshTopology(static_cast<int>(remesh.SiteIds.size()), remesh.Triangles);
  EXPECT_EQ(topology.Components, 1);
  EXPECT_EQ(topology.BoundaryLoops, 1);
  EXPECT_EQ(topology.EulerCharacteristic, 1);
}

TEST(RestrictedVoronoi, CurvedMeshMatchesBruteForce)
{
  cvt::SurfaceMesh mesh = Sphere(3);
  const std::vector<double> sites = SitesNearSphere(40, 5);
  cvt::RestrictedVoronoi engine;
  ASSERT_TRUE(engine.SetMesh(mesh));
  ASSERT_TRUE(engine.SetSites(sites));
  cvt::CellSums sums;
  ASSERT_TRUE(engine.ComputeCellSums(sums));
  const cvt::CellSums brute = BruteForceSums(mesh, sites, 24);
  EXPECT_NEAR(sums.TotalEnergy(), brute.TotalEnergy(), 2e-3 * brute.TotalEnergy());
  double area = 0.0;
  for (size_t i = 0; i < sums.Size(); ++i)
  {
    area += sums.Mass[i];
    EXPECT_NEAR(sums.Mass[i], brute.Mass[i], 0.01 * brute.Mass[i] + 1e-4) << "site " << i;
    EXPECT_NEAR(sums.Energy[i], brute.Energy[i], 0.02 * brute.Energy[i] + 1e-5) << "site " << i;
  }
  EXPECT_NEAR(area, cvt::SurfaceArea(mesh), 1e-12 * area);

  // A linear density (1 + z + 1): still exact against the quadrature.
  mesh.Density.resize(mesh.NumberOfPoints());
  for (int p = 0; p < mesh.NumberOfPoints(); ++p)
  {
    mesh.Density[p] = 2.0 + mesh.Point(p)[2];
  }
  ASSERT_TRUE(engine.SetMesh(mesh));
  ASSERT_TRUE(engine.SetSites(sites));
  ASSERT_TRUE(engine.ComputeCellSums(sums));
  const cvt::CellSums weighted = BruteForceSums(mesh, sites, 24);
  EXPECT_NEAR(sums.TotalEnergy(), weighted.TotalEnergy(), 2e-3 * weighted.TotalEnergy());
  double mass = 0.0, bruteMass = 0.0;
  for (size_t i = 0; i < sums.Size(); ++i)
  {
    mass += sums.Mass[i];
    bruteMass += weighted.Mass[i];
  }
  EXPECT_NEAR(mass, bruteMass, 1e-9 * mass);
}

TEST(RestrictedVoronoi, SetDensityGivesTheSumsOfTheMeshWithThatDensity)
{
  cvt::SurfaceMesh mesh = Sphere(3);
  const std::vector<double> sites = SitesNearSphere(40, 5);
  std::vector<double> density(mesh.NumberOfPoints());
  for (int p = 0; p < mesh.NumberOfPoints(); ++p)
  {
    density[p] = 2.0 + mesh.Point(p)[2];
  }
  cvt::RestrictedVoronoi engine;
  cvt::CellSums swapped, back, uniform;
  ASSERT_TRUE(engine.SetMesh(mesh) && engine.SetSites(sites) && engine.ComputeCellSums(uniform));
  ASSERT_TRUE(engine.SetDensity(density) && engine.ComputeCellSums(swapped));
  cvt::SurfaceMesh weighted = mesh;
  weighted.Density = density;
  const cvt::CellSums brute = BruteForceSums(weighted, sites, 24);
  EXPECT_NEAR(swapped.TotalEnergy(), brute.TotalEnergy(), 2e-3 * brute.TotalEnergy());
  // The same sums as an engine given the mesh with that density.
  cvt::RestrictedVoronoi fresh;
  cvt::CellSums expected;
  ASSERT_TRUE(fresh.SetMesh(weighted) && fresh.SetSites(sites) && fresh.ComputeCellSums(expected));
  EXPECT_EQ(swapped.Mass, expected.Mass);
  EXPECT_EQ(swapped.Energy, expected.Energy);
  EXPECT_EQ(swapped.MomentX, expected.MomentX);
  // Back to uniform (empty), then refused densities leave the engine as it was.
  ASSERT_TRUE(engine.SetDensity({}) && engine.ComputeCellSums(back));
  EXPECT_EQ(back.Energy, uniform.Energy);
  EXPECT_FALSE(engine.SetDensity(std::vector<double>(3, 1.0)));
  EXPECT_NE(engine.GetLastError().find("has 3 values for"), std::string::npos)
    << engine.GetLastError();
  density[7] = -1.0;
  EXPECT_FALSE(engine.SetDensity(density));
  EXPECT_NE(engine.GetLastError().find("negative"), std::string::npos);
  density[7] = std::nan("");
  EXPECT_FALSE(engine.SetDensity(density));
  EXPECT_NE(engine.GetLastError().find("NaN"), std::string::npos);
  EXPECT_FALSE(engine.SetDensity(std::vector<double>(density.size(), 0.0)));
  EXPECT_NE(engine.GetLastError().find("zero everywhere"), std::string::npos);
  ASSERT_TRUE(engine.ComputeCellSums(back));
  EXPECT_EQ(back.Energy, uniform.Energy);
  cvt::RestrictedVoronoi empty;
  EXPECT_FALSE(empty.SetDensity({}));
}

TEST(RestrictedVoronoi, GradientIsMinusTwiceTheMoment)
{
  const cvt::SurfaceMesh mesh = Sphere(3);
  std::vector<double> sites = SitesNearSphere(30, 8);
  cvt::RestrictedVoronoi engine;
  ASSERT_TRUE(engine.SetMesh(mesh));
  cvt::CellSums sums, plus, minus;
  ASSERT_TRUE(engine.SetSites(sites) && engine.ComputeCellSums(sums));
  const double h = 1e-6;
  for (int k : { 0, 4, 17, 50, 88 })
  {
    std::vector<double> moved = sites;
    moved[k] += h;
    ASSERT_TRUE(engine.SetSites(moved) && engine.ComputeCellSums(plus));
    moved[k] -= 2 * h;
    ASSERT_TRUE(engine.SetSites(moved) && engine.ComputeCellSums(minus));
    const double numeric = (plus.TotalEnergy() - minus.TotalEnergy()) / (2 * h);
    const std::vector<double>* moment[3] = { &sums.MomentX, &sums.MomentY, &sums.MomentZ };
    const double analytic = -2.0 * (*moment[k % 3])[k / 3];
    EXPECT_NEAR(numeric, analytic, 1e-5 * (1.0 + std::abs(analytic))) << "coordinate " << k;
  }
}

TEST(RestrictedVoronoi, SumsDoNotDependOnTheThreadCount)
{
  const cvt::SurfaceMesh mesh = Sphere(4);
  const std::vector<double> sites = SitesNearSphere(200, 9);
  cvt::CellSums one, two;
  {
    vtkSMPTools::Initialize(1);
    cvt::RestrictedVoronoi engine;
    ASSERT_TRUE(engine.SetMesh(mesh) && engine.SetSites(sites) && engine.ComputeCellSums(one));
  }
  {
    vtkSMPTools::Initialize(2);
    cvt::RestrictedVoronoi engine;
    ASSERT_TRUE(engine.SetMesh(mesh) && engine.SetSites(sites) && engine.ComputeCellSums(two));
  }
  EXPECT_EQ(one.Energy, two.Energy);
  EXPECT_EQ(one.MomentX, two.MomentX);
}

TEST(RestrictedVoronoi, MovedSitesGiveTheSumsOfAFreshEngine)
{
  // An engine keeps each site's nearest sites from one evaluation to the next while their moves
  // leave them certainly the nearest: its sums must stay, to the bit, those of an engine that
  // searches them all again. Small moves (kept), a site jumping next to another (not kept for
  // either) and all sites moving far (none kept).
  const cvt::SurfaceMesh mesh = Sphere(4);
  std::vector<double> sites = SitesNearSphere(300, 11);
  const double spacing = std::sqrt(cvt::SurfaceArea(mesh) / 300.0);
  std::mt19937_64 rng(3);
  cvt::RestrictedVoronoi kept;
  ASSERT_TRUE(kept.SetMesh(mesh));
  for (int step = 0; step < 40; ++step)
  {
    const double move = step == 30 ? spacing : 0.03 * spacing;
    for (double& c : sites)
    {
      c += move * (2.0 * cvt::Uniform01(rng) - 1.0);
    }
    if (step % 10 == 5)
    {
      for (int k = 0; k < 3; ++k)
      {
        sites[3 * step + k] = sites[3 * (step + 100) + k] + 0.1 * spacing;
      }
    }
    cvt::RestrictedVoronoi fresh;
    cvt::CellSums keptSums, freshSums;
    ASSERT_TRUE(kept.SetSites(sites) && kept.ComputeCellSums(keptSums));
    ASSERT_TRUE(fresh.SetMesh(mesh) && fresh.SetSites(sites) && fresh.ComputeCellSums(freshSums));
    ASSERT_EQ(keptSums.Energy, freshSums.Energy) << "step " << step;
    ASSERT_EQ(keptSums.Mass, freshSums.Mass) << "step " << step;
    ASSERT_EQ(keptSums.MomentX, freshSums.MomentX) << "step " << step;
    ASSERT_EQ(kept.GetPointLabels(), fresh.GetPointLabels()) << "step " << step;
  }
}

TEST(RestrictedVoronoi, SumsOverListedTrianglesAreThoseOfTheCellsWithinThem)
{
  // The triangles within 2.5 spacings of a site: its cell and its neighbours' lie within them
  // whole, and their sums are those of the whole mesh, to the bit (each cell's pieces are added in
  // triangle order either way); cells the list cuts short reach its edge, and are told.
  const cvt::SurfaceMesh mesh = Sphere(4);
  const std::vector<double> sites = SitesNearSphere(300, 5);
  const double spacing = std::sqrt(cvt::SurfaceArea(mesh) / 300.0);
  cvt::RestrictedVoronoi engine;
  cvt::CellSums whole, listed;
  std::vector<char> reachBeyond;
  ASSERT_TRUE(engine.SetMesh(mesh) && engine.SetSites(sites) && engine.ComputeCellSums(whole));
  const int centre = 17;
  const std::vector<double> at(&sites[3 * centre], &sites[3 * centre] + 3);
  const std::vector<int> near = cvt::TrianglesNear(mesh, at, 2.5 * spacing);
  ASSERT_GT(near.size(), 0u);
  ASSERT_LT(near.size(), mesh.Triangles.size() / 4);
  // Every triangle with a corner within the distance is listed; the sites near, by brute force.
  for (size_t t = 0; t < mesh.Triangles.size(); ++t)
  {
    for (int p : mesh.Triangles[t])
    {
      if (cvt::Distance2(mesh.Point(p), at.data()) < 6.25 * spacing * spacing)
      {
        EXPECT_TRUE(std::binary_search(near.begin(), near.end(), static_cast<int>(t))) << t;
      }
    }
  }
  const std::vector<int> sitesNear = cvt::PointsNear(sites, at, spacing);
  std::vector<int> bruteForce;
  for (size_t i = 0; i < sites.size() / 3; ++i)
  {
    if (cvt::Distance2(&sites[3 * i], at.data()) < spacing * spacing)
    {
      bruteForce.push_back(static_cast<int>(i));
    }
  }
  EXPECT_EQ(sitesNear, bruteForce);
  ASSERT_TRUE(engine.ComputeCellSums(near, listed, reachBeyond));
  ASSERT_EQ(reachBeyond.size(), sites.size() / 3);
  int cutShort = 0, within = 0;
  for (size_t i = 0; i < sites.size() / 3; ++i)
  {
    const double distance = std::sqrt(cvt::Distance2(&sites[3 * i], at.data()));
    if (distance < spacing)
    {
      EXPECT_FALSE(reachBeyond[i]) << "site " << i;
      EXPECT_EQ(listed.Mass[i], whole.Mass[i]) << "site " << i;
      EXPECT_EQ(listed.MomentX[i], whole.MomentX[i]) << "site " << i;
      EXPECT_EQ(listed.Energy[i], whole.Energy[i]) << "site " << i;
      ++within;
    }
    if (reachBeyond[i])
    {
      ++cutShort;
      EXPECT_GT(distance, spacing) << "site " << i;
    }
    else if (listed.Mass[i] > 0.0)
    {
      EXPECT_EQ(listed.Mass[i], whole.Mass[i]) << "site " << i; // not cut short: whole
    }
    EXPECT_LE(listed.Mass[i], whole.Mass[i] * (1.0 + 1e-12)) << "site " << i;
  }
  EXPECT_GE(within, 3);
  EXPECT_GT(cutShort, 0);
  // The whole mesh listed gives the whole sums; a triangle that is not the mesh's, an error.
  std::vector<int> all(mesh.Triangles.size());
  std::iota(all.begin(), all.end(), 0);
  ASSERT_TRUE(engine.ComputeCellSums(all, listed, reachBeyond));
  EXPECT_EQ(listed.Mass, whole.Mass);
  EXPECT_EQ(listed.Energy, whole.Energy);
  EXPECT_EQ(std::count(reachBeyond.begin(), reachBeyond.end(), 1), 0);
  EXPECT_FALSE(
    engine.ComputeCellSums({ static_cast<int>(mesh.Triangles.size()) }, listed, reachBeyond));
  EXPECT_NE(engine.GetLastError().find("not one of the mesh's"), std::string::npos);
}

TEST(RestrictedVoronoi, LocalSettlingMovesSitesAsLloydStepsOverTheWholeMesh)
{
  // Sites crowded below z = 0.2 on a sphere and four above it (cells there several spacings
  // wide), three added at the crowd's edge. Settled locally, the triangles near the moving sites
  // are clipped, farther where a moving cell reaches the edge of them; the moved sites must be
  // those of Lloyd steps of the same sites over the whole mesh, to the bit.
  const cvt::SurfaceMesh mesh = Sphere(4);
  std::vector<double> sites;
  const std::vector<double> crowd = SitesNearSphere(400, 7);
  for (size_t i = 0; i < crowd.size(); i += 3)
  {
    if (crowd[i + 2] < 0.2)
    {
      sites.insert(sites.end(), &crowd[i], &crowd[i] + 3);
    }
  }
  const auto onSphere = [](double azimuth, double z)
  {
    const double r = std::sqrt(1.0 - z * z);
    return std::vector<double>{ r * std::cos(azimuth), r * std::sin(azimuth), z };
  };
  for (double azimuth : { 0.0, 2.1, 4.2 })
  {
    const std::vector<double> sparse = onSphere(azimuth, 0.55);
    sites.insert(sites.end(), sparse.begin(), sparse.end());
  }
  sites.insert(sites.end(), { 0.0, 0.0, 1.0 });
  const size_t first = sites.size() / 3;
  std::vector<double> added;
  for (double azimuth : { 0.0, 2.1, 4.2 })
  {
    const std::vector<double> at = onSphere(azimuth, 0.25);
    added.insert(added.end(), at.begin(), at.end());
  }
  sites.insert(sites.end(), added.begin(), added.end());
  const double spacing = std::sqrt(cvt::SurfaceArea(mesh) / static_cast<double>(sites.size() / 3));
  const double radius = 2.0 * spacing;
  const std::vector<int> moving = cvt::PointsNear(sites, added, radius);
  cvt::RestrictedVoronoi engine;
  ASSERT_TRUE(engine.SetMesh(mesh) && engine.SetSites(sites));
  // The test needs a moving cell reaching beyond the first reach (1.25 spacings).
  std::vector<double> movingSites;
  for (int i : moving)
  {
    movingSites.insert(movingSites.end(), &sites[3 * i], &sites[3 * i] + 3);
  }
  cvt::CellSums sums;
  std::vector<char> reachBeyond;
  ASSERT_TRUE(engine.ComputeCellSums(
    cvt::TrianglesNear(mesh, movingSites, 1.25 * spacing), sums, reachBeyond));
  EXPECT_TRUE(std::any_of(moving.begin(), moving.end(), [&](int i) { return reachBeyond[i]; }));
  // Lloyd steps of the moving sites over the whole mesh, the others kept.
  std::vector<double> reference = sites;
  for (int iteration = 0; iteration < 3; ++iteration)
  {
    ASSERT_TRUE(engine.SetSites(reference) && engine.ComputeCellSums(sums));
    for (int i : moving)
    {
      if (sums.Mass[i] > 0.0) // a site whose cell misses the sphere stays
      {
        reference[3 * i] += sums.MomentX[i] / sums.Mass[i];
        reference[3 * i + 1] += sums.MomentY[i] / sums.Mass[i];
        reference[3 * i + 2] += sums.MomentZ[i] / sums.Mass[i];
      }
    }
  }
  std::vector<double> settled = sites;
  std::string error;
  ASSERT_TRUE(cvt::SettleSitesLocally(engine, mesh, first, radius, spacing, 3, settled, error))
    << error;
  EXPECT_EQ(settled, reference);
  EXPECT_GT(moving.size(), added.size() / 3); // neighbours moved too
  std::vector<double> unchanged = sites;
  EXPECT_FALSE(cvt::SettleSitesLocally(
    engine, mesh, sites.size() / 3 + 1, radius, spacing, 3, unchanged, error));
  EXPECT_FALSE(cvt::SettleSitesLocally(engine, mesh, first, radius, 0.0, 3, unchanged, error));
  EXPECT_NE(error.find("positive site spacing"), std::string::npos);
  EXPECT_EQ(unchanged, sites);
  EXPECT_GT(std::sqrt(cvt::Distance2(&settled[3 * (first - 2)], &sites[3 * (first - 2)])),
    0.1 * spacing); // a sparse site above the crowd
}

TEST(RestrictedVoronoi, SharedWorkAddsUpToTheSumsOfOneProcess)
{
  // Two engines play two MPI ranks: each clips half of the blocks of triangles; part 1 hands
  // its sums over, part 0 adds them to its own. The sum is one process's, up to the order of
  // the additions.
  const cvt::SurfaceMesh mesh = Sphere(4);
  const std::vector<double> sites = SitesNearSphere(200, 9);
  cvt::CellSums whole;
  cvt::RestrictedVoronoi alone;
  ASSERT_TRUE(alone.SetMesh(mesh) && alone.SetSites(sites) && alone.ComputeCellSums(whole));

  std::vector<double> fromPartOne;
  cvt::RestrictedVoronoi partOne, partZero;
  cvttest::PlayTwoRanks(partZero, partOne, fromPartOne);
  cvt::CellSums ownShare, combined;
  ASSERT_TRUE(partOne.SetMesh(mesh) && partOne.SetSites(sites));
  ASSERT_TRUE(partOne.ComputeCellSums(ownShare));
  ASSERT_EQ(fromPartOne.size(), 5 * whole.Size()); // mass, three moments, energy
  const double ownMass = std::accumulate(ownShare.Mass.begin(), ownShare.Mass.end(), 0.0);
  const double wholeMass = std::accumulate(whole.Mass.begin(), whole.Mass.end(), 0.0);
  EXPECT_GT(ownMass, 0.3 * wholeMass); // about half of the sphere each
  EXPECT_LT(ownMass, 0.7 * wholeMass);
  ASSERT_TRUE(partZero.SetMesh(mesh) && partZero.SetSites(sites));
  ASSERT_TRUE(partZero.ComputeCellSums(combined));
  for (size_t i = 0; i < whole.Size(); ++i)
  {
    EXPECT_NEAR(combined.Mass[i], whole.Mass[i], 1e-12 * wholeMass) << "site " << i;
    EXPECT_NEAR(combined.MomentZ[i], whole.MomentZ[i], 1e-12 * wholeMass) << "site " << i;
    EXPECT_NEAR(combined.Energy[i], whole.Energy[i], 1e-12 * whole.TotalEnergy()) << "site " << i;
  }

  // A part whose exchange fails says so.
  cvt::RestrictedVoronoi cutOff;
  cutOff.ShareWork(0, 2, [](std::vector<double>&) { return false; });
  ASSERT_TRUE(cutOff.SetMesh(mesh) && cutOff.SetSites(sites));
  cvt::CellSums none;
  EXPECT_FALSE(cutOff.ComputeCellSums(none));
  EXPECT_NE(cutOff.GetLastError().find("other processes"), std::string::npos);
}

TEST(RestrictedVoronoi, OptimisedSphereRemeshIsAClosedOrientedSphere)
{
  const cvt::SurfaceMesh mesh = Sphere(4);
  cvt::RestrictedVoronoi engine;
  ASSERT_TRUE(engine.SetMesh(mesh));
  cvt::OptimizerOptions options;
  options.MaximumNumberOfIterations = 60;
  options.LloydWarmUpIterations = 5;
  cvt::OptimizerResult result;
  std::string error;
  const std::vector<double> initial = cvt::SampleMeshSites(mesh, 300, 4);
  cvt::RestrictedProblem problem(engine);
  ASSERT_TRUE(cvt::RunLBFGS(problem, { initial, {} }, options, nullptr, result, error)) << error;
  EXPECT_LT(result.History.back().Energy, 0.7 * result.History.front().Energy);
  // Normalised energy of a good CVT: about 0.16 (hexagons), random sites about 0.32.
  const double area = cvt::SurfaceArea(mesh);
  EXPECT_LT(result.Sums.TotalEnergy() * 300 / (area * area), 0.165);
  cvt::RestrictedDual dual;
  ASSERT_TRUE(engine.ComputeDual(dual));
  const cvt::Remesh remesh = cvt::BuildRemesh(dual, 0);
  const cvt::MeshTopology topology =
    cvt::ComputeMeshTopology(static_cast<int>(remesh.SiteIds.size()), remesh.Triangles);
  EXPECT_EQ(topology.Components, 1);
  EXPECT_EQ(topology.BoundaryLoops, 0);
  EXPECT_EQ(topology.EulerCharacteristic, 2);
  EXPECT_EQ(remesh.SiteIds.size(), 300u);
  // Outward: every triangle's normal points away from the centre.
  for (const auto& t : remesh.Triangles)
  {
    const double* a = &remesh.Points[3 * t[0]];
    const double* b = &remesh.Points[3 * t[1]];
    const double* c = &remesh.Points[3 * t[2]];
    const double e1[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
    const double e2[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
    const double n[3] = { e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
      e1[0] * e2[1] - e1[1] * e2[0] };
    EXPECT_GT(n[0] * a[0] + n[1] * a[1] + n[2] * a[2], 0.0);
  }
  // Vertices lie on the surface (within the chord error of the mesh).
  for (size_t v = 0; v < remesh.SiteIds.size(); ++v)
  {
    const double* p = &remesh.Points[3 * v];
    EXPECT_NEAR(std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]), 1.0, 0.01);
  }
}

TEST(RestrictedVoronoi, LBFGSRunsAlikeOnASphereWhateverItsSize)
{
  // The same sphere at 1/128 of its size (an exact scaling: coordinates, energies and
  // gradients scale by powers of two) and 4096 times it. LBFGS++'s own energy test, absolute
  // below an energy of 1, ended the small one's run after a few iterations ("the solver
  // reported convergence"), and its test for keeping a correction pair dropped every pair of
  // the large one.
  const cvt::SurfaceMesh unit = Sphere(4);
  const std::vector<double> initial = cvt::SampleMeshSites(unit, 300, 4);
  cvt::OptimizerOptions options;
  options.MaximumNumberOfIterations = 40;
  options.LloydWarmUpIterations = 5;
  std::vector<cvt::OptimizerResult> results;
  for (double size : { 1.0, 1.0 / 128.0, 4096.0 })
  {
    cvt::SurfaceMesh mesh = unit;
    std::vector<double> sites = initial;
    for (double& x : mesh.Points)
    {
      x *= size;
    }
    for (double& x : sites)
    {
      x *= size;
    }
    cvt::RestrictedVoronoi engine;
    ASSERT_TRUE(engine.SetMesh(mesh));
    cvt::RestrictedProblem problem(engine);
    cvt::OptimizerResult result;
    std::string error;
    ASSERT_TRUE(cvt::RunLBFGS(problem, { sites, {} }, options, nullptr, result, error)) << error;
    EXPECT_EQ(result.StopReason, "iteration limit") << "size " << size;
    // Energy / size^4: the same at every size.
    const double size4 = size * size * size * size;
    EXPECT_NEAR(result.History.back().Energy / size4,
      results.empty() ? result.History.back().Energy : results.front().History.back().Energy,
      1e-9 * result.History.back().Energy / size4)
      << "size " << size;
    EXPECT_EQ(
      result.Evaluations, results.empty() ? result.Evaluations : results.front().Evaluations)
      << "size " << size;
    results.push_back(result);
  }
}

TEST(RestrictedVoronoi, DualFindsCellPartsThatAreNotDisks)
{
  // Sites on the axis of a tube thinner than their spacing: every cell is a ring (an annulus,
  // Euler characteristic 0) with no dual triangle; each gets three split points on its ring.
  const cvt::SurfaceMesh tube = Tube(0.05, 24, 40);
  cvt::RestrictedVoronoi engine;
  ASSERT_TRUE(engine.SetMesh(tube));
  ASSERT_TRUE(engine.SetSites({ 0, 0, 0.125, 0, 0, 0.375, 0, 0, 0.625, 0, 0, 0.875 }));
  cvt::RestrictedDual dual;
  ASSERT_TRUE(engine.ComputeDual(dual));
  ASSERT_EQ(dual.EulerCharacteristic.size(), 4u);
  for (int euler : dual.EulerCharacteristic)
  {
    EXPECT_EQ(euler, 0);
  }
  EXPECT_TRUE(dual.Triangles.empty());
  ASSERT_EQ(dual.SplitPoints.size(), 3u * 3u * 4u);
  for (size_t p = 0; p < dual.SplitPoints.size(); p += 3)
  {
    EXPECT_NEAR(std::hypot(dual.SplitPoints[p], dual.SplitPoints[p + 1]), 0.05, 0.005);
  }
  // One site on a sphere: its cell is the whole sphere (2); sites on a flat square: disks (1).
  ASSERT_TRUE(engine.SetMesh(Sphere(2)));
  ASSERT_TRUE(engine.SetSites({ 0.1, 0.2, 0.3 }));
  ASSERT_TRUE(engine.ComputeDual(dual));
  ASSERT_EQ(dual.EulerCharacteristic.size(), 1u);
  EXPECT_EQ(dual.EulerCharacteristic[0], 2);
  EXPECT_EQ(dual.SplitPoints.size(), 3u * 3u); // 3 (1 - 2), at least 3
  ASSERT_TRUE(engine.SetMesh(FlatSquare(12, 0.0, 1.0)));
  ASSERT_TRUE(engine.SetSites({ 0.2, 0.3, 0, 0.7, 0.2, 0, 0.5, 0.8, 0, 0.45, 0.5, 0.1 }));
  ASSERT_TRUE(engine.ComputeDual(dual));
  ASSERT_EQ(dual.EulerCharacteristic.size(), 4u);
  for (int euler : dual.EulerCharacteristic)
  {
    EXPECT_EQ(euler, 1);
  }
  EXPECT_TRUE(dual.SplitPoints.empty());
}

TEST(RestrictedVoronoi, CellsRoundHolesFarSmallerThanThemAreNoThinParts)
{
  // A unit sphere (octahedron subdivided 5 times: triangles about 0.05 across) without one
  // triangle, with 30 sites (cells about 0.65 across): the cell round the hole is an annulus
  // (Euler characteristic 0), but the hole is far smaller than it, the remesh opens it and no
  // site could keep it: no thin part, no split point. (The rings of a tube's ends hold its
  // loops whole too, but those are as long as the cells are wide: DualFindsCellPartsThatAreNotDisks
  // still splits them.)
  cvt::SurfaceMesh holed = Sphere(5);
  const std::array<int, 3> hole = holed.Triangles[100];
  holed.Triangles.erase(holed.Triangles.begin() + 100);
  cvt::RestrictedVoronoi engine;
  ASSERT_TRUE(engine.SetMesh(holed));
  ASSERT_TRUE(engine.SetSites(SitesNearSphere(30, 3)));
  cvt::RestrictedDual dual;
  ASSERT_TRUE(engine.ComputeDual(dual));
  const int holder = engine.GetPointLabels()[static_cast<size_t>(hole[0])];
  int annuli = 0;
  for (size_t v = 0; v < dual.Sites.size(); ++v)
  {
    EXPECT_EQ(dual.EulerCharacteristic[v], dual.Sites[v] == holder ? 0 : 1) << "vertex " << v;
    annuli += dual.EulerCharacteristic[v] == 0;
  }
  EXPECT_EQ(annuli, 1);
  EXPECT_EQ(dual.ThinParts, 0);
  EXPECT_TRUE(dual.SplitPoints.empty());
}

TEST(RestrictedVoronoi, DualOfAnEngineReusedIsThatOfAFreshEngine)
{
  // The dual keeps its work arrays from one call to the next (per piece and per mesh point): an
  // engine that computed duals of other meshes and site counts, larger and smaller, must give,
  // to the bit, the dual of a fresh engine. The tube's cells are rings, the open square's meet
  // its border.
  struct Job
  {
    cvt::SurfaceMesh Mesh;
    std::vector<double> Sites;
  };
  std::vector<Job> jobs;
  jobs.push_back({ Sphere(4), SitesNearSphere(300, 5) });
  jobs.push_back({ Tube(0.05, 24, 40), { 0, 0, 0.125, 0, 0, 0.375, 0, 0, 0.625, 0, 0, 0.875 } });
  jobs.push_back({ Sphere(3), SitesNearSphere(40, 6) });
  jobs.push_back({ FlatSquare(12, 0.0, 1.0),
    { 0.2, 0.3, 0, 0.7, 0.2, 0, 0.5, 0.8, 0, 0.45, 0.5, 0.1, 0.1, 0.9, 0 } });
  jobs.push_back({ Sphere(4), SitesNearSphere(120, 7) });
  cvt::RestrictedVoronoi reused;
  for (size_t j = 0; j < jobs.size(); ++j)
  {
    cvt::RestrictedVoronoi fresh;
    cvt::RestrictedDual a, b;
    ASSERT_TRUE(reused.SetMesh(jobs[j].Mesh) && reused.SetSites(jobs[j].Sites));
    ASSERT_TRUE(reused.ComputeDual(a));
    ASSERT_TRUE(fresh.SetMesh(jobs[j].Mesh) && fresh.SetSites(jobs[j].Sites));
    ASSERT_TRUE(fresh.ComputeDual(b));
    EXPECT_FALSE(b.Sites.empty()) << "job " << j;
    EXPECT_EQ(a.Sites, b.Sites) << "job " << j;
    EXPECT_EQ(a.Triangles, b.Triangles) << "job " << j;
    EXPECT_EQ(a.SurfacePoints, b.SurfacePoints) << "job " << j;
    EXPECT_EQ(a.Parts, b.Parts) << "job " << j;
    EXPECT_EQ(a.Pinned, b.Pinned) << "job " << j;
    EXPECT_EQ(a.BoundaryPoints, b.BoundaryPoints) << "job " << j;
    EXPECT_EQ(a.EulerCharacteristic, b.EulerCharacteristic) << "job " << j;
    EXPECT_EQ(a.SplitPoints, b.SplitPoints) << "job " << j;
    EXPECT_EQ(a.ThinParts, b.ThinParts) << "job " << j;
  }
}

TEST(RestrictedVoronoi, DualTellsThePartOfTheInputOfEachCellPart)
{
  // Two unit squares side by side, touching along x = 1 but not joined (like a CAD model's
  // patches): the cell of the site above that line has a part on each square.
  const cvt::SurfaceMesh squares = TwoParts(FlatSquare(8, 0.0, 1.0), FlatSquare(8, 0.0, 1.0), 1.0);
  cvt::RestrictedVoronoi engine;
  ASSERT_TRUE(engine.SetMesh(squares));
  ASSERT_TRUE(
    engine.SetSites({ 0.5, 0.25, 0, 0.5, 0.75, 0, 1.0, 0.5, 0.1, 1.5, 0.25, 0, 1.5, 0.75, 0 }));
  cvt::RestrictedDual dual;
  ASSERT_TRUE(engine.ComputeDual(dual));
  ASSERT_EQ(dual.Sites.size(), 6u); // the middle site twice
  ASSERT_EQ(dual.Parts.size(), dual.Sites.size());
  std::set<int> left, right;
  for (size_t v = 0; v < dual.Sites.size(); ++v)
  {
    (dual.SurfaceTriangles[v] < 2 * 8 * 8 ? left : right).insert(dual.Parts[v]);
  }
  ASSERT_EQ(left.size(), 1u);
  ASSERT_EQ(right.size(), 1u);
  EXPECT_NE(*left.begin(), *right.begin());
  EXPECT_GE(*left.begin(), 0);
  EXPECT_GE(*right.begin(), 0);
}

TEST(RestrictedVoronoi, OpenSquareRemeshKeepsItsBorder)
{
  const cvt::SurfaceMesh mesh = FlatSquare(20, 0.0, 1.0);
  cvt::RestrictedVoronoi engine;
  ASSERT_TRUE(engine.SetMesh(mesh));
  cvt::OptimizerOptions options;
  options.MaximumNumberOfIterations = 40;
  cvt::OptimizerResult result;
  std::string error;
  cvt::RestrictedProblem problem(engine);
  ASSERT_TRUE(cvt::RunLloyd(
    problem, { cvt::SampleMeshSites(mesh, 100, 2), {} }, options, nullptr, result, error));
  cvt::RestrictedDual dual;
  ASSERT_TRUE(engine.ComputeDual(dual));
  const cvt::Remesh remesh = cvt::BuildRemesh(dual, 1);
  const cvt::MeshTopology topology =
    cvt::ComputeMeshTopology(static_cast<int>(remesh.SiteIds.size()), remesh.Triangles);
  EXPECT_EQ(topology.Components, 1);
  EXPECT_EQ(topology.BoundaryLoops, 1);
  EXPECT_EQ(topology.EulerCharacteristic, 1);
  // The border loop's vertices lie on the square's border, its four corners among them.
  ASSERT_EQ(topology.Loops.size(), 1u);
  int corners = 0;
  for (int v : topology.Loops[0])
  {
    const double x = remesh.Points[3 * v], y = remesh.Points[3 * v + 1];
    const double toBorder = std::min({ x, 1.0 - x, y, 1.0 - y });
    EXPECT_NEAR(toBorder, 0.0, 1e-12);
    corners += (x == 0.0 || x == 1.0) && (y == 0.0 || y == 1.0);
  }
  EXPECT_EQ(corners, 4);
}

TEST(RestrictedVoronoi, RemeshOfThinPartsIsManifold)
{
  // Dual triangles as a part thinner than the cells gives them: two closed tetrahedra whose
  // cells meet only at the shared site 0 (a pinch), and the two sides of a sliver of three
  // sites (two triangles on the same sites, a pillow of no area).
  cvt::RestrictedDual dual =
    DualAt({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { -1, 0, 0 }, { 0, -1, 0 },
             { 0, 0, -1 }, { 5, 5, 5 }, { 6, 5, 5 }, { 5, 6, 5 } },
      false, {});
  dual.Triangles = { { 0, 2, 1 }, { 0, 1, 3 }, { 1, 2, 3 }, { 0, 3, 2 }, // first tetrahedron
    { 0, 5, 4 }, { 0, 4, 6 }, { 4, 5, 6 }, { 0, 6, 5 },                  // second, at site 0
    { 7, 8, 9 }, { 7, 9, 8 } };                                          // the pillow
  const cvt::Remesh remesh = cvt::BuildRemesh(dual, 0);
  EXPECT_EQ(remesh.RemovedTriangles, 2);
  EXPECT_EQ(remesh.SplitVertices, 1);
  ASSERT_EQ(remesh.Triangles.size(), 8u);
  ASSERT_EQ(remesh.SiteIds.size(), 8u); // 7 sites, site 0 twice
  EXPECT_EQ(remesh.SiteIds[7], 0);
  EXPECT_EQ(remesh.Points.size(), 3 * remesh.SiteIds.size());
  // The two copies of site 0 are moved apart (towards their own tetrahedra), so merging
  // coincident points downstream cannot pinch the remesh again.
  EXPECT_EQ(remesh.SeparatedVertices, 2);
  const int first = static_cast<int>(
    std::find(remesh.SiteIds.begin(), remesh.SiteIds.end(), 0) - remesh.SiteIds.begin());
  ASSERT_LT(first, 7);
  EXPECT_GT(std::sqrt(cvt::Distance2(&remesh.Points[3 * first], &remesh.Points[3 * 7])), 0.05);
  EXPECT_EQ(remesh.SourceTriangles.size(), remesh.SiteIds.size());
  const cvt::MeshTopology parts = cvt::ComputeMeshTopology(8, remesh.Triangles);
  EXPECT_EQ(parts.Components, 2);
  EXPECT_EQ(parts.BoundaryLoops, 0);
  EXPECT_EQ(parts.EulerCharacteristic, 4); // two spheres
  // The topology alone, without building the remesh, is the same.
  const cvt::MeshTopology quick = cvt::RemeshTopology(dual, 0);
  EXPECT_EQ(quick.Components, 2);
  EXPECT_EQ(quick.BoundaryLoops, 0);
  EXPECT_EQ(quick.EulerCharacteristic, 4);
}

TEST(RestrictedVoronoi, RemeshDropsFragmentsButKeepsSmallParts)
{
  // A 5 x 5 grid of cells on a square (part 0), a lone triangle pinched to its corner 24 that
  // the dropped non-manifold triangles around it left (part 0 too), and a part of the input
  // smaller than the cells (part 1), whose remesh is one triangle. All on the input's border,
  // which has two loops: the fragment's would be a third, closed as a hole into a pillow.
  std::vector<std::array<double, 3>> points;
  for (int j = 0; j < 5; ++j)
  {
    for (int i = 0; i < 5; ++i)
    {
      points.push_back({ double(i), double(j), 0.0 });
    }
  }
  points.insert(points.end(),
    { { 5.0, 4.5, 0.0 }, { 4.5, 5.0, 0.0 }, // the fragment's
      { 10.0, 10.0, 0.0 }, { 11.0, 10.0, 0.0 }, { 10.0, 11.0, 0.0 } });
  cvt::RestrictedDual dual = DualAt(points, true, {});
  AddGridTriangles(dual);
  dual.Triangles.push_back({ 24, 25, 26 });
  dual.Triangles.push_back({ 27, 28, 29 });
  dual.Parts.assign(points.size(), 0);
  dual.Parts[27] = dual.Parts[28] = dual.Parts[29] = 1;
  const cvt::Remesh remesh = cvt::BuildRemesh(dual, 2);
  for (const bool built : { false, true })
  {
    const cvt::MeshTopology topology = built
      ? cvt::ComputeMeshTopology(static_cast<int>(remesh.SiteIds.size()), remesh.Triangles)
      : cvt::RemeshTopology(dual, 2);
    EXPECT_EQ(topology.Components, 2);
    EXPECT_EQ(topology.BoundaryLoops, 2);
    EXPECT_EQ(topology.EulerCharacteristic, 2);
  }
  EXPECT_EQ(remesh.DroppedFragments, 1);
  EXPECT_EQ(remesh.FilledHoles, 0);
  EXPECT_EQ(remesh.Triangles.size(), 32u + 1u);
  EXPECT_EQ(std::count(remesh.SiteIds.begin(), remesh.SiteIds.end(), 25), 0);
  EXPECT_EQ(std::count(remesh.SiteIds.begin(), remesh.SiteIds.end(), 28), 1);
  // The part each site's vertex lies in: the grid's, the small part's, none for the fragment's.
  const std::vector<int> parts = cvt::RemeshSiteParts(dual, 2);
  ASSERT_EQ(parts.size(), points.size());
  EXPECT_EQ(parts[12], parts[0]);
  EXPECT_EQ(parts[24], parts[0]);
  EXPECT_EQ(parts[28], parts[27]);
  EXPECT_EQ(parts[29], parts[27]);
  EXPECT_NE(parts[27], parts[0]);
  EXPECT_GE(parts[0], 0);
  EXPECT_GE(parts[27], 0);
  EXPECT_EQ(parts[25], -1);
}

TEST(RestrictedVoronoi, RemeshTellsThePartOfTheInputUnderEachOfItsParts)
{
  // Two unit squares side by side (parts 0 and 1 of the input, 8 triangles each), and a remesh
  // of three pieces: two on part 0 (a part split in two, as the counts alone would not tell
  // where part 1 has none) and one on part 1 with a vertex whose source lies on part 0 (a vertex
  // fitted to the input near the other part): most of its vertices decide.
  const cvt::SurfaceMesh input =
    cvttest::TwoParts(cvttest::FlatSquare(2, 0.0, 1.0), cvttest::FlatSquare(2, 0.0, 1.0), 1.05);
  const cvt::MeshTopology inputTopology =
    cvt::ComputeMeshTopology(input.NumberOfPoints(), input.Triangles);
  ASSERT_EQ(inputTopology.Components, 2);
  cvt::Remesh remesh;
  remesh.Triangles = { { 0, 1, 2 }, { 3, 4, 5 }, { 6, 7, 8 }, { 6, 8, 9 } };
  remesh.SourceTriangles = { 0, 1, 2, 5, 6, 7, 8, 9, 3, 10 };
  remesh.SiteIds.resize(remesh.SourceTriangles.size());
  std::iota(remesh.SiteIds.begin(), remesh.SiteIds.end(), 0);
  const cvt::MeshTopology topology = cvt::RemeshTopologyOf(remesh, &input, &inputTopology);
  ASSERT_EQ(topology.Components, 3);
  EXPECT_EQ(topology.InputComponents, (std::vector<int>{ 0, 0, 1 }));
  // Without the input, no parts are told.
  EXPECT_TRUE(cvt::RemeshTopologyOf(remesh).InputComponents.empty());
}

TEST(RestrictedVoronoi, RemeshFlipsThinTrianglesButNotFeatureEdges)
{
  // A flat rhombus split along its long diagonal a-b: two triangles of 11.3 degrees, where the
  // short diagonal c-d gives 22.6 degrees. The flip is made unless a and b are pinned (then a-b
  // may be a crease or border line).
  for (bool pinned : { false, true })
  {
    // The rhombus is the whole (open) surface: every vertex is on its border.
    cvt::RestrictedDual dual = DualAt(
      { { -1, 0, 0 }, { 1, 0, 0 }, { 0, 0.2, 0 }, { 0, -0.2, 0 } }, true, { pinned, pinned, 0, 0 });
    dual.Triangles = { { 0, 1, 2 }, { 1, 0, 3 } };
    const cvt::Remesh remesh = cvt::BuildRemesh(dual, 1);
    ASSERT_EQ(remesh.Triangles.size(), 2u);
    EXPECT_EQ(remesh.FlippedEdges, pinned ? 0 : 1);
    const cvt::MeshQuality quality = cvt::MeasureMesh(remesh.Points, remesh.Triangles);
    EXPECT_NEAR(quality.MinimumAngle, pinned ? 11.31 : 22.62, 0.01);
    EXPECT_EQ(cvt::ComputeMeshTopology(4, remesh.Triangles).BoundaryLoops, 1);
  }
}

/// Each vertex's valence (its edges) in a triangle mesh.
std::map<int, int> Valences(const std::vector<std::array<int, 3>>& triangles)
{
  std::set<std::pair<int, int>> edges;
  for (const auto& t : triangles)
  {
    for (int e = 0; e < 3; ++e)
    {
      edges.emplace(std::min(t[e], t[(e + 1) % 3]), std::max(t[e], t[(e + 1) % 3]));
    }
  }
  std::map<int, int> valence;
  for (const auto& [a, b] : edges)
  {
    ++valence[a];
    ++valence[b];
  }
  return valence;
}

TEST(RestrictedVoronoi, RemeshFlipsTowardsValenceSix)
{
  // A flat 5 x 5 grid of squares split along one diagonal: every interior vertex has valence 6.
  // One square split the other way gives two vertices of valence 5 and two of 7, with the same
  // 45-degree angles, so only the valence tells the diagonals apart: the remesh flips it back,
  // unless the edge's two ends are pinned (a crease line). Lifting the square's far corner by
  // 0.26 bends its pair by 20 degrees either way, as on a thin part at 1000 sites: flipped too.
  for (const auto& [pinned, lift] : { std::pair(false, 0.0), { true, 0.0 }, { false, 0.26 } })
  {
    std::vector<std::array<double, 3>> points;
    for (int j = 0; j <= 5; ++j)
    {
      for (int i = 0; i <= 5; ++i)
      {
        points.push_back({ double(i), double(j), i == 3 && j == 3 ? lift : 0.0 });
      }
    }
    const auto id = [](int i, int j) { return j * 6 + i; };
    std::vector<char> pins(points.size(), 0);
    pins[id(3, 2)] = pins[id(2, 3)] = pinned;
    cvt::RestrictedDual dual = DualAt(points, false, pins);
    for (int j = 0; j < 5; ++j)
    {
      for (int i = 0; i < 5; ++i)
      {
        const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
        if (i == 2 && j == 2)
        {
          dual.Triangles.push_back({ a, b, d }); // diagonal b-d: the odd one
          dual.Triangles.push_back({ b, c, d });
        }
        else
        {
          dual.Triangles.push_back({ a, b, c }); // diagonal a-c
          dual.Triangles.push_back({ a, c, d });
        }
      }
    }
    for (int i = 0; i <= 5; ++i) // the grid's border is the surface's border
    {
      for (int v : { id(i, 0), id(i, 5), id(0, i), id(5, i) })
      {
        dual.OnBoundary[v] = 1;
      }
    }
    const cvt::Remesh remesh = cvt::BuildRemesh(dual, 1);
    EXPECT_EQ(remesh.ValenceFlips, pinned ? 0 : 1);
    EXPECT_EQ(remesh.FlippedEdges, 0);
    ASSERT_EQ(remesh.Triangles.size(), 50u);
    std::map<int, int> interior; // valence -> count, at the 16 interior sites
    const std::map<int, int> valence = Valences(remesh.Triangles);
    for (const auto& [vertex, edges] : valence)
    {
      const int site = remesh.SiteIds[vertex];
      if (!dual.OnBoundary[site])
      {
        ++interior[edges];
      }
    }
    if (pinned)
    {
      EXPECT_EQ(interior, (std::map<int, int>{ { 5, 2 }, { 6, 12 }, { 7, 2 } }));
    }
    else
    {
      EXPECT_EQ(interior, (std::map<int, int>{ { 6, 16 } }));
    }
    EXPECT_NEAR(SmallestAngle(remesh), 45.0, lift > 0 ? 5.0 : 1e-9);
  }
}

TEST(RestrictedVoronoi, RemeshFlipsBentPairsTowardsValenceSixWhereTheyStayOnTheInput)
{
  // The grid above with the odd square's far corner lifted by 1: its pair bends by 55 degrees
  // and would by 60 once flipped, as round sites added on a thin part. Past 30 degrees a flip
  // changes the shape, so it is taken only where the new pair lies no farther from the input:
  // on an input whose square has the other diagonal (the flip puts the remesh onto it), not on
  // an input that is the remesh itself, nor without an input.
  std::vector<std::array<double, 3>> points;
  for (int j = 0; j <= 5; ++j)
  {
    for (int i = 0; i <= 5; ++i)
    {
      points.push_back({ double(i), double(j), i == 3 && j == 3 ? 1.0 : 0.0 });
    }
  }
  const auto id = [](int i, int j) { return j * 6 + i; };
  const auto gridTriangles = [&id](bool oddSquare)
  {
    std::vector<std::array<int, 3>> triangles;
    for (int j = 0; j < 5; ++j)
    {
      for (int i = 0; i < 5; ++i)
      {
        const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
        if (oddSquare && i == 2 && j == 2)
        {
          triangles.push_back({ a, b, d });
          triangles.push_back({ b, c, d });
        }
        else
        {
          triangles.push_back({ a, b, c });
          triangles.push_back({ a, c, d });
        }
      }
    }
    return triangles;
  };
  cvt::RestrictedDual dual = DualAt(points, false, {});
  dual.Triangles = gridTriangles(true);
  for (int i = 0; i <= 5; ++i)
  {
    for (int v : { id(i, 0), id(i, 5), id(0, i), id(5, i) })
    {
      dual.OnBoundary[v] = 1;
    }
  }
  const auto inputWith = [&](bool oddSquare)
  {
    cvt::SurfaceMesh input;
    for (const auto& p : points)
    {
      input.Points.insert(input.Points.end(), p.begin(), p.end());
    }
    input.Triangles = gridTriangles(oddSquare);
    return input;
  };
  const cvt::SurfaceMesh flippedInput = inputWith(false), sameInput = inputWith(true);
  for (const auto& [input, flips] :
    { std::pair(&flippedInput, 1), { &sameInput, 0 }, { nullptr, 0 } })
  {
    const cvt::Remesh remesh = cvt::BuildRemesh(dual, 1, 8, input);
    EXPECT_EQ(remesh.ValenceFlips, flips);
    std::map<int, int> valenceOfSite;
    for (const auto& [vertex, edges] : Valences(remesh.Triangles))
    {
      valenceOfSite[remesh.SiteIds[vertex]] = edges;
    }
    EXPECT_EQ(valenceOfSite.at(id(2, 2)), flips ? 6 : 5); // two corners of the odd square
    EXPECT_EQ(valenceOfSite.at(id(3, 2)), flips ? 6 : 7);
    if (input)
    {
      EXPECT_EQ(remesh.MovedVertices + remesh.FittedVertices + remesh.CollapsedEdges, 0);
    }
  }
}

/// A flat triangular lattice of 7 x 7 points of unit spacing (every inner vertex of valence 6),
/// its outer ring pinned.
struct TriangularLattice
{
  static constexpr int N = 7;
  std::vector<std::array<double, 3>> Points;
  std::vector<char> Pinned;
  std::vector<std::array<int, 3>> Triangles;

  static int At(int i, int j) { return j * N + i; }
  TriangularLattice()
  {
    for (int j = 0; j < N; ++j)
    {
      for (int i = 0; i < N; ++i)
      {
        this->Points.push_back({ i + 0.5 * (j % 2), j * std::sqrt(3.0) / 2.0, 0.0 });
        this->Pinned.push_back(i == 0 || j == 0 || i == N - 1 || j == N - 1);
      }
    }
    for (int j = 0; j + 1 < N; ++j)
    {
      for (int i = 0; i + 1 < N; ++i)
      {
        if (j % 2 == 0)
        {
          this->Triangles.push_back({ At(i, j), At(i + 1, j), At(i, j + 1) });
          this->Triangles.push_back({ At(i + 1, j), At(i + 1, j + 1), At(i, j + 1) });
        }
        else
        {
          this->Triangles.push_back({ At(i, j), At(i + 1, j + 1), At(i, j + 1) });
          this->Triangles.push_back({ At(i, j), At(i + 1, j), At(i + 1, j + 1) });
        }
      }
    }
  }
};

TEST(RestrictedVoronoi, RemeshCollapsesEdgesTowardsValenceSix)
{
  // The lattice with a vertex m added at the middle of one inner edge (a, b) and joined to the
  // corners c and d across it: m has 4 edges, c and d 7. No flip mends that (each leaves a 5 or
  // a 7); the collapse of m with a, at their middle, leaves every inner vertex with 6 edges.
  TriangularLattice lattice;
  std::vector<std::array<double, 3>>& points = lattice.Points;
  std::vector<char>& pinned = lattice.Pinned;
  const std::vector<std::array<int, 3>>& triangles = lattice.Triangles;
  const auto at = &TriangularLattice::At;
  // The edge (a, b) = ((2, 3), (3, 3)) and its two triangles, split at m.
  const int a = at(2, 3), b = at(3, 3), m = static_cast<int>(points.size());
  points.push_back({ 0.5 * (points[a][0] + points[b][0]), points[a][1], 0.0 });
  pinned.push_back(0);
  std::vector<std::array<int, 3>> split;
  for (const auto& t : triangles)
  {
    const int k = static_cast<int>(std::find(t.begin(), t.end(), a) - t.begin());
    if (k < 3 && std::find(t.begin(), t.end(), b) != t.end())
    {
      std::array<int, 3> first = t, second = t;
      std::replace(first.begin(), first.end(), b, m);
      second[k] = m;
      split.push_back(first);
      split.push_back(second);
    }
    else
    {
      split.push_back(t);
    }
  }
  cvt::RestrictedDual dual = DualAt(points, true, pinned);
  dual.Triangles = split;
  const cvt::SurfaceMesh plane = FlatSquare(1, -2.0, 9.0);
  const cvt::Remesh remesh = cvt::BuildRemesh(dual, 1, 8, &plane);
  EXPECT_EQ(remesh.ValenceCollapses, 1);
  EXPECT_EQ(remesh.SiteIds.size(), points.size() - 1);
  const cvt::MeshQuality quality = cvt::MeasureMesh(remesh.Points, remesh.Triangles);
  EXPECT_DOUBLE_EQ(quality.InteriorValence6Fraction, 1.0);
  EXPECT_GE(quality.MinimumAngle, 30.0);
  const cvt::MeshTopology topology =
    cvt::ComputeMeshTopology(static_cast<int>(remesh.SiteIds.size()), remesh.Triangles);
  EXPECT_EQ(topology.BoundaryLoops, 1);
  EXPECT_EQ(topology.Genus, 0);
  std::cout << "[ measured ] lattice with a vertex on an edge: " << remesh.ValenceFlips
            << " valence flips, " << remesh.ValenceCollapses
            << " collapses, valence 6 off the border " << quality.InteriorValence6Fraction
            << ", smallest angle " << quality.MinimumAngle << "\n";
}

TEST(RestrictedVoronoi, RemeshWidensTheCornersOfValenceFlips)
{
  // The lattice with one inner edge (a, b) flipped to (c, d), and a and b moved apart (0.65
  // from the edge's middle) and c and d towards each other (0.35 from it): a and b have 5
  // edges, c and d 7, every corner is 30 degrees or wider. Flipping back gives every inner
  // vertex 6 edges but corners of 28.3 degrees at a and b, which the valence flips alone
  // refuse; moving the four to the mean of their new neighbours widens them again. Flat, and
  // folded by 35 degrees along a and b's row (the flipped pair then bends by 35 degrees and
  // lies on the input, as round thin parts).
  TriangularLattice lattice;
  const auto at = &TriangularLattice::At;
  const int a = at(2, 3), b = at(3, 3), c = at(3, 4), d = at(3, 2);
  std::vector<std::array<int, 3>> triangles;
  for (std::array<int, 3> t : lattice.Triangles)
  {
    const bool onEdge = std::count(t.begin(), t.end(), a) && std::count(t.begin(), t.end(), b);
    if (onEdge && std::count(t.begin(), t.end(), c))
    {
      std::replace(t.begin(), t.end(), b, d); // (a, b, c) -> (a, d, c)
    }
    else if (onEdge)
    {
      std::replace(t.begin(), t.end(), a, c); // (b, a, d) -> (b, c, d)
    }
    triangles.push_back(t);
  }
  std::vector<std::array<double, 3>> flatPoints = lattice.Points;
  const double row = 1.5 * std::sqrt(3.0); // a and b's
  flatPoints[a] = { 3.0 - 0.65, row, 0.0 };
  flatPoints[b] = { 3.0 + 0.65, row, 0.0 };
  flatPoints[c] = { 3.0, row + 0.35, 0.0 };
  flatPoints[d] = { 3.0, row - 0.35, 0.0 };
  for (const double foldDegrees : { 0.0, 35.0 })
  {
    // Points beyond the row turn up about it; the input is a square from -2 to 9 folded so.
    const double fold = foldDegrees * 3.14159265358979323846 / 180.0;
    const auto folded = [&](const std::array<double, 3>& p) -> std::array<double, 3>
    {
      const double beyond = std::max(0.0, p[1] - row);
      return { p[0], std::min(p[1], row) + beyond * std::cos(fold), beyond * std::sin(fold) };
    };
    std::vector<std::array<double, 3>> points;
    std::vector<double> flat;
    for (const auto& p : flatPoints)
    {
      points.push_back(folded(p));
      flat.insert(flat.end(), points.back().begin(), points.back().end());
    }
    cvt::SurfaceMesh input;
    for (const auto& p : { std::array<double, 3>{ -2.0, -2.0, 0.0 }, { 9.0, -2.0, 0.0 },
           { 9.0, row, 0.0 }, { -2.0, row, 0.0 }, { 9.0, 9.0, 0.0 }, { -2.0, 9.0, 0.0 } })
    {
      const std::array<double, 3> q = folded(p);
      input.Points.insert(input.Points.end(), q.begin(), q.end());
    }
    input.Triangles = { { 0, 1, 2 }, { 0, 2, 3 }, { 3, 2, 4 }, { 3, 4, 5 } };
    const cvt::MeshQuality start = cvt::MeasureMesh(flat, triangles);
    ASSERT_GE(start.MinimumAngle, 30.0); // no thin triangle for the other repairs to mend
    ASSERT_LT(start.InteriorValence6Fraction, 1.0);
    cvt::RestrictedDual dual = DualAt(points, true, lattice.Pinned);
    dual.Triangles = triangles;
    const cvt::Remesh remesh = cvt::BuildRemesh(dual, 1, 8, &input);
    const cvt::MeshQuality quality = cvt::MeasureMesh(remesh.Points, remesh.Triangles);
    EXPECT_EQ(remesh.ValenceFlips, 1) << foldDegrees << " degrees";
    EXPECT_EQ(remesh.ValenceCollapses + remesh.FittedVertices, 0) << foldDegrees << " degrees";
    EXPECT_DOUBLE_EQ(quality.InteriorValence6Fraction, 1.0) << foldDegrees << " degrees";
    EXPECT_GE(quality.MinimumAngle, 30.0) << foldDegrees << " degrees";
    for (size_t v = 0; v < remesh.SiteIds.size(); ++v)
    {
      const size_t site = static_cast<size_t>(remesh.SiteIds[v]);
      if (lattice.Pinned[site]) // the outer ring stays
      {
        EXPECT_EQ(points[site],
          (std::array<double, 3>{
            remesh.Points[3 * v], remesh.Points[3 * v + 1], remesh.Points[3 * v + 2] }));
      }
    }
    std::cout << "[ measured ] lattice with a flipped edge, folded by " << foldDegrees
              << " degrees: smallest angle " << start.MinimumAngle << " -> " << quality.MinimumAngle
              << ", valence 6 off the border " << start.InteriorValence6Fraction << " -> "
              << quality.InteriorValence6Fraction << "\n";
  }
}

TEST(RestrictedVoronoi, RemeshFillsHolesWithTheWidestTriangles)
{
  // A ring between two long octagons: the inner one is a hole of eight edges, away from the
  // input's border, which the remesh closes. Flat, a fan from any of its vertices has a corner
  // of at most 10.1 degrees where the best triangulation has none under 41.2; bent as here, no
  // flip can mend a fan (12.3 degrees) and the best has none under 38.2.
  const std::vector<std::array<double, 2>> octagon = { { -3, 0 }, { -1.5, -0.7 }, { 0, -0.8 },
    { 1.5, -0.7 }, { 3, 0 }, { 1.5, 0.7 }, { 0, 0.8 }, { -1.5, 0.7 } }; // counterclockwise
  std::vector<std::array<double, 3>> points;
  for (double scale : { 1.0, 2.0 })
  {
    for (const auto& p : octagon)
    {
      // Bent along its length, so that no flip between the fill's triangles is flat enough.
      points.push_back({ scale * p[0], scale * p[1], 0.2 * scale * p[0] * scale * p[0] });
    }
  }
  cvt::RestrictedDual dual = DualAt(points, false, {});
  for (int k = 0; k < 8; ++k)
  {
    const int inner = k, next = (k + 1) % 8;
    dual.Triangles.push_back({ inner, 8 + inner, 8 + next });
    dual.Triangles.push_back({ inner, 8 + next, next });
    dual.OnBoundary[8 + k] = 1; // the outer octagon is the input's border
  }
  const cvt::Remesh remesh = cvt::BuildRemesh(dual, 1);
  EXPECT_EQ(remesh.FilledHoles, 1);
  ASSERT_EQ(remesh.Triangles.size(), 16u + 6u);
  const cvt::MeshTopology topology =
    cvt::ComputeMeshTopology(static_cast<int>(remesh.SiteIds.size()), remesh.Triangles);
  EXPECT_EQ(topology.BoundaryLoops, 1);
  EXPECT_EQ(topology.EulerCharacteristic, 1);
  // The fill's triangles: all three vertices on the inner octagon.
  double smallest = 180.0;
  for (const auto& t : remesh.Triangles)
  {
    if (remesh.SiteIds[t[0]] < 8 && remesh.SiteIds[t[1]] < 8 && remesh.SiteIds[t[2]] < 8)
    {
      std::vector<double> corners;
      for (int v : t)
      {
        corners.insert(corners.end(), &remesh.Points[3 * v], &remesh.Points[3 * v] + 3);
      }
      smallest = std::min(smallest, cvt::MeasureMesh(corners, { { 0, 1, 2 } }).MinimumAngle);
    }
  }
  EXPECT_GT(smallest, 38.0);
}

/// A moved remesh vertex's source triangle and barycentric coordinates give its point back.
void ExpectSourceGivesThePointBack(
  const cvt::Remesh& remesh, const cvt::SurfaceMesh& surface, int vertex)
{
  const auto& source = surface.Triangles[remesh.SourceTriangles[vertex]];
  for (int c = 0; c < 3; ++c)
  {
    double x = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      x += remesh.SourceBarycentric[3 * vertex + k] * surface.Point(source[k])[c];
    }
    EXPECT_NEAR(x, remesh.Points[3 * vertex + c], 1e-9);
  }
}

TEST(RestrictedVoronoi, RemeshMovesFreeVerticesOfThinTrianglesAlongTheSurface)
{
  // A fan of six pinned vertices (a hexagon, as along a crease) around a free vertex close to
  // one of them: its two triangles there have corners of a few degrees, and no flip helps.
  // Given the input surface (the plane z = 0), the free vertex moves to the middle, on it.
  std::vector<std::array<double, 3>> points = { { 0.9, 0.0, 0.0 } };
  std::vector<char> pinned = { 0 };
  for (int k = 0; k < 6; ++k)
  {
    const double angle = k * 3.14159265358979323846 / 3.0;
    points.push_back({ std::cos(angle), std::sin(angle), 0.0 });
    pinned.push_back(1);
  }
  cvt::RestrictedDual dual = DualAt(points, true, pinned); // the hexagon is the border
  for (int k = 0; k < 6; ++k)
  {
    dual.Triangles.push_back({ 0, 1 + k, 1 + (k + 1) % 6 });
  }
  const cvt::SurfaceMesh plane = FlatSquare(1, -2.0, 2.0);
  const cvt::Remesh before = cvt::BuildRemesh(dual, 1);
  const cvt::Remesh after = cvt::BuildRemesh(dual, 1, 8, &plane);
  EXPECT_EQ(before.MovedVertices, 0);
  EXPECT_EQ(after.MovedVertices, 1);
  EXPECT_EQ(after.FittedVertices, 0); // flat: no input point is far from the remesh
  EXPECT_LT(SmallestAngle(before), 10.0);
  EXPECT_GT(SmallestAngle(after), 55.0);

  const int centre = static_cast<int>(
    std::find(after.SiteIds.begin(), after.SiteIds.end(), 0) - after.SiteIds.begin());
  EXPECT_NEAR(after.Points[3 * centre], 0.0, 1e-9);
  EXPECT_EQ(after.Points[3 * centre + 2], 0.0); // on the surface
  ExpectSourceGivesThePointBack(after, plane, centre);
}

TEST(RestrictedVoronoi, RemeshSearchesAroundFreeVerticesWhereTheMeanDoesNotWiden)
{
  // A 5 x 5 grid on the plane z = 0, its border pinned and its nine inner points jittered (one
  // of the random grids where moves to the neighbours' mean stop at a 25-degree corner and no
  // collapse helps). Searching around the free vertices of the thin triangles left widens them
  // past 30 degrees, with no vertex lost but to a collapse for valence 6 (two thirds of the inner
  // vertices have 6 edges before it, three quarters after).
  std::vector<std::array<double, 3>> points;
  std::vector<char> pinned;
  JitteredGrid(points, pinned);
  cvt::RestrictedDual dual = DualAt(points, false, pinned);
  for (int i = 0; i < 25; ++i)
  {
    dual.OnBoundary[i] = pinned[i];
  }
  AddGridTriangles(dual);
  const auto [before, after] = GridRemeshBeforeAndAfterMoves(dual);
  const double widthBefore = SmallestAngle(before);
  const double widthAfter = SmallestAngle(after);
  EXPECT_LT(widthBefore, 25.0);
  EXPECT_EQ(after.CollapsedEdges, 0);
  EXPECT_EQ(after.SiteIds.size() + static_cast<size_t>(after.ValenceCollapses), 25u);
  EXPECT_GE(after.MovedVertices, 1);
  EXPECT_GT(widthAfter, 30.0);
  for (size_t v = 0; v < after.SiteIds.size(); ++v)
  {
    EXPECT_EQ(after.Points[3 * v + 2], 0.0); // on the surface
  }
  std::cout << "[ measured ] smallest angle " << widthBefore << " -> " << widthAfter << " degrees, "
            << after.MovedVertices << " moves\n";
}

TEST(RestrictedVoronoi, RemeshCollapsesEdgesThatNoFlipOrMoveMends)
{
  // A 5 x 5 grid on the unit square, its border pinned, with the middle of the bottom side
  // doubled (two border cells 0.02 apart): their triangle with the grid point above is a needle
  // of 4.6 degrees there. No flip (the doubled edge is on the border) and no move of the free
  // vertex above mends it; collapsing the short border edge gives the grid back.
  std::vector<std::array<double, 3>> points;
  std::vector<char> pinned;
  for (int j = 0; j < 5; ++j)
  {
    for (int i = 0; i < 5; ++i)
    {
      points.push_back({ 0.25 * i, 0.25 * j, 0.0 });
      pinned.push_back(i == 0 || i == 4 || j == 0 || j == 4);
    }
  }
  points[2] = { 0.49, 0.0, 0.0 };
  points.push_back({ 0.51, 0.0, 0.0 }); // vertex 25, the double of vertex 2
  pinned.push_back(1);
  cvt::RestrictedDual dual = DualAt(points, false, pinned);
  dual.OnBoundary.assign(pinned.begin(), pinned.end());
  AddGridTriangles(dual, 25); // the square right of the double starts at vertex 25
  const cvt::SurfaceMesh plane = FlatSquare(1, -2.0, 2.0);

  const cvt::Remesh before = cvt::BuildRemesh(dual, 1);
  EXPECT_EQ(before.CollapsedEdges, 0);
  EXPECT_LT(SmallestAngle(before), 5.0);

  const cvt::Remesh after = cvt::BuildRemesh(dual, 1, 8, &plane);
  EXPECT_EQ(after.CollapsedEdges, 1);
  EXPECT_EQ(after.SiteIds.size(), 25u); // one vertex fewer, and none left in no triangle
  EXPECT_EQ(after.Points.size(), 3 * after.SiteIds.size());
  EXPECT_EQ(after.Triangles.size(), 32u);
  EXPECT_GT(SmallestAngle(after), 40.0);
  const cvt::MeshTopology topology =
    cvt::ComputeMeshTopology(static_cast<int>(after.SiteIds.size()), after.Triangles);
  EXPECT_EQ(topology.Components, 1);
  EXPECT_EQ(topology.BoundaryLoops, 1);
  EXPECT_EQ(topology.EulerCharacteristic, 1);
  // The border keeps one of the two doubled vertices, on the border.
  int doubled = 0;
  for (size_t v = 0; v < after.SiteIds.size(); ++v)
  {
    if (after.SiteIds[v] == 2 || after.SiteIds[v] == 25)
    {
      ++doubled;
      EXPECT_EQ(after.Points[3 * v + 1], 0.0);
    }
  }
  EXPECT_EQ(doubled, 1);
}

TEST(RestrictedVoronoi, RemeshSearchesAfterACollapseWithItsVerticesRenumbered)
{
  // The jittered grid of RemeshSearchesAroundFreeVerticesWhereTheMeanDoesNotWiden with the
  // middle of its bottom side doubled, as in RemeshCollapsesEdgesThatNoFlipOrMoveMends: the
  // collapse drops a vertex and numbers the others anew, and the search that follows must know
  // which of them are pinned under their new numbers (with the old ones it left a corner of 25
  // degrees, a free vertex taken for a pinned one).
  std::vector<std::array<double, 3>> points;
  std::vector<char> pinned;
  JitteredGrid(points, pinned);
  points[2] = { 1.98, 0.0, 0.0 };
  points.push_back({ 2.02, 0.0, 0.0 }); // vertex 25, the double of vertex 2
  pinned.push_back(1);
  cvt::RestrictedDual dual = DualAt(points, false, pinned);
  dual.OnBoundary.assign(pinned.begin(), pinned.end());
  AddGridTriangles(dual, 25);
  const cvt::SurfaceMesh plane = FlatSquare(1, -3.0, 7.0);

  const cvt::Remesh after = cvt::BuildRemesh(dual, 1, 8, &plane);
  EXPECT_EQ(after.CollapsedEdges, 1);
  EXPECT_EQ(after.SiteIds.size() + static_cast<size_t>(after.ValenceCollapses), 25u);
  EXPECT_GT(SmallestAngle(after), 30.0);
  for (size_t v = 0; v < after.SiteIds.size(); ++v)
  {
    const double x = after.Points[3 * v], y = after.Points[3 * v + 1];
    if (pinned[static_cast<size_t>(after.SiteIds[v])])
    {
      EXPECT_EQ(std::min({ x, 4.0 - x, y, 4.0 - y }), 0.0) << "border site " << after.SiteIds[v];
    }
  }
}

TEST(RestrictedVoronoi, RemeshSearchMovesCreaseVerticesButNotBorderOnes)
{
  // A 5 x 5 grid on the plane z = 0 whose vertices are all pinned: the border's to the border,
  // the inner ones as if to creases. The middle one sits close to the one below it, so their
  // triangles are thin. No vertex is free: the last search moves the crease vertex (its
  // triangles stay on the input), never one on the border.
  std::vector<std::array<double, 3>> points;
  for (int j = 0; j < 5; ++j)
  {
    for (int i = 0; i < 5; ++i)
    {
      points.push_back({ static_cast<double>(i), static_cast<double>(j), 0.0 });
    }
  }
  points[12] = { 2.0, 1.2, 0.0 };
  const std::vector<char> pinned(25, 1);
  cvt::RestrictedDual dual = DualAt(points, false, pinned);
  AddGridTriangles(dual);
  const auto onBorder = [](int v) { return v % 5 == 0 || v % 5 == 4 || v / 5 == 0 || v / 5 == 4; };
  for (int v = 0; v < 25; ++v)
  {
    dual.OnBoundary[v] = onBorder(v);
  }
  const auto [before, after] = GridRemeshBeforeAndAfterMoves(dual);
  const double widthBefore = SmallestAngle(before);
  const double widthAfter = SmallestAngle(after);
  EXPECT_LT(widthBefore, 25.0);
  EXPECT_GT(widthAfter, 30.0);
  for (size_t v = 0; v < after.SiteIds.size(); ++v)
  {
    const double x = after.Points[3 * v], y = after.Points[3 * v + 1];
    const int site = after.SiteIds[v];
    EXPECT_EQ(after.Points[3 * v + 2], 0.0); // on the surface
    if (onBorder(site))
    {
      EXPECT_EQ(x, points[site][0]);
      EXPECT_EQ(y, points[site][1]);
    }
  }
  std::cout << "[ measured ] smallest angle " << widthBefore << " -> " << widthAfter << " degrees, "
            << after.MovedVertices << " moves, " << after.FlippedEdges << " flips\n";
}

/// A hexagonal spike: six points round the unit circle at z = 0 and an apex at (0, 0, height),
/// and the dual of its remesh by a free vertex half way up the edge to point 1, with the six
/// round it pinned (the border).
std::pair<cvt::SurfaceMesh, cvt::RestrictedDual> SpikeAndFlatterRemesh(double height)
{
  cvt::SurfaceMesh spike;
  spike.Points = { 0.0, 0.0, height };
  std::vector<std::array<double, 3>> points = { { 0.5, 0.0, 0.5 * height } };
  std::vector<char> pinned = { 0 };
  for (int k = 0; k < 6; ++k)
  {
    const double angle = k * 3.14159265358979323846 / 3.0;
    spike.Points.insert(spike.Points.end(), { std::cos(angle), std::sin(angle), 0.0 });
    spike.Triangles.push_back({ 0, 1 + k, 1 + (k + 1) % 6 });
    points.push_back({ std::cos(angle), std::sin(angle), 0.0 });
    pinned.push_back(1);
  }
  cvt::RestrictedDual dual = DualAt(points, true, pinned);
  dual.Triangles = spike.Triangles; // the same fan, round the free vertex
  return { spike, dual };
}

TEST(RestrictedVoronoi, RemeshVerticesReachForTipsTheTrianglesCutOff)
{
  // The remesh of a spike whose free vertex sits half way up its side cuts the apex off (by
  // far more than 0.8% of the bounding-box diagonal of 2.7), with no corner under 30 degrees.
  // Given the input, the vertex moves to the apex and the remesh is the spike itself.
  const auto [spike, dual] = SpikeAndFlatterRemesh(0.5);
  const cvt::Remesh before = cvt::BuildRemesh(dual, 1);
  const cvt::Remesh after = cvt::BuildRemesh(dual, 1, 8, &spike);
  EXPECT_EQ(before.FittedVertices, 0);
  ASSERT_EQ(after.FittedVertices, 1);
  EXPECT_EQ(after.MovedVertices, 0); // not thin: the move is the fit's
  const int tip = static_cast<int>(
    std::find(after.SiteIds.begin(), after.SiteIds.end(), 0) - after.SiteIds.begin());
  EXPECT_NEAR(after.Points[3 * tip], 0.0, 1e-9);
  EXPECT_NEAR(after.Points[3 * tip + 1], 0.0, 1e-9);
  EXPECT_NEAR(after.Points[3 * tip + 2], 0.5, 1e-9);
  EXPECT_GT(SmallestAngle(after), 50.0);
  ExpectSourceGivesThePointBack(after, spike, tip);

  // A spike so sharp that its apex has a 26-degree corner: the vertex climbs only as far as its
  // corners stay at 27 degrees or more (in up to three moves), and still comes closer to the
  // apex.
  const auto [sharp, sharpDual] = SpikeAndFlatterRemesh(2.0);
  const cvt::Remesh climbed = cvt::BuildRemesh(sharpDual, 1, 8, &sharp);
  ASSERT_GE(climbed.FittedVertices, 1);
  EXPECT_GE(SmallestAngle(climbed), 27.0);
  const int vertex = static_cast<int>(
    std::find(climbed.SiteIds.begin(), climbed.SiteIds.end(), 0) - climbed.SiteIds.begin());
  EXPECT_GT(climbed.Points[3 * vertex + 2], 1.75); // 1.86; holding 30 degrees it stopped at 1.5
  EXPECT_LT(climbed.Points[3 * vertex + 2], 2.0 - 1e-6);
  std::cout << "[ measured ] sharp spike: the vertex climbed from height 1 to "
            << climbed.Points[3 * vertex + 2] << " of 2, smallest angle " << SmallestAngle(climbed)
            << " degrees\n";
}

TEST(RestrictedVoronoi, RemeshVerticesReachForRidgesBetweenInputVertices)
{
  // A roof of four triangles (a coarse CAD input): a ridge of length 2 at height 0.5 from
  // (0, -1) to (0, 1), sloping to z = 0 at x = -1 and x = 1. Every input point is a remesh
  // vertex, but the free one sits at (0.3, 0) on the right slope, so its fan cuts under the
  // middle of the ridge by about 0.2, far more than 0.8% of the bounding-box diagonal (2.87). Only
  // points along the input's edges show it: the vertex then moves onto the ridge, and the
  // remesh is the roof itself.
  const double h = 0.5;
  cvt::SurfaceMesh roof;
  roof.Points = { -1, -1, 0, 0, -1, h, 1, -1, 0, 1, 1, 0, 0, 1, h, -1, 1, 0 };
  enum Corner
  {
    L1,
    P,
    R1,
    R2,
    Q,
    L2
  };
  roof.Triangles = { { L1, P, Q }, { L1, Q, L2 }, { P, R1, R2 }, { P, R2, Q } };
  std::vector<std::array<double, 3>> points = { { 0.3, 0.0, 0.7 * h } };
  std::vector<char> pinned = { 0 };
  for (int c = 0; c < 6; ++c)
  {
    points.push_back({ roof.Points[3 * c], roof.Points[3 * c + 1], roof.Points[3 * c + 2] });
    pinned.push_back(1);
  }
  cvt::RestrictedDual dual = DualAt(points, true, pinned);
  const auto ring = [](Corner c) { return 1 + static_cast<int>(c); };
  dual.Triangles = { { 0, ring(R1), ring(R2) }, { 0, ring(R2), ring(Q) }, { 0, ring(Q), ring(L2) },
    { 0, ring(L2), ring(L1) }, { 0, ring(L1), ring(P) }, { 0, ring(P), ring(R1) } };
  const cvt::Remesh remesh = cvt::BuildRemesh(dual, 1, 8, &roof);
  ASSERT_EQ(remesh.FittedVertices, 1);
  const int vertex = static_cast<int>(
    std::find(remesh.SiteIds.begin(), remesh.SiteIds.end(), 0) - remesh.SiteIds.begin());
  EXPECT_NEAR(remesh.Points[3 * vertex], 0.0, 1e-9); // on the ridge
  EXPECT_NEAR(remesh.Points[3 * vertex + 2], h, 1e-9);
  EXPECT_NEAR(remesh.Points[3 * vertex + 1], 0.0, 0.05); // near its middle
  EXPECT_GE(SmallestAngle(remesh), 30.0);
  ExpectSourceGivesThePointBack(remesh, roof, vertex);
}

/// The farthest that points of `from` (its vertices and, per triangle, a grid of `steps` per
/// edge) lie from the triangles of `to`, by brute force.
double FarthestPoint(const std::vector<double>& fromPoints,
  const std::vector<std::array<int, 3>>& fromTriangles, const std::vector<double>& toPoints,
  const std::vector<std::array<int, 3>>& toTriangles, int steps)
{
  double farthest = 0.0;
  for (const auto& t : fromTriangles)
  {
    for (int i = 0; i <= steps; ++i)
    {
      for (int j = 0; i + j <= steps; ++j)
      {
        const double u = static_cast<double>(i) / steps, v = static_cast<double>(j) / steps;
        double p[3];
        for (int k = 0; k < 3; ++k)
        {
          p[k] = (1 - u - v) * fromPoints[3 * t[0] + k] + u * fromPoints[3 * t[1] + k] +
            v * fromPoints[3 * t[2] + k];
        }
        farthest = std::max(farthest, std::sqrt(BruteForceNearest2(p, toPoints, toTriangles)));
      }
    }
  }
  return farthest;
}

/// The dual of `sites` CVT sites on `mesh`, after 60 L-BFGS iterations.
cvt::RestrictedDual MeshDual(const cvt::SurfaceMesh& mesh, int sites)
{
  cvt::RestrictedVoronoi engine;
  EXPECT_TRUE(engine.SetMesh(mesh));
  cvt::OptimizerOptions options;
  options.MaximumNumberOfIterations = 60;
  cvt::OptimizerResult result;
  std::string error;
  cvt::RestrictedProblem problem(engine);
  EXPECT_TRUE(cvt::RunLBFGS(
    problem, { cvt::SampleMeshSites(mesh, sites, 4), {} }, options, nullptr, result, error))
    << error;
  cvt::RestrictedDual dual;
  EXPECT_TRUE(engine.ComputeDual(dual));
  return dual;
}

TEST(RestrictedVoronoi, RemeshBorderFollowsTheCornersOfTheInputsBorder)
{
  // A unit square whose lower border is a sawtooth, teeth 0.05 apart and 0.03 deep (2.1% of the
  // diagonal), under cells about 0.13 across: the border edges between the cells' border points
  // cut corners and teeth off, until their ends move onto them or they split there.
  cvt::SurfaceMesh saw = FlatSquare(40, 0.0, 1.0);
  for (int i = 1; i < 40; i += 2)
  {
    saw.Points[3 * static_cast<size_t>(i) + 1] = -0.03;
  }
  const cvt::RestrictedDual dual = MeshDual(saw, 60);
  const double diagonal = cvt::BoundingBoxDiagonal(saw);
  const cvt::Remesh cut = cvt::BuildRemesh(dual, 1);
  const cvt::RemeshInput input(saw);
  const cvt::Remesh following = cvt::BuildRemesh(dual, 1, 8, input);
  const double before =
    FarthestPoint(saw.Points, saw.Triangles, cut.Points, cut.Triangles, 4) / diagonal;
  const double after =
    FarthestPoint(saw.Points, saw.Triangles, following.Points, following.Triangles, 4) / diagonal;
  // The square's corners, cut 3.4% of the diagonal deep, get vertices or come closer; between
  // vertices on tooth tips, the edges run along the tips. Teeth narrower than the cells between
  // a corner and a tip stay cut: splits there would leave corners under 27 degrees.
  EXPECT_GT(before, 0.03);
  EXPECT_LT(after, 0.65 * before);
  EXPECT_EQ(
    cvt::ComputeMeshTopology(static_cast<int>(following.SiteIds.size()), following.Triangles)
      .BoundaryLoops,
    1);
  EXPECT_GE(SmallestAngle(following), 27.0);
  std::cout << "[ measured ] sawtooth border: input to remesh " << before << " -> " << after
            << " of the diagonal, " << following.BorderCorners << " border vertices added\n";
}

/// The teeth tests' tally over remeshes of saws (squares with teeth along their lower border):
/// tips farther than 0.8% of the diagonal from the remesh, teeth, border vertices added, the
/// smallest angle; each remesh keeps the saw's one boundary loop.
struct TeethTally
{
  int Cut = 0;
  int Teeth = 0;
  int Added = 0;
  double Smallest = 180.0;

  /// Remeshes `saw` from `sites` sites and counts its teeth, whose tips are `tips` (x, y, z).
  void Add(const cvt::SurfaceMesh& saw, const std::vector<double>& tips, int sites)
  {
    const cvt::RemeshInput input(saw);
    const cvt::Remesh remesh = cvt::BuildRemesh(MeshDual(saw, sites), 1, 8, input);
    for (size_t t = 0; t < tips.size() / 3; ++t)
    {
      const std::vector<double> tip(tips.begin() + 3 * t, tips.begin() + 3 * t + 3);
      this->Cut += FarthestPoint(tip, { { 0, 0, 0 } }, remesh.Points, remesh.Triangles, 1) >
        0.008 * input.Diagonal;
      ++this->Teeth;
    }
    this->Added += remesh.BorderCorners;
    this->Smallest = std::min(this->Smallest, SmallestAngle(remesh));
    EXPECT_EQ(cvt::ComputeMeshTopology(static_cast<int>(remesh.SiteIds.size()), remesh.Triangles)
                .BoundaryLoops,
      1);
  }
};

TEST(RestrictedVoronoi, RemeshBorderSplitsAtTeethNearAnEdgesEndWhereTheApexMovesToWidenIt)
{
  // Unit squares whose lower border has teeth 0.03 deep (2.1% of the diagonal) every 3 to 5
  // input points (0.075 to 0.125 apart), under cells about as wide: the border edges between
  // the cells' border points cut teeth off, often nearer one of their ends than a split there
  // can take with corners of 27 degrees, unless the edge's triangle's free apex moves along the
  // surface to widen the two new triangles. Without that, 35 of these 52 teeth stay cut off.
  TeethTally tally;
  for (const auto& [spacing, sites] :
    std::vector<std::pair<int, int>>{ { 3, 60 }, { 3, 70 }, { 4, 80 }, { 5, 80 }, { 5, 90 } })
  {
    cvt::SurfaceMesh saw = FlatSquare(40, 0.0, 1.0);
    std::vector<double> tips;
    for (int i = 2; i < 39; i += spacing)
    {
      saw.Points[3 * static_cast<size_t>(i) + 1] = -0.03;
      tips.insert(tips.end(), { saw.Points[3 * static_cast<size_t>(i)], -0.03, 0.0 });
    }
    tally.Add(saw, tips, sites);
  }
  EXPECT_EQ(tally.Teeth, 52);
  EXPECT_LE(tally.Cut, 30);
  EXPECT_GE(tally.Smallest, 27.0);
  std::cout << "[ measured ] " << tally.Cut << " of " << tally.Teeth
            << " teeth cut off, smallest angle " << tally.Smallest << " degrees\n";
}

TEST(RestrictedVoronoi, RemeshBorderGetsAnEarWhereItCutsATipOff)
{
  // Unit squares whose lower border has teeth 0.1 wide and 0.08 deep (5.7% of the diagonal)
  // under cells about as wide: a border edge that cuts a tooth's tip off, where neither end can
  // move onto the tip nor the edge split there with corners of 27 degrees, gets a triangle of
  // its own out to the tip (an ear). Without ears, 39 of these 50 teeth stay cut off.
  TeethTally tally;
  for (int sites : { 50, 55, 60, 70, 80 })
  {
    cvt::SurfaceMesh saw = FlatSquare(40, 0.0, 1.0);
    std::vector<double> tips;
    for (int i = 2; i + 2 <= 40; i += 4)
    {
      saw.Points[3 * static_cast<size_t>(i - 1) + 1] = -0.04;
      saw.Points[3 * static_cast<size_t>(i) + 1] = -0.08;
      saw.Points[3 * static_cast<size_t>(i + 1) + 1] = -0.04;
      tips.insert(tips.end(), { saw.Points[3 * static_cast<size_t>(i)], -0.08, 0.0 });
    }
    tally.Add(saw, tips, sites);
  }
  EXPECT_EQ(tally.Teeth, 50);
  EXPECT_LE(tally.Cut, 33);
  EXPECT_GE(tally.Smallest, 27.0);
  std::cout << "[ measured ] " << tally.Cut << " of " << tally.Teeth << " teeth cut off, "
            << tally.Added << " border vertices added, smallest angle " << tally.Smallest
            << " degrees\n";
}

TEST(RestrictedVoronoi, RemeshBorderVerticesSlideAlongTheBorderToWidenThinTriangles)
{
  // Strips narrower than two cells: most remesh vertices lie on the border, and where the cells'
  // border points on the two sides fall unevenly the triangles across the strip are thin. No
  // other pass moves border vertices for their angles: without the slides these three strips
  // keep corners of 22.9, 23.2 and 21.5 degrees (with them 26.2, 29.0 and 25.3).
  for (const auto& [width, sites] :
    std::vector<std::pair<double, int>>{ { 0.16, 32 }, { 0.16, 36 }, { 0.22, 24 } })
  {
    cvt::SurfaceMesh strip = FlatSquare(40, 0.0, 1.0);
    for (size_t p = 1; p < strip.Points.size(); p += 3)
    {
      strip.Points[p] *= width;
    }
    const cvt::RemeshInput input(strip);
    const cvt::Remesh remesh = cvt::BuildRemesh(MeshDual(strip, sites), 1, 8, input);
    EXPECT_GT(remesh.SlidBorderVertices, 0) << width << ", " << sites << " sites";
    EXPECT_GE(SmallestAngle(remesh), 25.0) << width << ", " << sites << " sites";
    EXPECT_EQ(cvt::ComputeMeshTopology(static_cast<int>(remesh.SiteIds.size()), remesh.Triangles)
                .BoundaryLoops,
      1);
    // The border's vertices stay on the strip's border.
    const std::vector<char> border = [&remesh]()
    {
      std::vector<char> flags(remesh.SiteIds.size(), 0);
      std::map<std::pair<int, int>, int> uses;
      for (const auto& t : remesh.Triangles)
      {
        for (int k = 0; k < 3; ++k)
        {
          ++uses[std::minmax(t[k], t[(k + 1) % 3])];
        }
      }
      for (const auto& [edge, count] : uses)
      {
        if (count == 1)
        {
          flags[static_cast<size_t>(edge.first)] = flags[static_cast<size_t>(edge.second)] = 1;
        }
      }
      return flags;
    }();
    for (size_t v = 0; v < border.size(); ++v)
    {
      if (border[v])
      {
        const double x = remesh.Points[3 * v], y = remesh.Points[3 * v + 1];
        EXPECT_LT(
          std::min({ std::abs(x), std::abs(x - 1.0), std::abs(y), std::abs(y - width) }), 1e-9)
          << "vertex " << v << " at " << x << ", " << y;
      }
    }
    std::cout << "[ measured ] strip " << width << " wide, " << sites << " sites: smallest angle "
              << SmallestAngle(remesh) << " degrees, " << remesh.SlidBorderVertices
              << " border vertices slid\n";
  }
}

TEST(RestrictedVoronoi, RemeshCreaseVerticesReachForTheFarCreaseOfANarrowBand)
{
  // A ridge with a flat top 0.2 wide (a CAD chamfer narrower than the cells): creases A at
  // x = -0.1 and B at x = 0.1, height 0.5, slopes down to z = 0 at x = -1 and x = 1. The one
  // vertex off the input's corners sits on crease A, pinned there, so its fan cuts crease B's
  // middle off by 0.083, 2.9% of the bounding-box diagonal (2.87). Given the input, the crease
  // vertex moves into the band, part way to crease B, where both creases lie closer.
  const double w = 0.1, h = 0.3, s = 0.4, y = 0.3;
  cvt::SurfaceMesh ridge;
  ridge.Points = { -s, -y, 0, -w, -y, h, w, -y, h, s, -y, 0, s, y, 0, w, y, h, -w, y, h, -s, y, 0 };
  enum Corner
  {
    L1,
    A1,
    B1,
    R1,
    R2,
    B2,
    A2,
    L2
  };
  ridge.Triangles = { { L1, A1, A2 }, { L1, A2, L2 }, { A1, B1, B2 }, { A1, B2, A2 },
    { B1, R1, R2 }, { B1, R2, B2 } };
  std::vector<std::array<double, 3>> points = { { -w, 0.0, h } };
  std::vector<char> pinned = { 1 }; // on crease A
  for (int c = 0; c < 8; ++c)
  {
    points.push_back({ ridge.Points[3 * c], ridge.Points[3 * c + 1], ridge.Points[3 * c + 2] });
    pinned.push_back(1);
  }
  cvt::RestrictedDual dual = DualAt(points, true, pinned);
  for (int c = 0; c < 8; ++c)
  {
    dual.Triangles.push_back({ 0, 1 + c, 1 + (c + 1) % 8 });
  }
  const double diagonal = cvt::BoundingBoxDiagonal(ridge);
  const cvt::Remesh cut = cvt::BuildRemesh(dual, 1);
  const cvt::Remesh remesh = cvt::BuildRemesh(dual, 1, 8, &ridge);
  const double before =
    FarthestPoint(ridge.Points, ridge.Triangles, cut.Points, cut.Triangles, 20) / diagonal;
  const double after =
    FarthestPoint(ridge.Points, ridge.Triangles, remesh.Points, remesh.Triangles, 20) / diagonal;
  const double backBefore =
    FarthestPoint(cut.Points, cut.Triangles, ridge.Points, ridge.Triangles, 20) / diagonal;
  const double backAfter =
    FarthestPoint(remesh.Points, remesh.Triangles, ridge.Points, ridge.Triangles, 20) / diagonal;
  EXPECT_GT(before, 0.028);
  ASSERT_GE(remesh.FittedVertices, 1);
  const int vertex = static_cast<int>(
    std::find(remesh.SiteIds.begin(), remesh.SiteIds.end(), 0) - remesh.SiteIds.begin());
  EXPECT_GT(remesh.Points[3 * vertex], -w + 0.02); // off crease A, into the band
  EXPECT_NEAR(remesh.Points[3 * vertex + 2], h, 1e-9);
  EXPECT_LT(after, 0.8 * before);
  EXPECT_LT(backAfter, 0.8 * backBefore);
  EXPECT_GE(SmallestAngle(remesh), 27.0);
  ExpectSourceGivesThePointBack(remesh, ridge, vertex);
  std::cout << "[ measured ] narrow band: input to remesh " << before << " -> " << after
            << ", remesh to input " << backBefore << " -> " << backAfter
            << " of the diagonal; the crease vertex moved to x = " << remesh.Points[3 * vertex]
            << "\n";
}

TEST(RestrictedVoronoi, FidelityFindsTheInputPointsTheRemeshCutsOff)
{
  // The remesh of the spike whose free vertex sits half way up its side cuts the apex off.
  // MeasureFidelity's distances either way agree with brute force (points on fine grids over
  // each triangle), and the apex is the first far point. Once the vertex has moved to the apex
  // (BuildRemesh given the input), no input point is far.
  const auto [spike, dual] = SpikeAndFlatterRemesh(0.5);
  const cvt::Remesh flat = cvt::BuildRemesh(dual, 1);
  const double diagonal = cvt::BoundingBoxDiagonal(spike);
  const cvt::RemeshInput input(spike);
  const cvt::RemeshFidelity f = cvt::MeasureFidelity(flat, input, 0.009, 10, 10);
  const double inputToRemesh =
    FarthestPoint(spike.Points, spike.Triangles, flat.Points, flat.Triangles, 40) / diagonal;
  const double remeshToInput =
    FarthestPoint(flat.Points, flat.Triangles, spike.Points, spike.Triangles, 40) / diagonal;
  EXPECT_GT(inputToRemesh, 0.05);
  EXPECT_NEAR(f.InputToRemesh, inputToRemesh, 0.002);
  EXPECT_NEAR(f.RemeshToInput, remeshToInput, 0.002);
  ASSERT_GE(f.FarPoints.size(), 3u);
  EXPECT_LT(cvt::Distance2(f.FarPoints.data(), spike.Point(0)), 1e-18);
  // None within twice its distance of one before it, and no more than asked for.
  for (size_t a = 0; a < f.FarPoints.size(); a += 3)
  {
    for (size_t b = a + 3; b < f.FarPoints.size(); b += 3)
    {
      EXPECT_GT(cvt::Distance2(&f.FarPoints[a], &f.FarPoints[b]), 0.0);
    }
  }
  EXPECT_EQ(cvt::MeasureFidelity(flat, input, 0.0001, 1, 0).FarPoints.size(), 3u);
  const cvt::Remesh fitted = cvt::BuildRemesh(dual, 1, 8, input);
  const cvt::RemeshFidelity after = cvt::MeasureFidelity(fitted, input, 0.009, 10, 10);
  EXPECT_LT(after.InputToRemesh, 0.009);
  EXPECT_TRUE(after.FarPoints.empty());
  std::cout << "[ measured ] spike cut off: " << f.InputToRemesh << " (brute force "
            << inputToRemesh << ") input to remesh, " << f.RemeshToInput << " (" << remeshToInput
            << ") remesh to input, " << f.FarPoints.size() / 3 << " far points\n";
}

/// A remesh of the unit square, 0.01 apart, with the vertex at its middle lifted 0.05 into a
/// narrow spike.
cvt::Remesh SpikedSquareRemesh()
{
  cvt::Remesh spiked;
  const cvt::SurfaceMesh fine = FlatSquare(100, 0.0, 1.0);
  spiked.Points = fine.Points;
  spiked.Triangles = fine.Triangles;
  spiked.Points[3 * (50 * 101 + 50) + 2] = 0.05;
  return spiked;
}

TEST(RestrictedVoronoi, FidelityFindsWhereTheRemeshLiesFarFromTheInput)
{
  // A remesh of a flat square, 0.01 apart, with one vertex lifted 0.05 into a narrow spike: every
  // input point lies within 0.01 of it (the spike's steep sides pass over the points below), but
  // the spike lies 3.5% of the diagonal from the input. The input point under its tip is the
  // first far point.
  const cvt::SurfaceMesh square = FlatSquare(10, 0.0, 1.0);
  const cvt::Remesh spiked = SpikedSquareRemesh();
  const double diagonal = cvt::BoundingBoxDiagonal(square);
  const cvt::RemeshInput input(square);
  const cvt::RemeshFidelity f = cvt::MeasureFidelity(spiked, input, 0.009, 10, 10);
  const double inputToRemesh =
    FarthestPoint(square.Points, square.Triangles, spiked.Points, spiked.Triangles, 3) / diagonal;
  EXPECT_LT(inputToRemesh, 0.009);
  EXPECT_NEAR(f.InputToRemesh, inputToRemesh, 0.002);
  EXPECT_NEAR(f.RemeshToInput, 0.05 / diagonal, 1e-9);
  ASSERT_GE(f.FarPoints.size(), 3u);
  const double under[3] = { 0.5, 0.5, 0.0 };
  EXPECT_LT(cvt::Distance2(f.FarPoints.data(), under), 1e-18);
  // Farther than twice their distance apart: the spike's other far points are below 0.009 * 2.
  EXPECT_EQ(f.FarPoints.size(), 3u);
}

TEST(RestrictedVoronoi, FidelityTellsFarPointsOnTheBorderApart)
{
  // The spiked remesh of FidelityFindsWhereTheRemeshLiesFarFromTheInput with its left column
  // moved 0.05 out, past the input's border: the overhang's far points are the feet of its
  // points on the border (x = 0), the spike's is the point under its tip, off the border. Each
  // kind has its own maximum.
  const cvt::SurfaceMesh square = FlatSquare(10, 0.0, 1.0);
  cvt::Remesh spiked = SpikedSquareRemesh();
  for (size_t j = 0; j <= 100; ++j)
  {
    spiked.Points[3 * (j * 101)] = -0.05;
  }
  const cvt::RemeshInput input(square);
  const double under[3] = { 0.5, 0.5, 0.0 };
  const auto count = [](const cvt::RemeshFidelity& f, bool border)
  { return std::count(f.FarOnBorder.begin(), f.FarOnBorder.end(), border); };
  const cvt::RemeshFidelity both = cvt::MeasureFidelity(spiked, input, 0.009, 10, 10);
  ASSERT_EQ(both.FarOnBorder.size(), both.FarPoints.size() / 3);
  EXPECT_EQ(count(both, false), 1);
  EXPECT_GE(count(both, true), 5); // 0.1 apart along the side (twice their distance)
  for (size_t i = 0; i < both.FarOnBorder.size(); ++i)
  {
    const double* p = &both.FarPoints[3 * i];
    if (both.FarOnBorder[i])
    {
      EXPECT_NEAR(p[0], 0.0, 1e-12) << "far point " << i;
    }
    else
    {
      EXPECT_LT(cvt::Distance2(p, under), 1e-18);
    }
  }
  const cvt::RemeshFidelity offOnly = cvt::MeasureFidelity(spiked, input, 0.009, 10, 0);
  EXPECT_EQ(offOnly.FarPoints.size(), 3u);
  EXPECT_EQ(count(offOnly, true), 0);
  const cvt::RemeshFidelity borderOnly = cvt::MeasureFidelity(spiked, input, 0.009, 0, 3);
  EXPECT_EQ(borderOnly.FarPoints.size(), 9u);
  EXPECT_EQ(count(borderOnly, true), 3);
}

/// The unit square folded into a valley along x = `crease`: z = |x - crease|, its points in
/// columns at `columns` (x) and rows `rowSpacing` apart (y), two triangles per cell.
cvt::SurfaceMesh Valley(double crease, const std::vector<double>& columns, double rowSpacing)
{
  cvt::SurfaceMesh mesh;
  const int rows = static_cast<int>(std::lround(1.0 / rowSpacing));
  const int width = static_cast<int>(columns.size());
  for (int j = 0; j <= rows; ++j)
  {
    for (double x : columns)
    {
      mesh.Points.insert(mesh.Points.end(), { x, j * rowSpacing, std::abs(x - crease) });
    }
  }
  for (int j = 0; j < rows; ++j)
  {
    for (int i = 0; i + 1 < width; ++i)
    {
      const int a = j * width + i, b = a + 1, c = a + width + 1, d = a + width;
      mesh.Triangles.push_back({ a, b, c });
      mesh.Triangles.push_back({ a, c, d });
    }
  }
  return mesh;
}

TEST(RestrictedVoronoi, FidelityFindsThePeaksBetweenItsPoints)
{
  // A valley, and the same valley bridged by a flat strip 0.05 wide across its crease (rows 0.01
  // apart): the strip's middle lies 0.025 / sqrt(2) from the valley (1.18% of the diagonal), and
  // so does the valley's crease from the strip. Measured at points 0.8% of the diagonal (0.012)
  // apart, which the strip has 0.01 apart across it, 0.005 either side of the crease, both ways
  // read 0.24% of the diagonal low; measured again closer near the points beyond 70% of the
  // share asked for, within 0.1% of it, and never above it.
  const double crease = 0.5;
  const cvt::SurfaceMesh valley = Valley(crease, { 0.0, crease, 1.0 }, 1.0);
  const cvt::SurfaceMesh bridged =
    Valley(crease, { 0.0, crease - 0.025, crease + 0.025, 1.0 }, 0.01);
  // Shares of each input's diagonal (the strip does not reach the crease).
  const double peak = 0.025 / std::sqrt(2.0);
  const double fromValley = peak / cvt::BoundingBoxDiagonal(valley);
  const double fromBridged = peak / cvt::BoundingBoxDiagonal(bridged);
  const auto asRemesh = [](const cvt::SurfaceMesh& mesh)
  {
    cvt::Remesh remesh;
    remesh.Points = mesh.Points;
    remesh.Triangles = mesh.Triangles;
    return remesh;
  };
  const cvt::RemeshInput valleyInput(valley), bridgedInput(bridged);
  const cvt::RemeshFidelity remeshAbove =
    cvt::MeasureFidelity(asRemesh(bridged), valleyInput, 1.1 * fromValley, 10, 10);
  const cvt::RemeshFidelity inputAbove =
    cvt::MeasureFidelity(asRemesh(valley), bridgedInput, 1.1 * fromBridged, 10, 10);
  EXPECT_NEAR(remeshAbove.RemeshToInput, fromValley, 0.001);
  EXPECT_LE(remeshAbove.RemeshToInput, fromValley + 1e-9);
  // The valley's crease lies right under the strip, at a point measured.
  EXPECT_NEAR(remeshAbove.InputToRemesh, 0.025 / cvt::BoundingBoxDiagonal(valley), 1e-12);
  EXPECT_NEAR(inputAbove.InputToRemesh, fromBridged, 0.001);
  EXPECT_LE(inputAbove.InputToRemesh, fromBridged + 1e-9);
  std::cout << "[ measured ] peak between the points: remesh to input " << remeshAbove.RemeshToInput
            << " of the diagonal (exactly " << fromValley << "), input to remesh "
            << inputAbove.InputToRemesh << " (" << fromBridged << ")\n";
}

TEST(RestrictedVoronoi, FidelityMeasuredAgainstTheRemeshBeforeIsTheSame)
{
  // A remesh 0.02 above a flat input, then the same with a dent down to the input (one vertex
  // lowered): measured again against the first, only probes and points near the dent are asked
  // anew, yet every distance is the one measured from scratch, to the bit, also those of probes
  // whose nearest triangle before is still there but which the dent's new triangles come nearer
  // to (0.011 instead of 0.02 a cell and a bit from the dent's bottom).
  const cvt::SurfaceMesh square = FlatSquare(10, 0.0, 1.0);
  const cvt::RemeshInput input(square);
  const cvt::SurfaceMesh fine = FlatSquare(100, 0.0, 1.0);
  cvt::Remesh above;
  above.Points = fine.Points;
  above.Triangles = fine.Triangles;
  for (size_t v = 0; v < above.Points.size() / 3; ++v)
  {
    above.Points[3 * v + 2] = 0.02;
  }
  cvt::Remesh dented = above;
  const size_t bottom = 50 * 101 + 50;
  dented.Points[3 * bottom + 2] = 0.0;
  const cvt::RemeshFidelity before = cvt::MeasureFidelity(above, input, 0.009, 10, 10);
  const cvt::RemeshFidelity scratch = cvt::MeasureFidelity(dented, input, 0.009, 10, 10);
  const cvt::RemeshFidelity again =
    cvt::MeasureFidelity(dented, input, 0.009, 10, 10, &above, &before);
  ASSERT_EQ(again.ProbeDistances.size(), scratch.ProbeDistances.size());
  int nearerNow = 0;
  for (size_t p = 0; p < scratch.ProbeDistances.size(); ++p)
  {
    EXPECT_EQ(again.ProbeDistances[p], scratch.ProbeDistances[p]);
    const double* at = &input.Probes[3 * p];
    const double offBottom = std::hypot(at[0] - 0.5, at[1] - 0.5);
    if (offBottom > 0.011 && scratch.ProbeDistances[p] < 0.019)
    {
      ++nearerNow; // its nearest triangle before (right above it) is not the nearest now
    }
  }
  EXPECT_GT(nearerNow, 0);
  EXPECT_EQ(again.RemeshPointDistances, scratch.RemeshPointDistances);
  EXPECT_EQ(again.InputToRemesh, scratch.InputToRemesh);
  EXPECT_EQ(again.RemeshToInput, scratch.RemeshToInput);
  EXPECT_EQ(again.FarPoints, scratch.FarPoints);
  EXPECT_NEAR(scratch.InputToRemesh * cvt::BoundingBoxDiagonal(square), 0.02, 1e-9);
  // A second dent far from the first: the input points between the probes round the first
  // (measured closer there, as they lie almost as far as the share) are not asked anew, yet
  // their distances are those from scratch too.
  cvt::Remesh twice = dented;
  twice.Points[3 * (20 * 101 + 20) + 2] = 0.0;
  const cvt::RemeshFidelity twiceScratch = cvt::MeasureFidelity(twice, input, 0.009, 10, 10);
  const cvt::RemeshFidelity twiceAgain =
    cvt::MeasureFidelity(twice, input, 0.009, 10, 10, &dented, &scratch);
  ASSERT_FALSE(scratch.FinerProbes.empty());
  EXPECT_GT(twiceScratch.FinerProbes.size(), scratch.FinerProbes.size());
  EXPECT_EQ(twiceAgain.FinerProbes, twiceScratch.FinerProbes);
  EXPECT_EQ(twiceAgain.FinerProbeDistances, twiceScratch.FinerProbeDistances);
  EXPECT_EQ(twiceAgain.ProbeDistances, twiceScratch.ProbeDistances);
  EXPECT_EQ(twiceAgain.RemeshPointDistances, twiceScratch.RemeshPointDistances);
  EXPECT_EQ(twiceAgain.FarPoints, twiceScratch.FarPoints);
}

TEST(RestrictedVoronoi, SphereRemeshStraddlesTheInput)
{
  // The remesh of 60 sites on a sphere, with its vertices at the sites' surface points, lies
  // inside the sphere: its flat triangles cut under the surface by up to the chord's sag (about
  // h^2 / 8 for edges h = 0.5), farther than 0.8% of the bounding-box diagonal (0.028). Given
  // the input, the vertices move out along their normals so that the remesh straddles the
  // sphere: the farthest distance either way falls, and the vertices' source points stay on
  // the input. With 300 sites the remesh lies within 0.8% everywhere, and stays.
  const cvt::SurfaceMesh sphere = Sphere(4);
  EXPECT_EQ(cvt::BuildRemesh(MeshDual(sphere, 300), 0, 8, &sphere).StraddlingVertices, 0);
  const cvt::RestrictedDual dual = MeshDual(sphere, 60);
  const cvt::Remesh inscribed = cvt::BuildRemesh(dual, 0);
  const cvt::Remesh straddling = cvt::BuildRemesh(dual, 0, 8, &sphere);
  EXPECT_EQ(inscribed.StraddlingVertices, 0);
  EXPECT_GT(straddling.StraddlingVertices, 50); // all but a few
  const auto twoWay = [&sphere](const cvt::Remesh& remesh)
  {
    return std::max(
      FarthestPoint(sphere.Points, sphere.Triangles, remesh.Points, remesh.Triangles, 1),
      FarthestPoint(remesh.Points, remesh.Triangles, sphere.Points, sphere.Triangles, 4));
  };
  const double before = twoWay(inscribed), after = twoWay(straddling);
  EXPECT_GT(before, 0.004);
  EXPECT_LT(after, 0.8 * before);
  // Outwards, by less than the sag.
  double radius = 0.0;
  for (size_t v = 0; v < straddling.SiteIds.size(); ++v)
  {
    radius += std::sqrt(cvt::Dot(&straddling.Points[3 * v], &straddling.Points[3 * v]));
  }
  radius /= static_cast<double>(straddling.SiteIds.size());
  EXPECT_GT(radius, 1.0);
  EXPECT_LT(radius, 1.0 + before);
  EXPECT_GE(SmallestAngle(straddling), 27.0);
  // The source points (which point arrays are interpolated from) stay on the input (within its
  // own sag, 0.004), under the vertices that moved out.
  int outside = 0;
  for (size_t v = 0; v < straddling.SiteIds.size(); ++v)
  {
    const auto& source = sphere.Triangles[straddling.SourceTriangles[v]];
    double x[3] = { 0.0, 0.0, 0.0 };
    for (int c = 0; c < 3; ++c)
    {
      for (int k = 0; k < 3; ++k)
      {
        x[k] += straddling.SourceBarycentric[3 * v + c] * sphere.Point(source[c])[k];
      }
    }
    const double sourceRadius = std::sqrt(cvt::Dot(x, x));
    EXPECT_NEAR(sourceRadius, 1.0, 0.004);
    outside += std::sqrt(cvt::Dot(&straddling.Points[3 * v], &straddling.Points[3 * v])) >
      sourceRadius + 0.004;
  }
  EXPECT_GT(outside, 50);
  std::cout << "[ measured ] sphere, 60 sites: farthest distance either way " << before
            << " inscribed, " << after << " straddling; mean vertex radius " << radius << "\n";
}

TEST(MeshQuality, CountsValencesOffTheBorderApart)
{
  // A hexagon fanned round its centre: the centre has 6 edges, the six border vertices 3 each.
  // The fraction off the border (what remeshes are judged by) is 1, that of all vertices 1/7.
  std::vector<double> points = { 0, 0, 0 };
  std::vector<std::array<int, 3>> triangles;
  for (int k = 0; k < 6; ++k)
  {
    const double angle = k * 3.14159265358979323846 / 3.0;
    points.insert(points.end(), { std::cos(angle), std::sin(angle), 0.0 });
    triangles.push_back({ 0, 1 + k, 1 + (k + 1) % 6 });
  }
  const cvt::MeshQuality fan = cvt::MeasureMesh(points, triangles);
  EXPECT_DOUBLE_EQ(fan.Valence6Fraction, 1.0 / 7.0);
  EXPECT_DOUBLE_EQ(fan.InteriorValence6Fraction, 1.0);
  EXPECT_NEAR(fan.MinimumAngle, 60.0, 1e-9);
  // An octahedron: closed, every vertex has 4 edges.
  const std::vector<double> corners = { 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1 };
  const std::vector<std::array<int, 3>> faces = { { 0, 2, 4 }, { 2, 1, 4 }, { 1, 3, 4 },
    { 3, 0, 4 }, { 2, 0, 5 }, { 1, 2, 5 }, { 3, 1, 5 }, { 0, 3, 5 } };
  const cvt::MeshQuality octahedron = cvt::MeasureMesh(corners, faces);
  EXPECT_EQ(octahedron.ValenceHistogram.at(4), 6);
  EXPECT_DOUBLE_EQ(octahedron.InteriorValence6Fraction, 0.0);
}

TEST(SurfaceMesh, DropsDuplicateTrianglesKeepingTheFirst)
{
  // A strip of four triangles over points 0..5 and five copies of three of them (one three
  // times, some turned over): copies with two different smallest points, each beside triangles
  // of the same smallest point that are no copies.
  cvt::SurfaceMesh mesh;
  mesh.Points = { 0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0, 1, 1, 0, 2, 1, 0 };
  mesh.Triangles = { { 0, 1, 4 }, { 0, 4, 3 }, { 1, 2, 5 }, { 1, 5, 4 }, { 4, 0, 1 }, { 2, 5, 1 },
    { 1, 4, 0 }, { 0, 4, 1 }, { 3, 4, 0 } };
  cvt::MeshRepairReport report;
  EXPECT_EQ(cvt::RepairSurfaceMesh(mesh, report), "");
  EXPECT_EQ(report.DuplicateTriangles, 5);
  // The first of each set stays, in input order (none was turned over: they agree).
  const std::vector<std::array<int, 3>> kept = { { 0, 1, 4 }, { 0, 4, 3 }, { 1, 2, 5 },
    { 1, 5, 4 } };
  EXPECT_EQ(mesh.Triangles, kept);
}

TEST(SurfaceMesh, RepairsWhatItCanAndSaysWhatItCannot)
{
  // A square of two triangles, one flipped, plus a duplicate, a degenerate and an unused point.
  cvt::SurfaceMesh mesh;
  mesh.Points = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 5, 5, 5 };
  mesh.Triangles = { { 0, 1, 2 }, { 0, 2, 3 }, { 2, 1, 0 }, { 0, 0, 3 } };
  mesh.Triangles[1] = { 0, 3, 2 }; // flipped against its neighbour
  cvt::MeshRepairReport report;
  EXPECT_EQ(cvt::RepairSurfaceMesh(mesh, report), "");
  EXPECT_EQ(report.DuplicateTriangles, 1);
  EXPECT_EQ(report.DegenerateTriangles, 1);
  EXPECT_EQ(report.FlippedTriangles, 1);
  EXPECT_EQ(report.UnusedPoints, 1);
  EXPECT_EQ(mesh.NumberOfTriangles(), 2);
  const cvt::MeshTopology square = cvt::ComputeMeshTopology(mesh.NumberOfPoints(), mesh.Triangles);
  EXPECT_EQ(square.BoundaryLoops, 1);
  EXPECT_EQ(square.EulerCharacteristic, 1);

  // Two triangles below a line and two above, joined by four zero-area triangles along it
  // (CGAL's degtri_sliding): their edges on the line end at different points (T-junctions).
  // Dropping the degenerate ones alone left two parts; the edges are split where the others'
  // points lie on them, so the four join as in the input: one disk.
  cvt::SurfaceMesh sliding;
  sliding.Points = { 4, -2, 0, 6, 0, 0, 4, 0, 0, 2, 0, 0, 1, 0, 0, 3, 0, 0, 5, 0, 0, 3, 2, 0 };
  sliding.Triangles = { { 0, 1, 2 }, { 0, 2, 3 }, { 3, 2, 4 }, { 2, 1, 6 }, { 2, 6, 4 },
    { 4, 6, 5 }, { 5, 6, 7 }, { 4, 5, 7 } };
  EXPECT_EQ(cvt::RepairSurfaceMesh(sliding, report), "");
  EXPECT_EQ(report.DegenerateTriangles, 4);
  EXPECT_EQ(report.JoinedAtLines, 4);
  const cvt::MeshTopology disk =
    cvt::ComputeMeshTopology(sliding.NumberOfPoints(), sliding.Triangles);
  EXPECT_EQ(disk.Components, 1);
  EXPECT_EQ(disk.BoundaryLoops, 1);
  EXPECT_EQ(disk.EulerCharacteristic, 1);
  double area = 0.0;
  for (const auto& triangle : sliding.Triangles)
  {
    area += cvt::TriangleArea(sliding, triangle);
  }
  EXPECT_DOUBLE_EQ(area, 8.0); // the four triangles' area, none overlapping

  // Two squares sharing one corner point: the point is split, one copy per fan.
  cvt::SurfaceMesh bowtie;
  bowtie.Points = { 0, 0, 0, 1, 0, 0, 0, 1, 0, -1, 0, 0, 0, -1, 0 };
  bowtie.Triangles = { { 0, 1, 2 }, { 0, 3, 4 } };
  EXPECT_EQ(cvt::RepairSurfaceMesh(bowtie, report), "");
  EXPECT_EQ(report.SplitPoints, 1);
  EXPECT_EQ(cvt::ComputeMeshTopology(bowtie.NumberOfPoints(), bowtie.Triangles).Components, 2);
  // The same with two triangles to each side, one of each pair turned over: the repair turns
  // them back and splits the point with the edges found before (turning keeps the edges).
  cvt::SurfaceMesh turnedBowtie;
  turnedBowtie.Points = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, -1, 0, 0, -1, -1, 0, 0, -1, 0 };
  turnedBowtie.Triangles = { { 0, 1, 2 }, { 0, 3, 2 }, { 0, 4, 5 }, { 0, 6, 5 } };
  EXPECT_EQ(cvt::RepairSurfaceMesh(turnedBowtie, report), "");
  EXPECT_EQ(report.SplitPoints, 1);
  EXPECT_EQ(report.FlippedTriangles, 2);
  const cvt::MeshTopology turnedParts =
    cvt::ComputeMeshTopology(turnedBowtie.NumberOfPoints(), turnedBowtie.Triangles);
  EXPECT_EQ(turnedParts.Components, 2);
  EXPECT_EQ(turnedParts.BoundaryLoops, 2);
  EXPECT_EQ(turnedParts.EulerCharacteristic, 2);

  // Three triangles on one edge: the third (the fin) is detached from it.
  cvt::SurfaceMesh fin;
  fin.Points = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1 };
  fin.Triangles = { { 0, 1, 2 }, { 1, 0, 3 }, { 0, 1, 4 } };
  EXPECT_EQ(cvt::RepairSurfaceMesh(fin, report), "");
  EXPECT_EQ(report.SplitEdges, 1);
  EXPECT_EQ(fin.NumberOfPoints(), 7);
  const cvt::MeshTopology finParts = cvt::ComputeMeshTopology(fin.NumberOfPoints(), fin.Triangles);
  EXPECT_EQ(finParts.Components, 2);
  EXPECT_EQ(finParts.BoundaryLoops, 2);
  EXPECT_EQ(fin.SourceIds[5] + fin.SourceIds[6], 1); // the copies of points 0 and 1

  // Two tetrahedra sharing an edge (four triangles on it): each pair of triangles through it
  // stays a sheet joined to the rest of its surface. Before, the two triangles beyond the first
  // pair were cut out whole: two single-triangle parts and two holes.
  cvt::SurfaceMesh touching;
  touching.Points = { 0, 0, 0, 1, 0, 0, 0.5, 1, 0.2, 0.5, 0.3, 1, 0.5, -1, 0.2, 0.5, -0.3, -1 };
  for (const std::array<int, 4>& tetrahedron :
    { std::array<int, 4>{ 0, 1, 2, 3 }, std::array<int, 4>{ 0, 1, 4, 5 } })
  {
    const auto& v = tetrahedron;
    touching.Triangles.insert(touching.Triangles.end(),
      { { v[0], v[2], v[1] }, { v[0], v[1], v[3] }, { v[1], v[2], v[3] }, { v[0], v[3], v[2] } });
  }
  const cvt::SurfaceMesh touchingInput = touching;
  EXPECT_EQ(cvt::RepairSurfaceMesh(touching, report), "");
  EXPECT_EQ(report.SplitEdges, 1);
  EXPECT_EQ(report.SplitEdgesApart, 0); // pairs that agree stay
  EXPECT_EQ(touching.NumberOfTriangles(), 8);
  const cvt::MeshTopology sheets =
    cvt::ComputeMeshTopology(touching.NumberOfPoints(), touching.Triangles);
  EXPECT_EQ(sheets.BoundaryLoops, 0);
  EXPECT_EQ(sheets.EulerCharacteristic, 2 * sheets.Components); // closed spheres
  EXPECT_LE(sheets.Components, 2);
  EXPECT_EQ(sheets.Genus, 0);

  // A plate crossed along a segment by a wall whose two halves face opposite ways (OpenFOAM's
  // motorBike.obj has such joins): round the 4 crowded edges the sheets pair with the
  // orientations they have, plate half to wall half, so that a loop through the wall's halves
  // and round the segment's end twists. Every triangle at the crowded edges is then set apart:
  // a slit in the plate, the wall's halves free, each oriented; before, "not orientable".
  cvt::SurfaceMesh crossed = FlatSquare(8, -2.0, 2.0);
  const int firstSpine = 4 * 9 + 2; // points (-1, 0, 0) .. (1, 0, 0), 0.5 apart
  std::vector<int> top, bottom;
  for (int i = 0; i < 5; ++i)
  {
    const double x = -1.0 + 0.5 * i;
    top.push_back(crossed.NumberOfPoints());
    crossed.Points.insert(crossed.Points.end(), { x, 0.0, 0.5 });
    bottom.push_back(crossed.NumberOfPoints());
    crossed.Points.insert(crossed.Points.end(), { x, 0.0, -0.5 });
  }
  for (int i = 0; i < 4; ++i)
  {
    const int s0 = firstSpine + i, s1 = s0 + 1;
    const std::array<std::array<int, 3>, 4> wall = { { { s0, s1, top[i + 1] },
      { s0, top[i + 1], top[i] }, { bottom[i], bottom[i + 1], s1 }, { bottom[i], s1, s0 } } };
    for (std::array<int, 3> triangle : wall)
    {
      if (i >= 2)
      {
        std::swap(triangle[1], triangle[2]); // the half at x > 0 faces the other way
      }
      crossed.Triangles.push_back(triangle);
    }
  }
  const cvt::SurfaceMesh crossedInput = crossed;
  EXPECT_EQ(cvt::RepairSurfaceMesh(crossed, report), "");
  EXPECT_GT(report.SplitEdges, 0);
  EXPECT_EQ(report.SplitEdgesApart, report.SplitEdges);
  EXPECT_NE(report.Summary().find("apart"), std::string::npos) << report.Summary();
  const cvt::MeshTopology apart =
    cvt::ComputeMeshTopology(crossed.NumberOfPoints(), crossed.Triangles);
  EXPECT_EQ(apart.Components, 3); // the slit plate and the wall's two strips
  const cvt::EdgeTable crossedEdges(crossed.Triangles);
  for (size_t e = 0; e < crossedEdges.NumberOfEdges(); ++e)
  {
    const cvt::EdgeTable::Range uses = crossedEdges.Edge(e);
    ASSERT_LE(uses.size(), 2u);
    if (uses.size() == 2)
    {
      const cvt::EdgeUse& first = uses.First[0];
      const cvt::EdgeUse& second = uses.First[1];
      EXPECT_NE(crossed.Triangles[first.Triangle][first.Local],
        crossed.Triangles[second.Triangle][second.Local])
        << "edge " << e << " is traversed one way twice";
    }
  }
  // Only the twisted part's sheets are set apart: beside it, the two tetrahedra sharing an edge
  // keep their pairs (closed surfaces, no border added).
  cvt::SurfaceMesh both = crossedInput;
  const int shift = both.NumberOfPoints();
  for (int p = 0; p < touchingInput.NumberOfPoints(); ++p)
  {
    const double* x = touchingInput.Point(p);
    both.Points.insert(both.Points.end(), { x[0] + 10.0, x[1], x[2] });
  }
  for (const auto& triangle : touchingInput.Triangles)
  {
    both.Triangles.push_back({ triangle[0] + shift, triangle[1] + shift, triangle[2] + shift });
  }
  EXPECT_EQ(cvt::RepairSurfaceMesh(both, report), "");
  EXPECT_EQ(report.SplitEdges, report.SplitEdgesApart + 1);
  EXPECT_EQ(cvt::ComputeMeshTopology(both.NumberOfPoints(), both.Triangles).BoundaryLoops,
    apart.BoundaryLoops);
  // A closed sphere far from the origin (georeferenced coordinates), facing outwards: left as it
  // is. Its volume summed from the origin was rounding noise of either sign (an elephant 1e6
  // away had all its triangles turned inwards).
  cvt::SurfaceMesh far = Sphere(3);
  for (size_t i = 0; i < far.Points.size(); ++i)
  {
    far.Points[i] += i % 3 == 0 ? 1e8 : -3e7;
  }
  EXPECT_EQ(cvt::RepairSurfaceMesh(far, report), "");
  EXPECT_EQ(report.FlippedTriangles, 0);
  for (auto& triangle : far.Triangles)
  {
    std::swap(triangle[1], triangle[2]); // facing inwards
  }
  EXPECT_EQ(cvt::RepairSurfaceMesh(far, report), "");
  EXPECT_EQ(report.FlippedTriangles, far.NumberOfTriangles());

  // A Moebius strip.
  cvt::SurfaceMesh strip;
  const int n = 12;
  for (int i = 0; i < n; ++i)
  {
    const double angle = 2.0 * 3.14159265358979 * i / n, twist = 0.5 * angle;
    for (int side : { -1, 1 })
    {
      const double r = 2.0 + 0.5 * side * std::cos(twist);
      strip.Points.insert(strip.Points.end(),
        { r * std::cos(angle), r * std::sin(angle), 0.5 * side * std::sin(twist) });
    }
  }
  for (int i = 0; i < n; ++i)
  {
    const int a = 2 * i, b = 2 * i + 1;
    const int c = i + 1 < n ? 2 * (i + 1) : 1, d = i + 1 < n ? 2 * (i + 1) + 1 : 0;
    strip.Triangles.push_back({ a, c, b });
    strip.Triangles.push_back({ b, c, d });
  }
  EXPECT_NE(cvt::RepairSurfaceMesh(strip, report).find("not orientable"), std::string::npos);

  // Bad values.
  cvt::SurfaceMesh bad = FlatSquare(2, 0.0, 1.0);
  bad.Points[4] = std::nan("");
  EXPECT_NE(cvt::CheckSurfaceMesh(bad).find("NaN"), std::string::npos);
  bad = FlatSquare(2, 0.0, 1.0);
  bad.Density.assign(bad.NumberOfPoints(), 1.0);
  bad.Density[3] = -1.0;
  EXPECT_NE(cvt::CheckSurfaceMesh(bad).find("negative"), std::string::npos);
  bad.Density.assign(bad.NumberOfPoints(), 0.0);
  EXPECT_NE(cvt::CheckSurfaceMesh(bad).find("zero everywhere"), std::string::npos);
}

TEST(SurfaceMesh, TopologyCountsGenusAndLoops)
{
  // A torus as a 12 x 8 grid with both borders identified: genus 1.
  const cvt::SurfaceMesh torus = cvttest::Torus(1.0, 0.4, 12, 8);
  const cvt::MeshTopology t = cvt::ComputeMeshTopology(torus.NumberOfPoints(), torus.Triangles);
  EXPECT_EQ(t.Components, 1);
  EXPECT_EQ(t.Genus, 1);
  EXPECT_EQ(t.BoundaryLoops, 0);
  EXPECT_EQ(t.EulerCharacteristic, 0);
}

// The split of small polygons, and the last resort for those that ear cutting leaves holes in:
// mpi.off's hexagon, whose corners almost lie in a line, with a deep notch, a thin hexagon bent
// out of its plane, and a dart. Each becomes n - 2 triangles in the polygon's orientation (each
// of its edges in one, the same way round), all facing its normal (so those of a flat one are its
// area, once), whose smallest angle is at least that of each fan from one corner that faces it
// too (the programme maximises it over all that do).
TEST(SurfaceMesh, PolygonsAreSplitIntoTheirWidestTriangles)
{
  const std::vector<std::vector<double>> polygons = {
    { -10.0219, -0.926781, -0.926781, -10, 10, 10, -9.99992, 10.0401, -9.99992, -10.008, 6.02406,
      -10.008, -10.008, 6.02406, 5.02005, -10.02, 0, -2.00802 },
    { 0, 0, 0, 3, 0, 0.4, 6, 0, 0, 6, 1, 0, 3, 1, -0.4, 0, 1, 0 },
    { 0, 0, 0, 2, 2.5, 0, 4, 0, 0, 2, 3, 0 }, // a dart: the wider split 0 2 lies outside it
  };
  for (size_t p = 0; p < polygons.size(); ++p)
  {
    const std::vector<double>& corners = polygons[p];
    const int n = static_cast<int>(corners.size() / 3);
    double normal[3] = { 0.0, 0.0, 0.0 }; // Newell's: twice the vector area
    for (int i = 0; i < n; ++i)
    {
      double edge[3];
      cvt::Cross(&corners[3 * i], &corners[3 * ((i + 1) % n)], edge);
      for (int c = 0; c < 3; ++c)
      {
        normal[c] += edge[c];
      }
    }
    // The smallest angle of `triangles`, and whether all face the normal; their summed area.
    const auto measure = [&](const std::vector<std::array<int, 3>>& triangles, bool& facing)
    {
      double least = 10.0, area = 0.0;
      facing = true;
      for (const auto& t : triangles)
      {
        double angle[3], n3[3];
        const double *a = &corners[3 * t[0]], *b = &corners[3 * t[1]], *c = &corners[3 * t[2]];
        cvt::CornerAngles(a, b, c, angle);
        least = std::min({ least, angle[0], angle[1], angle[2] });
        cvt::TriangleNormal(a, b, c, n3);
        facing = facing && cvt::Dot(n3, normal) > 0.0;
        area += 0.5 * std::sqrt(cvt::Dot(n3, n3));
      }
      return std::make_pair(least, area);
    };
    const std::vector<std::array<int, 3>> triangles = cvt::TriangulatePolygonByAngles(corners);
    ASSERT_EQ(static_cast<int>(triangles.size()), n - 2);
    std::map<std::pair<int, int>, int> directed;
    for (const auto& t : triangles)
    {
      for (int k = 0; k < 3; ++k)
      {
        ++directed[std::make_pair(t[k], t[(k + 1) % 3])];
      }
    }
    for (int i = 0; i < n; ++i)
    {
      EXPECT_EQ(directed[std::make_pair(i, (i + 1) % n)], 1) << "edge " << i;
      EXPECT_EQ(directed[std::make_pair((i + 1) % n, i)], 0) << "edge " << i;
    }
    bool facing = false;
    const auto [least, area] = measure(triangles, facing);
    EXPECT_TRUE(facing);
    if (p != 1) // flat
    {
      const double exact = 0.5 * std::sqrt(cvt::Dot(normal, normal));
      EXPECT_NEAR(area, exact, 1e-9 * exact);
    }
    int fansFacing = 0;
    for (int apex = 0; apex < n; ++apex)
    {
      std::vector<std::array<int, 3>> fan;
      for (int k = 1; k + 1 < n; ++k)
      {
        fan.push_back({ apex, (apex + k) % n, (apex + k + 1) % n });
      }
      bool fanFacing = false;
      const double fanLeast = measure(fan, fanFacing).first;
      if (fanFacing)
      {
        ++fansFacing;
        EXPECT_GE(least, fanLeast - 1e-12) << "fan from " << apex;
      }
    }
    EXPECT_GT(fansFacing, 0);
  }
  EXPECT_TRUE(cvt::TriangulatePolygonByAngles({ 0, 0, 0, 1, 0, 0 }).empty());
}

TEST(SurfaceMesh, ProjectorFindsTheNearestPointExactly)
{
  // A sphere of small triangles beside a plane of two large ones: the nearest centroids of a
  // point just above the plane are the sphere's (the 16 nearest made the point 6 from the
  // surface, not 0.2), yet the plane is nearest. Against brute force over every triangle.
  const cvt::SurfaceMesh mesh =
    cvttest::TwoParts(cvttest::FlatSquare(1, -20.0, 20.0), cvttest::Sphere(3), 3.0);
  const cvt::SurfaceProjector projector(mesh);
  const double above[3] = { 10.0, 0.0, 0.2 };
  EXPECT_NEAR(projector.DistanceTo(above), 0.2, 1e-12);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> across(-20.0, 20.0), height(-3.0, 3.0);
  for (int i = 0; i < 2000; ++i)
  {
    const double p[3] = { across(random), across(random) / 4.0, height(random) };
    const double nearest = BruteForceNearest2(p, mesh.Points, mesh.Triangles);
    double q[3], w[3];
    const int t = projector.Nearest(p, q, w);
    ASSERT_GE(t, 0);
    EXPECT_NEAR(cvt::Distance2(p, q), nearest, 1e-12)
      << "at " << p[0] << " " << p[1] << " " << p[2];
    // A guess of the triangle, right, wrong or out of range, changes nothing but the speed; the
    // guess is replaced by the nearest triangle.
    for (int guess : { t, (t * 7 + i) % mesh.NumberOfTriangles(), -5, 1 << 30 })
    {
      double guessed[3], weights[3];
      ASSERT_GE(projector.Nearest(p, guessed, weights, guess), 0);
      EXPECT_NEAR(cvt::Distance2(p, guessed), nearest, 1e-12)
        << "guess " << guess << " at " << p[0] << " " << p[1] << " " << p[2];
      int chained = guess;
      EXPECT_NEAR(projector.DistanceTo(p, &chained), std::sqrt(nearest), 1e-9);
      EXPECT_GE(chained, 0);
    }
    // q is the point of triangle t at weights w.
    const auto& tri = mesh.Triangles[static_cast<size_t>(t)];
    for (int k = 0; k < 3; ++k)
    {
      EXPECT_NEAR(q[k],
        w[0] * mesh.Point(tri[0])[k] + w[1] * mesh.Point(tri[1])[k] + w[2] * mesh.Point(tri[2])[k],
        1e-12);
    }
  }
  // A mesh without triangles has no nearest point.
  const cvt::SurfaceMesh empty;
  double q[3], w[3];
  EXPECT_EQ(cvt::SurfaceProjector(empty).Nearest(above, q, w), -1);
}

TEST(SurfaceMesh, ProjectorFindsTheNearestPointOnSliversExactly)
{
  // A CAD cylinder's side: 400 slivers a unit long and 0.0016 wide (cut into balls along their
  // length for the search), beside a sphere of small triangles that sets the pieces' size, and
  // a fan of slivers closing the tube's end. Against brute force over every triangle, at points
  // round the tube, inside it and beyond its ends.
  cvt::SurfaceMesh tube = cvttest::Tube(0.05, 200, 1);
  const int centre = tube.NumberOfPoints();
  tube.Points.insert(tube.Points.end(), { 0.0, 0.0, 0.0 });
  for (int i = 0; i < 200; ++i)
  {
    tube.Triangles.push_back({ centre, (i + 1) % 200, i });
  }
  const cvt::SurfaceMesh mesh = cvttest::TwoParts(tube, cvttest::Sphere(3), 1.5);
  const cvt::SurfaceProjector projector(mesh);
  std::mt19937 random(5);
  std::uniform_real_distribution<double> across(-0.2, 0.2), along(-0.3, 1.3);
  for (int i = 0; i < 3000; ++i)
  {
    const double scale = i % 3 == 0 ? 0.25 : 1.0; // a third of the points close to the axis
    const double p[3] = { scale * across(random), scale * across(random), along(random) };
    const double nearest = BruteForceNearest2(p, mesh.Points, mesh.Triangles);
    double q[3], w[3];
    ASSERT_GE(projector.Nearest(p, q, w), 0);
    ASSERT_NEAR(cvt::Distance2(p, q), nearest, 1e-14)
      << "at " << p[0] << " " << p[1] << " " << p[2];
  }
}

TEST(SurfaceMesh, ProjectorOfTrianglesShrunkToPointsFindsTheOthers)
{
  // Most triangles with their three corners at one point (a mesh not yet repaired): the median
  // triangle, which sizes the pieces, has no size; the others are still found, each whole.
  cvt::SurfaceMesh mesh = cvttest::FlatSquare(2, -1.0, 1.0);
  const int triangles = mesh.NumberOfTriangles();
  mesh.Points.insert(mesh.Points.end(), { 0.3, 0.2, 0.5 });
  for (int i = 0; i <= triangles; ++i)
  {
    const int p = mesh.NumberOfPoints() - 1;
    mesh.Triangles.push_back({ p, p, p });
  }
  const cvt::SurfaceProjector projector(mesh);
  for (double x : { -2.0, -0.5, 0.0, 0.7, 3.0 })
  {
    const double p[3] = { x, 0.5 * x, -1.0 };
    double q[3], w[3];
    ASSERT_GE(projector.Nearest(p, q, w), 0);
    EXPECT_NEAR(q[2], 0.0, 1e-15);
    EXPECT_NEAR(q[0], std::clamp(x, -1.0, 1.0), 1e-12);
  }
}

TEST(SurfaceMesh, ProjectorThatRemembersAnswersGivesTheSameAnswers)
{
  // Queries asked again (with the same guess or another, from two threads at once) and more
  // queries than it remembers: the same triangle, point and weights, to the bit, as a projector
  // that computes every answer.
  const cvt::SurfaceMesh mesh =
    cvttest::TwoParts(cvttest::FlatSquare(1, -20.0, 20.0), cvttest::Sphere(2), 3.0);
  const cvt::SurfaceProjector computing(mesh);
  cvt::SurfaceProjector remembering(mesh);
  remembering.SetRememberAnswers(true);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> across(-20.0, 20.0), height(-3.0, 3.0);
  std::vector<std::array<double, 3>> points(300000);
  for (auto& p : points)
  {
    p = { across(random), across(random) / 4.0, height(random) };
  }
  const auto same = [&](size_t begin, size_t end, int pass)
  {
    for (size_t i = begin; i < end; ++i)
    {
      const int guess = pass == 0 ? -1 : static_cast<int>(i) % mesh.NumberOfTriangles();
      double q0[3], w0[3], q1[3], w1[3];
      const int t0 = computing.Nearest(points[i].data(), q0, w0, guess);
      const int t1 = remembering.Nearest(points[i].data(), q1, w1, guess);
      if (t0 != t1 || !std::equal(q0, q0 + 3, q1) || !std::equal(w0, w0 + 3, w1))
      {
        return false;
      }
    }
    return true;
  };
  // Above the middle of the square's diagonal both of its triangles (the first two) are
  // nearest: the guess wins.
  const std::array<int, 2> pair{ 0, 1 };
  const double aboveDiagonal[3] = { 0.0, 0.0, 0.5 };
  std::array<int, 2> chosen;
  for (int k : { 0, 1, 0, 1 })
  {
    double q0[3], w0[3], q1[3], w1[3];
    chosen[k] = computing.Nearest(aboveDiagonal, q0, w0, pair[k]);
    EXPECT_EQ(remembering.Nearest(aboveDiagonal, q1, w1, pair[k]), chosen[k]);
    EXPECT_TRUE(std::equal(w0, w0 + 3, w1));
  }
  EXPECT_EQ(chosen, pair);
  // The first 1000 points, asked and asked again; then all of them, twice, split between two
  // threads (the last pass asking again what the one before asked).
  EXPECT_TRUE(same(0, 1000, 0));
  EXPECT_TRUE(same(0, 1000, 0));
  EXPECT_TRUE(same(0, 1000, 1));
  for (int pass : { 1, 1 })
  {
    bool firstHalf = false;
    std::thread other([&]() { firstHalf = same(0, points.size() / 2, pass); });
    const bool secondHalf = same(points.size() / 2, points.size(), pass);
    other.join();
    EXPECT_TRUE(firstHalf && secondHalf);
  }
}

TEST(SurfaceMesh, HasPointsWithinFindsWhatBruteForceFinds)
{
  // Points at the corners of a unit lattice (the grid cells of the search are 1000 tolerances
  // wide: 1 here) moved by up to 1.5 tolerances each way, so that close pairs straddle the
  // cells' faces, edges and corners; each set's answer against all pairs compared directly.
  const double tolerance = 1e-3;
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<int> corner(0, 4);
  std::uniform_real_distribution<double> offset(-1.5 * tolerance, 1.5 * tolerance);
  int withPair = 0, without = 0;
  for (int trial = 0; trial < 400; ++trial)
  {
    std::vector<double> points;
    for (int p = 0; p < 20; ++p)
    {
      for (int k = 0; k < 3; ++k)
      {
        points.push_back(corner(rng) + offset(rng));
      }
    }
    bool bruteForce = false;
    for (size_t a = 0; a < points.size(); a += 3)
    {
      for (size_t b = a + 3; b < points.size(); b += 3)
      {
        bruteForce = bruteForce || cvt::Distance2(&points[a], &points[b]) <= tolerance * tolerance;
      }
    }
    EXPECT_EQ(cvt::HasPointsWithin(points, tolerance), bruteForce) << "trial " << trial;
    (bruteForce ? withPair : without) += 1;
  }
  EXPECT_GT(withPair, 50); // both answers are tested
  EXPECT_GT(without, 50);
  // Coincident points, with or without a tolerance; one point; all points at one place.
  EXPECT_TRUE(cvt::HasPointsWithin({ 0, 0, 0, 1, 2, 3, 0, 0, 0 }, 0.0));
  EXPECT_FALSE(cvt::HasPointsWithin({ 0, 0, 0, 1, 2, 3, 0, 0, 1e-12 }, 0.0));
  EXPECT_FALSE(cvt::HasPointsWithin({ 1, 2, 3 }, 1.0));
  EXPECT_TRUE(cvt::HasPointsWithin({ 1, 2, 3, 1, 2, 3 }, 0.0));
}

TEST(SurfaceMesh, CoveringPointsLieNearEveryPointOfTheSurface)
{
  // A wide triangle (10 x 6), a sliver 10 long and 0.05 high, and a small one (0.4), measured
  // with a spacing of 0.5: every point of each (a fine grid of them) lies within the spacing of
  // a covering point, inside the wide triangle too, far from its edges; the mesh's own points
  // come first; and the count stays near area / spacing^2, not (length / spacing)^2 per sliver.
  cvt::SurfaceMesh mesh;
  mesh.Points = { 0, 0, 0, 10, 0, 0, 3, 6, 0, 0, 0, 1, 10, 0, 1, 5, 0.05, 1, 0, 0, 2, 0.4, 0, 2, 0,
    0.4, 2 };
  mesh.Triangles = { { 0, 1, 2 }, { 3, 4, 5 }, { 6, 7, 8 } };
  const double spacing = 0.5;
  const std::vector<double> points = cvt::CoveringPoints(mesh, spacing);
  ASSERT_EQ(points.size() % 3, 0u);
  EXPECT_TRUE(std::equal(mesh.Points.begin(), mesh.Points.end(), points.begin()));
  double farthest = 0.0;
  const int steps = 80;
  for (const auto& t : mesh.Triangles)
  {
    for (int i = 0; i <= steps; ++i)
    {
      for (int j = 0; i + j <= steps; ++j)
      {
        const double u = static_cast<double>(i) / steps, v = static_cast<double>(j) / steps;
        double p[3];
        for (int k = 0; k < 3; ++k)
        {
          p[k] =
            (1 - u - v) * mesh.Point(t[0])[k] + u * mesh.Point(t[1])[k] + v * mesh.Point(t[2])[k];
        }
        double nearest = 1e300;
        for (size_t q = 0; q < points.size(); q += 3)
        {
          nearest = std::min(nearest, cvt::Distance2(p, &points[q]));
        }
        farthest = std::max(farthest, std::sqrt(nearest));
      }
    }
  }
  EXPECT_LE(farthest, spacing);
  EXPECT_GT(farthest, 0.2 * spacing); // not a point per grid sample
  // Area 30 (about 110 inside the wide triangle, none inside the sliver), 47 along the wide
  // triangle's edges, 37 along the sliver's, and the 9 corners.
  EXPECT_LT(points.size() / 3, 250u);
  std::cout << "[ measured ] " << points.size() / 3 << " covering points, the farthest point "
            << farthest << " from them (spacing " << spacing << ")\n";
}

TEST(SurfaceMesh, DensityOfCellSizesMakesSmallCellsDense)
{
  // Four points in three cells of masses 1, 4 and 0 (an empty cell) and one point in none.
  // Relative to the mean mass (5/3), the density is (mean / mass)^2: 25/9 in the small cell,
  // 25/144 in the large one; 1 where no cell or mass tells. A given density counts by its ratio
  // to its own mean (the cell's area is mass / density): doubling it everywhere changes nothing,
  // doubling it at one point of the large cell doubles its ratio there.
  cvt::SurfaceMesh mesh;
  mesh.Points.assign(15, 0.0);
  const std::vector<int> labels = { 0, 1, 1, 2, -1 };
  const std::vector<double> masses = { 1.0, 4.0, 0.0 };
  const std::vector<double> density = cvt::DensityOfCellSizes(mesh, labels, masses);
  ASSERT_EQ(density.size(), 5u);
  EXPECT_NEAR(density[0], 25.0 / 9.0, 1e-12);
  EXPECT_NEAR(density[1], 25.0 / 144.0, 1e-12);
  EXPECT_NEAR(density[2], 25.0 / 144.0, 1e-12);
  EXPECT_NEAR(density[3], 1e4, 1e-9); // an empty cell: as dense as allowed
  EXPECT_EQ(density[4], 1.0);
  mesh.Density.assign(5, 2.0);
  EXPECT_EQ(cvt::DensityOfCellSizes(mesh, labels, masses), density);
  mesh.Density = { 1.0, 1.0, 2.0, 1.0, 1.0 }; // mean 1.2
  const std::vector<double> given = cvt::DensityOfCellSizes(mesh, labels, masses);
  EXPECT_NEAR(given[2] / given[1], 4.0, 1e-12);
}

// A triangle soup made manifold (as a labelling's dual across an atlas's seams): a triangle
// that runs an edge the same way as another goes, and the hole it leaves is closed; a fan
// folded onto itself (two copies of its centre with the same ring, the fan's two sides facing
// away from each other) keeps no two vertices at one place, which a point-merging reader would
// join into non-manifold edges (the copies' rings cannot tell them apart: they move along their
// own normals).
TEST(RestrictedVoronoi, ManifoldRemeshDropsDoubledEdgesAndSeparatesAFoldedFan)
{
  // An octahedron with one face given twice, the second time turned the other way.
  const std::vector<double> octahedron = { 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0,
    -1 };
  std::vector<std::array<int, 3>> faces = { { 0, 2, 4 }, { 2, 1, 4 }, { 1, 3, 4 }, { 3, 0, 4 },
    { 2, 0, 5 }, { 1, 2, 5 }, { 3, 1, 5 }, { 0, 3, 5 } };
  faces.push_back({ 0, 4, 2 });
  const cvt::Remesh closed = cvt::ManifoldRemesh(octahedron, faces, {});
  const cvt::MeshTopology topology =
    cvt::ComputeMeshTopology(static_cast<int>(closed.SiteIds.size()), closed.Triangles);
  EXPECT_EQ(topology.Components, 1);
  EXPECT_EQ(topology.BoundaryLoops, 0);
  EXPECT_EQ(topology.EulerCharacteristic, 2);
  EXPECT_GT(closed.RemovedTriangles, 0);

  // A pentagon's fan, centre 5, and the same fan the other way round about centre 6 at the same
  // place: a closed surface of no volume.
  std::vector<double> points;
  for (int k = 0; k < 5; ++k)
  {
    const double angle = 2.0 * 3.14159265358979323846 * k / 5;
    points.insert(points.end(), { std::cos(angle), std::sin(angle), 0.0 });
  }
  points.insert(points.end(), { 0.0, 0.0, 0.0, 0.0, 0.0, 0.0 });
  std::vector<std::array<int, 3>> fans;
  for (int k = 0; k < 5; ++k)
  {
    fans.push_back({ 5, k, (k + 1) % 5 });
    fans.push_back({ 6, (k + 1) % 5, k });
  }
  const cvt::Remesh folded = cvt::ManifoldRemesh(points, fans, {});
  ASSERT_EQ(folded.SiteIds.size(), 7u);
  double closest = std::numeric_limits<double>::max();
  for (size_t v = 0; v < 7; ++v)
  {
    for (size_t w = v + 1; w < 7; ++w)
    {
      closest =
        std::min(closest, std::sqrt(cvt::Distance2(&folded.Points[3 * v], &folded.Points[3 * w])));
    }
  }
  // Without the move along the normals the centres' rounds leave them 1e-18 apart.
  EXPECT_GT(closest, 0.01) << "two vertices (nearly) at one place";
}
