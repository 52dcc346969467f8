/**
 * @class   vtkCVTMeshFileReader
 * @brief   Base of the project's mesh file readers: the file name, opening the file, and errors
 *          that name the line.
 *
 * A subclass reads the open file in ReadMesh. The base class empties the output first, refuses
 * a missing FileName or a file it cannot open with a message saying so, and empties the output
 * again when ReadMesh fails (after LineError), so that a refused file never leaves part of a
 * mesh downstream.
 */
#ifndef vtkCVTMeshFileReader_h
#define vtkCVTMeshFileReader_h

#include "cvtIOModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

#include <iosfwd> // for std::istream
#include <string> // for std::string

class CVTIO_EXPORT vtkCVTMeshFileReader : public vtkPolyDataAlgorithm
{
public:
  vtkTypeMacro(vtkCVTMeshFileReader, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** The file to read. */
  vtkSetStdStringFromCharMacro(FileName);
  vtkGetCharFromStdStringMacro(FileName);
  ///@}

protected:
  vtkCVTMeshFileReader();
  ~vtkCVTMeshFileReader() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) final;

  /// Reads the open file `in` (binary mode) into the empty `output`; false after LineError.
  virtual bool ReadMesh(std::istream& in, vtkPolyData* output) = 0;
  /// The files' extension, for the messages (".off").
  virtual const char* GetExtension() const = 0;
  /// Reports that line `line` of the file is wrong: "'FILE' line LINE: what". Returns false.
  bool LineError(long long line, const std::string& what);

  std::string FileName;

private:
  vtkCVTMeshFileReader(const vtkCVTMeshFileReader&) = delete;
  void operator=(const vtkCVTMeshFileReader&) = delete;
};

#endif
