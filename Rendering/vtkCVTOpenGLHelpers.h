// Private to CVT::Rendering: small helpers shared by the GPU engines, on VTK's OpenGL classes.
#ifndef vtkCVTOpenGLHelpers_h
#define vtkCVTOpenGLHelpers_h

#include <memory>
#include <string>

class vtkCVTOpenGLContext;
class vtkOpenGLFramebufferObject;
class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkTextureObject;

namespace cvtgl
{

/// Makes an engine's context current for the lifetime of the object and gives the thread its
/// previous context back afterwards, whatever path the caller leaves by.
class ScopedContext
{
public:
  explicit ScopedContext(vtkCVTOpenGLContext* context);
  ~ScopedContext();
  ScopedContext(const ScopedContext&) = delete;
  ScopedContext& operator=(const ScopedContext&) = delete;

private:
  vtkCVTOpenGLContext* Context;
};

/// Makes `texture` a nearest-filtered float texture of the given size and components and
/// uploads `data` when given. Storage follows sizes: it is specified only when the texture has
/// none of that size and format (counted by vtkCVTOpenGLContext::GetNumberOfTextureAllocations);
/// otherwise `data` replaces the texels in place.
bool AllocateFloatTexture(vtkTextureObject* texture, vtkOpenGLRenderWindow* window, int width,
  int height, int components, const float* data = nullptr);

/// Lays `sites` slots out in a near-square block (site i at texel (i % width, i / width), as
/// vtkCVTSlots.glsl addresses them); false when they do not fit in maximumSize^2 texels.
bool LayoutSlots(int sites, int maximumSize, int slotSize[2]);

/// Attaches the targets (and a depth buffer when asked) to the framebuffer; false if incomplete.
bool AttachTargets(vtkOpenGLFramebufferObject* framebuffer, vtkOpenGLRenderWindow* window,
  vtkTextureObject* target0, vtkTextureObject* target1 = nullptr, bool depth = false);

/// A shader's source with the shared GLSL spliced in: the slot addressing (vtkCVTSlots.glsl) at
/// //CVT::Slots::Dec and, when given, a distance (vtkCVTPlaneDistance.glsl or
/// vtkCVTSurfaceDistance.glsl) at //CVT::Distance::Dec.
std::string SpliceShader(const char* source, const char* distance = nullptr);

/// Compiles (once; VTK's shader cache keeps it) and binds a point-drawing program of spliced
/// sources (the distance, when given, goes into the vertex shader); nullptr if it did not
/// compile.
vtkShaderProgram* ReadyProgram(vtkOpenGLRenderWindow* window, const char* vertex,
  const char* fragment, const char* distance = nullptr);

/// Creates a full-screen quad program of a spliced fragment shader on first use and binds it;
/// nullptr if it did not compile.
vtkShaderProgram* ReadyQuad(std::unique_ptr<vtkOpenGLQuadHelper>& quad,
  vtkOpenGLRenderWindow* window, const char* fragment, const char* distance = nullptr);

/// Reads a float render target back (format GL_RGBA or GL_RED).
void ReadTarget(vtkOpenGLFramebufferObject* framebuffer, vtkOpenGLRenderWindow* window,
  int attachment, int width, int height, unsigned int format, float* out);

/// Empty when OpenGL reports no error, else "OpenGL error 0x... during <where>"; clears the
/// error flags.
std::string GLErrorMessage(const char* where);

/// Binds `framebuffer` for drawing into its first target with a less-than depth test, and
/// clears it to -1 in every component ("nothing here", whatever the texel layout) and depth 1:
/// the set-up of every "keep the nearest" scatter (seeds, constrained centroids).
void BindForNearestScatter(vtkOpenGLFramebufferObject* framebuffer, vtkOpenGLRenderWindow* window);

/// The OpenGL version the engines need, as 10 * major + minor: they call 4.0 functions
/// (per-target blending, glBlendEquationi).
constexpr int MinimumOpenGLVersion = 40;

/// The current context's version as 10 * major + minor (0 when GL cannot say).
int CurrentOpenGLVersion();

/// "OpenGL 4.5" for 45; "no usable OpenGL" for 0.
std::string OpenGLVersionText(int version);

} // namespace cvtgl

#endif
