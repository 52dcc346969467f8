#include "vtkCVTAlgorithm.h"

#include "cvtOptimizer.h"
#include "vtkCVTOutputHelpers.h"

#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkPolyData.h"
#include "vtkTable.h"

//------------------------------------------------------------------------------
vtkCVTAlgorithm::vtkCVTAlgorithm()
{
  this->SetNumberOfOutputPorts(4);
}

//------------------------------------------------------------------------------
vtkCVTAlgorithm::~vtkCVTAlgorithm() = default;

//------------------------------------------------------------------------------
void vtkCVTAlgorithm::CopyOptimizerSettings(vtkCVTAlgorithm* other)
{
  this->SetNumberOfSites(other->NumberOfSites);
  this->SetRandomSeed(other->RandomSeed);
  this->SetMethod(other->Method);
  this->SetMaximumNumberOfIterations(other->MaximumNumberOfIterations);
  this->SetTolerance(other->Tolerance);
  this->SetGradientTolerance(other->GradientTolerance);
  this->SetNumberOfCorrections(other->NumberOfCorrections);
}

//------------------------------------------------------------------------------
vtkPolyData* vtkCVTAlgorithm::GetSitesOutput()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(SitesPort));
}

//------------------------------------------------------------------------------
vtkTable* vtkCVTAlgorithm::GetHistoryOutput()
{
  return vtkTable::SafeDownCast(this->GetOutputDataObject(HistoryPort));
}

//------------------------------------------------------------------------------
int vtkCVTAlgorithm::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(),
    port == LabelsPort ? this->GetLabelsDataType()
                       : (port == HistoryPort ? "vtkTable" : "vtkPolyData"));
  return 1;
}

//------------------------------------------------------------------------------
int vtkCVTAlgorithm::RequestUpdateExtent(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  for (int port = 0; port < this->GetNumberOfInputPorts(); ++port)
  {
    cvtvtk::RequestAllOfInput(inputVector[port]->GetInformationObject(0));
  }
  cvtvtk::ShareRequestedPiece(request, outputVector);
  return 1;
}

//------------------------------------------------------------------------------
int vtkCVTAlgorithm::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return cvtvtk::RunRequest(this, outputVector, this->FailPipelineOnError, this->LastFailure,
    this->LastRunFailed,
    [&]
    {
      for (int port = 0; port < outputVector->GetNumberOfInformationObjects(); ++port)
      {
        vtkDataObject::GetData(outputVector, port)->Initialize();
      }
      return this->Compute(inputVector, outputVector);
    });
}

//------------------------------------------------------------------------------
cvt::OptimizerOptions vtkCVTAlgorithm::GetOptimizerOptions() const
{
  cvt::OptimizerOptions options;
  options.MaximumNumberOfIterations = this->MaximumNumberOfIterations;
  options.Tolerance = this->Tolerance;
  options.GradientTolerance = this->GradientTolerance;
  options.NumberOfCorrections = this->NumberOfCorrections;
  return options;
}

//------------------------------------------------------------------------------
bool vtkCVTAlgorithm::Optimize(cvt::Problem& problem, const cvt::SiteState& initial,
  const cvt::OptimizerOptions& options, cvt::OptimizerResult& result, std::string& error,
  double progressShare)
{
  const auto progress = [this, progressShare](double fraction)
  {
    this->UpdateProgress(progressShare * fraction);
    return !this->GetAbortExecute();
  };
  const bool optimized = this->Method == LLOYD
    ? cvt::RunLloyd(problem, initial, options, progress, result, error)
    : cvt::RunLBFGS(problem, initial, options, progress, result, error);
  if (optimized && result.StopReason.rfind("no sufficient decrease", 0) == 0)
  {
    vtkWarningMacro("L-BFGS stopped after " << result.Iterations
                                            << " iterations: " << result.StopReason
                                            << "; the output holds its best sites.");
  }
  return optimized;
}

//------------------------------------------------------------------------------
void vtkCVTAlgorithm::AddRunFields(
  vtkFieldData* fields, const cvt::OptimizerResult& result, double gradientNorm)
{
  cvtvtk::AddFieldValue(fields, "Energy", result.Sums.TotalEnergy());
  cvtvtk::AddFieldValue(fields, "GradientNorm", gradientNorm);
  cvtvtk::AddFieldValue(fields, "Iterations", result.Iterations);
  cvtvtk::AddFieldValue(fields, "Evaluations", result.Evaluations);
  cvtvtk::AddFieldString(fields, "StopReason", result.StopReason);
}

//------------------------------------------------------------------------------
void vtkCVTAlgorithm::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfSites: " << this->NumberOfSites << "\n";
  os << indent << "RandomSeed: " << this->RandomSeed << "\n";
  os << indent << "Method: " << (this->Method == LLOYD ? "Lloyd" : "L-BFGS") << "\n";
  os << indent << "MaximumNumberOfIterations: " << this->MaximumNumberOfIterations << "\n";
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "GradientTolerance: " << this->GradientTolerance << "\n";
  os << indent << "NumberOfCorrections: " << this->NumberOfCorrections << "\n";
  os << indent << "FailPipelineOnError: " << this->FailPipelineOnError << "\n";
}
