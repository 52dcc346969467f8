#include "vtkCVTSceneRenderer.h"

#include "vtkActor.h"
#include "vtkCVTOpenGLContext.h"
#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkImageActor.h"
#include "vtkImageData.h"
#include "vtkImageMapToColors.h"
#include "vtkImageMapper3D.h"
#include "vtkLookupTable.h"
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
#include <cmath>
#include <random>

vtkStandardNewMacro(vtkCVTSceneRenderer);

//------------------------------------------------------------------------------
vtkImageData* vtkCVTSceneRenderer::Render(vtkImageData* labels, vtkPolyData* sites)
{
  this->LastError.clear();
  this->Picture = nullptr;
  if (!labels || !labels->GetPointData()->GetArray("SiteId"))
  {
    this->LastError = "the labels image has no SiteId array";
    return nullptr;
  }

  double bounds[6];
  labels->GetBounds(bounds);
  double spacing[3];
  labels->GetSpacing(spacing);
  // The domain reaches half a pixel beyond the first and last pixel centres.
  const double width = bounds[1] - bounds[0] + spacing[0];
  const double height = bounds[3] - bounds[2] + spacing[1];
  const int sizeX = width >= height
    ? this->Size
    : std::max(16, static_cast<int>(std::lround(this->Size * width / height)));
  const int sizeY = width >= height
    ? std::max(16, static_cast<int>(std::lround(this->Size * height / width)))
    : this->Size;

  // Pastel colours from a fixed seed: the same result always gives the same picture.
  double range[2];
  labels->GetPointData()->GetArray("SiteId")->GetRange(range);
  const int colours = std::max(1, static_cast<int>(range[1]) + 1);
  vtkNew<vtkLookupTable> table;
  table->SetNumberOfTableValues(colours);
  table->SetTableRange(0, colours - 1);
  std::mt19937 rng(12345);
  for (int i = 0; i < colours; ++i)
  {
    table->SetTableValue(i, 0.35 + 0.6 * (rng() % 1000) / 1000.0,
      0.35 + 0.6 * (rng() % 1000) / 1000.0, 0.35 + 0.6 * (rng() % 1000) / 1000.0, 1.0);
  }
  table->SetBelowRangeColor(0.0, 0.0, 0.0, 1.0);
  table->UseBelowRangeColorOn();
  table->Build();

  vtkNew<vtkImageMapToColors> colour;
  colour->SetInputData(labels);
  colour->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "SiteId");
  colour->SetLookupTable(table);
  colour->SetOutputFormatToRGB();
  vtkNew<vtkImageActor> cells;
  cells->GetMapper()->SetInputConnection(colour->GetOutputPort());
  cells->InterpolateOff();

  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(1.0, 1.0, 1.0);
  if (this->ShowCells)
  {
    renderer->AddActor(cells);
  }
  vtkNew<vtkPolyDataMapper> siteMapper;
  vtkNew<vtkActor> siteActor;
  if (sites && sites->GetNumberOfPoints() > 0)
  {
    siteMapper->SetInputData(sites);
    siteMapper->ScalarVisibilityOff();
    siteActor->SetMapper(siteMapper);
    siteActor->GetProperty()->SetColor(0.05, 0.05, 0.05);
    siteActor->GetProperty()->SetPointSize(this->PointSize);
    siteActor->GetProperty()->SetRepresentationToPoints();
    siteActor->SetPosition(0.0, 0.0, 1e-3 * std::max(width, height)); // in front of the cells
    renderer->AddActor(siteActor);
  }
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->ParallelProjectionOn();
  const double cx = 0.5 * (bounds[0] + bounds[1]), cy = 0.5 * (bounds[2] + bounds[3]);
  camera->SetFocalPoint(cx, cy, bounds[4]);
  camera->SetPosition(cx, cy, bounds[4] + 10.0 * std::max(width, height));
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->SetParallelScale(0.5 * height);
  renderer->ResetCameraClippingRange();

  return this->Snapshot(renderer, sizeX, sizeY);
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
