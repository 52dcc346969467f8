#include "vtkCVTOutputHelpers.h"

#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkStringArray.h"
#include "vtkTable.h"

namespace cvtvtk
{

void AddFieldValue(vtkFieldData* fields, const char* name, double value)
{
  vtkNew<vtkDoubleArray> array;
  array->SetName(name);
  array->InsertNextValue(value);
  fields->AddArray(array);
}

void AddFieldString(vtkFieldData* fields, const char* name, const std::string& value)
{
  vtkNew<vtkStringArray> array;
  array->SetName(name);
  array->InsertNextValue(value);
  fields->AddArray(array);
}

void FillHistoryTable(vtkTable* table, const std::vector<cvt::HistoryEntry>& history)
{
  vtkNew<vtkIntArray> iterationColumn, evaluationColumn;
  iterationColumn->SetName("iteration");
  evaluationColumn->SetName("evaluations");
  vtkNew<vtkDoubleArray> energyColumn, gradientColumn, secondsColumn;
  energyColumn->SetName("energy");
  gradientColumn->SetName("gradient_norm");
  secondsColumn->SetName("seconds");
  for (const cvt::HistoryEntry& entry : history)
  {
    iterationColumn->InsertNextValue(entry.Iteration);
    evaluationColumn->InsertNextValue(entry.Evaluations);
    energyColumn->InsertNextValue(entry.Energy);
    gradientColumn->InsertNextValue(entry.GradientNorm);
    secondsColumn->InsertNextValue(entry.Seconds);
  }
  table->AddColumn(iterationColumn);
  table->AddColumn(evaluationColumn);
  table->AddColumn(energyColumn);
  table->AddColumn(gradientColumn);
  table->AddColumn(secondsColumn);
}

} // namespace cvtvtk
