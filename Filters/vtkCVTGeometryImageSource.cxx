#include "vtkCVTGeometryImageSource.h"

#include "cvtSurface.h"
#include "vtkCVTOutputHelpers.h"

#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkParametricTorus.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkCVTGeometryImageSource);
vtkCxxSetObjectMacro(vtkCVTGeometryImageSource, ParametricFunction, vtkParametricFunction);

//------------------------------------------------------------------------------
vtkCVTGeometryImageSource::vtkCVTGeometryImageSource()
{
  this->SetNumberOfInputPorts(0);
  vtkNew<vtkParametricTorus> torus;
  torus->SetRingRadius(1.0);
  torus->SetCrossSectionRadius(0.4);
  this->SetParametricFunction(torus);
}

//------------------------------------------------------------------------------
vtkCVTGeometryImageSource::~vtkCVTGeometryImageSource()
{
  this->SetParametricFunction(nullptr);
}

//------------------------------------------------------------------------------
vtkMTimeType vtkCVTGeometryImageSource::GetMTime()
{
  vtkMTimeType time = this->Superclass::GetMTime();
  if (this->ParametricFunction)
  {
    time = std::max(time, this->ParametricFunction->GetMTime());
  }
  return time;
}

//------------------------------------------------------------------------------
int vtkCVTGeometryImageSource::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  const int extent[6] = { 0, std::max(this->Resolution[0], 1) - 1, 0,
    std::max(this->Resolution[1], 1) - 1, 0, 0 };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  const double spacing[3] = { 1.0, 1.0, 1.0 }, origin[3] = { 0.0, 0.0, 0.0 };
  outInfo->Set(vtkDataObject::SPACING(), spacing, 3);
  outInfo->Set(vtkDataObject::ORIGIN(), origin, 3);
  return 1;
}

//------------------------------------------------------------------------------
int vtkCVTGeometryImageSource::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkImageData* output = vtkImageData::GetData(outputVector, 0);
  output->Initialize();
  if (!this->ParametricFunction)
  {
    vtkErrorMacro("No parametric function is set; give one with SetParametricFunction.");
    return 0;
  }
  const int w = this->Resolution[0], h = this->Resolution[1];
  if (w < 2 || h < 2)
  {
    vtkErrorMacro("The resolution " << w << " x " << h << " is too small; use at least 2 x 2.");
    return 0;
  }
  const std::string memory = cvtvtk::GeometryImageMemoryError(w, h);
  if (!memory.empty())
  {
    vtkErrorMacro("The geometry image is too large for this machine: " << memory << ".");
    return 0;
  }
  vtkParametricFunction* f = this->ParametricFunction;
  cvt::GeometryImage image;
  image.Width = w;
  image.Height = h;
  image.WrapU = f->GetJoinU() != 0;
  image.WrapV = f->GetJoinV() != 0;
  const size_t pixels = static_cast<size_t>(w) * h;
  image.Position.resize(3 * pixels);
  image.Normal.resize(3 * pixels);
  const auto sample = [](double lo, double hi, int n, int k, bool periodic)
  { return periodic ? lo + (k + 0.5) * (hi - lo) / n : lo + k * (hi - lo) / (n - 1); };
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      double uvw[3] = { sample(f->GetMinimumU(), f->GetMaximumU(), w, i, image.WrapU),
        sample(f->GetMinimumV(), f->GetMaximumV(), h, j, image.WrapV), 0.0 };
      double point[3], derivatives[9];
      f->Evaluate(uvw, point, derivatives);
      double normal[3];
      vtkMath::Cross(derivatives, derivatives + 3, normal);
      if (vtkMath::Normalize(normal) == 0.0)
      {
        normal[0] = normal[1] = 0.0;
        normal[2] = 1.0; // a pole: any unit vector; its weight is tiny
      }
      const size_t p = static_cast<size_t>(j) * w + i;
      for (int c = 0; c < 3; ++c)
      {
        image.Position[3 * p + c] = static_cast<float>(point[c]);
        image.Normal[3 * p + c] = static_cast<float>(normal[c]);
      }
    }
  }
  image.AreaWeight = cvt::ComputeAreaWeights(image);

  cvtvtk::WriteGeometryImage(image, output);
  return 1;
}

//------------------------------------------------------------------------------
void vtkCVTGeometryImageSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Resolution: " << this->Resolution[0] << " x " << this->Resolution[1] << "\n";
  os << indent << "ParametricFunction: "
     << (this->ParametricFunction ? this->ParametricFunction->GetClassName() : "(none)") << "\n";
}
