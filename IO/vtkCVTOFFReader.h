/**
 * @class   vtkCVTOFFReader
 * @brief   Reads a polygon mesh in the ASCII Object File Format (.off).
 *
 * OFF is the format of Geomview, CGAL, Geogram and many shape collections (Princeton's shape
 * benchmark among them); VTK has no reader for it. The reader takes the keywords OFF, COFF,
 * NOFF, CNOFF, STOFF and their combinations (extra per-vertex numbers: normals, colours,
 * texture coordinates are skipped), the counts on the keyword line or on the next one, "#"
 * comments, and faces of any number of vertices (per-face colours are skipped). The output is
 * a vtkPolyData of the points (double precision) and the faces as polygons.
 *
 * Binary OFF, 4-dimensional or n-dimensional OFF, a missing or truncated vertex or face list,
 * a face with fewer than three vertices or an index outside the vertex list are errors that
 * say which line is wrong; the output is then empty.
 */
#ifndef vtkCVTOFFReader_h
#define vtkCVTOFFReader_h

#include "cvtIOModule.h" // for export macro
#include "vtkCVTMeshFileReader.h"

class CVTIO_EXPORT vtkCVTOFFReader : public vtkCVTMeshFileReader
{
public:
  static vtkCVTOFFReader* New();
  vtkTypeMacro(vtkCVTOFFReader, vtkCVTMeshFileReader);

protected:
  vtkCVTOFFReader() = default;
  ~vtkCVTOFFReader() override = default;

  bool ReadMesh(std::istream& in, vtkPolyData* output) override;
  const char* GetExtension() const override { return ".off"; }

private:
  vtkCVTOFFReader(const vtkCVTOFFReader&) = delete;
  void operator=(const vtkCVTOFFReader&) = delete;
};

#endif
