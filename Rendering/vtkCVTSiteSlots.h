// Private to CVT::Rendering: the sites as the OpenGL engines' shaders read them, one RGBA float
// texel per site (its "slot", laid out by cvtgl::LayoutSlots). It owns the slot textures: one,
// or two with framebuffers where a shader writes the next sites from the current ones (the 2D
// engine's Lloyd step on the GPU). Storage follows the site count, not the uploads; Release
// forgets the layout too, so that the next upload allocates again (on another context).
#ifndef vtkCVTSiteSlots_h
#define vtkCVTSiteSlots_h

#include <functional>
#include <vector>

class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkTextureObject;

class vtkCVTSiteSlots
{
public:
  /// `copies`: 1, or 2 (ping-pong: each copy then has a framebuffer to be drawn into).
  explicit vtkCVTSiteSlots(int copies);
  ~vtkCVTSiteSlots();
  vtkCVTSiteSlots(const vtkCVTSiteSlots&) = delete;
  vtkCVTSiteSlots& operator=(const vtkCVTSiteSlots&) = delete;

  enum class Upload
  {
    Done,
    TooManySites,   // more slots than textures of `maximumSize` hold
    OutOfResources, // the GPU refused the textures or framebuffers
  };

  /// `sites` sites into copy 0, which becomes the current one: `pack(i, texel)` writes site i's
  /// four floats. Textures (and framebuffers) are allocated only when the layout changes.
  Upload Set(vtkOpenGLRenderWindow* window, int sites, int maximumSize,
    const std::function<void(int, float*)>& pack);

  /// The current copy's texels (four floats per slot, row after row); two copies only.
  void Read(vtkOpenGLRenderWindow* window, std::vector<float>& texels);

  ///@{
  /** The copy holding the current sites, and (two copies) the other one's framebuffer, where
   * the next sites are drawn before Swap makes them current. */
  vtkTextureObject* GetCurrent() const { return this->Textures[this->Current]; }
  vtkOpenGLFramebufferObject* GetNextFramebuffer() const
  {
    return this->Framebuffers[1 - this->Current];
  }
  void Swap() { this->Current = 1 - this->Current; }
  ///@}

  /// How many sites were set (0: none since construction, Forget or Release).
  int GetNumberOfSites() const { return this->NumberOfSites; }
  const int* GetSlotSize() const { return this->SlotSize; }
  /// The sites are no longer valid (a new domain); the textures stay for the next Set.
  void Forget() { this->NumberOfSites = 0; }

  /// Frees the textures and framebuffers and forgets the layout.
  void Release(vtkOpenGLRenderWindow* window);

private:
  std::vector<vtkTextureObject*> Textures;               // owned, one per copy
  std::vector<vtkOpenGLFramebufferObject*> Framebuffers; // owned, two copies only
  int Current = 0;
  int NumberOfSites = 0;
  int SlotSize[2] = { 0, 0 };
};

#endif
