#include "vtkCVTGPUEngine.h"

#include "vtkCVTJumpFlooding.h"
#include "vtkCVTOpenGLContext.h"
#include "vtkCVTOpenGLHelpers.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtk_glew.h"

#include <chrono>

//------------------------------------------------------------------------------
vtkCVTGPUEngine::vtkCVTGPUEngine(const char* distance)
  : Flooding(new vtkCVTJumpFlooding(distance))
{
}

//------------------------------------------------------------------------------
vtkCVTGPUEngine::~vtkCVTGPUEngine() = default;

//------------------------------------------------------------------------------
std::string vtkCVTGPUEngine::GetContextDescription() const
{
  return this->Context->GetDescription();
}

//------------------------------------------------------------------------------
void vtkCVTGPUEngine::SetRenderWindow(vtkRenderWindow* window)
{
  auto* openGLWindow = vtkOpenGLRenderWindow::SafeDownCast(window);
  if (openGLWindow != this->Context->GetHandedInWindow())
  {
    this->ReleaseGraphicsResources();
    this->Context->SetRenderWindow(openGLWindow);
  }
}

//------------------------------------------------------------------------------
void vtkCVTGPUEngine::ReleaseGraphicsResources()
{
  if (this->Context->IsInitialized())
  {
    cvtgl::ScopedContext current(this->Context);
    this->ReleaseObjects(this->Context->GetRenderWindow());
    this->Flooding->Release(this->Context->GetRenderWindow());
  }
}

//------------------------------------------------------------------------------
bool vtkCVTGPUEngine::LabelAndReduce(cvt::CellSums& sums)
{
  using Clock = std::chrono::steady_clock;
  const auto millisecondsSince = [](Clock::time_point start)
  { return std::chrono::duration<double, std::milli>(Clock::now() - start).count(); };
  for (int initialStep = this->Flooding->GetInitialStep(this->AdaptiveStep && this->CanAdaptStep());
       ; initialStep = this->Flooding->GetFullStep())
  {
    auto start = Clock::now();
    if (!this->Label(initialStep))
    {
      return false;
    }
    if (this->MeasureTimings)
    {
      glFinish();
    }
    this->LastLabelMilliseconds = millisecondsSince(start);
    start = Clock::now();
    double maximumRadius = 0.0;
    if (!this->Reduce(sums, maximumRadius))
    {
      return false;
    }
    this->LastReductionMilliseconds = millisecondsSince(start);
    if (this->Flooding->AcceptLabelling(initialStep, maximumRadius))
    {
      return true;
    }
  }
}

//------------------------------------------------------------------------------
int vtkCVTGPUEngine::GetLastInitialStep() const
{
  return this->Flooding->GetLastInitialStep();
}

//------------------------------------------------------------------------------
int vtkCVTGPUEngine::GetNumberOfSafeguardFallbacks() const
{
  return this->Flooding->GetNumberOfFallbacks();
}

//------------------------------------------------------------------------------
double vtkCVTGPUEngine::GetLastMaximumCellRadius() const
{
  return this->Flooding->GetLastMaximumRadius();
}

//------------------------------------------------------------------------------
void vtkCVTGPUEngine::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Context: " << this->GetContextDescription() << "\n";
  os << indent << "AdaptiveStep: " << this->AdaptiveStep << "\n";
  os << indent << "MeasureTimings: " << this->MeasureTimings << "\n";
  os << indent << "LastInitialStep: " << this->GetLastInitialStep() << "\n";
  os << indent << "SafeguardFallbacks: " << this->GetNumberOfSafeguardFallbacks() << "\n";
}
