// Helpers shared by the tests of the OpenGL engines (and the filters' GL-object tests): a torus
// geometry image made without the filter layer, and a count of a context's live GL objects.
#ifndef cvtRenderingTestSupport_h
#define cvtRenderingTestSupport_h

#include "cvtSurface.h"
#include "vtkCVTOpenGLContext.h"
#include "vtk_glew.h"

#include <cmath>

namespace cvttest
{

/// The torus of ring radius 1 and tube radius 0.4 sampled on a w x h grid, both borders
/// wrapped (the same surface vtkCVTGeometryImageSource makes by default).
inline cvt::GeometryImage TorusGeometryImage(int w, int h)
{
  cvt::GeometryImage gi;
  gi.Width = w;
  gi.Height = h;
  gi.WrapU = gi.WrapV = true;
  gi.Position.resize(3 * static_cast<size_t>(w) * h);
  gi.Normal.resize(gi.Position.size());
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      const double u = 2.0 * M_PI * (i + 0.5) / w, v = 2.0 * M_PI * (j + 0.5) / h;
      const double normal[3] = { std::cos(u) * std::cos(v), std::sin(u) * std::cos(v),
        std::sin(v) };
      const size_t p = 3 * (static_cast<size_t>(j) * w + i);
      for (int c = 0; c < 3; ++c)
      {
        gi.Normal[p + c] = static_cast<float>(normal[c]);
      }
      gi.Position[p] = static_cast<float>((1.0 + 0.4 * std::cos(v)) * std::cos(u));
      gi.Position[p + 1] = static_cast<float>((1.0 + 0.4 * std::cos(v)) * std::sin(u));
      gi.Position[p + 2] = static_cast<float>(0.4 * std::sin(v));
    }
  }
  gi.AreaWeight = cvt::ComputeAreaWeights(gi);
  return gi;
}

/// Live OpenGL objects of a context: the names up to 4096 that are textures, framebuffers,
/// renderbuffers, buffers, vertex arrays, programs or shaders (names are small integers,
/// handed out from 1; a leak of one per update passes 4096 in a soak).
inline int LiveGLObjects(vtkCVTOpenGLContext* context)
{
  context->MakeCurrent();
  int live = 0;
  for (GLuint name = 1; name <= 4096; ++name)
  {
    live += (glIsTexture(name) ? 1 : 0) + (glIsFramebuffer(name) ? 1 : 0) +
      (glIsRenderbuffer(name) ? 1 : 0) + (glIsBuffer(name) ? 1 : 0) +
      (glIsVertexArray(name) ? 1 : 0) + (glIsProgram(name) ? 1 : 0) + (glIsShader(name) ? 1 : 0);
  }
  context->RestorePrevious();
  return live;
}

} // namespace cvttest

#endif
