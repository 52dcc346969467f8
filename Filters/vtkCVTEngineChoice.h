// Private to CVT::Filters: which engine a filter runs on. Auto takes OpenGL on a hardware GPU
// and the CPU engine when the only OpenGL is a software renderer (llvmpipe, softpipe, swrast:
// tens of times slower than the parallel CPU code) or there is none.
#ifndef vtkCVTEngineChoice_h
#define vtkCVTEngineChoice_h

#include <string>

namespace cvtvtk
{

/// The values of the filters' Engine property.
enum EngineKind
{
  ENGINE_AUTO = 0,
  ENGINE_OPENGL = 1,
  ENGINE_CPU = 2
};

struct EngineChoice
{
  bool UseOpenGL = false;
  std::string Name;   // "OpenGL" or "CPU"
  std::string Reason; // one sentence, for field data and the command line
};

/// The engine for the `requested` EngineKind. Auto probes an OpenGL context once per process.
EngineChoice ChooseEngine(int requested);

/// "Auto", "OpenGL" or "CPU".
const char* EngineKindName(int kind);

} // namespace cvtvtk

#endif
