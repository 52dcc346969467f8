#include "vtkCVTOutputHelpers.h"

#include "cvtSurface.h"

#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkStringArray.h"
#include "vtkTable.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>

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

void WriteGeometryImage(const cvt::GeometryImage& image, vtkImageData* output)
{
  const vtkIdType pixels = static_cast<vtkIdType>(image.NumberOfPixels());
  output->SetExtent(0, image.Width - 1, 0, image.Height - 1, 0, 0);
  vtkNew<vtkFloatArray> position, normal, weight;
  position->SetName("Position");
  position->SetNumberOfComponents(3);
  position->SetNumberOfTuples(pixels);
  normal->SetName("Normal");
  normal->SetNumberOfComponents(3);
  normal->SetNumberOfTuples(pixels);
  weight->SetName("AreaWeight");
  weight->SetNumberOfTuples(pixels);
  vtkNew<vtkUnsignedCharArray> mask;
  mask->SetName("Mask");
  mask->SetNumberOfTuples(pixels);
  double minimum = VTK_DOUBLE_MAX, maximum = 0.0, total = 0.0;
  for (vtkIdType p = 0; p < pixels; ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      position->SetValue(3 * p + c, image.Position[3 * p + c]);
      normal->SetValue(3 * p + c, image.Normal[3 * p + c]);
    }
    weight->SetValue(p, image.AreaWeight[p]);
    mask->SetValue(p, image.IsValid(p) ? 1 : 0);
    if (image.IsValid(p))
    {
      minimum = std::min(minimum, static_cast<double>(image.AreaWeight[p]));
      maximum = std::max(maximum, static_cast<double>(image.AreaWeight[p]));
      total += image.AreaWeight[p];
    }
  }
  output->GetPointData()->AddArray(position);
  output->GetPointData()->AddArray(normal);
  output->GetPointData()->AddArray(weight);
  output->GetPointData()->AddArray(mask);
  vtkFieldData* fields = output->GetFieldData();
  AddFieldValue(fields, "WrapU", image.WrapU ? 1.0 : 0.0);
  AddFieldValue(fields, "WrapV", image.WrapV ? 1.0 : 0.0);
  AddFieldValue(fields, "MinimumAreaWeight", minimum);
  AddFieldValue(fields, "MaximumAreaWeight", maximum);
  AddFieldValue(fields, "TotalArea", total);
}

} // namespace cvtvtk
