/**
 * @class   vtkCVTSceneRenderer
 * @brief   Pictures of CVT results: cells coloured by site with sites on top, and remeshes.
 *
 * Both draw on the CPU: no OpenGL and no display are needed, a picture costs milliseconds, and
 * it has the same pixels on every machine. Colours come from seeded tables, so a result always
 * gives the same picture.
 */
#ifndef vtkCVTSceneRenderer_h
#define vtkCVTSceneRenderer_h

#include "cvtRenderingModule.h" // for export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // for the picture

#include <string> // for std::string

class vtkImageData;
class vtkPolyData;
class vtkUnsignedCharArray;

class CVTRENDERING_EXPORT vtkCVTSceneRenderer : public vtkObject
{
public:
  static vtkCVTSceneRenderer* New();
  vtkTypeMacro(vtkCVTSceneRenderer, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** Size of the picture's longer side in pixels (default 800). */
  vtkSetClampMacro(Size, int, 16, 8192);
  vtkGetMacro(Size, int);
  ///@}

  ///@{
  /** Draw the cells coloured by site (default on); off draws black dots on white (stippling). */
  vtkSetMacro(ShowCells, bool);
  vtkGetMacro(ShowCells, bool);
  vtkBooleanMacro(ShowCells, bool);
  ///@}

  ///@{
  /** Diameter of the site dots in pixels (default 4). */
  vtkSetClampMacro(PointSize, double, 0.0, 64.0);
  vtkGetMacro(PointSize, double);
  ///@}

  /**
   * Render `labels` (a 2D image with an int SiteId point array) and `sites` (vertices) into an
   * RGB image, each picture pixel coloured by the label under its centre, the sites as dots of
   * PointSize pixels. Needs no OpenGL. Returns nullptr with a message in GetLastError() when
   * the labels have no SiteId array.
   *
   * The picture belongs to this renderer and is replaced by its next Render or RenderMesh
   * (hold it in a vtkSmartPointer, or in Python a variable, to keep it). A plain pointer, not
   * a vtkSmartPointer, so that the Python wrappers of VTK 9.1 convert it as well as 9.2's.
   */
  vtkImageData* Render(vtkImageData* labels, vtkPolyData* sites);

  /**
   * Render a surface mesh (a remesh) of any shape, size and orientation, seen mostly along its
   * thinnest principal axis (an open sheet from the side its normals face) and tilted, the
   * longest axis across, framed whole (within 90% of the picture's width and height), each
   * triangle in its own colour
   * (lit from the camera) with its edges drawn, into an RGB image of Size x 3/4 Size (a
   * z-buffer, drawn on the CPU). nullptr with a message in GetLastError() when the mesh has no
   * polygons. The picture belongs to this renderer, as with Render.
   */
  vtkImageData* RenderMesh(vtkPolyData* mesh);
  const std::string& GetLastError() const { return this->LastError; }

protected:
  vtkCVTSceneRenderer() = default;
  ~vtkCVTSceneRenderer() override = default;

private:
  vtkCVTSceneRenderer(const vtkCVTSceneRenderer&) = delete;
  void operator=(const vtkCVTSceneRenderer&) = delete;

  /** Makes `pixels` (RGB, width x height) a new Picture and returns it. */
  vtkImageData* KeepPicture(vtkUnsignedCharArray* pixels, int width, int height);

  int Size = 800;
  bool ShowCells = true;
  double PointSize = 4.0;
  std::string LastError;
  vtkSmartPointer<vtkImageData> Picture; // the last picture, returned by Render/RenderMesh
};

#endif
