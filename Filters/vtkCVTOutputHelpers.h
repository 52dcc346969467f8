// Private to CVT::Filters: pieces of output building shared by the CVT filters.
#ifndef vtkCVTOutputHelpers_h
#define vtkCVTOutputHelpers_h

#include "cvtLloyd.h" // for HistoryEntry

#include <string>
#include <vector>

#include "vtkIntArray.h"     // for SiteIdArray
#include "vtkSmartPointer.h" // for return values

class vtkFieldData;
class vtkImageData;
class vtkInformation;
class vtkPoints;
class vtkPolyData;
class vtkTable;
namespace cvt
{
struct CellSums;
struct GeometryImage;
struct MeshQuality;
}

namespace cvtvtk
{

/// A one-value double array named `name` in `fields`.
void AddFieldValue(vtkFieldData* fields, const char* name, double value);

/// A one-value string array named `name` in `fields`.
void AddFieldString(vtkFieldData* fields, const char* name, const std::string& value);

/// The sites output: one vertex per site (flat `sites`, 2 or 3 coordinates each; z for 2D),
/// point arrays SiteId, Mass, Energy. Returns the points, for the dual or remesh to share.
vtkSmartPointer<vtkPoints> FillSites(vtkPolyData* output, const std::vector<double>& sites,
  int dimensions, double z, const cvt::CellSums& sums);

/// An int array named SiteId with these values (labels per pixel or point, sites per vertex).
vtkSmartPointer<vtkIntArray> SiteIdArray(const std::vector<int>& values);

/// A remesh's quality in its field data: Valence6Fraction, MinimumAngle, MaximumAngle and the
/// ValenceHistogram and AngleHistogram arrays.
void AddMeshQuality(vtkFieldData* fields, const cvt::MeshQuality& quality);

/// Asks the upstream image for its whole extent: every pixel takes part in every cell.
void RequestWholeExtent(vtkInformation* inputInformation);

/// Columns iteration, evaluations, energy, gradient_norm, seconds.
void FillHistoryTable(vtkTable* table, const std::vector<cvt::HistoryEntry>& history);

/// A geometry image as vtkImageData: point arrays Position, Normal, AreaWeight, Mask; field
/// data WrapU, WrapV, MinimumAreaWeight, MaximumAreaWeight, TotalArea.
void WriteGeometryImage(const cvt::GeometryImage& image, vtkImageData* output);

} // namespace cvtvtk

#endif
