/**
 * @class   vtkCVTGPUEngine
 * @brief   What the OpenGL CVT engines share: their context (their own, or a render window's
 *          handed in) and the lifetime of their GL objects.
 *
 * A subclass frees its GL objects in ReleaseObjects(), which ReleaseGraphicsResources() calls
 * with the context current: on request, when the context changes, and from the subclass's
 * destructor (a base class cannot reach a subclass's objects from its own).
 */
#ifndef vtkCVTGPUEngine_h
#define vtkCVTGPUEngine_h

#include "cvtRenderingModule.h" // for export macro
#include "vtkNew.h"             // for Context
#include "vtkObject.h"

#include <string> // for std::string

class vtkCVTOpenGLContext;
class vtkOpenGLRenderWindow;
class vtkRenderWindow;

class CVTRENDERING_EXPORT vtkCVTGPUEngine : public vtkObject
{
public:
  vtkTypeMacro(vtkCVTGPUEngine, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** Which OpenGL context the engine runs on (empty before it has one). */
  std::string GetContextDescription() const;
  /** The engine's OpenGL context (tests count its live objects). */
  vtkCVTOpenGLContext* GetContext() const { return this->Context; }

  /**
   * Run on this render window's OpenGL context instead of one of the engine's own (see
   * vtkCVTOpenGLContext::SetRenderWindow); nullptr (the default) finds one. A change of context
   * releases the engine's GL objects, so its domain must be set again.
   */
  void SetRenderWindow(vtkRenderWindow* window);

  /** Free every GL object now (also done on destruction). */
  void ReleaseGraphicsResources();

protected:
  vtkCVTGPUEngine();
  ~vtkCVTGPUEngine() override;

  /** Free the subclass's GL objects; `window`'s context is current. */
  virtual void ReleaseObjects(vtkOpenGLRenderWindow* window) = 0;

  vtkNew<vtkCVTOpenGLContext> Context;

private:
  vtkCVTGPUEngine(const vtkCVTGPUEngine&) = delete;
  void operator=(const vtkCVTGPUEngine&) = delete;
};

#endif
