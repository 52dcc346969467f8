#include "cvtSurface.h"

#include "cvtGeometry.h"
#include "cvtPointCloud.h"
#include "cvtSampling.h"

#include "cvtThreads.h"

#include <cstdint>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <set>
#include <sstream>
#include <unordered_set>

namespace cvt
{

namespace
{
using Vec3 = std::array<double, 3>;

Vec3 At(const std::vector<float>& values, long long p)
{
  return { values[3 * p], values[3 * p + 1], values[3 * p + 2] };
}
Vec3 Sub(const Vec3& a, const Vec3& b)
{
  return { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
}
double Dot(const Vec3& a, const Vec3& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
Vec3 Cross(const Vec3& a, const Vec3& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}
double Distance2(const Vec3& a, const Vec3& b)
{
  const Vec3 d = Sub(a, b);
  return Dot(d, d);
}

/// The four pixels of the quad whose lower-left corner is (i, j), counter-clockwise in (u, v);
/// false when the quad leaves the image or touches a masked pixel.
bool Quad(const GeometryImage& image, int i, int j, long long quad[4])
{
  quad[0] = image.Neighbor(i, j, 0, 0);
  quad[1] = image.Neighbor(i, j, 1, 0);
  quad[2] = image.Neighbor(i, j, 1, 1);
  quad[3] = image.Neighbor(i, j, 0, 1);
  for (int k = 0; k < 4; ++k)
  {
    if (quad[k] < 0 || !image.IsValid(quad[k]))
    {
      return false;
    }
  }
  return true;
}
}

long long GeometryImage::Neighbor(int i, int j, int di, int dj) const
{
  int u = i + di, v = j + dj;
  if (this->WrapU)
  {
    u = ((u % this->Width) + this->Width) % this->Width;
  }
  if (this->WrapV)
  {
    v = ((v % this->Height) + this->Height) % this->Height;
  }
  if (u < 0 || v < 0 || u >= this->Width || v >= this->Height)
  {
    return -1;
  }
  return static_cast<long long>(v) * this->Width + u;
}

std::vector<float> ComputeAreaWeights(const GeometryImage& image)
{
  std::vector<double> weights(static_cast<size_t>(image.NumberOfPixels()), 0.0);
  long long quad[4];
  for (int j = 0; j < image.Height; ++j)
  {
    for (int i = 0; i < image.Width; ++i)
    {
      if (!Quad(image, i, j, quad))
      {
        continue;
      }
      // Triangles (0, 1, 2) and (0, 2, 3): a third of each area to each corner.
      const int triangles[2][3] = { { 0, 1, 2 }, { 0, 2, 3 } };
      for (const auto& t : triangles)
      {
        const Vec3 a = At(image.Position, quad[t[0]]), b = At(image.Position, quad[t[1]]),
                   c = At(image.Position, quad[t[2]]);
        const Vec3 n = Cross(Sub(b, a), Sub(c, a));
        const double third = 0.5 * std::sqrt(Dot(n, n)) / 3.0;
        for (int k : t)
        {
          weights[quad[k]] += third;
        }
      }
    }
  }
  return std::vector<float>(weights.begin(), weights.end());
}

std::string CheckGeometryImage(const GeometryImage& image, int numberOfSites)
{
  const long long pixels = image.NumberOfPixels();
  if (image.Width < 2 || image.Height < 2)
  {
    return "the geometry image needs at least 2 x 2 pixels";
  }
  if (static_cast<long long>(image.Position.size()) != 3 * pixels)
  {
    return "the geometry image has no 3-component position per pixel";
  }
  if (static_cast<long long>(image.Normal.size()) != 3 * pixels)
  {
    return "the geometry image has no 3-component normal per pixel";
  }
  if (static_cast<long long>(image.AreaWeight.size()) != pixels)
  {
    return "the geometry image has no area weight per pixel";
  }
  if (!image.Mask.empty() && static_cast<long long>(image.Mask.size()) != pixels)
  {
    return "the geometry image's mask does not hold one value per pixel";
  }
  if (!image.SeamPartner.empty() && static_cast<long long>(image.SeamPartner.size()) != pixels)
  {
    return "the geometry image's seam partners do not hold one value per pixel";
  }
  if (!image.Border.empty() && static_cast<long long>(image.Border.size()) != pixels)
  {
    return "the geometry image's border marks do not hold one value per pixel";
  }
  for (size_t p = 0; p < image.SeamPartner.size(); ++p)
  {
    const int partner = image.SeamPartner[p];
    if (partner < -1 || partner >= pixels || (partner >= 0 && !image.IsValid(partner)))
    {
      std::ostringstream msg;
      msg << "pixel " << p << " has a seam partner (" << partner
          << ") that is not a valid pixel of the image";
      return msg.str();
    }
  }
  long long valid = 0;
  for (long long p = 0; p < pixels; ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      if (!std::isfinite(image.Position[3 * p + c]) || !std::isfinite(image.Normal[3 * p + c]))
      {
        std::ostringstream msg;
        msg << "pixel " << p << " has a position or normal that is not finite (NaN)";
        return msg.str();
      }
    }
    if (!std::isfinite(image.AreaWeight[p]) || image.AreaWeight[p] < 0.0f)
    {
      std::ostringstream msg;
      msg << "pixel " << p << " has a negative or non-finite area weight";
      return msg.str();
    }
    valid += image.IsValid(p) ? 1 : 0;
  }
  if (numberOfSites <= 0)
  {
    return "there are no sites; ask for at least one";
  }
  if (valid < numberOfSites)
  {
    std::ostringstream msg;
    msg << "the mask leaves " << valid << " pixels on the surface, fewer than the " << numberOfSites
        << " sites; use fewer sites or a finer geometry image";
    return msg.str();
  }
  return std::string();
}

std::vector<double> SampleSurfaceSites(
  const GeometryImage& image, int count, std::uint64_t seed, std::vector<long long>& pixels)
{
  std::mt19937_64 rng(seed);
  const auto uniform = [&rng]() { return Uniform01(rng); };
  const long long n = image.NumberOfPixels();
  std::vector<double> cumulative(static_cast<size_t>(n));
  double total = 0.0;
  for (long long p = 0; p < n; ++p)
  {
    total += image.IsValid(p) ? image.AreaWeight[p] : 0.0;
    cumulative[p] = total;
  }
  std::vector<double> sites;
  pixels.clear();
  std::unordered_set<long long> taken;
  for (int attempt = 0; static_cast<int>(pixels.size()) < count && attempt < 100 * count + 1000;
       ++attempt)
  {
    long long p = std::upper_bound(cumulative.begin(), cumulative.end(), uniform() * total) -
      cumulative.begin();
    p = std::min(p, n - 1);
    if (!image.IsValid(p) || !taken.insert(p).second)
    {
      continue; // one site per pixel: sites never coincide
    }
    pixels.push_back(p);
    for (int c = 0; c < 3; ++c)
    {
      sites.push_back(image.Position[3 * p + c]);
    }
  }
  return sites;
}

void NearestPointsInCells(const GeometryImage& image, const std::vector<int>& labels,
  const std::vector<double>& targets, std::vector<double>& sites, std::vector<long long>& pixels)
{
  const size_t n = targets.size() / 3;
  std::vector<double> best(n, std::numeric_limits<double>::infinity());
  long long quad[4];
  for (int j = 0; j < image.Height; ++j)
  {
    for (int i = 0; i < image.Width; ++i)
    {
      const long long p = static_cast<long long>(j) * image.Width + i;
      const int label = labels[p];
      if (label < 0 || !image.IsValid(p) || !Quad(image, i, j, quad))
      {
        continue;
      }
      const Vec3 target{ targets[3 * label], targets[3 * label + 1], targets[3 * label + 2] };
      const int triangles[2][3] = { { 0, 1, 2 }, { 0, 2, 3 } };
      for (const auto& t : triangles)
      {
        const Vec3 a = At(image.Position, quad[t[0]]), b = At(image.Position, quad[t[1]]),
                   c = At(image.Position, quad[t[2]]);
        Vec3 q, weights;
        ClosestPointOnTriangle(
          target.data(), a.data(), b.data(), c.data(), q.data(), weights.data());
        const double d2 = Distance2(q, target);
        if (d2 < best[label])
        {
          best[label] = d2;
          for (int k = 0; k < 3; ++k)
          {
            sites[3 * label + k] = q[k];
          }
          // The pixel holding the site: the triangle corner nearest to it.
          long long nearest = quad[t[0]];
          for (int k : t)
          {
            if (Distance2(At(image.Position, quad[k]), q) <
              Distance2(At(image.Position, nearest), q))
            {
              nearest = quad[k];
            }
          }
          pixels[label] = nearest;
        }
      }
    }
  }
}

std::vector<std::array<int, 3>> DualTriangles(
  const GeometryImage& image, const std::vector<int>& labels, const std::vector<double>& sites)
{
  std::vector<std::array<int, 3>> triangles;
  std::set<std::array<int, 3>> seen;
  const auto add = [&](int a, int b, int c)
  {
    std::array<int, 3> key{ a, b, c };
    std::sort(key.begin(), key.end());
    if (key[0] != key[1] && key[1] != key[2] && seen.insert(key).second)
    {
      triangles.push_back({ a, b, c });
    }
  };
  const auto site = [&sites](int s) {
    return Vec3{ sites[3 * s], sites[3 * s + 1], sites[3 * s + 2] };
  };
  // One triangle per three labels round a corner (two, split along the shorter diagonal, for
  // four); `normal`, when given, is the surface's side: the triangle is turned to face it.
  const auto corner = [&](const long long quad[4], const Vec3* normal)
  {
    // Labels around the corner, counter-clockwise, consecutive repeats merged.
    std::vector<int> ring;
    for (int k = 0; k < 4; ++k)
    {
      const int label = labels[quad[k]];
      if (label < 0)
      {
        return;
      }
      if (ring.empty() || ring.back() != label)
      {
        ring.push_back(label);
      }
    }
    if (ring.size() > 1 && ring.front() == ring.back())
    {
      ring.pop_back();
    }
    const auto facing = [&](int a, int b, int c)
    {
      if (normal && Dot(Cross(Sub(site(b), site(a)), Sub(site(c), site(a))), *normal) < 0.0)
      {
        std::swap(b, c);
      }
      add(a, b, c);
    };
    if (ring.size() == 3)
    {
      facing(ring[0], ring[1], ring[2]);
    }
    else if (ring.size() == 4 && ring[0] != ring[2] && ring[1] != ring[3])
    {
      if (Distance2(site(ring[0]), site(ring[2])) <= Distance2(site(ring[1]), site(ring[3])))
      {
        facing(ring[0], ring[1], ring[2]);
        facing(ring[0], ring[2], ring[3]);
      }
      else
      {
        facing(ring[0], ring[1], ring[3]);
        facing(ring[1], ring[2], ring[3]);
      }
    }
  };
  long long quad[4];
  for (int j = 0; j < image.Height; ++j)
  {
    for (int i = 0; i < image.Width; ++i)
    {
      if (Quad(image, i, j, quad))
      {
        corner(quad, nullptr);
      }
    }
  }
  // Across an atlas's seams: two neighbouring border pixels and their partners in the other
  // chart make a corner too.
  for (long long p = 0; p < static_cast<long long>(image.SeamPartner.size()); ++p)
  {
    const int i = static_cast<int>(p % image.Width), j = static_cast<int>(p / image.Width);
    if (image.SeamPartner[p] < 0)
    {
      continue;
    }
    const Vec3 normal = At(image.Normal, p);
    for (const long long next : { image.Neighbor(i, j, 1, 0), image.Neighbor(i, j, 0, 1) })
    {
      if (next >= 0 && image.IsValid(next) && image.SeamPartner[next] >= 0)
      {
        const long long across[4] = { p, next, image.SeamPartner[next], image.SeamPartner[p] };
        corner(across, &normal);
      }
    }
  }
  return triangles;
}

void GeometryImageMesh(const GeometryImage& image, int stride, std::vector<double>& points,
  std::vector<std::array<int, 3>>& triangles, std::vector<long long>* pixels)
{
  stride = std::max(1, stride);
  // The sampled columns and rows; the last one too when the border is not identified.
  const auto samples = [stride](int size, bool wrap)
  {
    std::vector<int> at;
    for (int k = 0; k < size; k += stride)
    {
      at.push_back(k);
    }
    if (!wrap && at.back() != size - 1)
    {
      at.push_back(size - 1);
    }
    return at;
  };
  const std::vector<int> columns = samples(image.Width, image.WrapU);
  const std::vector<int> rows = samples(image.Height, image.WrapV);
  const int nu = static_cast<int>(columns.size()), nv = static_cast<int>(rows.size());
  std::vector<int> index(static_cast<size_t>(nu) * nv, -1);
  points.clear();
  triangles.clear();
  if (pixels)
  {
    pixels->clear();
  }
  for (int b = 0; b < nv; ++b)
  {
    for (int a = 0; a < nu; ++a)
    {
      const long long p = static_cast<long long>(rows[b]) * image.Width + columns[a];
      if (image.IsValid(p))
      {
        index[static_cast<size_t>(b) * nu + a] = static_cast<int>(points.size() / 3);
        points.insert(points.end(), &image.Position[3 * p], &image.Position[3 * p] + 3);
        if (pixels)
        {
          pixels->push_back(p);
        }
      }
    }
  }
  const int quadsU = image.WrapU ? nu : nu - 1, quadsV = image.WrapV ? nv : nv - 1;
  for (int b = 0; b < quadsV; ++b)
  {
    for (int a = 0; a < quadsU; ++a)
    {
      const int a1 = (a + 1) % nu, b1 = (b + 1) % nv;
      const int p00 = index[static_cast<size_t>(b) * nu + a];
      const int p10 = index[static_cast<size_t>(b) * nu + a1];
      const int p11 = index[static_cast<size_t>(b1) * nu + a1];
      const int p01 = index[static_cast<size_t>(b1) * nu + a];
      if (p00 >= 0 && p10 >= 0 && p11 >= 0)
      {
        triangles.push_back({ p00, p10, p11 });
      }
      if (p00 >= 0 && p11 >= 0 && p01 >= 0)
      {
        triangles.push_back({ p00, p11, p01 });
      }
    }
  }
}

std::vector<int> NearestSiteLabels(const GeometryImage& image, const std::vector<double>& sites)
{
  std::vector<int> labels(static_cast<size_t>(image.NumberOfPixels()), -1);
  if (sites.size() < 3)
  {
    return labels;
  }
  PointCloud<3> cloud;
  cloud.Points = &sites;
  const PointTree<3> tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
  cvt::For(0, image.NumberOfPixels(), 4096,
    [&](long long first, long long last)
    {
      for (long long p = first; p < last; ++p)
      {
        if (!image.IsValid(p))
        {
          continue;
        }
        const double x[3] = { image.Position[3 * p], image.Position[3 * p + 1],
          image.Position[3 * p + 2] };
        std::uint32_t id = 0;
        double d2 = 0.0;
        tree.knnSearch(x, 1, &id, &d2);
        labels[p] = static_cast<int>(id);
      }
    });
  return labels;
}

} // namespace cvt
