#include "vtkCVTOpenGLHelpers.h"

#include "vtkCVTOpenGLContext.h"
#include "vtkCVTSlots.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace cvtgl
{

int CurrentOpenGLVersion()
{
  GLint major = 0, minor = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  return 10 * major + minor;
}

std::string OpenGLVersionText(int version)
{
  return version > 0 ? "OpenGL " + std::to_string(version / 10) + "." + std::to_string(version % 10)
                     : "no usable OpenGL";
}

ScopedContext::ScopedContext(vtkCVTOpenGLContext* context)
  : Context(context)
{
  this->Context->MakeCurrent();
}

ScopedContext::~ScopedContext()
{
  this->Context->RestorePrevious();
}

bool AllocateFloatTexture(vtkTextureObject* texture, vtkOpenGLRenderWindow* window, int width,
  int height, int components, const float* data)
{
  if (texture->GetHandle() && texture->GetContext() == window &&
    texture->GetWidth() == static_cast<unsigned int>(width) &&
    texture->GetHeight() == static_cast<unsigned int>(height) &&
    texture->GetComponents() == components && texture->GetVTKDataType() == VTK_FLOAT)
  {
    if (data)
    {
      texture->Activate();
      window->GetState()->vtkglPixelStorei(GL_UNPACK_ALIGNMENT, 1);
      glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, height,
        texture->GetFormat(VTK_FLOAT, components, false), GL_FLOAT, data);
      texture->Deactivate();
    }
    return true;
  }
  vtkCVTOpenGLContext::CountTextureAllocation();
  texture->SetContext(window);
  texture->SetMinificationFilter(vtkTextureObject::Nearest);
  texture->SetMagnificationFilter(vtkTextureObject::Nearest);
  texture->SetWrapS(vtkTextureObject::ClampToEdge);
  texture->SetWrapT(vtkTextureObject::ClampToEdge);
  if (data)
  {
    return texture->Create2DFromRaw(width, height, components, VTK_FLOAT, const_cast<float*>(data));
  }
  return texture->Allocate2D(width, height, components, VTK_FLOAT);
}

bool LayoutSlots(int sites, int maximumSize, int slotSize[2])
{
  slotSize[0] =
    std::max(1, std::min(maximumSize, static_cast<int>(std::ceil(std::sqrt(double(sites))))));
  slotSize[1] = (sites + slotSize[0] - 1) / slotSize[0];
  return sites > 0 && slotSize[1] <= maximumSize;
}

bool AttachTargets(vtkOpenGLFramebufferObject* framebuffer, vtkOpenGLRenderWindow* window,
  vtkTextureObject* target0, vtkTextureObject* target1, bool depth)
{
  framebuffer->SetContext(window);
  window->GetState()->PushFramebufferBindings();
  framebuffer->Bind();
  framebuffer->AddColorAttachment(0, target0);
  if (depth)
  {
    framebuffer->AddDepthAttachment();
  }
  if (target1)
  {
    framebuffer->AddColorAttachment(1, target1);
  }
  framebuffer->ActivateDrawBuffers(target1 ? 2 : 1);
  const bool complete = framebuffer->CheckFrameBufferStatus(GL_FRAMEBUFFER) != 0;
  window->GetState()->PopFramebufferBindings();
  return complete;
}

std::string SpliceShader(const char* source, const char* distance)
{
  std::string spliced = source;
  vtkShaderProgram::Substitute(spliced, "//CVT::Slots::Dec", vtkCVTSlots);
  if (distance)
  {
    vtkShaderProgram::Substitute(spliced, "//CVT::Distance::Dec", distance);
  }
  return spliced;
}

vtkShaderProgram* ReadyProgram(
  vtkOpenGLRenderWindow* window, const char* vertex, const char* fragment, const char* distance)
{
  return window->GetShaderCache()->ReadyShaderProgram(
    SpliceShader(vertex, distance).c_str(), SpliceShader(fragment).c_str(), "");
}

/// Creates a full-screen quad program on first use and binds it; nullptr if it did not compile.
vtkShaderProgram* ReadyQuad(std::unique_ptr<vtkOpenGLQuadHelper>& quad,
  vtkOpenGLRenderWindow* window, const char* fragment, const char* distance)
{
  if (!quad)
  {
    quad.reset(
      new vtkOpenGLQuadHelper(window, nullptr, SpliceShader(fragment, distance).c_str(), ""));
  }
  else
  {
    window->GetShaderCache()->ReadyShaderProgram(quad->Program);
  }
  return quad->Program && quad->Program->GetCompiled() ? quad->Program : nullptr;
}

/// Reads a float render target back (RGBA or R).
void ReadTarget(vtkOpenGLFramebufferObject* framebuffer, vtkOpenGLRenderWindow* window,
  int attachment, int width, int height, unsigned int format, float* out)
{
  vtkOpenGLState* state = window->GetState();
  state->PushFramebufferBindings();
  framebuffer->Bind(GL_READ_FRAMEBUFFER);
  framebuffer->ActivateReadBuffer(attachment);
  state->vtkglPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, format, GL_FLOAT, out);
  state->PopFramebufferBindings();
}

std::string GLErrorMessage(const char* where)
{
  const GLenum error = glGetError();
  if (error == GL_NO_ERROR)
  {
    return std::string();
  }
  while (glGetError() != GL_NO_ERROR)
  {
  }
  char code[16];
  std::snprintf(code, sizeof(code), "0x%x", error);
  return std::string("OpenGL error ") + code + " during " + where;
}

void BindForNearestScatter(vtkOpenGLFramebufferObject* framebuffer, vtkOpenGLRenderWindow* window)
{
  vtkOpenGLState* state = window->GetState();
  framebuffer->Bind();
  framebuffer->ActivateDrawBuffers(1);
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDepthFunc(GL_LESS);
  state->vtkglDepthMask(GL_TRUE);
  state->vtkglClearColor(-1.0f, -1.0f, -1.0f, -1.0f);
  state->vtkglClearDepth(1.0);
  state->vtkglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

} // namespace cvtgl
