/**
 * @class   vtkCVTOpenGLContext
 * @brief   Finds an OpenGL >= 4.0 context for the CVT engine, with or without a display.
 *
 * Tries, in order: a headless EGL context (vtkCVTEGLRenderWindow), then VTK's own offscreen
 * render window when an X display is set. The environment variable CVT_OPENGL_CONTEXT
 * narrows the choice: "egl", "window", or "none" (no context at all: used to test the error
 * path). MakeCurrent() remembers whatever EGL or GLX context the thread had (ParaView renders
 * from the same thread) and RestorePrevious() puts it back.
 */
#ifndef vtkCVTOpenGLContext_h
#define vtkCVTOpenGLContext_h

#include "cvtRenderingModule.h" // for export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // for ivar

#include <memory> // for unique_ptr
#include <string> // for std::string

class vtkOpenGLRenderWindow;

class CVTRENDERING_EXPORT vtkCVTOpenGLContext : public vtkObject
{
public:
  static vtkCVTOpenGLContext* New();
  vtkTypeMacro(vtkCVTOpenGLContext, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Use the context of this render window instead of finding one (the SetRenderWindow pattern of
   * VTK's GPU image filters: an application or a view shares its context). It must have, or be
   * able to initialise, an OpenGL >= 4.0 context; it is never finalised here. nullptr goes back
   * to a context of our own. A context already in use is let go: its owner (an engine) must have
   * released its GL objects first.
   */
  void SetRenderWindow(vtkOpenGLRenderWindow* window);
  vtkOpenGLRenderWindow* GetHandedInWindow() const;

  /** Find a context. Returns false with a message in GetLastError() when there is none. */
  bool Initialize();
  bool IsInitialized() const { return this->Window != nullptr; }
  vtkOpenGLRenderWindow* GetRenderWindow() const;

  /** Make the context current, remembering the thread's previous context. */
  void MakeCurrent();
  /** Make the previously current context current again (or none). */
  void RestorePrevious();

  const std::string& GetLastError() const { return this->LastError; }
  /** "EGL device", "EGL surfaceless", "X11 offscreen window", plus the GL renderer string. */
  const std::string& GetDescription() const { return this->Description; }
  /** Largest texture side the context supports. */
  int GetMaximumTextureSize() const { return this->MaximumTextureSize; }
  /** Whether the renderer draws on the CPU (llvmpipe, softpipe, swrast). */
  bool IsSoftwareRenderer() const { return this->SoftwareRenderer; }
  /**
   * Bytes free for textures, 0 when unknown: the GPU's free memory where the driver tells it
   * (NVIDIA's GL_NVX_gpu_memory_info), the system's available memory for software renderers.
   */
  double GetAvailableMemory() const;
  /**
   * "" or why textures of width x height pixels do not fit this context: a side beyond the
   * largest texture, or more memory than is free at `gpuBytesPerPixel` on a GPU and
   * `softwareBytesPerPixel` on a software renderer (its textures and its own copies, in system
   * memory). `what` names them ("the grid"), `advice` says what to do ("use a coarser image").
   */
  std::string CheckTextures(int width, int height, double gpuBytesPerPixel,
    double softwareBytesPerPixel, const std::string& what, const std::string& advice) const;

  /**
   * How often the CVT engines gave a texture storage in this process. Storage follows sizes
   * (domain, site count), so evaluations and optimiser steps add nothing; tests check this.
   */
  static long long GetNumberOfTextureAllocations();
  static void CountTextureAllocation();

protected:
  vtkCVTOpenGLContext();
  ~vtkCVTOpenGLContext() override;

private:
  vtkCVTOpenGLContext(const vtkCVTOpenGLContext&) = delete;
  void operator=(const vtkCVTOpenGLContext&) = delete;

  /** Stops using the current window, finalising it if it is our own. */
  void LetGo();

  struct SavedContext;
  std::unique_ptr<SavedContext> Saved;
  vtkSmartPointer<vtkOpenGLRenderWindow> Window;
  vtkSmartPointer<vtkOpenGLRenderWindow> HandedIn; // see SetRenderWindow
  void* XDisplay = nullptr; // our X window's connection (Display*), closed after the window
  std::string LastError;
  std::string Description;
  int MaximumTextureSize = 0;
  bool SoftwareRenderer = false;
  bool HasMemoryInfo = false; // GL_NVX_gpu_memory_info
};

#endif
