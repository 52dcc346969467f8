/**
 * @class   vtkCVTGPUEngine
 * @brief   What the OpenGL CVT engines share: their context (their own, or a render window's
 *          handed in), the lifetime of their GL objects, the jump flooding's adaptive step and
 *          the timings.
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

#include <memory> // for unique_ptr
#include <string> // for std::string

namespace cvt
{
struct CellSums;
}
class vtkCVTJumpFlooding;
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

  ///@{
  /**
   * Shrink the initial JFA step once sites are spread (Rong 3.1), with the safeguard (see
   * vtkCVTJumpFlooding). On by default; off runs the full 1+JFA every time.
   */
  vtkSetMacro(AdaptiveStep, bool);
  vtkGetMacro(AdaptiveStep, bool);
  vtkBooleanMacro(AdaptiveStep, bool);
  ///@}

  /** Initial JFA step of the last labelling, and how often the safeguard fell back. */
  int GetLastInitialStep() const;
  int GetNumberOfSafeguardFallbacks() const;
  /** Largest distance (pixels) of a pixel from its site (on a geometry image: from the site's
   * pixel), last labelling. */
  double GetLastMaximumCellRadius() const;

  ///@{
  /**
   * Wait for the GPU after each phase so that the phase timings below are true (benchmarks);
   * off by default, since waiting costs throughput.
   */
  vtkSetMacro(MeasureTimings, bool);
  vtkGetMacro(MeasureTimings, bool);
  ///@}

  /** Milliseconds of the last labelling (seed + JFA) and reduction (+ readback). */
  double GetLastLabelMilliseconds() const { return this->LastLabelMilliseconds; }
  double GetLastReductionMilliseconds() const { return this->LastReductionMilliseconds; }

protected:
  /** `distance`: the jump flooding's distance, vtkCVTPlaneDistance or vtkCVTSurfaceDistance. */
  explicit vtkCVTGPUEngine(const char* distance);
  ~vtkCVTGPUEngine() override;

  /** Free the subclass's GL objects; `window`'s context is current. */
  virtual void ReleaseObjects(vtkOpenGLRenderWindow* window) = 0;

  ///@{
  /**
   * The two halves of ComputeCellSums, on the current context: label every pixel (seed, then
   * 1+JFA from `initialStep`); then the cell sums of that labelling and the largest distance,
   * in pixels, of a pixel from its site.
   */
  virtual bool Label(int initialStep) = 0;
  virtual bool Reduce(cvt::CellSums& sums, double& maximumRadius) = 0;
  ///@}

  /** Label and Reduce from the adaptive (or full) step, again from the full step when the
   * safeguard asks, timed. */
  bool LabelAndReduce(cvt::CellSums& sums);

  /** Whether pixel distances to a site's pixel bound where its cell reaches, as the adaptive
   * step needs (not on an atlas, whose cells cross seams). */
  virtual bool CanAdaptStep() const { return true; }

  vtkNew<vtkCVTOpenGLContext> Context;
  std::unique_ptr<vtkCVTJumpFlooding> Flooding;
  bool AdaptiveStep = true;
  bool MeasureTimings = false;
  double LastLabelMilliseconds = 0.0;
  double LastReductionMilliseconds = 0.0;

private:
  vtkCVTGPUEngine(const vtkCVTGPUEngine&) = delete;
  void operator=(const vtkCVTGPUEngine&) = delete;
};

#endif
