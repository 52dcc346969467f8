/**
 * @class   vtkCVTOBJReader
 * @brief   Reads the geometry of a Wavefront OBJ file (.obj): its vertices, faces, lines and
 *          points.
 *
 * VTK's vtkOBJReader (9.1 and 9.2) stops at forms that exporters write: it refuses faces whose
 * corners end in a slash (`f 1/ 2/ 3/`, as in Cura's printer models) or crashes on them, and
 * stops at a `usemtl` without a name. This reader takes every corner form (`v`, `v/vt`, `v//vn`,
 * `v/vt/vn`, `v/`, `v/vt/`), negative (relative) indices, indices of vertices defined further down,
 * lines continued with a backslash, "#" comments, and skips what is not geometry (texture
 * coordinates, normals, groups, objects, smoothing groups, materials, free-form curves and
 * surfaces). Extra numbers on a vertex line (a weight, or the colour some exporters add) are
 * skipped too.
 *
 * The output is a vtkPolyData of the vertices (in file order, in single precision as
 * vtkOBJReader stores them, so that both give the same points and so the same merges) with the
 * faces as polygons, `l` lines as polylines and `p` points as vertex cells; it has no point arrays
 * (vtkOBJReader's texture coordinates and normals split the points at seams).
 *
 * A vertex with fewer than three numbers, a face of fewer than three corners, a line of fewer
 * than two, a corner that is not an index or names vertex 0 or one that does not exist, and a
 * file without vertices are errors that say which line is wrong; the output is then empty.
 */
#ifndef vtkCVTOBJReader_h
#define vtkCVTOBJReader_h

#include "cvtIOModule.h" // for export macro
#include "vtkCVTMeshFileReader.h"

class CVTIO_EXPORT vtkCVTOBJReader : public vtkCVTMeshFileReader
{
public:
  static vtkCVTOBJReader* New();
  vtkTypeMacro(vtkCVTOBJReader, vtkCVTMeshFileReader);

protected:
  vtkCVTOBJReader() = default;
  ~vtkCVTOBJReader() override = default;

  bool ReadMesh(std::istream& in, vtkPolyData* output) override;
  const char* GetExtension() const override { return ".obj"; }

private:
  vtkCVTOBJReader(const vtkCVTOBJReader&) = delete;
  void operator=(const vtkCVTOBJReader&) = delete;
};

#endif
