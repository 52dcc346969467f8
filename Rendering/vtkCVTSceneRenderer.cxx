#include "vtkCVTSceneRenderer.h"

#include "vtkActor.h"
#include "vtkCVTOpenGLContext.h"
#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
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
vtkImageData* vtkCVTSceneRenderer::Snapshot(vtkRenderer* renderer, int width, int height)
{
  vtkNew<vtkCVTOpenGLContext> context;
  if (!context->Initialize())
  {
    this->LastError = context->GetLastError();
    return nullptr;
  }
  context->MakeCurrent();
  vtkOpenGLRenderWindow* window = context->GetRenderWindow();
  window->SetSize(width, height);
  window->AddRenderer(renderer);
  window->Render();
  vtkNew<vtkUnsignedCharArray> pixels;
  window->GetPixelData(0, 0, width - 1, height - 1, 0, pixels, 0);
  window->RemoveRenderer(renderer);
  renderer->ReleaseGraphicsResources(window);
  context->RestorePrevious();
  return this->KeepPicture(pixels, width, height);
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
vtkImageData* vtkCVTSceneRenderer::RenderMesh(vtkPolyData* mesh)
{
  this->LastError.clear();
  this->Picture = nullptr;
  if (!mesh || mesh->GetNumberOfPolys() == 0)
  {
    this->LastError = "the mesh has no triangles";
    return nullptr;
  }

  // One pastel colour per triangle, from a fixed seed.
  vtkNew<vtkPolyData> coloured;
  coloured->ShallowCopy(mesh);
  vtkNew<vtkUnsignedCharArray> colours;
  colours->SetName("Colour");
  colours->SetNumberOfComponents(3);
  std::mt19937 rng(12345);
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    colours->InsertNextTuple3(90 + rng() % 150, 90 + rng() % 150, 90 + rng() % 150);
  }
  coloured->GetCellData()->SetScalars(colours);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(coloured);
  mapper->SetScalarModeToUseCellData();
  mapper->SetColorModeToDirectScalars();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->EdgeVisibilityOn();
  actor->GetProperty()->SetEdgeColor(0.1, 0.1, 0.1);

  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(1.0, 1.0, 1.0);
  renderer->AddActor(actor);
  // Any surface, any size: look mostly along the box's thinnest axis (the largest face in
  // view), tilted so relief shows, with the longest axis across the (landscape) picture.
  vtkCamera* camera = renderer->GetActiveCamera();
  double bounds[6];
  mesh->GetBounds(bounds);
  const double center[3] = { 0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
    0.5 * (bounds[4] + bounds[5]) };
  int axes[3] = { 0, 1, 2 }; // thinnest, middle, longest
  std::sort(axes, axes + 3,
    [&bounds](int a, int b)
    { return bounds[2 * a + 1] - bounds[2 * a] < bounds[2 * b + 1] - bounds[2 * b]; });
  double direction[3] = { 0.0, 0.0, 0.0 }, up[3] = { 0.0, 0.0, 0.0 };
  direction[axes[0]] = 1.0;
  direction[axes[1]] = -0.6;
  up[axes[1]] = 1.0;
  camera->SetFocalPoint(center);
  camera->SetPosition(center[0] + direction[0], center[1] + direction[1], center[2] + direction[2]);
  camera->SetViewUp(up);
  camera->OrthogonalizeViewUp();
  renderer->ResetCamera();
  camera->Zoom(1.3);
  return this->Snapshot(renderer, this->Size, (this->Size * 3) / 4);
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
