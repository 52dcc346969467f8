#include "cvtParameterization.h"

#include "cvtSurfaceMesh.h" // for LoopLengths

#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <sstream>

namespace cvt
{

namespace
{
using Edge = std::pair<int, int>;
Edge Key(int a, int b)
{
  return { std::min(a, b), std::max(a, b) };
}

double Norm3(const double* a, const double* b)
{
  return std::sqrt(
    (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

double TriangleArea(const TriangleMesh& mesh, const std::array<int, 3>& t)
{
  const double* a = &mesh.Points[3 * t[0]];
  const double* b = &mesh.Points[3 * t[1]];
  const double* c = &mesh.Points[3 * t[2]];
  const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
  const double v[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
  const double n[3] = { u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
    u[0] * v[1] - u[1] * v[0] };
  return 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
}

/// The boundary loop, in the order of the triangles' orientation (empty when not one loop).
std::vector<int> BoundaryLoop(const TriangleMesh& mesh)
{
  std::map<Edge, int> uses;
  for (const auto& t : mesh.Triangles)
  {
    for (int e = 0; e < 3; ++e)
    {
      ++uses[Key(t[e], t[(e + 1) % 3])];
    }
  }
  std::map<int, int> next; // boundary edges keep the triangle's direction
  for (const auto& t : mesh.Triangles)
  {
    for (int e = 0; e < 3; ++e)
    {
      if (uses[Key(t[e], t[(e + 1) % 3])] == 1)
      {
        next[t[e]] = t[(e + 1) % 3];
      }
    }
  }
  if (next.empty())
  {
    return {};
  }
  std::vector<int> loop{ next.begin()->first };
  while (loop.size() <= next.size())
  {
    auto it = next.find(loop.back());
    if (it == next.end())
    {
      return {};
    }
    if (it->second == loop.front())
    {
      break;
    }
    loop.push_back(it->second);
  }
  return loop.size() == next.size() ? loop : std::vector<int>();
}
}

std::string CheckMesh(const TriangleMesh& mesh, bool& closed, bool* manifold)
{
  closed = false;
  if (manifold)
  {
    *manifold = false;
  }
  const int n = static_cast<int>(mesh.Points.size() / 3);
  if (mesh.Triangles.empty())
  {
    return "the mesh has no triangles";
  }
  for (double c : mesh.Points)
  {
    if (!std::isfinite(c))
    {
      return "the mesh has a point with a coordinate that is not finite (NaN)";
    }
  }
  std::map<Edge, int> uses;
  std::vector<int> component(n);
  std::iota(component.begin(), component.end(), 0);
  const auto find = [&component](int a)
  {
    while (component[a] != a)
    {
      a = component[a] = component[component[a]];
    }
    return a;
  };
  std::vector<bool> used(n, false);
  for (size_t k = 0; k < mesh.Triangles.size(); ++k)
  {
    const auto& t = mesh.Triangles[k];
    for (int v : t)
    {
      if (v < 0 || v >= n)
      {
        return "a triangle refers to a point the mesh does not have";
      }
      used[v] = true;
    }
    if (TriangleArea(mesh, t) <= 1e-14)
    {
      std::ostringstream msg;
      msg << "triangle " << k << " has zero area; remove degenerate triangles first";
      return msg.str();
    }
    for (int e = 0; e < 3; ++e)
    {
      if (++uses[Key(t[e], t[(e + 1) % 3])] > 2)
      {
        std::ostringstream msg;
        msg << "the edge (" << t[e] << ", " << t[(e + 1) % 3]
            << ") belongs to more than two triangles: the mesh is not manifold";
        return msg.str();
      }
      component[find(t[e])] = find(t[(e + 1) % 3]);
    }
  }
  if (manifold)
  {
    *manifold = true; // what follows is about topology only
  }
  int components = 0, vertices = 0;
  for (int v = 0; v < n; ++v)
  {
    if (used[v])
    {
      ++vertices;
      components += find(v) == v ? 1 : 0;
    }
  }
  if (components != 1)
  {
    std::ostringstream msg;
    msg << "the mesh has " << components << " connected components; give one surface";
    return msg.str();
  }
  int boundaryEdges = 0;
  for (const auto& e : uses)
  {
    boundaryEdges += e.second == 1 ? 1 : 0;
  }
  const long long euler =
    vertices - static_cast<long long>(uses.size()) + static_cast<long long>(mesh.Triangles.size());
  if (boundaryEdges == 0)
  {
    if (euler == 2)
    {
      closed = true;
      return std::string();
    }
    std::ostringstream msg;
    msg << "the mesh is closed with Euler characteristic " << euler << " (genus " << (2 - euler) / 2
        << "); the parameterisations need a disk (one boundary loop) or a closed genus-0 surface";
    return msg.str();
  }
  if (euler != 1 || BoundaryLoop(mesh).empty())
  {
    std::ostringstream msg;
    msg << "the mesh is not a disk (Euler characteristic " << euler << ", boundary edges "
        << boundaryEdges
        << "); this parameterisation needs one boundary loop and Euler characteristic 1";
    return msg.str();
  }
  return std::string();
}

bool ParameterizeDisk(const TriangleMesh& mesh, std::vector<double>& uv, std::string& error)
{
  const int n = static_cast<int>(mesh.Points.size() / 3);
  const std::vector<int> loop = BoundaryLoop(mesh);
  if (loop.empty())
  {
    error = "the mesh has no single boundary loop";
    return false;
  }
  // Boundary: arc length around the loop, onto the square's perimeter (4 sides of length 1).
  uv.assign(2 * static_cast<size_t>(n), 0.0);
  std::vector<int> fixed(n, 0);
  const std::vector<double> arc = LoopLengths(mesh.Points, loop);
  for (size_t k = 0; k < loop.size(); ++k)
  {
    const double t = 4.0 * arc[k] / arc.back();
    const int side = std::min(3, static_cast<int>(t));
    const double s = t - side;
    const double square[4][2] = { { s, 0.0 }, { 1.0, s }, { 1.0 - s, 1.0 }, { 0.0, 1.0 - s } };
    uv[2 * loop[k]] = square[side][0];
    uv[2 * loop[k] + 1] = square[side][1];
    fixed[loop[k]] = 1;
  }
  // Interior: mean-value weights w_ij = (tan(a/2) + tan(b/2)) / |x_i - x_j|, with a and b the
  // angles at i of the two triangles on edge ij. Always positive: a bijection onto the square.
  std::vector<std::map<int, double>> weights(n);
  for (const auto& t : mesh.Triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      const int i = t[k], j = t[(k + 1) % 3], l = t[(k + 2) % 3];
      const double* xi = &mesh.Points[3 * i];
      const double* xj = &mesh.Points[3 * j];
      const double* xl = &mesh.Points[3 * l];
      const double dij = Norm3(xi, xj), dil = Norm3(xi, xl), djl = Norm3(xj, xl);
      const double cosine =
        std::clamp((dij * dij + dil * dil - djl * djl) / (2 * dij * dil), -1.0, 1.0);
      const double halfTan = std::tan(0.5 * std::acos(cosine));
      weights[i][j] += halfTan / dij;
      weights[i][l] += halfTan / dil;
    }
  }
  std::vector<int> index(n, -1);
  int unknowns = 0;
  for (int v = 0; v < n; ++v)
  {
    if (!fixed[v] && !weights[v].empty())
    {
      index[v] = unknowns++;
    }
  }
  if (unknowns == 0)
  {
    return true;
  }
  std::vector<Eigen::Triplet<double>> triplets;
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(unknowns, 2);
  for (int v = 0; v < n; ++v)
  {
    if (index[v] < 0)
    {
      continue;
    }
    double total = 0.0;
    for (const auto& [w, weight] : weights[v])
    {
      total += weight;
      if (index[w] >= 0)
      {
        triplets.emplace_back(index[v], index[w], -weight);
      }
      else
      {
        rhs(index[v], 0) += weight * uv[2 * w];
        rhs(index[v], 1) += weight * uv[2 * w + 1];
      }
    }
    triplets.emplace_back(index[v], index[v], total);
  }
  Eigen::SparseMatrix<double> matrix(unknowns, unknowns);
  matrix.setFromTriplets(triplets.begin(), triplets.end());
  Eigen::SparseLU<Eigen::SparseMatrix<double>> solver;
  solver.compute(matrix);
  if (solver.info() != Eigen::Success)
  {
    error = "the parameterisation's linear system could not be factorised";
    return false;
  }
  const Eigen::MatrixXd solution = solver.solve(rhs);
  if (solver.info() != Eigen::Success)
  {
    error = "the parameterisation's linear system could not be solved";
    return false;
  }
  for (int v = 0; v < n; ++v)
  {
    if (index[v] >= 0)
    {
      uv[2 * v] = solution(index[v], 0);
      uv[2 * v + 1] = solution(index[v], 1);
    }
  }
  return true;
}

GeometryImage ResampleMesh(const TriangleMesh& mesh, const std::vector<double>& uv, int width,
  int height, PixelSources* sources)
{
  GeometryImage image;
  image.Width = width;
  image.Height = height;
  const size_t pixels = static_cast<size_t>(width) * height;
  image.Position.assign(3 * pixels, 0.0f);
  image.Mask.assign(pixels, 0);
  if (sources)
  {
    sources->Triangle.assign(pixels, -1);
    sources->Barycentric.assign(3 * pixels, 0.0f);
  }
  // Bin the triangles by their (u, v) boxes on the pixel grid, then test each pixel centre.
  std::vector<std::vector<int>> bins(pixels);
  for (size_t k = 0; k < mesh.Triangles.size(); ++k)
  {
    const auto& t = mesh.Triangles[k];
    double lo[2] = { 1e300, 1e300 }, hi[2] = { -1e300, -1e300 };
    for (int v : t)
    {
      for (int c = 0; c < 2; ++c)
      {
        lo[c] = std::min(lo[c], uv[2 * v + c]);
        hi[c] = std::max(hi[c], uv[2 * v + c]);
      }
    }
    const int i0 = std::max(0, static_cast<int>(std::floor(lo[0] * width - 0.5)));
    const int i1 = std::min(width - 1, static_cast<int>(std::ceil(hi[0] * width - 0.5)));
    const int j0 = std::max(0, static_cast<int>(std::floor(lo[1] * height - 0.5)));
    const int j1 = std::min(height - 1, static_cast<int>(std::ceil(hi[1] * height - 0.5)));
    for (int j = j0; j <= j1; ++j)
    {
      for (int i = i0; i <= i1; ++i)
      {
        bins[static_cast<size_t>(j) * width + i].push_back(static_cast<int>(k));
      }
    }
  }
  for (int j = 0; j < height; ++j)
  {
    for (int i = 0; i < width; ++i)
    {
      const size_t p = static_cast<size_t>(j) * width + i;
      const double u = (i + 0.5) / width, v = (j + 0.5) / height;
      for (int k : bins[p])
      {
        const auto& t = mesh.Triangles[k];
        const double* a = &uv[2 * t[0]];
        const double* b = &uv[2 * t[1]];
        const double* c = &uv[2 * t[2]];
        const double det = (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
        if (det == 0.0)
        {
          continue;
        }
        const double beta = ((u - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (v - a[1])) / det;
        const double gamma = ((b[0] - a[0]) * (v - a[1]) - (u - a[0]) * (b[1] - a[1])) / det;
        const double alpha = 1.0 - beta - gamma;
        const double eps = -1e-9;
        if (alpha >= eps && beta >= eps && gamma >= eps)
        {
          for (int d = 0; d < 3; ++d)
          {
            image.Position[3 * p + d] = static_cast<float>(alpha * mesh.Points[3 * t[0] + d] +
              beta * mesh.Points[3 * t[1] + d] + gamma * mesh.Points[3 * t[2] + d]);
          }
          image.Mask[p] = 1;
          if (sources)
          {
            sources->Triangle[p] = k;
            sources->Barycentric[3 * p] = static_cast<float>(alpha);
            sources->Barycentric[3 * p + 1] = static_cast<float>(beta);
            sources->Barycentric[3 * p + 2] = static_cast<float>(gamma);
          }
          break;
        }
      }
    }
  }
  image.Normal = NormalsFromPositions(image);
  image.AreaWeight = ComputeAreaWeights(image);
  return image;
}

std::vector<float> NormalsFromPositions(const GeometryImage& image)
{
  std::vector<float> normals(image.Position.size(), 0.0f);
  for (int j = 0; j < image.Height; ++j)
  {
    for (int i = 0; i < image.Width; ++i)
    {
      const long long here = image.Neighbor(i, j, 0, 0);
      const auto at = [&](int di, int dj)
      {
        const long long q = image.Neighbor(i, j, di, dj);
        return q < 0 || !image.IsValid(q) ? here : q;
      };
      const long long right = at(1, 0), left = at(-1, 0), up = at(0, 1), down = at(0, -1);
      double du[3], dv[3];
      for (int c = 0; c < 3; ++c)
      {
        du[c] = image.Position[3 * right + c] - image.Position[3 * left + c];
        dv[c] = image.Position[3 * up + c] - image.Position[3 * down + c];
      }
      const double n[3] = { du[1] * dv[2] - du[2] * dv[1], du[2] * dv[0] - du[0] * dv[2],
        du[0] * dv[1] - du[1] * dv[0] };
      const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      for (int c = 0; c < 3; ++c)
      {
        normals[3 * here + c] =
          length > 0.0 ? static_cast<float>(n[c] / length) : (c == 2 ? 1.0f : 0.0f);
      }
    }
  }
  return normals;
}

} // namespace cvt
