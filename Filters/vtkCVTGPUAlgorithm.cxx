#include "vtkCVTGPUAlgorithm.h"

#include "vtkCVTEngineChoice.h"
#include "vtkCVTGPUEngine.h"
#include "vtkCVTOutputHelpers.h"

#include "vtkInformationVector.h"
#include "vtkRenderWindow.h"

//------------------------------------------------------------------------------
vtkCVTGPUAlgorithm::vtkCVTGPUAlgorithm() = default;

//------------------------------------------------------------------------------
vtkCVTGPUAlgorithm::~vtkCVTGPUAlgorithm() = default;

//------------------------------------------------------------------------------
void vtkCVTGPUAlgorithm::SetRenderWindow(vtkRenderWindow* window)
{
  if (window != this->RenderWindow)
  {
    this->RenderWindow = window;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkRenderWindow* vtkCVTGPUAlgorithm::GetRenderWindow() const
{
  return this->RenderWindow;
}

//------------------------------------------------------------------------------
void vtkCVTGPUAlgorithm::ReleaseGraphicsResources()
{
  this->OpenGLEngine = nullptr; // its GL objects, then its context
}

//------------------------------------------------------------------------------
int vtkCVTGPUAlgorithm::RequestInformation(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  cvtvtk::DescribeLabelsLikeInput(
    inputVector[0]->GetInformationObject(0), outputVector->GetInformationObject(LabelsPort));
  return 1;
}

//------------------------------------------------------------------------------
int vtkCVTGPUAlgorithm::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  this->ContextDescription.clear(); // set again by a run on the OpenGL engine
  const int result = this->Superclass::RequestData(request, inputVector, outputVector);
  this->LastJumpFloodingStep = this->OpenGLEngine && !this->ContextDescription.empty()
    ? this->OpenGLEngine->GetLastInitialStep()
    : 0;
  return result;
}

//------------------------------------------------------------------------------
void vtkCVTGPUAlgorithm::ConfigureOpenGLEngine()
{
  this->OpenGLEngine->SetRenderWindow(this->RenderWindow);
  this->OpenGLEngine->SetAdaptiveStep(this->AdaptiveJumpFlooding);
}

//------------------------------------------------------------------------------
void vtkCVTGPUAlgorithm::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Engine: " << cvtvtk::EngineKindName(this->Engine) << "\n";
  os << indent << "AdaptiveJumpFlooding: " << this->AdaptiveJumpFlooding << "\n";
  os << indent << "LastJumpFloodingStep: " << this->LastJumpFloodingStep << "\n";
  os << indent << "ContextDescription: "
     << (this->ContextDescription.empty() ? "(none)" : this->ContextDescription) << "\n";
  os << indent << "RenderWindow: " << this->RenderWindow.Get() << "\n";
  os << indent << "OpenGLEngine: " << (this->OpenGLEngine ? "kept" : "(none yet)") << "\n";
}
