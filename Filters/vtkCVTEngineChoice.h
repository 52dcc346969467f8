// Private to CVT::Filters: which engine a filter runs on. Auto takes the CPU engine when the only
// OpenGL is a software renderer (llvmpipe, softpipe, swrast: tens of times slower than the
// parallel CPU code) or there is none; on a hardware GPU it times both engines once per process
// on a small job and takes the faster.
#ifndef vtkCVTEngineChoice_h
#define vtkCVTEngineChoice_h

#include "cvtFiltersModule.h" // for export macro

#include <string>

class vtkRenderWindow;

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
  bool HardwareOpenGL = false; // Auto found a hardware GPU (and may still have taken the CPU)
  std::string Name;            // "OpenGL" or "CPU"
  std::string Reason;          // one sentence, for field data and the command line
  // Auto on a hardware GPU: a calibration Lloyd iteration's milliseconds (negative: not timed).
  double OpenGLMilliseconds = -1.0;
  double CPUMilliseconds = -1.0;
};

/// The engine for the `requested` EngineKind. Auto probes an OpenGL context once per process.
EngineChoice ChooseEngine(int requested);

/// Times both engines on one small job (1000 sites, 512x512, uniform) and takes the faster:
/// what Auto does on a hardware GPU, whose `contextDescription` goes into the reason. The OpenGL
/// engine runs on `window`'s context (nullptr: a context of its own).
CVTFILTERS_EXPORT EngineChoice CompareEngines(
  vtkRenderWindow* window, const std::string& contextDescription);

/// "Auto", "OpenGL" or "CPU".
const char* EngineKindName(int kind);

} // namespace cvtvtk

#endif
