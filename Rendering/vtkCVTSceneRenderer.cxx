#include "vtkCVTSceneRenderer.h"

#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

vtkStandardNewMacro(vtkCVTSceneRenderer);

//------------------------------------------------------------------------------
vtkImageData* vtkCVTSceneRenderer::Render(vtkImageData* labels, vtkPolyData* sites)
{
  this->LastError.clear();
  this->Picture = nullptr;
  vtkDataArray* siteIds = labels ? labels->GetPointData()->GetArray("SiteId") : nullptr;
  int dims[3] = { 0, 0, 0 };
  if (labels)
  {
    labels->GetDimensions(dims);
  }
  if (!siteIds || dims[0] < 1 || dims[1] < 1)
  {
    this->LastError = "the labels image has no SiteId array";
    return nullptr;
  }
  if (siteIds->GetNumberOfTuples() < static_cast<vtkIdType>(dims[0]) * dims[1])
  {
    this->LastError = "the labels' SiteId array is shorter than the image";
    return nullptr;
  }

  double origin[3], spacing[3];
  labels->GetOrigin(origin);
  labels->GetSpacing(spacing);
  // The domain reaches half a pixel beyond the first and last pixel centres.
  const double x0 = origin[0] - 0.5 * spacing[0], y0 = origin[1] - 0.5 * spacing[1];
  const double width = dims[0] * spacing[0];
  const double height = dims[1] * spacing[1];
  const int sizeX = width >= height
    ? this->Size
    : std::max(16, static_cast<int>(std::lround(this->Size * width / height)));
  const int sizeY = width >= height
    ? std::max(16, static_cast<int>(std::lround(this->Size * height / width)))
    : this->Size;

  // Pastel colours from a fixed seed: the same result always gives the same picture. Pixels
  // of no site (negative ids) are black.
  double range[2];
  siteIds->GetRange(range);
  const int colours = std::max(1, static_cast<int>(range[1]) + 1);
  std::vector<std::array<unsigned char, 3>> table(colours);
  std::mt19937 rng(12345);
  for (auto& colour : table)
  {
    for (unsigned char& channel : colour)
    {
      channel =
        static_cast<unsigned char>(std::lround(255.0 * (0.35 + 0.6 * (rng() % 1000) / 1000.0)));
    }
  }

  // Drawn on the CPU, not rendered: a flat picture needs no OpenGL, so it costs a few
  // milliseconds instead of a context and a shader compile, and looks the same everywhere.
  vtkNew<vtkUnsignedCharArray> pixels;
  pixels->SetNumberOfComponents(3);
  pixels->SetNumberOfTuples(static_cast<vtkIdType>(sizeX) * sizeY);
  unsigned char* rgb = pixels->GetPointer(0);
  std::fill(rgb, rgb + 3 * static_cast<size_t>(sizeX) * sizeY, 255);
  if (this->ShowCells)
  {
    // Each picture pixel takes the label of the labels pixel under its centre.
    std::vector<int> column(sizeX);
    for (int px = 0; px < sizeX; ++px)
    {
      column[px] = std::min(dims[0] - 1, static_cast<int>((px + 0.5) * dims[0] / sizeX));
    }
    for (int py = 0; py < sizeY; ++py)
    {
      const int row = std::min(dims[1] - 1, static_cast<int>((py + 0.5) * dims[1] / sizeY));
      for (int px = 0; px < sizeX; ++px)
      {
        const double id = siteIds->GetTuple1(column[px] + static_cast<vtkIdType>(row) * dims[0]);
        unsigned char* pixel = rgb + 3 * (px + static_cast<size_t>(py) * sizeX);
        const auto& colour = table[std::clamp(static_cast<int>(id), 0, colours - 1)];
        for (int c = 0; c < 3; ++c)
        {
          pixel[c] = id < 0 ? 0 : colour[c];
        }
      }
    }
  }

  // Sites: round dots of PointSize pixels across, centred where the site falls in the picture,
  // their rims blended by the share of each pixel they cover (no jagged or lost dots).
  const vtkIdType numberOfSites = sites ? sites->GetNumberOfPoints() : 0;
  const double radius = 0.5 * this->PointSize;
  const double dotColour = 13.0;
  for (vtkIdType s = 0; s < numberOfSites && radius > 0.0; ++s)
  {
    double p[3];
    sites->GetPoint(s, p);
    const double cx = (p[0] - x0) / width * sizeX, cy = (p[1] - y0) / height * sizeY;
    const int xFirst = std::max(0, static_cast<int>(std::floor(cx - radius)));
    const int xLast = std::min(sizeX - 1, static_cast<int>(std::ceil(cx + radius)));
    const int yFirst = std::max(0, static_cast<int>(std::floor(cy - radius)));
    const int yLast = std::min(sizeY - 1, static_cast<int>(std::ceil(cy + radius)));
    for (int py = yFirst; py <= yLast; ++py)
    {
      for (int px = xFirst; px <= xLast; ++px)
      {
        const double distance = std::hypot(px + 0.5 - cx, py + 0.5 - cy);
        const double cover = std::clamp(radius + 0.5 - distance, 0.0, 1.0);
        unsigned char* pixel = rgb + 3 * (px + static_cast<size_t>(py) * sizeX);
        for (int c = 0; c < 3; ++c)
        {
          pixel[c] =
            static_cast<unsigned char>(std::lround(cover * dotColour + (1.0 - cover) * pixel[c]));
        }
      }
    }
  }

  return this->KeepPicture(pixels, sizeX, sizeY);
}

//------------------------------------------------------------------------------
vtkImageData* vtkCVTSceneRenderer::KeepPicture(vtkUnsignedCharArray* pixels, int width, int height)
{
  // A new image each time: a caller may still hold the previous picture.
  this->Picture = vtkSmartPointer<vtkImageData>::New();
  this->Picture->SetDimensions(width, height, 1);
  pixels->SetName("RGB");
  this->Picture->GetPointData()->SetScalars(pixels);
  return this->Picture;
}

//------------------------------------------------------------------------------
namespace
{
/// The principal axes of a mesh's surface, longest first (unit columns of `axes`), from the
/// area-weighted second moments of its polygons (fans), and the middle of its extent along them.
/// A curved or tilted open sheet is thinnest along its best-fit plane's normal, which an
/// axis-aligned box misses. The thinnest axis points the way the surface's normals mostly face,
/// so an open sheet is seen from its front. False when the polygons have no area.
bool PrincipalAxes(vtkPolyData* mesh, double axes[3][3], double center[3], double extent[3])
{
  double bounds[6];
  mesh->GetBounds(bounds);
  // Moments about the box's middle: no cancellation far from the origin.
  const double origin[3] = { 0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
    0.5 * (bounds[4] + bounds[5]) };
  double area = 0.0, first[3] = { 0.0, 0.0, 0.0 }, second[3][3] = {}, normals[3] = {};
  vtkCellArray* polys = mesh->GetPolys();
  vtkIdType cellSize = 0;
  const vtkIdType* cell = nullptr;
  for (polys->InitTraversal(); polys->GetNextCell(cellSize, cell);)
  {
    for (vtkIdType corner = 1; corner + 1 < cellSize; ++corner)
    {
      double x[3][3], e1[3], e2[3], normal[3], sum[3];
      const vtkIdType ids[3] = { cell[0], cell[corner], cell[corner + 1] };
      for (int v = 0; v < 3; ++v)
      {
        mesh->GetPoint(ids[v], x[v]);
        vtkMath::Subtract(x[v], origin, x[v]);
      }
      vtkMath::Subtract(x[1], x[0], e1);
      vtkMath::Subtract(x[2], x[0], e2);
      vtkMath::Cross(e1, e2, normal);
      const double a = 0.5 * vtkMath::Norm(normal);
      area += a;
      for (int i = 0; i < 3; ++i)
      {
        normals[i] += 0.5 * normal[i];
        sum[i] = x[0][i] + x[1][i] + x[2][i];
        first[i] += a * sum[i] / 3.0;
      }
      // The integral of x x^T over a triangle: A / 12 (sum of v v^T + s s^T), s = sum of v.
      for (int i = 0; i < 3; ++i)
      {
        for (int j = 0; j < 3; ++j)
        {
          double corners = sum[i] * sum[j];
          for (int v = 0; v < 3; ++v)
          {
            corners += x[v][i] * x[v][j];
          }
          second[i][j] += a / 12.0 * corners;
        }
      }
    }
  }
  if (!(area > 0.0))
  {
    return false;
  }
  double covariance[3][3], eigenvalues[3], eigenvectors[3][3];
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      covariance[i][j] = second[i][j] / area - first[i] * first[j] / (area * area);
    }
  }
  double* rows[3] = { covariance[0], covariance[1], covariance[2] };
  double* vectorRows[3] = { eigenvectors[0], eigenvectors[1], eigenvectors[2] };
  vtkMath::Jacobi(rows, eigenvalues, vectorRows); // decreasing, vectors in columns
  for (int axis = 0; axis < 3; ++axis)
  {
    for (int k = 0; k < 3; ++k)
    {
      axes[axis][k] = eigenvectors[k][axis];
    }
  }
  if (vtkMath::Dot(axes[2], normals) < 0.0)
  {
    vtkMath::MultiplyScalar(axes[2], -1.0);
  }
  // The extent along each axis of the points the polygons use.
  double low[3], high[3];
  std::fill(low, low + 3, VTK_DOUBLE_MAX);
  std::fill(high, high + 3, -VTK_DOUBLE_MAX);
  for (polys->InitTraversal(); polys->GetNextCell(cellSize, cell);)
  {
    for (vtkIdType corner = 0; corner < cellSize; ++corner)
    {
      double x[3];
      mesh->GetPoint(cell[corner], x);
      for (int axis = 0; axis < 3; ++axis)
      {
        const double along = vtkMath::Dot(x, axes[axis]);
        low[axis] = std::min(low[axis], along);
        high[axis] = std::max(high[axis], along);
      }
    }
  }
  for (int k = 0; k < 3; ++k)
  {
    center[k] = 0.0;
  }
  for (int axis = 0; axis < 3; ++axis)
  {
    extent[axis] = high[axis] - low[axis];
    for (int k = 0; k < 3; ++k)
    {
      center[k] += 0.5 * (low[axis] + high[axis]) * axes[axis][k];
    }
  }
  return true;
}

/// Points a camera at a mesh of any shape, size and orientation: mostly along its thinnest
/// principal axis (the largest face in view), tilted so relief shows, the longest axis across
/// the (landscape) picture of width / height `aspect`; the distance is the least at which every
/// point lies within PictureFill of the picture's half-width and half-height from its middle.
/// (Fitting the bounding sphere, as vtkRenderer::ResetCamera does, zoomed by 1.3 so that long
/// shapes filled the picture, cut the top off every cube: 7 of 133 CGAL meshes.) `direction`
/// receives the unit vector towards the camera.
void FitCamera(vtkPolyData* mesh, vtkCamera* camera, double aspect, double direction[3])
{
  constexpr double PictureFill = 0.9;
  double axes[3][3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } }, center[3], extent[3];
  if (!PrincipalAxes(mesh, axes, center, extent))
  {
    // No area (every polygon degenerate): the bounding box, along the coordinate axes.
    double bounds[6];
    mesh->GetBounds(bounds);
    for (int k = 0; k < 3; ++k)
    {
      center[k] = 0.5 * (bounds[2 * k] + bounds[2 * k + 1]);
      extent[k] = bounds[2 * k + 1] - bounds[2 * k];
    }
  }
  double up[3];
  for (int k = 0; k < 3; ++k)
  {
    direction[k] = axes[2][k] - 0.6 * axes[1][k];
    up[k] = axes[1][k];
  }
  vtkMath::Normalize(direction);
  const double radius = std::max(0.5 * vtkMath::Norm(extent), 1e-12);
  // The picture's axes: up (made normal to the direction) and across.
  double across[3];
  vtkMath::Cross(up, direction, across);
  vtkMath::Normalize(across);
  vtkMath::Cross(direction, across, up);
  // A point at depth z towards the camera, x across and y up from the middle, lies within the
  // fill where (distance - z) tan(half the view angle) fill is at least |y| and |x| / aspect.
  const double reach =
    std::tan(0.5 * vtkMath::RadiansFromDegrees(camera->GetViewAngle())) * PictureFill;
  double distance = 1e-3 * radius;
  for (vtkIdType p = 0; p < mesh->GetNumberOfPoints(); ++p)
  {
    double q[3];
    mesh->GetPoint(p, q);
    vtkMath::Subtract(q, center, q);
    const double half =
      std::max(std::abs(vtkMath::Dot(q, up)), std::abs(vtkMath::Dot(q, across)) / aspect);
    distance = std::max(distance, vtkMath::Dot(q, direction) + half / reach);
  }
  camera->SetFocalPoint(center);
  camera->SetPosition(center[0] + distance * direction[0], center[1] + distance * direction[1],
    center[2] + distance * direction[2]);
  camera->SetViewUp(up);
  camera->OrthogonalizeViewUp();
  camera->SetClippingRange(
    std::max(1e-3 * distance, distance - 1.01 * radius), distance + 1.01 * radius);
}

/// A z-buffered RGB picture of flat triangles with dark edges, drawn on the CPU.
class TriangleRaster
{
public:
  using Corner = std::array<double, 3>; // picture x, y (pixels) and depth (smaller is nearer)

  TriangleRaster(int width, int height, unsigned char* rgb)
    : Width(width)
    , Height(height)
    , RGB(rgb)
    , Depth(static_cast<size_t>(width) * height, 2.0)
  {
    std::fill(rgb, rgb + 3 * static_cast<size_t>(width) * height, 255);
  }

  /// Draws triangle a, b, c in `colour` where it is nearest; pixels within EdgeHalfWidth of an
  /// edge that `outline` flags (edge i is opposite corner i) take the edge colour instead, so
  /// each side of an edge draws half the line and hidden edges stay hidden.
  void Fill(const Corner& a, const Corner& b, const Corner& c, const bool outline[3],
    const unsigned char colour[3])
  {
    const double area = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    if (area == 0.0)
    {
      return;
    }
    const Corner* corners[3] = { &a, &b, &c };
    double edgeLength[3];
    for (int i = 0; i < 3; ++i)
    {
      const Corner& p = *corners[(i + 1) % 3];
      const Corner& q = *corners[(i + 2) % 3];
      edgeLength[i] = std::hypot(q[0] - p[0], q[1] - p[1]);
    }
    const int xFirst = std::max(0, static_cast<int>(std::floor(std::min({ a[0], b[0], c[0] }))));
    const int xLast =
      std::min(this->Width - 1, static_cast<int>(std::ceil(std::max({ a[0], b[0], c[0] }))));
    const int yFirst = std::max(0, static_cast<int>(std::floor(std::min({ a[1], b[1], c[1] }))));
    const int yLast =
      std::min(this->Height - 1, static_cast<int>(std::ceil(std::max({ a[1], b[1], c[1] }))));
    for (int py = yFirst; py <= yLast; ++py)
    {
      for (int px = xFirst; px <= xLast; ++px)
      {
        // Barycentric weights of the pixel centre: edge i's function over the area, positive
        // inside; times |area| it is the distance to the edge times the edge's length.
        const double sx = px + 0.5, sy = py + 0.5;
        double lambda[3];
        bool inside = true;
        for (int i = 0; i < 3; ++i)
        {
          const Corner& p = *corners[(i + 1) % 3];
          const Corner& q = *corners[(i + 2) % 3];
          lambda[i] = ((q[0] - p[0]) * (sy - p[1]) - (q[1] - p[1]) * (sx - p[0])) / area;
          inside = inside && lambda[i] >= 0.0;
        }
        const size_t pixel = px + static_cast<size_t>(py) * this->Width;
        const double z = lambda[0] * a[2] + lambda[1] * b[2] + lambda[2] * c[2];
        if (!inside || z >= this->Depth[pixel] || z < -1.0)
        {
          continue;
        }
        this->Depth[pixel] = z;
        bool onEdge = false;
        for (int i = 0; i < 3; ++i)
        {
          onEdge =
            onEdge || (outline[i] && lambda[i] * std::abs(area) < EdgeHalfWidth * edgeLength[i]);
        }
        for (int k = 0; k < 3; ++k)
        {
          this->RGB[3 * pixel + k] = onEdge ? EdgeColour : colour[k];
        }
      }
    }
  }

private:
  static constexpr double EdgeHalfWidth = 0.7; // pixels
  static constexpr unsigned char EdgeColour = 25;
  int Width, Height;
  unsigned char* RGB;
  std::vector<double> Depth;
};
}

//------------------------------------------------------------------------------
vtkImageData* vtkCVTSceneRenderer::RenderMesh(vtkPolyData* mesh)
{
  this->LastError.clear();
  this->Picture = nullptr;
  if (!mesh || mesh->GetNumberOfPolys() == 0 || !mesh->GetPoints())
  {
    this->LastError = "the mesh has no triangles";
    return nullptr;
  }
  const int width = this->Size, height = (this->Size * 3) / 4;
  double direction[3];
  vtkNew<vtkCamera> camera;
  FitCamera(mesh, camera, static_cast<double>(width) / height, direction);
  vtkMatrix4x4* toView =
    camera->GetCompositeProjectionTransformMatrix(static_cast<double>(width) / height, -1.0, 1.0);
  const vtkIdType pointCount = mesh->GetNumberOfPoints();
  std::vector<TriangleRaster::Corner> screen(pointCount);
  std::vector<char> inFront(pointCount);
  for (vtkIdType p = 0; p < pointCount; ++p)
  {
    double world[4] = { 0.0, 0.0, 0.0, 1.0 }, view[4];
    mesh->GetPoint(p, world);
    toView->MultiplyPoint(world, view);
    inFront[p] = view[3] > 0.0;
    if (inFront[p])
    {
      screen[p] = { 0.5 * (view[0] / view[3] + 1.0) * width,
        0.5 * (view[1] / view[3] + 1.0) * height, view[2] / view[3] };
    }
  }

  // Drawn on the CPU, not rendered: each triangle in its own pastel colour (fixed seed), lit by
  // a light at the camera (both sides), its edges dark. It needs no OpenGL, costs milliseconds
  // instead of a context and a shader compile (0.3 s on llvmpipe), and gives the same picture
  // on every machine.
  vtkNew<vtkUnsignedCharArray> pixels;
  pixels->SetNumberOfComponents(3);
  pixels->SetNumberOfTuples(static_cast<vtkIdType>(width) * height);
  TriangleRaster raster(width, height, pixels->GetPointer(0));
  std::mt19937 rng(12345);
  vtkCellArray* polys = mesh->GetPolys();
  vtkIdType cellSize = 0;
  const vtkIdType* cell = nullptr;
  for (polys->InitTraversal(); polys->GetNextCell(cellSize, cell);)
  {
    double pastel[3];
    for (double& channel : pastel)
    {
      channel = 90 + rng() % 150;
    }
    for (vtkIdType corner = 1; corner + 1 < cellSize; ++corner)
    {
      // A polygon is drawn as a fan; only its outline is an edge.
      const vtkIdType ids[3] = { cell[0], cell[corner], cell[corner + 1] };
      const bool outline[3] = { true, corner + 2 == cellSize, corner == 1 };
      if (!inFront[ids[0]] || !inFront[ids[1]] || !inFront[ids[2]])
      {
        continue;
      }
      double x[3][3], e1[3], e2[3], normal[3];
      for (int v = 0; v < 3; ++v)
      {
        mesh->GetPoint(ids[v], x[v]);
      }
      for (int k = 0; k < 3; ++k)
      {
        e1[k] = x[1][k] - x[0][k];
        e2[k] = x[2][k] - x[0][k];
      }
      vtkMath::Cross(e1, e2, normal);
      const double norm = vtkMath::Norm(normal);
      const double light = norm > 0.0 ? std::abs(vtkMath::Dot(normal, direction)) / norm : 0.0;
      unsigned char colour[3];
      for (int k = 0; k < 3; ++k)
      {
        colour[k] = static_cast<unsigned char>(std::lround((0.25 + 0.75 * light) * pastel[k]));
      }
      raster.Fill(screen[ids[0]], screen[ids[1]], screen[ids[2]], outline, colour);
    }
  }
  return this->KeepPicture(pixels, width, height);
}

//------------------------------------------------------------------------------
void vtkCVTSceneRenderer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Size: " << this->Size << "\n";
  os << indent << "ShowCells: " << this->ShowCells << "\n";
  os << indent << "PointSize: " << this->PointSize << "\n";
  os << indent << "Picture: " << (this->Picture ? "the last render's" : "(none)") << "\n";
}
