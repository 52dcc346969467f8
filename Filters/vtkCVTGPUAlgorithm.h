/**
 * @class   vtkCVTGPUAlgorithm
 * @brief   A CVT filter with an OpenGL engine and a CPU one: the Engine choice and the OpenGL
 *          engine's lifetime.
 *
 * Engine AUTO (default) takes the CPU engine (multi-threaded) when the only OpenGL is a software
 * renderer such as llvmpipe, or there is none, and on a hardware GPU whichever engine is faster
 * on a calibration job timed once per process; OPENGL is an
 * error without an OpenGL context. The choice and its reason are in the sites' field data
 * (Engine, EngineReason).
 *
 * The OpenGL engine (its context, compiled shaders and textures) lives as long as the filter,
 * so an update after a changed property pays only for what changed. SetRenderWindow runs it on
 * that window's context instead of one of its own (nullptr, the default, finds one);
 * ReleaseGraphicsResources frees the engine, its GL objects and context now (the next update
 * makes them again).
 */
#ifndef vtkCVTGPUAlgorithm_h
#define vtkCVTGPUAlgorithm_h

#include "cvtFiltersModule.h" // for export macro
#include "vtkCVTAlgorithm.h"
#include "vtkSmartPointer.h" // for OpenGLEngine

#include <string> // for std::string

class vtkCVTGPUEngine;
class vtkRenderWindow;

class CVTFILTERS_EXPORT vtkCVTGPUAlgorithm : public vtkCVTAlgorithm
{
public:
  vtkTypeMacro(vtkCVTGPUAlgorithm, vtkCVTAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** The engine: AUTO (default), OPENGL or CPU (see above). */
  enum Engines
  {
    AUTO = 0,
    OPENGL = 1,
    CPU = 2
  };
  vtkSetClampMacro(Engine, int, AUTO, CPU);
  vtkGetMacro(Engine, int);
  void SetEngineToAuto() { this->SetEngine(AUTO); }
  void SetEngineToOpenGL() { this->SetEngine(OPENGL); }
  void SetEngineToCPU() { this->SetEngine(CPU); }
  ///@}

  ///@{
  /**
   * On the OpenGL engine, shorten the jump flooding once the sites are spread, with a safeguard
   * that runs the full flooding again when a cell is larger than the short one reaches (on by
   * default; see vtkCVTGPUEngine::SetAdaptiveStep).
   */
  vtkSetMacro(AdaptiveJumpFlooding, bool);
  vtkGetMacro(AdaptiveJumpFlooding, bool);
  vtkBooleanMacro(AdaptiveJumpFlooding, bool);
  ///@}

  ///@{
  /** The OpenGL engine's context and lifetime (see above). */
  void SetRenderWindow(vtkRenderWindow* window);
  vtkRenderWindow* GetRenderWindow() const;
  void ReleaseGraphicsResources();
  ///@}

  /** Description of the OpenGL context the last run used (empty before a run or on the CPU). */
  const std::string& GetContextDescription() const { return this->ContextDescription; }
  /** Initial jump flooding step of the last run's last labelling (0 before a run or on the
   * CPU): shorter than the full step once AdaptiveJumpFlooding has shortened it. */
  int GetLastJumpFloodingStep() const { return this->LastJumpFloodingStep; }

protected:
  vtkCVTGPUAlgorithm();
  ~vtkCVTGPUAlgorithm() override;

  /** The input is an image (a density or a geometry image) and the labels output is an image
   * like it: its whole extent, spacing and origin. */
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  const char* GetLabelsDataType() const override { return "vtkImageData"; }
  /** Forgets the last run's context description, then runs as vtkCVTAlgorithm does. */
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  /** The kept OpenGL engine of type EngineType, made on first use, on the RenderWindow and with
   * the options above. */
  template<class EngineType>
  EngineType* GetOpenGLEngine()
  {
    if (!EngineType::SafeDownCast(this->OpenGLEngine))
    {
      this->OpenGLEngine = vtkSmartPointer<EngineType>::New();
    }
    this->ConfigureOpenGLEngine();
    return EngineType::SafeDownCast(this->OpenGLEngine);
  }

  int Engine = AUTO;
  bool AdaptiveJumpFlooding = true;
  std::string ContextDescription;
  int LastJumpFloodingStep = 0;

private:
  void ConfigureOpenGLEngine();

  vtkSmartPointer<vtkRenderWindow> RenderWindow;
  vtkSmartPointer<vtkCVTGPUEngine> OpenGLEngine; // made on first use, kept across updates

  vtkCVTGPUAlgorithm(const vtkCVTGPUAlgorithm&) = delete;
  void operator=(const vtkCVTGPUAlgorithm&) = delete;
};

#endif
