// Private to CVT::Filters: pieces of output building shared by the CVT filters.
#ifndef vtkCVTOutputHelpers_h
#define vtkCVTOutputHelpers_h

#include "cvtLloyd.h" // for HistoryEntry

#include <string>
#include <vector>

class vtkFieldData;
class vtkTable;

namespace cvtvtk
{

/// A one-value double array named `name` in `fields`.
void AddFieldValue(vtkFieldData* fields, const char* name, double value);

/// A one-value string array named `name` in `fields`.
void AddFieldString(vtkFieldData* fields, const char* name, const std::string& value);

/// Columns iteration, evaluations, energy, gradient_norm, seconds.
void FillHistoryTable(vtkTable* table, const std::vector<cvt::HistoryEntry>& history);

} // namespace cvtvtk

#endif
