#include "vtkCVTOpenGLEngine.h"

#include "vtkCVTJumpFlooding.h"
#include "vtkCVTOpenGLContext.h"
#include "vtkCVTOpenGLHelpers.h"
#include "vtkCVTSlotReduction.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include "vtkCVTCollectFS.h"
#include "vtkCVTLloydFS.h"
#include "vtkCVTPlaneDistance.h"
#include "vtkCVTReduceFS.h"
#include "vtkCVTReduceVS.h"
#include "vtkCVTSiteSlots.h"
#include "vtkCVTSplitPixelsFS.h"

#include <algorithm>
#include <climits>
#include <cmath>

vtkStandardNewMacro(vtkCVTOpenGLEngine);

using namespace cvtgl;

namespace
{
constexpr int MaxCandidates = 4; // must match vtkCVTSplitPixelsFS.glsl
}

/// GL objects: textures, their framebuffers and the shader programs.
struct vtkCVTOpenGLEngine::Internals
{
  vtkNew<vtkTextureObject> Density;
  vtkCVTSiteSlots Sites{ 2 };                     // two copies: Lloyd steps on the GPU
  vtkNew<vtkTextureObject> Candidates;            // split pixels: candidate sites and collectors
  vtkNew<vtkTextureObject> Pieces[MaxCandidates]; // split pixels: each candidate's piece
  // Per slot: the cell sums, and the largest distance of a pixel from its site (pixels).
  vtkCVTSlotReduction Reduction{ { { 4, vtkCVTSlotReduction::Blend::Sum },
    { 1, vtkCVTSlotReduction::Blend::Maximum } } };
  vtkNew<vtkOpenGLFramebufferObject> SplitFramebuffer;
  std::unique_ptr<vtkOpenGLQuadHelper> SplitQuad;
  std::unique_ptr<vtkOpenGLQuadHelper> CollectQuad;
  std::unique_ptr<vtkOpenGLQuadHelper> LloydQuad;
  int CurrentSeeds = 0; // which Seeds texture holds the last labelling
  bool HaveSums = false;

  void Release(vtkOpenGLRenderWindow* window)
  {
    this->Density->ReleaseGraphicsResources(window);
    this->Candidates->ReleaseGraphicsResources(window);
    for (auto& piece : this->Pieces)
    {
      piece->ReleaseGraphicsResources(window);
    }
    this->SplitFramebuffer->ReleaseGraphicsResources(window);
    this->Reduction.Release(window);
    this->Sites.Release(window);
    for (auto* quad : { &this->SplitQuad, &this->CollectQuad, &this->LloydQuad })
    {
      if (*quad)
      {
        (*quad)->ReleaseGraphicsResources(window);
        quad->reset();
      }
    }
    this->HaveSums = false;
  }
};

//------------------------------------------------------------------------------
vtkCVTOpenGLEngine::vtkCVTOpenGLEngine()
  : vtkCVTGPUEngine(vtkCVTPlaneDistance)
  , cvt::SharedCellSums(Split::ImageRows)
  , Internal(new Internals)
{
}

//------------------------------------------------------------------------------
vtkCVTOpenGLEngine::~vtkCVTOpenGLEngine()
{
  this->ReleaseGraphicsResources();
}

//------------------------------------------------------------------------------
void vtkCVTOpenGLEngine::ReleaseObjects(vtkOpenGLRenderWindow* window)
{
  this->Internal->Release(window);
}

//------------------------------------------------------------------------------
bool vtkCVTOpenGLEngine::CheckGLError(const char* where)
{
  const std::string message = GLErrorMessage(where);
  return message.empty() || this->Fail(message);
}

//------------------------------------------------------------------------------
bool vtkCVTOpenGLEngine::SetDomain(const cvt::Grid& grid, const std::vector<float>& density)
{
  if (grid.Width <= 0 || grid.Height <= 0)
  {
    return this->Fail("the domain has no pixels");
  }
  if (static_cast<long long>(density.size()) != grid.NumberOfPixels())
  {
    return this->Fail("the density must hold one value per pixel");
  }
  if (grid.NumberOfPixels() > INT_MAX / MaxCandidates)
  {
    return this->Fail("the domain has too many pixels for one draw call");
  }
  if (!this->Context->Initialize())
  {
    return this->Fail(this->Context->GetLastError());
  }
  // Textures per pixel: density (4 bytes), two seed buffers and the candidates (16 each), the
  // split pieces (16 each); llvmpipe took 170 bytes per pixel in all (`cvt image --engine opengl`
  // at 2048^2 and 4096^2).
  const std::string tooLarge = this->Context->CheckTextures(
    grid.Width, grid.Height, 52.0 + 16.0 * MaxCandidates, 170.0, "the grid", "use a coarser image");
  if (!tooLarge.empty())
  {
    return this->Fail(tooLarge);
  }

  ScopedContext current(this->Context);
  vtkOpenGLRenderWindow* window = this->Context->GetRenderWindow();
  vtkOpenGLState* state = window->GetState();
  Internals& in = *this->Internal;
  this->Grid = grid;
  this->GridSize[0] = grid.Width;
  this->GridSize[1] = grid.Height;
  this->Metric[0] = static_cast<float>(grid.Spacing[0]);
  this->Metric[1] = static_cast<float>(grid.Spacing[1]);
  this->Internal->Sites.Forget();
  bool ok = AllocateFloatTexture(in.Density, window, grid.Width, grid.Height, 1, density.data());
  ok = ok && this->Flooding->Allocate(window, grid.Width, grid.Height);
  ok = ok && AllocateFloatTexture(in.Candidates, window, grid.Width, grid.Height, 4);
  for (int k = 0; k < MaxCandidates && ok; ++k)
  {
    ok = AllocateFloatTexture(in.Pieces[k], window, grid.Width, grid.Height, 4);
  }
  if (ok)
  {
    in.SplitFramebuffer->SetContext(window);
    state->PushFramebufferBindings();
    in.SplitFramebuffer->Bind();
    in.SplitFramebuffer->AddColorAttachment(0, in.Candidates);
    for (int k = 0; k < MaxCandidates; ++k)
    {
      in.SplitFramebuffer->AddColorAttachment(1 + k, in.Pieces[k]);
    }
    in.SplitFramebuffer->ActivateDrawBuffers(1 + MaxCandidates);
    ok = in.SplitFramebuffer->CheckFrameBufferStatus(GL_FRAMEBUFFER) != 0;
    state->PopFramebufferBindings();
  }
  if (!ok)
  {
    this->ReleaseGraphicsResources();
    return this->Fail("the GPU could not allocate float textures for a " +
      std::to_string(grid.Width) + " x " + std::to_string(grid.Height) + " grid");
  }
  return this->CheckGLError("domain set-up");
}

//------------------------------------------------------------------------------
bool vtkCVTOpenGLEngine::SetSites(const std::vector<double>& sites)
{
  if (!this->Internal->Density->GetHandle())
  {
    return this->Fail("SetDomain must succeed before SetSites");
  }
  const int n = static_cast<int>(sites.size() / 2);
  if (n <= 0)
  {
    return this->Fail("there are no sites");
  }
  ScopedContext current(this->Context);
  vtkOpenGLRenderWindow* window = this->Context->GetRenderWindow();
  Internals& in = *this->Internal;
  const int before = in.Sites.GetNumberOfSites();
  // In grid units, as the shaders work.
  const auto upload = in.Sites.Set(window, n, this->Context->GetMaximumTextureSize(),
    [&](int i, float* texel)
    {
      texel[0] = static_cast<float>((sites[2 * i] - this->Grid.Origin[0]) / this->Grid.Spacing[0]);
      texel[1] =
        static_cast<float>((sites[2 * i + 1] - this->Grid.Origin[1]) / this->Grid.Spacing[1]);
    });
  if (upload == vtkCVTSiteSlots::Upload::TooManySites)
  {
    return this->Fail("too many sites for this GPU's textures");
  }
  if (upload != vtkCVTSiteSlots::Upload::Done ||
    !in.Reduction.Allocate(window, in.Sites.GetSlotSize()))
  {
    return this->Fail("the GPU could not allocate the site textures");
  }
  in.HaveSums = false;
  if (n != before)
  {
    this->Flooding->ForgetSpacing();
  }
  return this->CheckGLError("site upload");
}

//------------------------------------------------------------------------------
bool vtkCVTOpenGLEngine::Label(int initialStep)
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
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDisable(GL_SCISSOR_TEST);
  state->vtkglViewport(0, 0, this->GridSize[0], this->GridSize[1]);
  state->PushFramebufferBindings();

  // Seed, then 1+JFA from the seeds.
  const auto planeUniforms = [this](vtkShaderProgram* program)
  { program->SetUniform2f("metric", this->Metric); };
  const int seeded = this->Flooding->Seed(window, in.Sites.GetCurrent(), in.Sites.GetSlotSize(),
    in.Sites.GetNumberOfSites(), this->GridSize, planeUniforms);
  const int labelled = seeded < 0
    ? -1
    : this->Flooding->Flood(window, seeded, initialStep, this->GridSize, planeUniforms);
  state->PopFramebufferBindings();
  if (labelled < 0)
  {
    return this->Fail("the seed or jump flooding shader did not compile");
  }
  in.CurrentSeeds = labelled;
  return this->CheckGLError("jump flooding");
}

//------------------------------------------------------------------------------
bool vtkCVTOpenGLEngine::Reduce(cvt::CellSums& sums, double& maximumRadius)
{
  if (!this->ScatterToSlots())
  {
    return false;
  }
  Internals& in = *this->Internal;
  std::vector<float> texels, radius;
  vtkOpenGLRenderWindow* window = this->Context->GetRenderWindow();
  in.Reduction.Read(window, 0, texels);
  in.Reduction.Read(window, 1, radius);
  const int n = in.Sites.GetNumberOfSites();
  sums.Resize(n);
  maximumRadius = 0.0;
  for (int i = 0; i < n; ++i)
  {
    sums.Mass[i] = texels[4 * i + 0];
    sums.MomentX[i] = texels[4 * i + 1];
    sums.MomentY[i] = texels[4 * i + 2];
    sums.Energy[i] = texels[4 * i + 3];
    maximumRadius = std::max(maximumRadius, static_cast<double>(radius[i]));
  }
  if (this->Parts > 1)
  {
    // This part reduced its band of rows: the whole sums and radius are those of all parts,
    // and the Lloyd update reads the whole sums from the slots.
    if (!this->SumAcrossParts(sums) || !this->MaximumAcrossParts(maximumRadius))
    {
      return this->Fail("the cell sums of the other processes sharing the work did not arrive");
    }
    for (int i = 0; i < n; ++i)
    {
      texels[4 * i + 0] = static_cast<float>(sums.Mass[i]);
      texels[4 * i + 1] = static_cast<float>(sums.MomentX[i]);
      texels[4 * i + 2] = static_cast<float>(sums.MomentY[i]);
      texels[4 * i + 3] = static_cast<float>(sums.Energy[i]);
    }
    const int* slots = in.Sites.GetSlotSize();
    if (!AllocateFloatTexture(
          in.Reduction.GetTexture(0), window, slots[0], slots[1], 4, texels.data()))
    {
      return this->Fail("the GPU could not take the shared cell sums back");
    }
  }
  return this->CheckGLError("reading the reduction back");
}

//------------------------------------------------------------------------------
bool vtkCVTOpenGLEngine::ScatterToSlots()
{
  vtkOpenGLRenderWindow* window = this->Context->GetRenderWindow();
  vtkOpenGLState* state = window->GetState();
  Internals& in = *this->Internal;
  vtkTextureObject* seeds = this->Flooding->GetTexture(in.CurrentSeeds);
  // The other jump flooding texture is free now: it receives the collected sums.
  vtkTextureObject* collected = this->Flooding->GetTexture(1 - in.CurrentSeeds);

  vtkOpenGLState::ScopedglViewport viewport(state);
  vtkOpenGLState::ScopedglEnableDisable blend(state, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depth(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable scissor(state, GL_SCISSOR_TEST);
  vtkOpenGLState::ScopedglScissor scissorBox(state);
  state->vtkglDisable(GL_BLEND);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDisable(GL_SCISSOR_TEST);
  state->vtkglViewport(0, 0, this->GridSize[0], this->GridSize[1]);
  state->PushFramebufferBindings();
  // This part's band of rows (all of them with one part). Step 2 reads the pieces of the 3x3
  // neighbourhood, so step 1 covers the band and one row on either side.
  int firstRow = 0, lastRow = 0;
  this->PartRange(this->GridSize[1], firstRow, lastRow);
  const auto scissorRows = [&](int first, int last)
  {
    first = std::max(0, first);
    last = std::min(this->GridSize[1], last);
    state->vtkglScissor(0, first, this->GridSize[0], last - first);
  };
  if (this->Parts > 1)
  {
    state->vtkglEnable(GL_SCISSOR_TEST);
    scissorRows(firstRow - 1, lastRow + 1);
  }

  // Step 1: split pixels between candidate sites (fragment pass over the grid).
  vtkShaderProgram* split = ReadyQuad(in.SplitQuad, window, vtkCVTSplitPixelsFS);
  if (!split)
  {
    state->PopFramebufferBindings();
    return this->Fail("the pixel splitting shader did not compile");
  }
  in.SplitFramebuffer->Bind();
  in.SplitFramebuffer->ActivateDrawBuffers(1 + MaxCandidates);
  seeds->Activate();
  in.Density->Activate();
  split->SetUniformi("seeds", seeds->GetTextureUnit());
  split->SetUniformi("density", in.Density->GetTextureUnit());
  split->SetUniform2i("gridSize", this->GridSize);
  split->SetUniform2f("metric", this->Metric);
  split->SetUniformi("candidateLimit", this->SplitBoundaryPixels ? MaxCandidates : 1);
  in.SplitQuad->Render();
  in.Density->Deactivate();

  // Step 2: every pixel collects the pieces its neighbours hand to its site.
  scissorRows(firstRow, lastRow);
  vtkShaderProgram* collect = ReadyQuad(in.CollectQuad, window, vtkCVTCollectFS);
  if (!collect)
  {
    seeds->Deactivate();
    state->PopFramebufferBindings();
    return this->Fail("the collecting shader did not compile");
  }
  this->Flooding->GetFramebuffer(1 - in.CurrentSeeds)->Bind();
  this->Flooding->GetFramebuffer(1 - in.CurrentSeeds)->ActivateDrawBuffers(1);
  in.Candidates->Activate();
  collect->SetUniformi("candidates", in.Candidates->GetTextureUnit());
  const char* pieceNames[MaxCandidates] = { "piece0", "piece1", "piece2", "piece3" };
  for (int k = 0; k < MaxCandidates; ++k)
  {
    in.Pieces[k]->Activate();
    collect->SetUniformi(pieceNames[k], in.Pieces[k]->GetTextureUnit());
  }
  collect->SetUniform2i("gridSize", this->GridSize);
  in.CollectQuad->Render();
  for (int k = 0; k < MaxCandidates; ++k)
  {
    in.Pieces[k]->Deactivate();
  }
  in.Candidates->Deactivate();

  // Step 3: one point per pixel, scattered to its site's slot: the sums, and the radius.
  vtkShaderProgram* reduce = ReadyProgram(window, vtkCVTReduceVS, vtkCVTReduceFS);
  if (!reduce)
  {
    seeds->Deactivate();
    state->PopFramebufferBindings();
    return this->Fail("the reduction shader did not compile");
  }
  collected->Activate();
  reduce->SetUniformi("seeds", seeds->GetTextureUnit());
  reduce->SetUniformi("collected", collected->GetTextureUnit());
  reduce->SetUniform2i("gridSize", this->GridSize);
  reduce->SetUniform2i("slotSize", this->Internal->Sites.GetSlotSize());
  reduce->SetUniform2f("metric", this->Metric);
  reduce->SetUniformf("radiusScale",
    static_cast<float>(1.0 / std::min(this->Grid.Spacing[0], this->Grid.Spacing[1])));
  state->vtkglDisable(GL_SCISSOR_TEST);
  in.Reduction.Scatter(window, static_cast<vtkIdType>(firstRow) * this->GridSize[0],
    static_cast<vtkIdType>(lastRow - firstRow) * this->GridSize[0]);
  collected->Deactivate();
  seeds->Deactivate();
  state->PopFramebufferBindings();
  in.HaveSums = true;
  return this->CheckGLError("regional reduction");
}

//------------------------------------------------------------------------------
bool vtkCVTOpenGLEngine::ComputeCellSums(cvt::CellSums& sums)
{
  if (this->Internal->Sites.GetNumberOfSites() <= 0)
  {
    return this->Fail("SetSites must succeed before ComputeCellSums");
  }
  ScopedContext current(this->Context);
  return this->LabelAndReduce(sums);
}

//------------------------------------------------------------------------------
bool vtkCVTOpenGLEngine::MoveSitesToCentroids()
{
  Internals& in = *this->Internal;
  if (!in.HaveSums)
  {
    return this->Fail("ComputeCellSums must run before MoveSitesToCentroids");
  }
  ScopedContext current(this->Context);
  vtkOpenGLRenderWindow* window = this->Context->GetRenderWindow();
  vtkOpenGLState* state = window->GetState();
  vtkOpenGLState::ScopedglViewport viewport(state);
  vtkOpenGLState::ScopedglEnableDisable blend(state, GL_BLEND);
  state->vtkglDisable(GL_BLEND);
  state->vtkglViewport(0, 0, in.Sites.GetSlotSize()[0], in.Sites.GetSlotSize()[1]);
  state->PushFramebufferBindings();
  in.Sites.GetNextFramebuffer()->Bind();
  in.Sites.GetNextFramebuffer()->ActivateDrawBuffers(1);
  vtkShaderProgram* lloyd = ReadyQuad(in.LloydQuad, window, vtkCVTLloydFS);
  if (!lloyd)
  {
    state->PopFramebufferBindings();
    return this->Fail("the Lloyd update shader did not compile");
  }
  in.Sites.GetCurrent()->Activate();
  vtkTextureObject* cellSums = in.Reduction.GetTexture(0);
  cellSums->Activate();
  lloyd->SetUniformi("sites", in.Sites.GetCurrent()->GetTextureUnit());
  lloyd->SetUniformi("sums", cellSums->GetTextureUnit());
  lloyd->SetUniform2i("slotSize", in.Sites.GetSlotSize());
  lloyd->SetUniformi("numberOfSites", in.Sites.GetNumberOfSites());
  lloyd->SetUniform2f("metric", this->Metric);
  lloyd->SetUniform2i("gridSize", this->GridSize);
  in.LloydQuad->Render();
  cellSums->Deactivate();
  in.Sites.GetCurrent()->Deactivate();
  state->PopFramebufferBindings();
  if (this->MeasureTimings)
  {
    glFinish();
  }
  in.Sites.Swap();
  in.HaveSums = false;
  return this->CheckGLError("Lloyd update");
}

//------------------------------------------------------------------------------
bool vtkCVTOpenGLEngine::GetSites(std::vector<double>& sites)
{
  if (this->Internal->Sites.GetNumberOfSites() <= 0)
  {
    return this->Fail("there are no sites");
  }
  ScopedContext current(this->Context);
  Internals& in = *this->Internal;
  std::vector<float> texels;
  in.Sites.Read(this->Context->GetRenderWindow(), texels);
  const int n = in.Sites.GetNumberOfSites();
  sites.resize(2 * static_cast<size_t>(n));
  for (int i = 0; i < n; ++i)
  {
    sites[2 * i] = this->Grid.Origin[0] + texels[4 * i] * this->Grid.Spacing[0];
    sites[2 * i + 1] = this->Grid.Origin[1] + texels[4 * i + 1] * this->Grid.Spacing[1];
  }
  return this->CheckGLError("reading sites back");
}

//------------------------------------------------------------------------------
bool vtkCVTOpenGLEngine::GetLabels(std::vector<int>& labels)
{
  if (!this->Internal->HaveSums && this->Internal->Sites.GetNumberOfSites() <= 0)
  {
    return this->Fail("there is no labelling yet");
  }
  ScopedContext current(this->Context);
  Internals& in = *this->Internal;
  const size_t pixels = static_cast<size_t>(this->Grid.NumberOfPixels());
  std::vector<float> texels(4 * pixels);
  ReadTarget(this->Flooding->GetFramebuffer(in.CurrentSeeds), this->Context->GetRenderWindow(), 0,
    this->Grid.Width, this->Grid.Height, GL_RGBA, texels.data());
  labels.resize(pixels);
  for (size_t p = 0; p < pixels; ++p)
  {
    labels[p] = static_cast<int>(texels[4 * p + 2]);
  }
  return this->CheckGLError("reading labels back");
}

//------------------------------------------------------------------------------
void vtkCVTOpenGLEngine::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Grid: " << this->Grid.Width << " x " << this->Grid.Height << "\n";
  os << indent << "NumberOfSites: " << this->Internal->Sites.GetNumberOfSites() << "\n";
  os << indent << "SplitBoundaryPixels: " << this->SplitBoundaryPixels << "\n";
}
