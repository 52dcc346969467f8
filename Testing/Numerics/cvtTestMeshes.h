// Test meshes made in the repository (no downloads), shared by the test programs: a flat
// square, an open tube, a sphere, a torus and two disjoint parts.
#ifndef cvtTestMeshes_h
#define cvtTestMeshes_h

#include "cvtSurfaceMesh.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace cvttest
{

/// The square [lo, hi]^2 at z = 0 as an n x n grid of quads, two triangles each.
inline cvt::SurfaceMesh FlatSquare(int n, double lo, double hi)
{
  cvt::SurfaceMesh mesh;
  for (int j = 0; j <= n; ++j)
  {
    for (int i = 0; i <= n; ++i)
    {
      mesh.Points.insert(
        mesh.Points.end(), { lo + (hi - lo) * i / n, lo + (hi - lo) * j / n, 0.0 });
    }
  }
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const int a = j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
      mesh.Triangles.push_back({ a, b, c });
      mesh.Triangles.push_back({ a, c, d });
    }
  }
  return mesh;
}

/// An open tube of radius `radius` along z from 0 to 1: `around` x `along` quads, two
/// triangles each.
inline cvt::SurfaceMesh Tube(double radius, int around, int along)
{
  cvt::SurfaceMesh mesh;
  for (int j = 0; j <= along; ++j)
  {
    for (int i = 0; i < around; ++i)
    {
      const double angle = 2.0 * 3.14159265358979323846 * i / around;
      mesh.Points.insert(mesh.Points.end(),
        { radius * std::cos(angle), radius * std::sin(angle), static_cast<double>(j) / along });
    }
  }
  for (int j = 0; j < along; ++j)
  {
    for (int i = 0; i < around; ++i)
    {
      const int a = j * around + i, b = j * around + (i + 1) % around, c = b + around,
                d = a + around;
      mesh.Triangles.push_back({ a, b, c });
      mesh.Triangles.push_back({ a, c, d });
    }
  }
  return mesh;
}

/// A unit sphere: an octahedron subdivided `levels` times, points pushed onto the sphere.
inline cvt::SurfaceMesh Sphere(int levels)
{
  cvt::SurfaceMesh mesh;
  mesh.Points = { 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1 };
  mesh.Triangles = { { 0, 2, 4 }, { 2, 1, 4 }, { 1, 3, 4 }, { 3, 0, 4 }, { 2, 0, 5 }, { 1, 2, 5 },
    { 3, 1, 5 }, { 0, 3, 5 } };
  for (int level = 0; level < levels; ++level)
  {
    std::map<std::pair<int, int>, int> middle;
    const auto midpoint = [&mesh, &middle](int a, int b)
    {
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      auto found = middle.find(key);
      if (found != middle.end())
      {
        return found->second;
      }
      double p[3];
      double length = 0.0;
      for (int k = 0; k < 3; ++k)
      {
        p[k] = 0.5 * (mesh.Points[3 * a + k] + mesh.Points[3 * b + k]);
        length += p[k] * p[k];
      }
      for (double& c : p)
      {
        mesh.Points.push_back(c / std::sqrt(length));
      }
      return middle[key] = mesh.NumberOfPoints() - 1;
    };
    std::vector<std::array<int, 3>> finer;
    for (const auto& t : mesh.Triangles)
    {
      const int ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
      finer.push_back({ t[0], ab, ca });
      finer.push_back({ ab, t[1], bc });
      finer.push_back({ ca, bc, t[2] });
      finer.push_back({ ab, bc, ca });
    }
    mesh.Triangles = finer;
  }
  return mesh;
}

/// A torus of radii R and r about z: an nu x nv grid with both borders identified (genus 1).
inline cvt::SurfaceMesh Torus(double R, double r, int nu, int nv)
{
  cvt::SurfaceMesh mesh;
  for (int i = 0; i < nu; ++i)
  {
    for (int j = 0; j < nv; ++j)
    {
      const double u = 2 * 3.14159265358979323846 * i / nu;
      const double v = 2 * 3.14159265358979323846 * j / nv;
      mesh.Points.insert(mesh.Points.end(),
        { (R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u),
          r * std::sin(v) });
    }
  }
  for (int i = 0; i < nu; ++i)
  {
    for (int j = 0; j < nv; ++j)
    {
      const int a = i * nv + j, b = ((i + 1) % nu) * nv + j, c = ((i + 1) % nu) * nv + (j + 1) % nv,
                d = i * nv + (j + 1) % nv;
      mesh.Triangles.push_back({ a, b, c });
      mesh.Triangles.push_back({ a, c, d });
    }
  }
  return mesh;
}

/// Two meshes as one, the second moved by `offset` along x.
inline cvt::SurfaceMesh TwoParts(
  const cvt::SurfaceMesh& a, const cvt::SurfaceMesh& b, double offset)
{
  cvt::SurfaceMesh mesh = a;
  const int first = a.NumberOfPoints();
  for (int i = 0; i < b.NumberOfPoints(); ++i)
  {
    mesh.Points.insert(mesh.Points.end(), { b.Point(i)[0] + offset, b.Point(i)[1], b.Point(i)[2] });
  }
  for (const auto& t : b.Triangles)
  {
    mesh.Triangles.push_back({ t[0] + first, t[1] + first, t[2] + first });
  }
  return mesh;
}

} // namespace cvttest

#endif
