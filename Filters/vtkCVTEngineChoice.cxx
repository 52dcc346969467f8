#include "vtkCVTEngineChoice.h"

#include "vtkCVTOpenGLContext.h"
#include "vtkNew.h"

#include <algorithm>
#include <cctype>
#include <mutex>

namespace cvtvtk
{

namespace
{
/// What Auto learns from one probe of the OpenGL context (the GPU does not change while a
/// process runs; the probe's context is released at once).
EngineChoice ProbeOpenGL()
{
  EngineChoice choice;
  vtkNew<vtkCVTOpenGLContext> context;
  if (!context->Initialize())
  {
    choice.Name = "CPU";
    choice.Reason = "Auto: no OpenGL context (" + context->GetLastError() + ")";
    return choice;
  }
  if (context->IsSoftwareRenderer())
  {
    choice.Name = "CPU";
    choice.Reason =
      "Auto: the only OpenGL is a software renderer (" + context->GetDescription() + ")";
    return choice;
  }
  choice.UseOpenGL = true;
  choice.Name = "OpenGL";
  choice.Reason = "Auto: hardware OpenGL (" + context->GetDescription() + ")";
  return choice;
}
}

EngineChoice ChooseEngine(int requested)
{
  if (requested == ENGINE_OPENGL)
  {
    return { true, "OpenGL", "asked for OpenGL" };
  }
  if (requested == ENGINE_CPU)
  {
    return { false, "CPU", "asked for the CPU" };
  }
  static std::once_flag probed;
  static EngineChoice automatic;
  std::call_once(probed, []() { automatic = ProbeOpenGL(); });
  return automatic;
}

const char* EngineKindName(int kind)
{
  return kind == ENGINE_OPENGL ? "OpenGL" : (kind == ENGINE_CPU ? "CPU" : "Auto");
}

} // namespace cvtvtk
