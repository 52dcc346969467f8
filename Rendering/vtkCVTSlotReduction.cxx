#include "vtkCVTSlotReduction.h"

#include "vtkCVTOpenGLHelpers.h"

#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

//------------------------------------------------------------------------------
vtkCVTSlotReduction::vtkCVTSlotReduction(std::vector<Target> targets)
  : Targets(std::move(targets))
{
  for (size_t t = 0; t < this->Targets.size(); ++t)
  {
    this->Textures.push_back(vtkTextureObject::New());
  }
}

//------------------------------------------------------------------------------
vtkCVTSlotReduction::~vtkCVTSlotReduction()
{
  for (vtkTextureObject* texture : this->Textures)
  {
    texture->Delete();
  }
}

//------------------------------------------------------------------------------
bool vtkCVTSlotReduction::Allocate(vtkOpenGLRenderWindow* window, const int slotSize[2])
{
  const bool resized = slotSize[0] != this->SlotSize[0] || slotSize[1] != this->SlotSize[1];
  if (!resized && this->Textures[0]->GetHandle())
  {
    return true;
  }
  for (size_t t = 0; t < this->Targets.size(); ++t)
  {
    if (!cvtgl::AllocateFloatTexture(
          this->Textures[t], window, slotSize[0], slotSize[1], this->Targets[t].Components))
    {
      return false;
    }
  }
  this->Framebuffer->SetContext(window);
  vtkOpenGLState* state = window->GetState();
  state->PushFramebufferBindings();
  this->Framebuffer->Bind();
  for (size_t t = 0; t < this->Targets.size(); ++t)
  {
    this->Framebuffer->AddColorAttachment(static_cast<unsigned int>(t), this->Textures[t]);
  }
  this->Framebuffer->ActivateDrawBuffers(static_cast<unsigned int>(this->Targets.size()));
  const bool complete = this->Framebuffer->CheckFrameBufferStatus(GL_FRAMEBUFFER) != 0;
  state->PopFramebufferBindings();
  this->SlotSize[0] = slotSize[0];
  this->SlotSize[1] = slotSize[1];
  return complete;
}

//------------------------------------------------------------------------------
void vtkCVTSlotReduction::Scatter(vtkOpenGLRenderWindow* window, vtkIdType first, vtkIdType count)
{
  vtkOpenGLState* state = window->GetState();
  vtkOpenGLState::ScopedglViewport viewport(state);
  vtkOpenGLState::ScopedglEnableDisable blend(state, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depth(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable scissor(state, GL_SCISSOR_TEST);
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFunction(state);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDisable(GL_SCISSOR_TEST);
  state->vtkglViewport(0, 0, this->SlotSize[0], this->SlotSize[1]);
  state->PushFramebufferBindings();
  this->Framebuffer->Bind();
  this->Framebuffer->ActivateDrawBuffers(static_cast<unsigned int>(this->Targets.size()));
  state->vtkglClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  state->vtkglClear(GL_COLOR_BUFFER_BIT);
  state->vtkglEnable(GL_BLEND);
  state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_ONE);
  state->vtkglBlendEquation(GL_FUNC_ADD);
  // vtkOpenGLState caches one blend equation for all targets: the per-target ones are set
  // directly and put back to FUNC_ADD afterwards.
  for (size_t t = 0; t < this->Targets.size(); ++t)
  {
    if (this->Targets[t].Blending == Blend::Maximum)
    {
      glBlendEquationi(static_cast<GLuint>(t), GL_MAX);
    }
  }
  this->EmptyVertexArray->Bind();
  glDrawArrays(GL_POINTS, static_cast<GLint>(first), static_cast<GLsizei>(count));
  this->EmptyVertexArray->Release();
  for (size_t t = 0; t < this->Targets.size(); ++t)
  {
    if (this->Targets[t].Blending == Blend::Maximum)
    {
      glBlendEquationi(static_cast<GLuint>(t), GL_FUNC_ADD);
    }
  }
  state->PopFramebufferBindings();
}

//------------------------------------------------------------------------------
void vtkCVTSlotReduction::Read(
  vtkOpenGLRenderWindow* window, int target, std::vector<float>& values)
{
  const int components = this->Targets[static_cast<size_t>(target)].Components;
  values.resize(static_cast<size_t>(components) * this->SlotSize[0] * this->SlotSize[1]);
  cvtgl::ReadTarget(this->Framebuffer, window, target, this->SlotSize[0], this->SlotSize[1],
    components == 4 ? GL_RGBA : GL_RED, values.data());
}

//------------------------------------------------------------------------------
void vtkCVTSlotReduction::Release(vtkOpenGLRenderWindow* window)
{
  for (vtkTextureObject* texture : this->Textures)
  {
    texture->ReleaseGraphicsResources(window);
  }
  this->Framebuffer->ReleaseGraphicsResources(window);
  this->EmptyVertexArray->ReleaseGraphicsResources();
  this->SlotSize[0] = this->SlotSize[1] = 0;
}
