// The `cvt` program's outputs: the --output folder, the files of one run (written under
// temporary names and renamed into place together), and the summary it prints.
#ifndef cvtOutputs_h
#define cvtOutputs_h

#include "cvtCommandLine.h"

#include "vtkErrorCode.h"
#include "vtkNew.h"

#include <string>
#include <vector>

class vtkDataObject;
class vtkImageData;
class vtkPolyData;
class vtkTable;

namespace cvtcli
{

/// Creates the --output folder and checks that files can be made there, before any work.
std::string OutputFolder(const Options& options);

/// The files of one run, written under temporary names in the output folder and renamed into
/// place together once all are written: a full disk, a file-size limit or a folder that turns
/// read-only leaves the previous results or nothing, never a truncated file under a real name.
/// Errors throw (main reports them), so that the destructor removes the temporary files.
class OutputFiles
{
public:
  explicit OutputFiles(const std::string& folder);
  ~OutputFiles();
  OutputFiles(const OutputFiles&) = delete;
  OutputFiles& operator=(const OutputFiles&) = delete;

  /// Where to write `name` for now.
  std::string Add(const std::string& name);
  /// The complaint for a file that could not be written.
  [[noreturn]] void Failed(const std::string& name, const std::string& why) const;
  /// Renames every written file into place.
  void Commit();

private:
  std::string Temporary(const std::string& name) const;
  std::string Folder;
  std::vector<std::string> Pending;
};

/// Writes `data` as `name` with a VTK XML writer.
template<typename Writer>
void Write(vtkDataObject* data, OutputFiles& files, const std::string& name)
{
  vtkNew<Writer> writer;
  // Inline base64, not appended raw data: Debian 12's expat rejects the raw appended section,
  // so VTK and ParaView there could not read the files back.
  writer->SetDataModeToBinary();
  writer->SetCompressorTypeToNone(); // zlib took longer than the whole remesh of small meshes
  writer->SetHeaderTypeToUInt64();   // 32-bit block headers fail past 4 GB (32768^2 labels)
  writer->SetInputData(data);
  writer->SetFileName(files.Add(name).c_str());
  if (writer->Write() != 1 || writer->GetErrorCode() != vtkErrorCode::NoError)
  {
    files.Failed(name, vtkErrorCode::GetStringFromErrorCode(writer->GetErrorCode()));
  }
}

/// sites.csv (x,y or x,y,z per line: the --initial-sites format) and history.csv.
void WriteCsv(vtkPolyData* sites, vtkTable* history, int dimensions, OutputFiles& files);

/// cvt.png; without a picture (nothing to draw) only a warning. Returns whether it was written.
bool WritePicture(vtkImageData* picture, const std::string& error, OutputFiles& files);

/// The first value of a field-data array of the filters' outputs (their measures).
double Field(vtkDataObject* data, const char* name);

/// The lines printed after a run (none with --quiet); `files` lists the outputs, cvt.png last.
void PrintSummary(const Options& options, vtkPolyData* sites, const std::string& context,
  const char* files, bool pictureWritten);

} // namespace cvtcli

#endif
