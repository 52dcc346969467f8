#include "vtkCVTGPUEngine.h"

#include "vtkCVTJumpFlooding.h"
#include "vtkCVTOpenGLContext.h"
#include "vtkCVTOpenGLHelpers.h"
#include "vtkOpenGLRenderWindow.h"

//------------------------------------------------------------------------------
vtkCVTGPUEngine::vtkCVTGPUEngine() = default;

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
  }
}

//------------------------------------------------------------------------------
int vtkCVTGPUEngine::GetLastInitialStep() const
{
  return this->GetJumpFlooding().GetLastInitialStep();
}

//------------------------------------------------------------------------------
int vtkCVTGPUEngine::GetNumberOfSafeguardFallbacks() const
{
  return this->GetJumpFlooding().GetNumberOfFallbacks();
}

//------------------------------------------------------------------------------
double vtkCVTGPUEngine::GetLastMaximumCellRadius() const
{
  return this->GetJumpFlooding().GetLastMaximumRadius();
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
