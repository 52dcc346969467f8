#include "vtkCVTAlgorithm.h"

#include "cvtEngine.h"
#include "cvtOptimizer.h"
#include "vtkCVTOutputHelpers.h"

#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiProcessController.h"
#include "vtkPolyData.h"
#include "vtkTable.h"

#include <vector>

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
void vtkCVTAlgorithm::ShareRanksLike(vtkInformation* outerRequest)
{
  int piece, pieces;
  const bool asksPiece = cvtvtk::RequestedPiece(outerRequest, piece, pieces);
  this->OuterPiece = asksPiece ? piece : 0;
  this->OuterPieces = asksPiece ? pieces : 0;
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
      this->RanksStopTogether = this->AnyRankAborted = false;
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
bool vtkCVTAlgorithm::StopRequested() const
{
  return this->RanksStopTogether ? this->AnyRankAborted : this->AbortExecute != 0;
}

//------------------------------------------------------------------------------
int vtkCVTAlgorithm::ShareCellSumsAcrossRanks(
  cvt::SharedCellSums* engine, bool ready, vtkInformationVector* outputVector)
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  const int ranks = controller ? controller->GetNumberOfProcesses() : 1;
  int piece = this->OuterPiece, pieces = this->OuterPieces;
  if (pieces == 0)
  {
    cvtvtk::RequestedPiece(outputVector->GetInformationObject(0), piece, pieces);
  }
  const bool allRanksRun = ranks > 1 && pieces == ranks && piece == controller->GetLocalProcessId();
  // The ranks share only if every one is ready and splits the work the same way: the smallest
  // and largest split agree and are not 0.
  const int split = engine && ready ? static_cast<int>(engine->GetWorkSplit()) : 0;
  bool canShare = split != 0;
  if (allRanksRun)
  {
    int mine[2] = { split, -split }, everyRank[2] = { 0, 0 };
    canShare = controller->AllReduce(mine, everyRank, 2, vtkCommunicator::MIN_OP) &&
      everyRank[0] != 0 && everyRank[0] == -everyRank[1];
  }
  if (!allRanksRun || !canShare)
  {
    if (engine)
    {
      engine->ShareWork(0, 1, nullptr);
    }
    return 1;
  }
  this->RanksStopTogether = true;
  engine->ShareWork(controller->GetLocalProcessId(), ranks,
    [this, controller](std::vector<double>& sums)
    {
      sums.push_back(this->GetAbortExecute() ? 1.0 : 0.0); // this rank's stop, summed with the sums
      std::vector<double> total(sums.size());
      if (!controller->AllReduce(sums.data(), total.data(), static_cast<vtkIdType>(sums.size()),
            vtkCommunicator::SUM_OP))
      {
        return false;
      }
      this->AnyRankAborted = this->AnyRankAborted || total.back() > 0.0;
      total.pop_back();
      sums.swap(total);
      return true;
    });
  return ranks;
}

//------------------------------------------------------------------------------
bool vtkCVTAlgorithm::Optimize(cvt::Problem& problem, const cvt::SiteState& initial,
  const cvt::OptimizerOptions& options, cvt::OptimizerResult& result, std::string& error,
  double progressShare)
{
  const auto progress = [this, progressShare](double fraction)
  {
    this->UpdateProgress(progressShare * fraction);
    return !this->StopRequested();
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
  if (this->OuterPieces > 0)
  {
    os << indent << "ShareRanksLike: piece " << this->OuterPiece << " of " << this->OuterPieces
       << "\n";
  }
}
