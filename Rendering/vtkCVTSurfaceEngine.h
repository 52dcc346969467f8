/**
 * @class   vtkCVTSurfaceEngine
 * @brief   GPU engine for the constrained CVT on a surface given as a geometry image.
 *
 * Implements the cvt::SurfaceEngine seam (Rong et al. 2011, section 4.2): sites are 3D points
 * held by geometry-image pixels; 1+JFA labels every pixel of the image with the nearest site
 * by 3D Euclidean distance between stored positions, honouring the identified borders (wrap
 * flags) and the mask; a regional reduction by additive float blending gives each cell's mass,
 * moments and energy, weighted by the pixels' area weights. A cell split by the cut into
 * several parts of the image is summed as one. The optimisers (constrained centroids,
 * tangential gradients, projection) run on the CPU side of the seam. The initial JFA step
 * adapts to the sites' spacing in pixels (AdaptiveStep, see vtkCVTGPUEngine).
 *
 * Under MPI (cvt::SharedCellSums::ShareWork) every part labels the whole image but reduces,
 * and looks for constrained centroids in, only its band of rows; the parts' sums are added, the
 * nearest of their centroid candidates kept.
 */
#ifndef vtkCVTSurfaceEngine_h
#define vtkCVTSurfaceEngine_h

#include "cvtEngine.h"          // for cvt::SharedCellSums
#include "cvtRenderingModule.h" // for export macro
#include "cvtSurface.h"         // for cvt::SurfaceEngine
#include "vtkCVTGPUEngine.h"
#include "vtkNew.h" // for ivars

#include <memory> // for unique_ptr

class CVTRENDERING_EXPORT vtkCVTSurfaceEngine
  : public vtkCVTGPUEngine
  , public cvt::SurfaceEngine
  , public cvt::SharedCellSums
{
public:
  static vtkCVTSurfaceEngine* New();
  vtkTypeMacro(vtkCVTSurfaceEngine, vtkCVTGPUEngine);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** cvt::SurfaceEngine */
  bool SetGeometryImage(const cvt::GeometryImage& image) override;
  bool SetSites(const std::vector<double>& sites, const std::vector<long long>& pixels) override;
  bool ComputeCellSums(cvt::CellSums& sums) override;
  bool GetLabels(std::vector<int>& labels) override;
  bool NearestPointsInCells(const std::vector<double>& targets, std::vector<double>& sites,
    std::vector<long long>& pixels) override;
  ///@}

protected:
  vtkCVTSurfaceEngine();
  ~vtkCVTSurfaceEngine() override;
  void ReleaseObjects(vtkOpenGLRenderWindow* window) override;
  bool Label(int initialStep) override;
  bool Reduce(cvt::CellSums& sums, double& maximumRadius) override;
  bool CanAdaptStep() const override { return !this->HasSeams; }

private:
  vtkCVTSurfaceEngine(const vtkCVTSurfaceEngine&) = delete;
  void operator=(const vtkCVTSurfaceEngine&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;

  bool CheckGLError(const char* where);
  bool AttachNearestTargets(int width, int height);
  /** Keeps, for every site, the nearest of all parts' candidates (sites, pixels) to its target;
   * `found` tells which of this part's are candidates. */
  bool NearestAcrossParts(const std::vector<double>& targets, const std::vector<char>& found,
    std::vector<double>& sites, std::vector<long long>& pixels);

  cvt::GeometryImage Image; // for the CPU fallback of NearestPointsInCells
  int GridSize[2] = { 0, 0 };
  double Diagonal = 1.0; // of the surface's bounding box: the depth scale of nearest points
  int Wrap[2] = { 0, 0 };
  bool HasSeams = false; // an atlas: chart-border pixels have seam partners
};

#endif
