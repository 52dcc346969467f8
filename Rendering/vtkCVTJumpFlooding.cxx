#include "vtkCVTJumpFlooding.h"

#include "vtkCVTJumpFloodFS.h"
#include "vtkCVTOpenGLHelpers.h"
#include "vtkCVTPassThroughFS.h"
#include "vtkCVTSeedVS.h"

#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <algorithm>
#include <vector>

//------------------------------------------------------------------------------
vtkCVTJumpFlooding::vtkCVTJumpFlooding(const char* distance)
  : Distance(distance)
{
}

//------------------------------------------------------------------------------
vtkCVTJumpFlooding::~vtkCVTJumpFlooding() = default;

//------------------------------------------------------------------------------
bool vtkCVTJumpFlooding::Allocate(vtkOpenGLRenderWindow* window, int width, int height)
{
  for (int i = 0; i < 2; ++i)
  {
    if (!cvtgl::AllocateFloatTexture(this->Textures[i], window, width, height, 4) ||
      !cvtgl::AttachTargets(this->Framebuffers[i], window, this->Textures[i], nullptr, true))
    {
      return false;
    }
  }
  this->FullInitialStep = vtkCVTJumpFlooding::FullStep(width, height);
  this->NextInitialStep = this->FullInitialStep;
  return true;
}

//------------------------------------------------------------------------------
bool vtkCVTJumpFlooding::AcceptLabelling(int initialStep, double maximumRadius)
{
  // A pixel labelled with a site r pixels away has its true nearest site within r too (in the
  // plane; on a geometry image as far as its pixels are evenly sized), so every label is right
  // when r, with a margin for JFA's own misses, is within the 2 * step - 1 pixels that the
  // passes can carry a site.
  const int reach = 2 * initialStep - 1;
  if (initialStep < this->FullInitialStep && 1.5 * maximumRadius > reach)
  {
    ++this->Fallbacks;
    return false;
  }
  this->LastInitialStep = initialStep;
  this->LastMaximumRadius = maximumRadius;
  // Next time, start from the smallest step whose reach covers twice the largest cell radius.
  this->NextInitialStep = std::min(this->FullInitialStep, NextPowerOfTwo(maximumRadius + 0.5));
  return true;
}

//------------------------------------------------------------------------------
int vtkCVTJumpFlooding::NextPowerOfTwo(double value)
{
  int power = 1;
  while (power < value && power < (1 << 30))
  {
    power *= 2;
  }
  return power;
}

//------------------------------------------------------------------------------
int vtkCVTJumpFlooding::FullStep(int width, int height)
{
  return std::max(1, NextPowerOfTwo(std::max(width, height)) / 2);
}

//------------------------------------------------------------------------------
int vtkCVTJumpFlooding::Seed(vtkOpenGLRenderWindow* window, vtkTextureObject* sites,
  const int slotSize[2], int numberOfSites, const int gridSize[2],
  const std::function<void(vtkShaderProgram*)>& setUniforms)
{
  vtkShaderProgram* seed =
    cvtgl::ReadyProgram(window, vtkCVTSeedVS, vtkCVTPassThroughFS, this->Distance);
  if (!seed)
  {
    return -1;
  }
  // Pass 0 into texture 0: one seed per site, the lowest id winning a shared pixel.
  cvtgl::BindForNearestScatter(this->Framebuffers[0], window);
  sites->Activate();
  seed->SetUniformi("sites", sites->GetTextureUnit());
  seed->SetUniform2i("slotSize", slotSize);
  seed->SetUniform2i("gridSize", gridSize);
  seed->SetUniformi("numberOfSites", numberOfSites);
  setUniforms(seed);
  seed->SetUniformi("secondChance", 0);
  this->EmptyVertexArray->Bind();
  glDrawArrays(GL_POINTS, 0, numberOfSites);
  // Pass 1 into texture 1: pass 0's seeds, then the sites that lost their pixel, each in its
  // nearest free neighbour.
  vtkOpenGLState* state = window->GetState();
  this->Framebuffers[1]->Bind();
  this->Framebuffers[1]->ActivateDrawBuffers(1);
  this->Framebuffers[0]->Bind(GL_READ_FRAMEBUFFER);
  this->Framebuffers[0]->ActivateReadBuffer(0);
  state->vtkglBlitFramebuffer(0, 0, gridSize[0], gridSize[1], 0, 0, gridSize[0], gridSize[1],
    GL_COLOR_BUFFER_BIT, GL_NEAREST);
  state->vtkglClear(GL_DEPTH_BUFFER_BIT);
  this->Textures[0]->Activate();
  seed->SetUniformi("placed", this->Textures[0]->GetTextureUnit());
  seed->SetUniformi("secondChance", 1);
  glDrawArrays(GL_POINTS, 0, numberOfSites);
  this->Textures[0]->Deactivate();
  this->EmptyVertexArray->Release();
  sites->Deactivate();
  state->vtkglDisable(GL_DEPTH_TEST);
  return 1;
}

//------------------------------------------------------------------------------
int vtkCVTJumpFlooding::Flood(vtkOpenGLRenderWindow* window, int seeded, int initialStep,
  const int gridSize[2], const std::function<void(vtkShaderProgram*)>& setUniforms)
{
  vtkShaderProgram* jump = cvtgl::ReadyQuad(this->Quad, window, vtkCVTJumpFloodFS, this->Distance);
  if (!jump)
  {
    return -1;
  }
  jump->SetUniform2i("gridSize", gridSize);
  setUniforms(jump);
  std::vector<int> steps{ 1 };
  for (int step = initialStep; step >= 1; step /= 2)
  {
    steps.push_back(step);
  }
  int source = seeded;
  for (int step : steps)
  {
    const int target = 1 - source;
    this->Framebuffers[target]->Bind();
    this->Framebuffers[target]->ActivateDrawBuffers(1);
    this->Textures[source]->Activate();
    jump->SetUniformi("seeds", this->Textures[source]->GetTextureUnit());
    jump->SetUniformi("stepLength", step);
    this->Quad->Render();
    this->Textures[source]->Deactivate();
    source = target;
  }
  return source;
}

//------------------------------------------------------------------------------
void vtkCVTJumpFlooding::Release(vtkOpenGLRenderWindow* window)
{
  for (int i = 0; i < 2; ++i)
  {
    this->Textures[i]->ReleaseGraphicsResources(window);
    this->Framebuffers[i]->ReleaseGraphicsResources(window);
  }
  this->EmptyVertexArray->ReleaseGraphicsResources();
  if (this->Quad)
  {
    this->Quad->ReleaseGraphicsResources(window);
    this->Quad.reset();
  }
}
