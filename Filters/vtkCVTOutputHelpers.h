// Private to CVT::Filters: pieces of output building shared by the CVT filters.
#ifndef vtkCVTOutputHelpers_h
#define vtkCVTOutputHelpers_h

#include "cvtOptimizer.h" // for HistoryEntry

#include <array>
#include <string>
#include <vector>

#include "vtkIntArray.h"     // for SiteIdArray
#include "vtkSmartPointer.h" // for return values
#include "vtkTimeStamp.h"    // for RequestOutcome

class vtkAlgorithm;
class vtkCellArray;
class vtkFieldData;
class vtkImageData;
class vtkInformation;
class vtkInformationVector;
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

/// Renames the arrays of `data` whose names are not UTF-8 (Latin-1 text, as an OBJ file's
/// material names give VTK's OBJ reader) to that text in UTF-8: VTK's XML writers write names
/// as they are, and a .vtp with such a name cannot be read back. Returns how many were renamed.
int MakeArrayNamesUtf8(vtkFieldData* data);

/// The sites output: one vertex per site (flat `sites`, 2 or 3 coordinates each; z for 2D),
/// point arrays SiteId, Mass, Energy. Returns the points, for the dual or remesh to share.
vtkSmartPointer<vtkPoints> FillSites(vtkPolyData* output, const std::vector<double>& sites,
  int dimensions, double z, const cvt::CellSums& sums);

/// Triangles (vertex ids) as the cells of a vtkPolyData's polys.
vtkSmartPointer<vtkCellArray> TriangleCells(const std::vector<std::array<int, 3>>& triangles);

/// An int array with this name and these values.
vtkSmartPointer<vtkIntArray> IntArray(const char* name, const std::vector<int>& values);

/// An int array named SiteId with these values (labels per pixel or point, sites per vertex).
vtkSmartPointer<vtkIntArray> SiteIdArray(const std::vector<int>& values);

/// A remesh's quality in its field data: Valence6Fraction, MinimumAngle, MaximumAngle and the
/// ValenceHistogram and AngleHistogram arrays.
void AddMeshQuality(vtkFieldData* fields, const cvt::MeshQuality& quality);

/// In RequestInformation: the labels image has the input image's whole extent, spacing and
/// origin, and may be asked for a sub-extent (under MPI each rank keeps its piece of it).
void DescribeLabelsLikeInput(vtkInformation* inputInformation, vtkInformation* labelsInformation);

/// Asks upstream for all of its data: the whole extent of an image, the one piece of a mesh.
/// Every pixel or triangle takes part in every cell, so under MPI each rank reads it all.
void RequestAllOfInput(vtkInformation* inputInformation);

/// The piece an output's information asks for (UPDATE_PIECE_NUMBER of
/// UPDATE_NUMBER_OF_PIECES); false, and piece 0 of 1, when it asks for none.
bool RequestedPiece(vtkInformation* info, int& piece, int& pieces);

/// In RequestUpdateExtent: gives every output port the piece the request's port asks for (under
/// MPI, rank r of N asks one port for piece r of N; the others would get the whole outputs and
/// run the filter again when they are asked in turn).
void ShareRequestedPiece(vtkInformation* request, vtkInformationVector* outputs);

/// Under MPI (ParaView's pvbatch or pvserver with N ranks) every rank computes the same CVT and
/// keeps its share of each output, so that every site, triangle and history row appears once
/// in the whole: piece p of N keeps the p-th N-th of a polydata's cells (with the points they
/// use), an image is cropped to the piece's update extent, and only piece 0 keeps the history.
/// Nothing changes when a single piece is asked for.
void KeepRequestedPieces(vtkInformationVector* outputs);

/// Whether the algorithm or one upstream of it was modified after `time`.
bool ChangedSince(vtkAlgorithm* self, const vtkTimeStamp& time);

/// 1 on success; else empties every output and returns 0, or 1 when `failPipeline` is off.
int FinishRequest(vtkInformationVector* outputs, bool succeeded, bool failPipeline);

/// What a CVT filter's RequestData returns around its work (a callable returning false after
/// reporting an error): on failure every output is emptied and the result is 0 (VTK's
/// convention: Update() reports the failure), or 1 when `failPipeline` is off, which ParaView
/// needs to show the emptied outputs. Off, a request with nothing changed since a failure
/// (neither the filter nor an algorithm upstream: each of ParaView's views updates its port,
/// and an empty image never satisfies its extent) repeats neither the work nor the error.
/// `lastFailure` and `failed` are the filter's memory of its last run.
template<class Work>
int RunRequest(vtkAlgorithm* self, vtkInformationVector* outputs, bool failPipeline,
  vtkTimeStamp& lastFailure, bool& failed, Work&& work)
{
  const bool repeat = !failPipeline && failed && !ChangedSince(self, lastFailure);
  const bool succeeded = !repeat && work();
  if (!succeeded && !repeat)
  {
    lastFailure.Modified();
  }
  failed = !succeeded;
  return FinishRequest(outputs, succeeded, failPipeline);
}

/// Columns iteration, evaluations, energy, gradient_norm, seconds.
void FillHistoryTable(vtkTable* table, const std::vector<cvt::HistoryEntry>& history);

/// A geometry image as vtkImageData: point arrays Position, Normal, AreaWeight, Mask; field
/// data WrapU, WrapV, MinimumAreaWeight, MaximumAreaWeight, TotalArea.
void WriteGeometryImage(const cvt::GeometryImage& image, vtkImageData* output);

/// "" or why a geometry image of width x height pixels does not fit in this machine's memory
/// (checked before the sources allocate it: its arrays and their VTK copies).
std::string GeometryImageMemoryError(int width, int height);

} // namespace cvtvtk

#endif
