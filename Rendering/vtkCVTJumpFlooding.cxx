#include "vtkCVTJumpFlooding.h"

#include "vtkCVTJumpFloodFS.h"
#include "vtkCVTOpenGLHelpers.h"

#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

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
  if (this->Quad)
  {
    this->Quad->ReleaseGraphicsResources(window);
    this->Quad.reset();
  }
}
