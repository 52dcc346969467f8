#include "vtkCVTOutputHelpers.h"

#include "cvtSurface.h"

#include "cvtEngine.h"
#include "cvtMemory.h"
#include "cvtQuality.h"

#include "vtkAlgorithm.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataObject.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkExtentTranslator.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"
#include "vtkTable.h"
#include "vtkUnsignedCharArray.h"

#include <utf8.h> // utfcpp

#include <algorithm>
#include <cstring>
#include <iterator>
#include <numeric>
#include <vector>

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

int MakeArrayNamesUtf8(vtkFieldData* data)
{
  int renamed = 0;
  for (int a = 0; a < data->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* array = data->GetAbstractArray(a);
    const char* name = array ? array->GetName() : nullptr;
    if (!name || utf8::is_valid(name, name + std::strlen(name)))
    {
      continue;
    }
    std::string text; // each byte a Latin-1 character, that is a code point below 256
    for (const char* c = name; *c; ++c)
    {
      utf8::append(static_cast<unsigned char>(*c), std::back_inserter(text));
    }
    array->SetName(text.c_str());
    ++renamed;
  }
  return renamed;
}

vtkSmartPointer<vtkCellArray> TriangleCells(const std::vector<std::array<int, 3>>& triangles)
{
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->AllocateExact(static_cast<vtkIdType>(triangles.size()), 3 * triangles.size());
  for (const auto& t : triangles)
  {
    const vtkIdType ids[3] = { t[0], t[1], t[2] };
    cells->InsertNextCell(3, ids);
  }
  return cells;
}

vtkSmartPointer<vtkPoints> FillSites(vtkPolyData* output, const std::vector<double>& sites,
  int dimensions, double z, const cvt::CellSums& sums)
{
  const vtkIdType n = static_cast<vtkIdType>(sites.size() / dimensions);
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(n);
  vtkNew<vtkCellArray> vertices;
  vtkNew<vtkIntArray> siteIds;
  siteIds->SetName("SiteId");
  vtkNew<vtkDoubleArray> mass, energy;
  mass->SetName("Mass");
  energy->SetName("Energy");
  for (vtkIdType i = 0; i < n; ++i)
  {
    const double* x = &sites[dimensions * i];
    points->SetPoint(i, x[0], x[1], dimensions == 3 ? x[2] : z);
    vertices->InsertNextCell(1, &i);
    siteIds->InsertNextValue(static_cast<int>(i));
    mass->InsertNextValue(sums.Mass[i]);
    energy->InsertNextValue(sums.Energy[i]);
  }
  output->SetPoints(points);
  output->SetVerts(vertices);
  output->GetPointData()->AddArray(siteIds);
  output->GetPointData()->AddArray(mass);
  output->GetPointData()->AddArray(energy);
  return points;
}

vtkSmartPointer<vtkIntArray> IntArray(const char* name, const std::vector<int>& values)
{
  auto array = vtkSmartPointer<vtkIntArray>::New();
  array->SetName(name);
  array->SetNumberOfValues(static_cast<vtkIdType>(values.size()));
  std::copy(values.begin(), values.end(), array->GetPointer(0));
  return array;
}

vtkSmartPointer<vtkIntArray> SiteIdArray(const std::vector<int>& values)
{
  return IntArray("SiteId", values);
}

void AddMeshQuality(vtkFieldData* fields, const cvt::MeshQuality& quality)
{
  AddFieldValue(fields, "Valence6Fraction", quality.Valence6Fraction);
  AddFieldValue(fields, "InteriorValence6Fraction", quality.InteriorValence6Fraction);
  AddFieldValue(fields, "MinimumAngle", quality.MinimumAngle);
  AddFieldValue(fields, "MaximumAngle", quality.MaximumAngle);
  for (const auto& histogram : { std::make_pair("ValenceHistogram", &quality.ValenceHistogram),
         std::make_pair("AngleHistogram", &quality.AngleHistogram) })
  {
    vtkNew<vtkIntArray> counts;
    counts->SetName(histogram.first);
    for (int count : *histogram.second)
    {
      counts->InsertNextValue(count);
    }
    fields->AddArray(counts);
  }
}

void DescribeLabelsLikeInput(vtkInformation* inputInformation, vtkInformation* labelsInformation)
{
  using SDDP = vtkStreamingDemandDrivenPipeline;
  if (inputInformation->Has(SDDP::WHOLE_EXTENT()))
  {
    labelsInformation->Set(SDDP::WHOLE_EXTENT(), inputInformation->Get(SDDP::WHOLE_EXTENT()), 6);
    // The executive then splits the extent into the pieces MPI ranks ask for.
    labelsInformation->Set(vtkAlgorithm::CAN_PRODUCE_SUB_EXTENT(), 1);
  }
  if (inputInformation->Has(vtkDataObject::SPACING()))
  {
    labelsInformation->Set(
      vtkDataObject::SPACING(), inputInformation->Get(vtkDataObject::SPACING()), 3);
  }
  if (inputInformation->Has(vtkDataObject::ORIGIN()))
  {
    labelsInformation->Set(
      vtkDataObject::ORIGIN(), inputInformation->Get(vtkDataObject::ORIGIN()), 3);
  }
}

bool RequestedPiece(vtkInformation* info, int& piece, int& pieces)
{
  using SDDP = vtkStreamingDemandDrivenPipeline;
  const bool asks =
    info && info->Has(SDDP::UPDATE_NUMBER_OF_PIECES()) && info->Has(SDDP::UPDATE_PIECE_NUMBER());
  piece = asks ? info->Get(SDDP::UPDATE_PIECE_NUMBER()) : 0;
  pieces = asks ? info->Get(SDDP::UPDATE_NUMBER_OF_PIECES()) : 1;
  return asks;
}

void ShareRequestedPiece(vtkInformation* request, vtkInformationVector* outputs)
{
  using SDDP = vtkStreamingDemandDrivenPipeline;
  const int from = request->Has(vtkExecutive::FROM_OUTPUT_PORT())
    ? request->Get(vtkExecutive::FROM_OUTPUT_PORT())
    : 0;
  vtkInformation* asked = outputs->GetInformationObject(std::max(from, 0));
  int piece, pieces;
  if (!RequestedPiece(asked, piece, pieces))
  {
    return;
  }
  for (int port = 0; port < outputs->GetNumberOfInformationObjects(); ++port)
  {
    vtkInformation* info = outputs->GetInformationObject(port);
    if (info == asked)
    {
      continue;
    }
    info->Set(SDDP::UPDATE_PIECE_NUMBER(), piece);
    info->Set(SDDP::UPDATE_NUMBER_OF_PIECES(), pieces);
    info->Set(SDDP::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
    if (info->Has(SDDP::WHOLE_EXTENT()))
    {
      // The whole extent with the piece: the executive splits it (CAN_PRODUCE_SUB_EXTENT) as it
      // does when that port is asked for the piece.
      info->Set(SDDP::UPDATE_EXTENT(), info->Get(SDDP::WHOLE_EXTENT()), 6);
    }
  }
}

void RequestAllOfInput(vtkInformation* inputInformation)
{
  using SDDP = vtkStreamingDemandDrivenPipeline;
  if (!inputInformation)
  {
    return;
  }
  if (inputInformation->Has(SDDP::WHOLE_EXTENT()))
  {
    inputInformation->Set(SDDP::UPDATE_EXTENT(), inputInformation->Get(SDDP::WHOLE_EXTENT()), 6);
    inputInformation->Set(SDDP::EXACT_EXTENT(), 1);
  }
  inputInformation->Set(SDDP::UPDATE_PIECE_NUMBER(), 0);
  inputInformation->Set(SDDP::UPDATE_NUMBER_OF_PIECES(), 1);
}

namespace
{
/// Keeps cells [first, last) of `data` and the points they use, with their point and cell
/// data (vtkPolyData::CopyCells); field data stays.
void KeepCells(vtkPolyData* data, vtkIdType first, vtkIdType last)
{
  vtkNew<vtkPolyData> kept;
  vtkNew<vtkPoints> points;
  points->SetDataType(data->GetPoints() ? data->GetPoints()->GetDataType() : VTK_FLOAT);
  kept->SetPoints(points);
  kept->GetPointData()->CopyAllocate(data->GetPointData());
  kept->GetCellData()->CopyAllocate(data->GetCellData());
  kept->AllocateEstimate(last - first, 3);
  vtkNew<vtkIdList> cells;
  cells->SetNumberOfIds(last - first);
  std::iota(cells->begin(), cells->end(), first);
  kept->CopyCells(data, cells);
  kept->GetFieldData()->ShallowCopy(data->GetFieldData());
  data->ShallowCopy(kept);
}
}

void KeepRequestedPieces(vtkInformationVector* outputs)
{
  using SDDP = vtkStreamingDemandDrivenPipeline;
  for (int port = 0; port < outputs->GetNumberOfInformationObjects(); ++port)
  {
    vtkInformation* info = outputs->GetInformationObject(port);
    const int pieces =
      info->Has(SDDP::UPDATE_NUMBER_OF_PIECES()) ? info->Get(SDDP::UPDATE_NUMBER_OF_PIECES()) : 1;
    const int piece =
      info->Has(SDDP::UPDATE_PIECE_NUMBER()) ? info->Get(SDDP::UPDATE_PIECE_NUMBER()) : 0;
    if (pieces <= 1 || piece < 0 || piece >= pieces)
    {
      continue;
    }
    vtkDataObject* output = vtkDataObject::GetData(outputs, port);
    if (auto* mesh = vtkPolyData::SafeDownCast(output))
    {
      const vtkIdType cells = mesh->GetNumberOfCells();
      if (cells == 0 && piece > 0)
      {
        mesh->Initialize(); // points without cells: all on piece 0
      }
      else if (cells > 0)
      {
        KeepCells(mesh, cells * piece / pieces, cells * (piece + 1) / pieces);
      }
    }
    else if (auto* image = vtkImageData::SafeDownCast(output))
    {
      // The executive asks each rank for its piece's extent (one shared layer between pieces).
      int extent[6];
      if (info->Has(SDDP::UPDATE_EXTENT()))
      {
        info->Get(SDDP::UPDATE_EXTENT(), extent);
        image->Crop(extent);
      }
    }
    else if (auto* table = vtkTable::SafeDownCast(output))
    {
      if (piece > 0)
      {
        table->Initialize();
      }
    }
  }
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
  if (!image.SeamPartner.empty())
  {
    output->GetPointData()->AddArray(IntArray("SeamPartner", image.SeamPartner));
  }
  if (!image.Border.empty())
  {
    vtkNew<vtkUnsignedCharArray> border;
    border->SetName("SurfaceBorder");
    border->SetNumberOfValues(static_cast<vtkIdType>(image.Border.size()));
    std::copy(image.Border.begin(), image.Border.end(), border->GetPointer(0));
    output->GetPointData()->AddArray(border);
  }
  vtkFieldData* fields = output->GetFieldData();
  AddFieldValue(fields, "WrapU", image.WrapU ? 1.0 : 0.0);
  AddFieldValue(fields, "WrapV", image.WrapV ? 1.0 : 0.0);
  AddFieldValue(fields, "MinimumAreaWeight", minimum);
  AddFieldValue(fields, "MaximumAreaWeight", maximum);
  AddFieldValue(fields, "TotalArea", total);
}

//------------------------------------------------------------------------------
bool ChangedSince(vtkAlgorithm* self, const vtkTimeStamp& time)
{
  // Algorithms, not their data: ParaView re-executes a reader for each view's request, which
  // renews the data's time stamps without any change.
  if (self->GetMTime() > time.GetMTime())
  {
    return true;
  }
  for (int port = 0; port < self->GetNumberOfInputPorts(); ++port)
  {
    for (int c = 0; c < self->GetNumberOfInputConnections(port); ++c)
    {
      vtkAlgorithm* upstream = self->GetInputAlgorithm(port, c);
      if (upstream && ChangedSince(upstream, time))
      {
        return true;
      }
    }
  }
  return false;
}

//------------------------------------------------------------------------------
int FinishRequest(vtkInformationVector* outputs, bool succeeded, bool failPipeline)
{
  if (succeeded)
  {
    KeepRequestedPieces(outputs);
    return 1;
  }
  for (int port = 0; port < outputs->GetNumberOfInformationObjects(); ++port)
  {
    if (vtkDataObject* output = vtkDataObject::GetData(outputs, port))
    {
      output->Initialize();
    }
  }
  return failPipeline ? 0 : 1;
}

//------------------------------------------------------------------------------
std::string GeometryImageMemoryError(int width, int height)
{
  // Position and normal (12 bytes each), area weight (4) as floats, then as VTK arrays with the
  // mask (29): 57 bytes per pixel.
  return cvt::CheckMemory(57.0 * width * static_cast<double>(height), cvt::AvailableSystemMemory(),
    "a geometry image of " + std::to_string(width) + " x " + std::to_string(height) + " pixels",
    "memory", "use a smaller resolution");
}

} // namespace cvtvtk
