#include "vtkCVTSiteSlots.h"

#include "vtkCVTOpenGLHelpers.h"

#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

//------------------------------------------------------------------------------
vtkCVTSiteSlots::vtkCVTSiteSlots(int copies)
{
  for (int c = 0; c < copies; ++c)
  {
    this->Textures.push_back(vtkTextureObject::New());
    if (copies > 1)
    {
      this->Framebuffers.push_back(vtkOpenGLFramebufferObject::New());
    }
  }
}

//------------------------------------------------------------------------------
vtkCVTSiteSlots::~vtkCVTSiteSlots()
{
  for (vtkTextureObject* texture : this->Textures)
  {
    texture->Delete();
  }
  for (vtkOpenGLFramebufferObject* framebuffer : this->Framebuffers)
  {
    framebuffer->Delete();
  }
}

//------------------------------------------------------------------------------
vtkCVTSiteSlots::Upload vtkCVTSiteSlots::Set(vtkOpenGLRenderWindow* window, int sites,
  int maximumSize, const std::function<void(int, float*)>& pack)
{
  int slotSize[2];
  if (sites <= 0 || !cvtgl::LayoutSlots(sites, maximumSize, slotSize))
  {
    return Upload::TooManySites;
  }
  std::vector<float> texels(static_cast<size_t>(slotSize[0]) * slotSize[1] * 4, 0.0f);
  for (int i = 0; i < sites; ++i)
  {
    pack(i, &texels[4 * static_cast<size_t>(i)]);
  }
  const bool laidOut = slotSize[0] == this->SlotSize[0] && slotSize[1] == this->SlotSize[1] &&
    this->Textures.back()->GetHandle() && this->Textures.back()->GetContext() == window;
  // Same layout: AllocateFloatTexture only uploads into copy 0.
  bool ok = cvtgl::AllocateFloatTexture(
    this->Textures[0], window, slotSize[0], slotSize[1], 4, texels.data());
  for (size_t c = 1; ok && !laidOut && c < this->Textures.size(); ++c)
  {
    ok = cvtgl::AllocateFloatTexture(this->Textures[c], window, slotSize[0], slotSize[1], 4);
  }
  for (size_t c = 0; ok && !laidOut && c < this->Framebuffers.size(); ++c)
  {
    ok = cvtgl::AttachTargets(this->Framebuffers[c], window, this->Textures[c]);
  }
  if (!ok)
  {
    this->Release(window);
    return Upload::OutOfResources;
  }
  this->Current = 0;
  this->NumberOfSites = sites;
  this->SlotSize[0] = slotSize[0];
  this->SlotSize[1] = slotSize[1];
  return Upload::Done;
}

//------------------------------------------------------------------------------
void vtkCVTSiteSlots::Read(vtkOpenGLRenderWindow* window, std::vector<float>& texels)
{
  texels.resize(static_cast<size_t>(this->SlotSize[0]) * this->SlotSize[1] * 4);
  cvtgl::ReadTarget(this->Framebuffers[this->Current], window, 0, this->SlotSize[0],
    this->SlotSize[1], GL_RGBA, texels.data());
}

//------------------------------------------------------------------------------
void vtkCVTSiteSlots::Release(vtkOpenGLRenderWindow* window)
{
  for (vtkTextureObject* texture : this->Textures)
  {
    texture->ReleaseGraphicsResources(window);
  }
  for (vtkOpenGLFramebufferObject* framebuffer : this->Framebuffers)
  {
    framebuffer->ReleaseGraphicsResources(window);
  }
  this->Current = 0;
  this->NumberOfSites = 0;
  this->SlotSize[0] = this->SlotSize[1] = 0;
}
