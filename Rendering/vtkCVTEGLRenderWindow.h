/**
 * @class   vtkCVTEGLRenderWindow
 * @brief   An OpenGL render window on a headless EGL context (no display needed).
 *
 * Debian's VTK builds know only X11 windows. This window makes its own EGL context (the
 * device platform on NVIDIA GPUs, Mesa's surfaceless platform otherwise, then the default
 * display), makes it current and hands it to VTK's OpenGL classes as a generic window.
 * VTK initialises GLEW through GLX, which fails with "no GLX display" under EGL although every
 * GL entry point loads; OpenGLInitContext accepts that case once GL >= 4.0 is confirmed.
 */
#ifndef vtkCVTEGLRenderWindow_h
#define vtkCVTEGLRenderWindow_h

#include "cvtRenderingModule.h" // for export macro
#include "vtkGenericOpenGLRenderWindow.h"

#include <string>

class CVTRENDERING_EXPORT vtkCVTEGLRenderWindow : public vtkGenericOpenGLRenderWindow
{
public:
  static vtkCVTEGLRenderWindow* New();
  vtkTypeMacro(vtkCVTEGLRenderWindow, vtkGenericOpenGLRenderWindow);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Create the EGL context and initialise VTK's OpenGL state on it. Returns false with a
   * message in GetLastError() when no EGL context with OpenGL >= 4.0 can be made.
   */
  bool CreateHeadlessContext();
  const std::string& GetLastError() const { return this->LastError; }
  /** Which EGL platform the context came from ("device", "surfaceless", "default"). */
  const std::string& GetPlatformName() const { return this->PlatformName; }

  void MakeCurrent() override;
  void ReleaseCurrent() override;
  bool IsCurrent() override;
  int SupportsOpenGL() override { return this->Context != nullptr ? 1 : 0; }
  void Finalize() override;

protected:
  vtkCVTEGLRenderWindow();
  ~vtkCVTEGLRenderWindow() override;

  void OpenGLInitContext() override;

private:
  vtkCVTEGLRenderWindow(const vtkCVTEGLRenderWindow&) = delete;
  void operator=(const vtkCVTEGLRenderWindow&) = delete;

  bool TryDisplay(void* display, const char* platformName);
  void DestroyContext();

  void* Display = nullptr; // EGLDisplay
  void* Context = nullptr; // EGLContext
  void* Surface = nullptr; // EGLSurface (a small pbuffer, or none when surfaceless)
  std::string LastError;
  std::string PlatformName;
};

#endif
