// The `cvt` program's inputs: the density image of `cvt image`, the --initial-sites CSV and the
// mesh of `cvt surface --input`. Each fails with a clear "cvt: ..." line on a missing, unknown
// or corrupt file instead of returning.
#ifndef cvtReaders_h
#define cvtReaders_h

#include "cvtCommandLine.h"

#include "vtkSmartPointer.h"

#include <string>

class vtkAlgorithm;
class vtkImageData;
class vtkPolyData;

namespace cvtcli
{

/// The image domain with a one-component float array "density" as its scalars, read from
/// --input (its --array), or with no array (uniform) on --domain at --resolution.
vtkSmartPointer<vtkImageData> ReadDensityImage(const Options& options);

/// The --initial-sites file as points.
vtkSmartPointer<vtkPolyData> ReadSitesCsv(const std::string& path);

/// What gives the --input mesh: the reader for its extension, not updated yet, or, where that
/// reader has read the file in a child process first (to contain its crashes), the mesh that
/// the child handed over.
vtkSmartPointer<vtkAlgorithm> MeshReader(const Options& options);

} // namespace cvtcli

#endif
