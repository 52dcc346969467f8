// Private to CVT::Rendering: the regional reduction (Rong et al. 2011, 3.2) shared by the
// OpenGL engines. It owns float targets of one texel per site slot and their framebuffer; a
// scatter draws one point per pixel, which the caller's vertex shader moves to its site's slot,
// and blending combines the points there: summed, or kept at the largest.
#ifndef vtkCVTSlotReduction_h
#define vtkCVTSlotReduction_h

#include "vtkNew.h"  // for the framebuffer
#include "vtkType.h" // for vtkIdType

#include <vector>

class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkOpenGLVertexArrayObject;
class vtkTextureObject;

class vtkCVTSlotReduction
{
public:
  enum class Blend
  {
    Sum,
    Maximum
  };
  struct Target
  {
    int Components; // 1 or 4
    Blend Blending;
  };

  /// Up to four targets, in the order of the fragment shader's outputs.
  explicit vtkCVTSlotReduction(std::vector<Target> targets);
  ~vtkCVTSlotReduction();
  vtkCVTSlotReduction(const vtkCVTSlotReduction&) = delete;
  vtkCVTSlotReduction& operator=(const vtkCVTSlotReduction&) = delete;

  /// Targets of `slotSize` texels; storage follows sizes.
  bool Allocate(vtkOpenGLRenderWindow* window, const int slotSize[2]);

  /// Clears the targets and draws `count` attribute-less points, gl_VertexID from `first` on,
  /// with the bound program into them (the caller has set its uniforms and activated its
  /// textures).
  void Scatter(vtkOpenGLRenderWindow* window, vtkIdType first, vtkIdType count);

  /// Target `target`'s texels: Components floats per slot, row after row.
  void Read(vtkOpenGLRenderWindow* window, int target, std::vector<float>& values);

  vtkTextureObject* GetTexture(int target) { return this->Textures[target]; }

  /// Frees the targets, framebuffer and vertex array.
  void Release(vtkOpenGLRenderWindow* window);

private:
  std::vector<Target> Targets;
  std::vector<vtkTextureObject*> Textures; // owned
  vtkNew<vtkOpenGLFramebufferObject> Framebuffer;
  vtkNew<vtkOpenGLVertexArrayObject> EmptyVertexArray; // attribute-less point draws
  int SlotSize[2] = { 0, 0 };
};

#endif
