// Private to CVT::Filters: pieces of output building shared by the CVT filters.
#ifndef vtkCVTOutputHelpers_h
#define vtkCVTOutputHelpers_h

#include "cvtLloyd.h" // for HistoryEntry

#include <string>
#include <vector>

class vtkFieldData;
class vtkImageData;
class vtkTable;
namespace cvt
{
struct GeometryImage;
}

namespace cvtvtk
{

/// A one-value double array named `name` in `fields`.
void AddFieldValue(vtkFieldData* fields, const char* name, double value);

/// A one-value string array named `name` in `fields`.
void AddFieldString(vtkFieldData* fields, const char* name, const std::string& value);

/// Columns iteration, evaluations, energy, gradient_norm, seconds.
void FillHistoryTable(vtkTable* table, const std::vector<cvt::HistoryEntry>& history);

/// A geometry image as vtkImageData: point arrays Position, Normal, AreaWeight, Mask; field
/// data WrapU, WrapV, MinimumAreaWeight, MaximumAreaWeight, TotalArea.
void WriteGeometryImage(const cvt::GeometryImage& image, vtkImageData* output);

} // namespace cvtvtk

#endif
