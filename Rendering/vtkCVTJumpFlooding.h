// Private to CVT::Rendering: the jump flooding pass (1+JFA, Rong et al. 2011) shared by the
// OpenGL engines. It owns two ping-pong float textures with their framebuffers and the quad
// program; the distance is a GLSL snippet spliced into vtkCVTSeedVS.glsl and
// vtkCVTJumpFloodFS.glsl (the plane's or the geometry image's).
//
// It also chooses the initial step (Rong 3.1): the full one (half the next power of two of the
// grid side) until sites are known to be spread, then the smallest power of two that reaches
// twice the largest cell radius seen (in pixels), with a safeguard: a labelling whose largest
// cell radius, with a margin for JFA's own misses, is beyond what its step can reach is redone
// with the full step.
#ifndef vtkCVTJumpFlooding_h
#define vtkCVTJumpFlooding_h

#include "vtkNew.h" // for the textures

#include <functional>
#include <memory>

class vtkOpenGLFramebufferObject;
class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkOpenGLVertexArrayObject;
class vtkShaderProgram;
class vtkTextureObject;

class vtkCVTJumpFlooding
{
public:
  /// `distance`: the GLSL source of vtkCVTPlaneDistance or vtkCVTSurfaceDistance.
  explicit vtkCVTJumpFlooding(const char* distance);
  ~vtkCVTJumpFlooding();

  /// Two width x height RGBA float textures, each with a framebuffer and a depth buffer (the
  /// seeding keeps the lowest site id per pixel by depth test); storage follows sizes. A new
  /// grid starts from the full step.
  bool Allocate(vtkOpenGLRenderWindow* window, int width, int height);

  ///@{
  /// The initial step: with `adaptive`, the one the last accepted labelling asks for.
  int GetInitialStep(bool adaptive) const
  {
    return adaptive ? this->NextInitialStep : this->FullInitialStep;
  }
  int GetFullStep() const { return this->FullInitialStep; }
  /// A new site set: nothing is known about its spacing. (The same number of sites moved by an
  /// optimiser's step keeps the adaptive step; the safeguard catches large moves.)
  void ForgetSpacing() { this->NextInitialStep = this->FullInitialStep; }
  /// Whether a labelling from `initialStep` whose farthest pixel lies `maximumRadius` pixels
  /// from its site can be trusted; if so the next step follows that radius, else the caller
  /// labels again with the full step (counted in GetNumberOfFallbacks).
  bool AcceptLabelling(int initialStep, double maximumRadius);
  int GetLastInitialStep() const { return this->LastInitialStep; }
  double GetLastMaximumRadius() const { return this->LastMaximumRadius; }
  int GetNumberOfFallbacks() const { return this->Fallbacks; }
  ///@}

  vtkTextureObject* GetTexture(int i) { return this->Textures[i]; }
  vtkOpenGLFramebufferObject* GetFramebuffer(int i) { return this->Framebuffers[i]; }

  /// The smallest power of two at or above `value` (at most 2^30).
  static int NextPowerOfTwo(double value);

  /// The step that reaches across the whole grid: half the power of two at or above its side.
  static int FullStep(int width, int height);

  /// Draws one seed per site into the pixel that holds it (the slot texture `sites`, read
  /// through the distance's cvtSeedPixel and cvtSeedTexel): the lowest id wins a shared pixel,
  /// and a site that lost its pixel gets a free neighbouring one that takes part, so no site
  /// is dropped. `setUniforms` sets the distance's own uniforms (and activates its textures).
  /// The caller sets the viewport and saves the depth state. Returns the texture that holds
  /// the seeds, -1 when the shader did not compile.
  int Seed(vtkOpenGLRenderWindow* window, vtkTextureObject* sites, const int slotSize[2],
    int numberOfSites, const int gridSize[2],
    const std::function<void(vtkShaderProgram*)>& setUniforms);

  /// 1+JFA from the seeds in texture `seeded`: one pass of step 1, then initialStep,
  /// initialStep / 2, ..., 1, each pixel keeping its nearest site. `setUniforms` sets the
  /// distance's own uniforms (and activates its textures). The caller sets the viewport and
  /// disables blending and depth. Returns which texture holds the labelling, -1 when the shader
  /// did not compile.
  int Flood(vtkOpenGLRenderWindow* window, int seeded, int initialStep, const int gridSize[2],
    const std::function<void(vtkShaderProgram*)>& setUniforms);

  /// Frees the textures, framebuffers, vertex array and program.
  void Release(vtkOpenGLRenderWindow* window);

private:
  const char* Distance;
  int FullInitialStep = 1;
  int NextInitialStep = 1;
  int LastInitialStep = 0;
  double LastMaximumRadius = 0.0;
  int Fallbacks = 0;
  vtkNew<vtkTextureObject> Textures[2];
  vtkNew<vtkOpenGLFramebufferObject> Framebuffers[2];
  vtkNew<vtkOpenGLVertexArrayObject> EmptyVertexArray; // the seeds are drawn from gl_VertexID
  std::unique_ptr<vtkOpenGLQuadHelper> Quad;
};

#endif
