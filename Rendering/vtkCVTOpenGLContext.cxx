#include "vtkCVTOpenGLContext.h"
#include "cvtMemory.h"

#include "vtkAutoInit.h"
#include "vtkCVTEGLRenderWindow.h"
#include "vtkCVTOpenGLHelpers.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkRenderWindow.h"
#include "vtk_glew.h"

#include <EGL/egl.h>
#include <GL/glx.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cstdlib>
#include <cstring>

// vtkRenderWindow::New() yields a stub unless the OpenGL2 factory overrides are registered.
VTK_MODULE_INIT(vtkRenderingOpenGL2);

vtkStandardNewMacro(vtkCVTOpenGLContext);

struct vtkCVTOpenGLContext::SavedContext
{
  EGLDisplay EglDisplay = EGL_NO_DISPLAY;
  EGLContext EglContext = EGL_NO_CONTEXT;
  EGLSurface EglDraw = EGL_NO_SURFACE, EglRead = EGL_NO_SURFACE;
  Display* GlxDisplay = nullptr;
  GLXContext GlxContext = nullptr;
  GLXDrawable GlxDraw = 0, GlxRead = 0;
  bool Valid = false;
};

//------------------------------------------------------------------------------
vtkCVTOpenGLContext::vtkCVTOpenGLContext()
  : Saved(new SavedContext)
{
}

//------------------------------------------------------------------------------
vtkCVTOpenGLContext::~vtkCVTOpenGLContext()
{
  this->LetGo();
}

//------------------------------------------------------------------------------
void vtkCVTOpenGLContext::SetRenderWindow(vtkOpenGLRenderWindow* window)
{
  if (window != this->HandedIn)
  {
    this->LetGo();
    this->HandedIn = window;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkCVTOpenGLContext::LetGo()
{
  if (this->Window && this->Window != this->HandedIn)
  {
    // Release every GL object of our own window while its context is current, then give the
    // thread its previous context back. A handed-in window is its owner's to finalise.
    this->MakeCurrent();
    this->Window->Finalize();
    this->RestorePrevious();
  }
  this->Window = nullptr;
  if (this->XDisplay)
  {
    XCloseDisplay(static_cast<Display*>(this->XDisplay));
    this->XDisplay = nullptr;
  }
}

//------------------------------------------------------------------------------
bool vtkCVTOpenGLContext::Initialize()
{
  if (this->Window)
  {
    return true;
  }
  const char* choice = std::getenv("CVT_OPENGL_CONTEXT");
  const std::string wanted = choice ? choice : "";
  const bool tryEgl = wanted.empty() || wanted == "egl";
  const char* display = std::getenv("DISPLAY");
  const bool haveDisplay = display != nullptr && display[0] != '\0';
  const bool tryWindow = (wanted.empty() || wanted == "window") && haveDisplay;
  std::string reasons;

  this->Saved->Valid = false;
  this->MakeCurrent(); // remembers the thread's context; no window yet
  if (this->HandedIn)
  {
    this->HandedIn->Initialize(); // nothing to do for a window that has its context
    this->HandedIn->MakeCurrent();
    const int version = this->HandedIn->IsCurrent() ? cvtgl::CurrentOpenGLVersion() : 0;
    if (version < cvtgl::MinimumOpenGLVersion)
    {
      this->LastError = std::string("the render window handed in (") +
        this->HandedIn->GetClassName() + ") has no OpenGL >= 4.0 context (it has " +
        cvtgl::OpenGLVersionText(version) + ")";
      this->RestorePrevious();
      return false;
    }
    this->Window = this->HandedIn;
    this->Description = std::string("handed-in ") + this->HandedIn->GetClassName();
  }
  if (!this->Window && tryEgl)
  {
    vtkNew<vtkCVTEGLRenderWindow> egl;
    if (egl->CreateHeadlessContext())
    {
      this->Window = egl;
      this->Description = "EGL " + egl->GetPlatformName();
    }
    else
    {
      reasons += "EGL: " + egl->GetLastError() + ". ";
    }
  }
  if (!this->Window && tryWindow)
  {
    // The connection is opened here and handed to VTK: VTK's X window aborts the process,
    // silently when its error output is off, on a server that refuses it (not running, busy).
    Display* xDisplay = XOpenDisplay(nullptr);
    if (!xDisplay)
    {
      reasons += std::string("X11 window: cannot connect to the X server DISPLAY=") + display +
        " (is it running?). ";
    }
    else
    {
      vtkSmartPointer<vtkRenderWindow> window = vtkSmartPointer<vtkRenderWindow>::New();
      auto* openGLWindow = vtkOpenGLRenderWindow::SafeDownCast(window);
      if (openGLWindow)
      {
        openGLWindow->SetDisplayId(xDisplay);
        openGLWindow->SetOffScreenRendering(1);
        openGLWindow->SetSize(16, 16);
        openGLWindow->Initialize();
        int version = 0;
        if (openGLWindow->GetGenericContext())
        {
          openGLWindow->MakeCurrent();
          version = cvtgl::CurrentOpenGLVersion();
        }
        if (version >= cvtgl::MinimumOpenGLVersion)
        {
          this->Window = openGLWindow;
          this->XDisplay = xDisplay;
          this->Description = "X11 offscreen window";
        }
        else
        {
          reasons += "X11 window: it could not be initialised with OpenGL >= 4.0 (it has " +
            cvtgl::OpenGLVersionText(version) + "). ";
          openGLWindow->Finalize();
        }
      }
      window = nullptr; // the window goes before its connection
      if (!this->XDisplay)
      {
        XCloseDisplay(xDisplay);
      }
    }
  }
  if (!this->Window)
  {
    if (!tryWindow && !haveDisplay && wanted != "egl" && wanted != "none")
    {
      reasons += "X11 window: no DISPLAY is set. ";
    }
    if (wanted == "none")
    {
      reasons += "CVT_OPENGL_CONTEXT=none forbids every context. ";
    }
    this->LastError = "no OpenGL >= 4.0 context is available (" + reasons +
      ") Install Mesa's EGL (libegl1, libegl-mesa0) or a GPU driver with EGL, or run under an "
      "X server.";
    this->RestorePrevious();
    return false;
  }
  this->Window->MakeCurrent();
  const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  this->Description += std::string(": ") + (renderer ? renderer : "unknown renderer");
  GLint size = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &size);
  this->MaximumTextureSize = size;
  std::string lower = renderer ? renderer : "";
  std::transform(lower.begin(), lower.end(), lower.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  this->SoftwareRenderer = false;
  for (const char* software : { "llvmpipe", "softpipe", "swrast", "software rasterizer" })
  {
    this->SoftwareRenderer = this->SoftwareRenderer || lower.find(software) != std::string::npos;
  }
  GLint extensions = 0;
  glGetIntegerv(GL_NUM_EXTENSIONS, &extensions);
  this->HasMemoryInfo = false;
  for (GLint i = 0; i < extensions && !this->HasMemoryInfo; ++i)
  {
    const char* name = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, i));
    this->HasMemoryInfo = name && std::strcmp(name, "GL_NVX_gpu_memory_info") == 0;
  }
  this->RestorePrevious();
  return true;
}

//------------------------------------------------------------------------------
double vtkCVTOpenGLContext::GetAvailableMemory() const
{
  if (!this->Window)
  {
    return 0.0;
  }
  if (this->SoftwareRenderer)
  {
    return cvt::AvailableSystemMemory();
  }
  if (!this->HasMemoryInfo)
  {
    return 0.0;
  }
  constexpr GLenum CurrentAvailableVideoMemoryNVX = 0x9049; // in KiB
  auto* self = const_cast<vtkCVTOpenGLContext*>(this);
  self->MakeCurrent();
  GLint kilobytes = 0;
  glGetIntegerv(CurrentAvailableVideoMemoryNVX, &kilobytes);
  self->RestorePrevious();
  return 1024.0 * kilobytes;
}

//------------------------------------------------------------------------------
std::string vtkCVTOpenGLContext::CheckTextures(int width, int height, double gpuBytesPerPixel,
  double softwareBytesPerPixel, const std::string& what, const std::string& advice) const
{
  const std::string size = std::to_string(width) + " x " + std::to_string(height) + " pixels";
  const int largest = this->MaximumTextureSize;
  if (width > largest || height > largest)
  {
    return what + " of " + size + " exceeds this GPU's largest texture (" +
      std::to_string(largest) + " x " + std::to_string(largest) + "); " + advice;
  }
  const double pixels = static_cast<double>(width) * height;
  return cvt::CheckMemory(
    pixels * (this->SoftwareRenderer ? softwareBytesPerPixel : gpuBytesPerPixel),
    this->GetAvailableMemory(), what + " of " + size,
    this->SoftwareRenderer ? "memory (software OpenGL)" : "GPU memory",
    advice + " or the CPU engine");
}

//------------------------------------------------------------------------------
namespace
{
std::atomic<long long> TextureAllocations{ 0 };
}

long long vtkCVTOpenGLContext::GetNumberOfTextureAllocations()
{
  return TextureAllocations;
}

void vtkCVTOpenGLContext::CountTextureAllocation()
{
  ++TextureAllocations;
}

//------------------------------------------------------------------------------
vtkOpenGLRenderWindow* vtkCVTOpenGLContext::GetHandedInWindow() const
{
  return this->HandedIn;
}

//------------------------------------------------------------------------------
vtkOpenGLRenderWindow* vtkCVTOpenGLContext::GetRenderWindow() const
{
  return this->Window;
}

//------------------------------------------------------------------------------
void vtkCVTOpenGLContext::MakeCurrent()
{
  SavedContext& saved = *this->Saved;
  saved.EglDisplay = eglGetCurrentDisplay();
  saved.EglContext = eglGetCurrentContext();
  saved.EglDraw = eglGetCurrentSurface(EGL_DRAW);
  saved.EglRead = eglGetCurrentSurface(EGL_READ);
  saved.GlxContext = glXGetCurrentContext();
  saved.GlxDisplay = saved.GlxContext ? glXGetCurrentDisplay() : nullptr;
  saved.GlxDraw = saved.GlxContext ? glXGetCurrentDrawable() : 0;
  saved.GlxRead = saved.GlxContext ? glXGetCurrentReadDrawable() : 0;
  saved.Valid = true;
  // libglvnd keeps one current context per thread and will not make an EGL context current
  // while a GLX one is (eglMakeCurrent fails): release the GLX context first, also before the
  // EGL context is created in Initialize().
  if (saved.GlxContext)
  {
    glXMakeContextCurrent(saved.GlxDisplay, None, None, nullptr);
  }
  if (this->Window)
  {
    this->Window->MakeCurrent();
  }
}

//------------------------------------------------------------------------------
void vtkCVTOpenGLContext::RestorePrevious()
{
  SavedContext& saved = *this->Saved;
  if (!saved.Valid)
  {
    return;
  }
  saved.Valid = false;
  if (saved.EglContext != EGL_NO_CONTEXT)
  {
    if (eglGetCurrentContext() != saved.EglContext)
    {
      eglMakeCurrent(saved.EglDisplay, saved.EglDraw, saved.EglRead, saved.EglContext);
    }
  }
  else if (saved.GlxContext)
  {
    if (glXGetCurrentContext() != saved.GlxContext)
    {
      if (eglGetCurrentContext() != EGL_NO_CONTEXT)
      {
        // One API at a time (see MakeCurrent).
        eglMakeCurrent(eglGetCurrentDisplay(), EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
      }
      glXMakeContextCurrent(saved.GlxDisplay, saved.GlxDraw, saved.GlxRead, saved.GlxContext);
    }
  }
  else if (this->Window && this->Window->IsCurrent())
  {
    this->Window->ReleaseCurrent();
  }
}

//------------------------------------------------------------------------------
void vtkCVTOpenGLContext::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Context: " << (this->Window ? this->Description : std::string("(none)")) << "\n";
  os << indent << "MaximumTextureSize: " << this->MaximumTextureSize << "\n";
  os << indent << "SoftwareRenderer: " << this->SoftwareRenderer << "\n";
  if (!this->LastError.empty())
  {
    os << indent << "LastError: " << this->LastError << "\n";
  }
}
