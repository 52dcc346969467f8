#include "vtkCVTEGLRenderWindow.h"

#include "vtkCVTOpenGLHelpers.h"
#include "vtkObjectFactory.h"
#include "vtk_glew.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

vtkStandardNewMacro(vtkCVTEGLRenderWindow);

//------------------------------------------------------------------------------
vtkCVTEGLRenderWindow::vtkCVTEGLRenderWindow()
{
  this->SetOwnContext(0);
  this->SetSize(16, 16);
}

//------------------------------------------------------------------------------
vtkCVTEGLRenderWindow::~vtkCVTEGLRenderWindow()
{
  this->Finalize();
}

//------------------------------------------------------------------------------
bool vtkCVTEGLRenderWindow::CreateHeadlessContext()
{
  if (this->Context)
  {
    return true;
  }
  this->LastError.clear();
  auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
    eglGetProcAddress("eglGetPlatformDisplayEXT"));
  auto queryDevices =
    reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));

  // 1. A GPU without any window system (NVIDIA's EGL device platform).
  if (getPlatformDisplay && queryDevices)
  {
    EGLDeviceEXT devices[8];
    EGLint count = 0;
    if (queryDevices(8, devices, &count))
    {
      for (EGLint i = 0; i < count && !this->Context; ++i)
      {
        this->TryDisplay(
          getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr), "device");
      }
    }
  }
  // 2. Mesa's surfaceless platform (llvmpipe or a Mesa GPU driver, no display).
  if (!this->Context && getPlatformDisplay)
  {
    this->TryDisplay(
      getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr),
      "surfaceless");
  }
  // 3. Whatever the EGL vendor offers by default.
  if (!this->Context)
  {
    this->TryDisplay(eglGetDisplay(EGL_DEFAULT_DISPLAY), "default");
  }
  if (!this->Context)
  {
    if (this->LastError.empty())
    {
      this->LastError = "no EGL display could be opened";
    }
    return false;
  }

  this->InitializeFromCurrentContext();
  if (!this->Initialized)
  {
    this->LastError = "VTK could not initialise OpenGL on the EGL context: " + this->LastError;
    this->DestroyContext();
    return false;
  }
  this->SetReadyForRendering(true);
  this->SetIsCurrent(true);
  this->SetMapped(1);
  return true;
}

//------------------------------------------------------------------------------
bool vtkCVTEGLRenderWindow::TryDisplay(void* displayHandle, const char* platformName)
{
  EGLDisplay display = static_cast<EGLDisplay>(displayHandle);
  if (display == EGL_NO_DISPLAY)
  {
    return false;
  }
  EGLint major = 0, minor = 0;
  if (!eglInitialize(display, &major, &minor) || !eglBindAPI(EGL_OPENGL_API))
  {
    this->LastError = std::string("eglInitialize failed on the ") + platformName + " platform";
    return false; // displays are per-process singletons: never terminated here (see DestroyContext)
  }
  const EGLint pbufferConfig[] = { EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE,
    EGL_OPENGL_BIT, EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8, EGL_ALPHA_SIZE, 8,
    EGL_DEPTH_SIZE, 24, EGL_NONE };
  const EGLint anyConfig[] = { EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE };
  EGLConfig config = nullptr;
  EGLint numConfigs = 0;
  bool pbuffer = eglChooseConfig(display, pbufferConfig, &config, 1, &numConfigs) && numConfigs > 0;
  if (!pbuffer && !(eglChooseConfig(display, anyConfig, &config, 1, &numConfigs) && numConfigs > 0))
  {
    this->LastError =
      std::string("no OpenGL-capable EGL config on the ") + platformName + " platform";
    return false;
  }
  // NVIDIA gives exactly the version asked for (a 3.2 context lacks the 4.0 entry points the
  // engine calls, such as glBlendEquationi); Mesa gives its newest core version whatever is
  // asked. So ask for the newest first.
  EGLContext context = EGL_NO_CONTEXT;
  const EGLint versions[][2] = { { 4, 6 }, { 4, 5 }, { 4, 3 }, { 4, 1 }, { 4, 0 } };
  for (const auto& version : versions)
  {
    const EGLint contextAttributes[] = { EGL_CONTEXT_MAJOR_VERSION, version[0],
      EGL_CONTEXT_MINOR_VERSION, version[1], EGL_CONTEXT_OPENGL_PROFILE_MASK,
      EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE };
    context = eglCreateContext(display, config, EGL_NO_CONTEXT, contextAttributes);
    if (context != EGL_NO_CONTEXT)
    {
      break;
    }
  }
  if (context == EGL_NO_CONTEXT)
  {
    this->LastError = std::string("no OpenGL 4.0 core context could be created on the ") +
      platformName + " platform";
    return false;
  }
  // A small pbuffer gives VTK a default framebuffer to query; surfaceless works without.
  EGLSurface surface = EGL_NO_SURFACE;
  if (pbuffer)
  {
    const EGLint surfaceAttributes[] = { EGL_WIDTH, 16, EGL_HEIGHT, 16, EGL_NONE };
    surface = eglCreatePbufferSurface(display, config, surfaceAttributes);
  }
  if (!eglMakeCurrent(display, surface, surface, context))
  {
    this->LastError =
      std::string("the EGL context of the ") + platformName + " platform could not be made current";
    if (surface != EGL_NO_SURFACE)
    {
      eglDestroySurface(display, surface);
    }
    eglDestroyContext(display, context);
    return false;
  }
  this->Display = display;
  this->Context = context;
  this->Surface = surface;
  this->PlatformName = platformName;
  return true;
}

//------------------------------------------------------------------------------
void vtkCVTEGLRenderWindow::OpenGLInitContext()
{
  this->ContextCreationTime.Modified();
  if (this->Initialized)
  {
    return;
  }
  // GLEW loads the GL entry points first, then fails in its GLX step because there is no X
  // display: GLEW_ERROR_NO_GLX_DISPLAY is expected here and harmless.
  const GLenum result = glewInit();
  if (result != GLEW_OK && result != GLEW_ERROR_NO_GLX_DISPLAY)
  {
    this->LastError = std::string("GLEW could not be initialised: ") +
      reinterpret_cast<const char*>(glewGetErrorString(result));
    return;
  }
  const int version = cvtgl::CurrentOpenGLVersion();
  if (version < cvtgl::MinimumOpenGLVersion)
  {
    this->LastError = "the EGL context offers " + cvtgl::OpenGLVersionText(version) +
      ", but 4.0 or later is needed";
    return;
  }
  this->GlewInitValid = true;
  this->Initialized = true;
  this->MaximumHardwareLineWidth = 1.0;
}

//------------------------------------------------------------------------------
void vtkCVTEGLRenderWindow::MakeCurrent()
{
  if (this->Context)
  {
    eglMakeCurrent(static_cast<EGLDisplay>(this->Display), static_cast<EGLSurface>(this->Surface),
      static_cast<EGLSurface>(this->Surface), static_cast<EGLContext>(this->Context));
  }
}

//------------------------------------------------------------------------------
void vtkCVTEGLRenderWindow::ReleaseCurrent()
{
  if (this->Context && this->IsCurrent())
  {
    eglMakeCurrent(
      static_cast<EGLDisplay>(this->Display), EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  }
}

//------------------------------------------------------------------------------
bool vtkCVTEGLRenderWindow::IsCurrent()
{
  return this->Context != nullptr && eglGetCurrentContext() == this->Context;
}

//------------------------------------------------------------------------------
void vtkCVTEGLRenderWindow::Finalize()
{
  if (this->Context)
  {
    this->MakeCurrent();
    if (this->Initialized)
    {
      this->ReleaseGraphicsResources(this);
    }
    this->DestroyContext();
  }
}

//------------------------------------------------------------------------------
void vtkCVTEGLRenderWindow::DestroyContext()
{
  if (!this->Context)
  {
    return;
  }
  EGLDisplay display = static_cast<EGLDisplay>(this->Display);
  if (eglGetCurrentContext() == this->Context)
  {
    eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  }
  if (this->Surface)
  {
    eglDestroySurface(display, static_cast<EGLSurface>(this->Surface));
  }
  eglDestroyContext(display, static_cast<EGLContext>(this->Context));
  // The display is shared per process by EGL; terminating it would pull it from under other
  // users in the same process, so it is left initialised.
  this->Display = nullptr;
  this->Context = nullptr;
  this->Surface = nullptr;
  this->Initialized = false;
}

//------------------------------------------------------------------------------
void vtkCVTEGLRenderWindow::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Platform: " << (this->PlatformName.empty() ? "(none)" : this->PlatformName)
     << "\n";
  os << indent << "HasContext: " << (this->Context != nullptr) << "\n";
}
