#include "vtkCVTGPUAlgorithm.h"

#include "vtkCVTEngineChoice.h"
#include "vtkCVTGPUEngine.h"

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
int vtkCVTGPUAlgorithm::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  this->ContextDescription.clear(); // set again by a run on the OpenGL engine
  return this->Superclass::RequestData(request, inputVector, outputVector);
}

//------------------------------------------------------------------------------
void vtkCVTGPUAlgorithm::UseRenderWindow()
{
  this->OpenGLEngine->SetRenderWindow(this->RenderWindow);
}

//------------------------------------------------------------------------------
void vtkCVTGPUAlgorithm::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Engine: " << cvtvtk::EngineKindName(this->Engine) << "\n";
  os << indent << "ContextDescription: "
     << (this->ContextDescription.empty() ? "(none)" : this->ContextDescription) << "\n";
  os << indent << "RenderWindow: " << this->RenderWindow.Get() << "\n";
  os << indent << "OpenGLEngine: " << (this->OpenGLEngine ? "kept" : "(none yet)") << "\n";
}
