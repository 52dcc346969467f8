#include "vtkCVTSurfaceEngine.h"

#include "vtkCVTJumpFlooding.h"
#include "vtkCVTOpenGLContext.h"
#include "vtkCVTOpenGLHelpers.h"
#include "vtkCVTSiteSlots.h"
#include "vtkCVTSlotReduction.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include "vtkCVTPassThroughFS.h"
#include "vtkCVTSurfaceDistance.h"
#include "vtkCVTSurfaceNearestFS.h"
#include "vtkCVTSurfaceNearestVS.h"
#include "vtkCVTSurfaceReduceFS.h"
#include "vtkCVTSurfaceReduceVS.h"

#include <algorithm>
#include <climits>
#include <cmath>

vtkStandardNewMacro(vtkCVTSurfaceEngine);

using namespace cvtgl;

struct vtkCVTSurfaceEngine::Internals
{
  vtkNew<vtkTextureObject> Positions; // (x, y, z, valid)
  vtkNew<vtkTextureObject> Weights;
  vtkNew<vtkTextureObject> Seams; // (i, j) of each pixel's seam partner; 1 x 1 without seams
  vtkCVTSiteSlots Sites{ 1 };     // (x, y, z, pixel index)
  vtkCVTSiteSlots Targets{ 1 };   // constrained centroids: where each site should go
  // Per slot: the cell sums, the energy, and the largest pixel distance from the site's pixel.
  vtkCVTSlotReduction Reduction{ { { 4, vtkCVTSlotReduction::Blend::Sum },
    { 1, vtkCVTSlotReduction::Blend::Sum }, { 1, vtkCVTSlotReduction::Blend::Maximum } } };
  vtkNew<vtkTextureObject> NearestPoints;  // per pixel: (point, distance)
  vtkNew<vtkTextureObject> NearestCorners; // per pixel: pixel index of that point
  vtkNew<vtkTextureObject> Nearest;        // slot per site: (point, pixel index)
  vtkNew<vtkTextureObject> NearestDepth;   // its depth buffer (distance)
  vtkNew<vtkOpenGLFramebufferObject> NearestPixelsFramebuffer;
  vtkNew<vtkOpenGLFramebufferObject> NearestFramebuffer;
  std::unique_ptr<vtkOpenGLQuadHelper> NearestQuad;
  vtkNew<vtkOpenGLVertexArrayObject> EmptyVertexArray;
  int CurrentSeeds = 0;

  void Release(vtkOpenGLRenderWindow* window)
  {
    for (vtkTextureObject* t :
      { this->Positions.Get(), this->Weights.Get(), this->Seams.Get(), this->NearestPoints.Get(),
        this->NearestCorners.Get(), this->Nearest.Get(), this->NearestDepth.Get() })
    {
      t->ReleaseGraphicsResources(window);
    }
    for (vtkOpenGLFramebufferObject* f :
      { this->NearestPixelsFramebuffer.Get(), this->NearestFramebuffer.Get() })
    {
      f->ReleaseGraphicsResources(window);
    }
    this->Sites.Release(window);
    this->Targets.Release(window);
    this->Reduction.Release(window);
    this->EmptyVertexArray->ReleaseGraphicsResources();
    if (this->NearestQuad)
    {
      this->NearestQuad->ReleaseGraphicsResources(window);
      this->NearestQuad.reset();
    }
  }
};

//------------------------------------------------------------------------------
vtkCVTSurfaceEngine::vtkCVTSurfaceEngine()
  : vtkCVTGPUEngine(vtkCVTSurfaceDistance)
  , cvt::SharedCellSums(Split::ImageRows)
  , Internal(new Internals)
{
}

//------------------------------------------------------------------------------
vtkCVTSurfaceEngine::~vtkCVTSurfaceEngine()
{
  this->ReleaseGraphicsResources();
}

//------------------------------------------------------------------------------
void vtkCVTSurfaceEngine::ReleaseObjects(vtkOpenGLRenderWindow* window)
{
  this->Internal->Release(window);
}

//------------------------------------------------------------------------------
bool vtkCVTSurfaceEngine::CheckGLError(const char* where)
{
  const std::string message = GLErrorMessage(where);
  return message.empty() || this->Fail(message);
}

//------------------------------------------------------------------------------
bool vtkCVTSurfaceEngine::SetGeometryImage(const cvt::GeometryImage& image)
{
  const std::string problem = cvt::CheckGeometryImage(image, 1);
  if (!problem.empty())
  {
    return this->Fail(problem);
  }
  if (image.NumberOfPixels() > INT_MAX)
  {
    return this->Fail("the geometry image has too many pixels for one draw call");
  }
  if (!this->Context->Initialize())
  {
    return this->Fail(this->Context->GetLastError());
  }
  // Textures per pixel: positions, two seed buffers and nearest points (16 bytes each), area
  // weight, nearest corner and depth (4 each); on llvmpipe about 150 of the 227 bytes per pixel
  // a whole `cvt surface --engine opengl` run took (1024x512 to 2048x1024; the rest is the
  // geometry image's own arrays, checked by its source).
  const std::string tooLarge = this->Context->CheckTextures(
    image.Width, image.Height, 76.0, 150.0, "the geometry image", "use a smaller one");
  if (!tooLarge.empty())
  {
    return this->Fail(tooLarge);
  }
  ScopedContext current(this->Context);
  vtkOpenGLRenderWindow* window = this->Context->GetRenderWindow();
  Internals& in = *this->Internal;
  this->Image = image;
  this->GridSize[0] = image.Width;
  this->GridSize[1] = image.Height;
  this->Wrap[0] = image.WrapU ? 1 : 0;
  this->Wrap[1] = image.WrapV ? 1 : 0;
  in.Sites.Forget();
  const size_t pixels = static_cast<size_t>(image.NumberOfPixels());
  std::vector<float> positions(4 * pixels);
  for (size_t p = 0; p < pixels; ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      positions[4 * p + c] = image.Position[3 * p + c];
    }
    positions[4 * p + 3] = image.IsValid(static_cast<long long>(p)) ? 1.0f : 0.0f;
  }
  // Seam partners as pixel coordinates (exact in floats for any texture size).
  this->HasSeams = !image.SeamPartner.empty();
  std::vector<float> seams(this->HasSeams ? 2 * pixels : 2, -1.0f);
  for (size_t p = 0; p < image.SeamPartner.size(); ++p)
  {
    if (image.SeamPartner[p] >= 0)
    {
      seams[2 * p] = static_cast<float>(image.SeamPartner[p] % image.Width);
      seams[2 * p + 1] = static_cast<float>(image.SeamPartner[p] / image.Width);
    }
  }
  bool ok =
    AllocateFloatTexture(in.Positions, window, image.Width, image.Height, 4, positions.data()) &&
    AllocateFloatTexture(in.Seams, window, this->HasSeams ? image.Width : 1,
      this->HasSeams ? image.Height : 1, 2, seams.data()) &&
    AllocateFloatTexture(in.Weights, window, image.Width, image.Height, 1, image.AreaWeight.data());
  ok = ok && this->Flooding->Allocate(window, image.Width, image.Height);
  ok = ok && AllocateFloatTexture(in.NearestPoints, window, image.Width, image.Height, 4) &&
    AllocateFloatTexture(in.NearestCorners, window, image.Width, image.Height, 1) &&
    AttachTargets(in.NearestPixelsFramebuffer, window, in.NearestPoints, in.NearestCorners);
  if (!ok)
  {
    this->ReleaseGraphicsResources();
    return this->Fail("the GPU could not allocate the geometry image textures");
  }
  double lo[3] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX };
  double hi[3] = { -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  for (size_t p = 0; p < pixels; ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      lo[c] = std::min(lo[c], static_cast<double>(image.Position[3 * p + c]));
      hi[c] = std::max(hi[c], static_cast<double>(image.Position[3 * p + c]));
    }
  }
  this->Diagonal = std::max(1e-30,
    std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
      (hi[2] - lo[2]) * (hi[2] - lo[2])));
  return this->CheckGLError("geometry image set-up");
}

//------------------------------------------------------------------------------
bool vtkCVTSurfaceEngine::SetSites(
  const std::vector<double>& sites, const std::vector<long long>& pixels)
{
  if (!this->Internal->Positions->GetHandle())
  {
    return this->Fail("SetGeometryImage must succeed before SetSites");
  }
  const int n = static_cast<int>(pixels.size());
  if (n <= 0 || sites.size() != 3 * pixels.size())
  {
    return this->Fail("the sites need three coordinates and one pixel each");
  }
  const long long total = static_cast<long long>(this->GridSize[0]) * this->GridSize[1];
  for (long long pixel : pixels)
  {
    if (pixel < 0 || pixel >= total || pixel >= (1LL << 24))
    {
      return this->Fail("a site's pixel lies outside the geometry image");
    }
  }
  ScopedContext current(this->Context);
  vtkOpenGLRenderWindow* window = this->Context->GetRenderWindow();
  Internals& in = *this->Internal;
  const int before = in.Sites.GetNumberOfSites();
  const auto upload = in.Sites.Set(window, n, this->Context->GetMaximumTextureSize(),
    [&](int i, float* texel)
    {
      for (int c = 0; c < 3; ++c)
      {
        texel[c] = static_cast<float>(sites[3 * i + c]);
      }
      texel[3] = static_cast<float>(pixels[i]);
    });
  if (upload == vtkCVTSiteSlots::Upload::TooManySites)
  {
    return this->Fail("too many sites for this GPU's textures");
  }
  if (upload != vtkCVTSiteSlots::Upload::Done)
  {
    return this->Fail("the GPU could not allocate the site texture");
  }
  const int* slotSize = in.Sites.GetSlotSize();
  bool ok = in.Reduction.Allocate(window, slotSize);
  // The nearest-point slots (and their depth) follow the site slots' layout.
  if (ok &&
    (!in.Nearest->GetHandle() || in.Nearest->GetWidth() != static_cast<unsigned int>(slotSize[0]) ||
      in.Nearest->GetHeight() != static_cast<unsigned int>(slotSize[1])))
  {
    ok = AllocateFloatTexture(in.Nearest, window, slotSize[0], slotSize[1], 4) &&
      this->AttachNearestTargets(slotSize[0], slotSize[1]);
  }
  if (!ok)
  {
    return this->Fail("the GPU could not allocate the reduction targets");
  }
  if (n != before)
  {
    this->Flooding->ForgetSpacing();
  }
  return this->CheckGLError("site upload");
}

//------------------------------------------------------------------------------
bool vtkCVTSurfaceEngine::ComputeCellSums(cvt::CellSums& sums)
{
  if (this->Internal->Sites.GetNumberOfSites() <= 0)
  {
    return this->Fail("SetSites must succeed before ComputeCellSums");
  }
  ScopedContext current(this->Context);
  return this->LabelAndReduce(sums);
}

//------------------------------------------------------------------------------
bool vtkCVTSurfaceEngine::Label(int initialStep)
{
  vtkOpenGLRenderWindow* window = this->Context->GetRenderWindow();
  vtkOpenGLState* state = window->GetState();
  Internals& in = *this->Internal;
  vtkOpenGLState::ScopedglViewport viewport(state);
  vtkOpenGLState::ScopedglEnableDisable blend(state, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depth(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable scissor(state, GL_SCISSOR_TEST);
  vtkOpenGLState::ScopedglDepthFunc depthFunction(state);
  vtkOpenGLState::ScopedglDepthMask depthMask(state);
  state->vtkglDisable(GL_BLEND);
  state->vtkglDisable(GL_SCISSOR_TEST);
  state->vtkglViewport(0, 0, this->GridSize[0], this->GridSize[1]);
  state->PushFramebufferBindings();

  // Seed, then 1+JFA from the seeds. Across an atlas's seams a site reaches the other chart
  // only through the border pixels, possibly in the last passes: a second sweep carries it on
  // (both from the full step: CanAdaptStep).
  in.Positions->Activate();
  in.Seams->Activate();
  const auto surfaceUniforms = [this](vtkShaderProgram* program)
  {
    program->SetUniformi("positions", this->Internal->Positions->GetTextureUnit());
    program->SetUniform2i("wrap", this->Wrap);
    program->SetUniformi("seams", this->Internal->Seams->GetTextureUnit());
    program->SetUniformi("hasSeams", this->HasSeams ? 1 : 0);
  };
  const int seeded = this->Flooding->Seed(window, in.Sites.GetCurrent(), in.Sites.GetSlotSize(),
    in.Sites.GetNumberOfSites(), this->GridSize, surfaceUniforms);
  int labelled = seeded < 0
    ? -1
    : this->Flooding->Flood(window, seeded, initialStep, this->GridSize, surfaceUniforms);
  if (this->HasSeams && labelled >= 0)
  {
    labelled =
      this->Flooding->Flood(window, labelled, initialStep, this->GridSize, surfaceUniforms);
  }
  in.Seams->Deactivate();
  in.Positions->Deactivate();
  state->PopFramebufferBindings();
  if (labelled < 0)
  {
    return this->Fail("the surface seed or jump flooding shader did not compile");
  }
  in.CurrentSeeds = labelled;
  return this->CheckGLError("surface jump flooding");
}

//------------------------------------------------------------------------------
bool vtkCVTSurfaceEngine::Reduce(cvt::CellSums& sums, double& maximumRadius)
{
  vtkOpenGLRenderWindow* window = this->Context->GetRenderWindow();
  Internals& in = *this->Internal;
  // One point per pixel into its site's slot: sums and energy added, the radius the largest.
  vtkShaderProgram* reduce = ReadyProgram(window, vtkCVTSurfaceReduceVS, vtkCVTSurfaceReduceFS);
  if (!reduce)
  {
    return this->Fail("the surface reduction shader did not compile");
  }
  vtkTextureObject* seeds = this->Flooding->GetTexture(in.CurrentSeeds);
  seeds->Activate();
  in.Positions->Activate();
  in.Weights->Activate();
  in.Sites.GetCurrent()->Activate();
  reduce->SetUniformi("seeds", seeds->GetTextureUnit());
  reduce->SetUniformi("positions", in.Positions->GetTextureUnit());
  reduce->SetUniformi("weights", in.Weights->GetTextureUnit());
  reduce->SetUniformi("sites", in.Sites.GetCurrent()->GetTextureUnit());
  reduce->SetUniform2i("gridSize", this->GridSize);
  reduce->SetUniform2i("slotSize", in.Sites.GetSlotSize());
  reduce->SetUniform2i("wrap", this->Wrap);
  int firstRow = 0, lastRow = 0;
  this->PartRange(this->GridSize[1], firstRow, lastRow); // all rows with one part
  in.Reduction.Scatter(window, static_cast<vtkIdType>(firstRow) * this->GridSize[0],
    static_cast<vtkIdType>(lastRow - firstRow) * this->GridSize[0]);
  in.Sites.GetCurrent()->Deactivate();
  in.Weights->Deactivate();
  in.Positions->Deactivate();
  seeds->Deactivate();

  std::vector<float> texels, energy, radius;
  in.Reduction.Read(window, 0, texels);
  in.Reduction.Read(window, 1, energy);
  in.Reduction.Read(window, 2, radius);
  const int n = in.Sites.GetNumberOfSites();
  sums.Resize(n, true);
  maximumRadius = 0.0;
  for (int i = 0; i < n; ++i)
  {
    sums.Mass[i] = texels[4 * i];
    sums.MomentX[i] = texels[4 * i + 1];
    sums.MomentY[i] = texels[4 * i + 2];
    sums.MomentZ[i] = texels[4 * i + 3];
    sums.Energy[i] = energy[i];
    maximumRadius = std::max(maximumRadius, static_cast<double>(radius[i]));
  }
  if (!this->SumAcrossParts(sums) || !this->MaximumAcrossParts(maximumRadius))
  {
    return this->Fail("the cell sums of the other processes sharing the work did not arrive");
  }
  return this->CheckGLError("surface reduction");
}

//------------------------------------------------------------------------------
bool vtkCVTSurfaceEngine::GetLabels(std::vector<int>& labels)
{
  if (this->Internal->Sites.GetNumberOfSites() <= 0)
  {
    return this->Fail("there is no labelling yet");
  }
  ScopedContext current(this->Context);
  const size_t pixels = static_cast<size_t>(this->GridSize[0]) * this->GridSize[1];
  std::vector<float> texels(4 * pixels);
  ReadTarget(this->Flooding->GetFramebuffer(this->Internal->CurrentSeeds),
    this->Context->GetRenderWindow(), 0, this->GridSize[0], this->GridSize[1], GL_RGBA,
    texels.data());
  labels.resize(pixels);
  for (size_t p = 0; p < pixels; ++p)
  {
    labels[p] = static_cast<int>(texels[4 * p + 3]);
  }
  return this->CheckGLError("reading labels back");
}

//------------------------------------------------------------------------------
bool vtkCVTSurfaceEngine::AttachNearestTargets(int width, int height)
{
  // A depth texture of the slots' size rather than a default depth renderbuffer: the latter
  // came out unusable with VTK's X11 window (the fallback context), leaving the slots empty.
  vtkOpenGLRenderWindow* window = this->Context->GetRenderWindow();
  Internals& in = *this->Internal;
  in.NearestDepth->SetContext(window);
  if (!in.NearestDepth->AllocateDepth(width, height, vtkTextureObject::Float32))
  {
    return false;
  }
  in.NearestFramebuffer->SetContext(window);
  window->GetState()->PushFramebufferBindings();
  in.NearestFramebuffer->Bind();
  in.NearestFramebuffer->AddColorAttachment(0, in.Nearest);
  in.NearestFramebuffer->AddDepthAttachment(in.NearestDepth);
  in.NearestFramebuffer->ActivateDrawBuffers(1);
  const bool complete = in.NearestFramebuffer->CheckFrameBufferStatus(GL_FRAMEBUFFER) != 0;
  window->GetState()->PopFramebufferBindings();
  return complete;
}

//------------------------------------------------------------------------------
bool vtkCVTSurfaceEngine::NearestPointsInCells(
  const std::vector<double>& targets, std::vector<double>& sites, std::vector<long long>& pixels)
{
  const int n = this->Internal->Sites.GetNumberOfSites();
  if (n <= 0 || targets.size() != 3 * static_cast<size_t>(n) || sites.size() != targets.size() ||
    pixels.size() != targets.size() / 3)
  {
    return this->Fail("NearestPointsInCells needs a labelling and one target per site");
  }
  if (this->Context->GetDescription().rfind("EGL", 0) != 0)
  {
    // With VTK's X11 window (the fallback context) the depth-tested scatter below leaves the
    // slots empty, for a reason not found yet; there the CPU reference does this step.
    std::vector<int> labels;
    if (!this->GetLabels(labels))
    {
      return false;
    }
    cvt::NearestPointsInCells(this->Image, labels, targets, sites, pixels);
    // Of the whole image: nearest of all under MPI too (parts on EGL contexts take part).
    return this->NearestAcrossParts(targets, std::vector<char>(n, 1), sites, pixels);
  }
  ScopedContext current(this->Context);
  vtkOpenGLRenderWindow* window = this->Context->GetRenderWindow();
  vtkOpenGLState* state = window->GetState();
  Internals& in = *this->Internal;
  const int* slotSize = in.Sites.GetSlotSize();
  if (in.Targets.Set(window, n, this->Context->GetMaximumTextureSize(),
        [&targets](int i, float* texel)
        {
          for (int c = 0; c < 3; ++c)
          {
            texel[c] = static_cast<float>(targets[3 * i + c]);
          }
        }) != vtkCVTSiteSlots::Upload::Done)
  {
    return this->Fail("the GPU could not allocate the target texture");
  }
  vtkShaderProgram* nearest =
    ReadyQuad(in.NearestQuad, window, vtkCVTSurfaceNearestFS, vtkCVTSurfaceDistance);
  vtkShaderProgram* scatter =
    nearest ? ReadyProgram(window, vtkCVTSurfaceNearestVS, vtkCVTPassThroughFS) : nullptr;
  if (!nearest || !scatter)
  {
    return this->Fail("the constrained centroid shaders did not compile");
  }

  vtkOpenGLState::ScopedglViewport viewport(state);
  vtkOpenGLState::ScopedglEnableDisable blend(state, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depth(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglDepthFunc depthFunction(state);
  vtkOpenGLState::ScopedglDepthMask depthMask(state);
  state->vtkglDisable(GL_BLEND);
  state->PushFramebufferBindings();

  // Step 1: every pixel's nearest point on its quad's two triangles.
  window->GetShaderCache()->ReadyShaderProgram(nearest);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglViewport(0, 0, this->GridSize[0], this->GridSize[1]);
  in.NearestPixelsFramebuffer->Bind();
  in.NearestPixelsFramebuffer->ActivateDrawBuffers(2);
  vtkTextureObject* seeds = this->Flooding->GetTexture(in.CurrentSeeds);
  seeds->Activate();
  in.Positions->Activate();
  in.Targets.GetCurrent()->Activate();
  nearest->SetUniformi("seeds", seeds->GetTextureUnit());
  nearest->SetUniformi("positions", in.Positions->GetTextureUnit());
  nearest->SetUniformi("targets", in.Targets.GetCurrent()->GetTextureUnit());
  nearest->SetUniform2i("gridSize", this->GridSize);
  nearest->SetUniform2i("slotSize", slotSize);
  nearest->SetUniform2i("wrap", this->Wrap);
  // This part's band of rows (all of them with one part).
  int firstRow = 0, lastRow = 0;
  this->PartRange(this->GridSize[1], firstRow, lastRow);
  vtkOpenGLState::ScopedglEnableDisable scissor(state, GL_SCISSOR_TEST);
  vtkOpenGLState::ScopedglScissor scissorBox(state);
  state->vtkglEnable(GL_SCISSOR_TEST);
  state->vtkglScissor(0, firstRow, this->GridSize[0], lastRow - firstRow);
  in.NearestQuad->Render();
  state->vtkglDisable(GL_SCISSOR_TEST);
  in.Targets.GetCurrent()->Deactivate();
  in.Positions->Deactivate();

  // Step 2: scatter to the slots, the depth test keeping the nearest point of each cell.
  window->GetShaderCache()->ReadyShaderProgram(scatter);
  state->vtkglViewport(0, 0, slotSize[0], slotSize[1]);
  BindForNearestScatter(in.NearestFramebuffer, window);
  in.NearestPoints->Activate();
  in.NearestCorners->Activate();
  scatter->SetUniformi("seeds", seeds->GetTextureUnit());
  scatter->SetUniformi("nearest", in.NearestPoints->GetTextureUnit());
  scatter->SetUniformi("corners", in.NearestCorners->GetTextureUnit());
  scatter->SetUniform2i("gridSize", this->GridSize);
  scatter->SetUniform2i("slotSize", slotSize);
  scatter->SetUniformf("maximumDistance", static_cast<float>(2.0 * this->Diagonal));
  in.EmptyVertexArray->Bind();
  glDrawArrays(GL_POINTS, firstRow * this->GridSize[0], (lastRow - firstRow) * this->GridSize[0]);
  in.EmptyVertexArray->Release();
  in.NearestCorners->Deactivate();
  in.NearestPoints->Deactivate();
  seeds->Deactivate();
  state->PopFramebufferBindings();

  std::vector<float> texels(static_cast<size_t>(slotSize[0]) * slotSize[1] * 4);
  ReadTarget(in.NearestFramebuffer, window, 0, slotSize[0], slotSize[1], GL_RGBA, texels.data());
  std::vector<char> found(n, 0);
  for (int i = 0; i < n; ++i)
  {
    if (texels[4 * i + 3] < 0.0f)
    {
      continue; // an empty cell (in this part's rows): the site stays
    }
    for (int c = 0; c < 3; ++c)
    {
      sites[3 * i + c] = texels[4 * i + c];
    }
    pixels[i] = static_cast<long long>(texels[4 * i + 3]);
    found[i] = 1;
  }
  return this->CheckGLError("constrained centroids") &&
    this->NearestAcrossParts(targets, found, sites, pixels);
}

//------------------------------------------------------------------------------
bool vtkCVTSurfaceEngine::NearestAcrossParts(const std::vector<double>& targets,
  const std::vector<char>& found, std::vector<double>& sites, std::vector<long long>& pixels)
{
  if (this->Parts <= 1)
  {
    return true;
  }
  // Per site: distance to the target (-1: no candidate), point, pixel.
  const size_t n = pixels.size();
  std::vector<double> candidates(5 * n);
  for (size_t i = 0; i < n; ++i)
  {
    double* c = &candidates[5 * i];
    double distance2 = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      c[1 + k] = sites[3 * i + k];
      distance2 +=
        (sites[3 * i + k] - targets[3 * i + k]) * (sites[3 * i + k] - targets[3 * i + k]);
    }
    c[0] = found[i] ? std::sqrt(distance2) : -1.0;
    c[4] = static_cast<double>(pixels[i]);
  }
  if (!this->GatherAcrossParts(candidates))
  {
    return this->Fail("the constrained centroids of the other processes did not arrive");
  }
  for (size_t i = 0; i < n; ++i)
  {
    // The nearest; on a tie the first part's (lower rows, as one process's depth test keeps the
    // first point drawn).
    const double* best = nullptr;
    for (int part = 0; part < this->Parts; ++part)
    {
      const double* c = &candidates[5 * (static_cast<size_t>(part) * n + i)];
      if (c[0] >= 0.0 && (!best || c[0] < best[0]))
      {
        best = c;
      }
    }
    if (best)
    {
      std::copy(best + 1, best + 4, sites.begin() + static_cast<std::ptrdiff_t>(3 * i));
      pixels[i] = static_cast<long long>(best[4]);
    }
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkCVTSurfaceEngine::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "GeometryImage: " << this->GridSize[0] << " x " << this->GridSize[1] << " (wrap "
     << this->Wrap[0] << ", " << this->Wrap[1] << ")\n";
  os << indent << "Seams: " << (this->HasSeams ? "yes" : "no") << "\n";
  os << indent << "NumberOfSites: " << this->Internal->Sites.GetNumberOfSites() << "\n";
}
