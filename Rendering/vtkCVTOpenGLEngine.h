/**
 * @class   vtkCVTOpenGLEngine
 * @brief   GPU engine for 2D CVT: 1+JFA labelling and regional reductions on VTK's OpenGL classes.
 *
 * Implements the cvt::Engine seam (Rong et al. 2011, sections 3.1-3.3):
 * - sites live in a float texture, one texel ("slot") per site, at sub-pixel positions;
 * - a seed pass draws each site into its pixel, then 1+JFA passes label every pixel with its
 *   nearest site (distances from pixel centres, in physical units);
 * - a regional reduction draws points, moved by the vertex shader to their site's slot and
 *   summed by additive float blending: mass, moments about the site and energy per cell.
 *   Pixels on cell boundaries are split between the sites of their neighbourhood by the
 *   bisectors, so the sums are the integrals over the true (continuous) Voronoi cells;
 * - the Lloyd update runs in a fragment pass over the site texture; sites are read back only
 *   when asked for.
 *
 * The initial JFA step adapts to the sites' spacing (AdaptiveStep, see vtkCVTGPUEngine).
 *
 * Under MPI (cvt::SharedCellSums::ShareWork) every part labels the whole grid but reduces only
 * its band of rows; the sums and the largest cell radius are then combined across the parts,
 * and the Lloyd update runs on the combined sums.
 *
 * All work happens on the context of a vtkCVTOpenGLContext; the thread's previous context is
 * restored after every call.
 */
#ifndef vtkCVTOpenGLEngine_h
#define vtkCVTOpenGLEngine_h

#include "cvtEngine.h"          // for cvt::Engine
#include "cvtRenderingModule.h" // for export macro
#include "vtkCVTGPUEngine.h"
#include "vtkNew.h" // for ivars

#include <memory> // for unique_ptr

class CVTRENDERING_EXPORT vtkCVTOpenGLEngine
  : public vtkCVTGPUEngine
  , public cvt::Engine
  , public cvt::SharedCellSums
{
public:
  static vtkCVTOpenGLEngine* New();
  vtkTypeMacro(vtkCVTOpenGLEngine, vtkCVTGPUEngine);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** cvt::Engine */
  bool SetDomain(const cvt::Grid& grid, const std::vector<float>& density) override;
  bool SetSites(const std::vector<double>& sites) override;
  bool ComputeCellSums(cvt::CellSums& sums) override;
  bool MoveSitesToCentroids() override;
  bool GetSites(std::vector<double>& sites) override;
  bool GetLabels(std::vector<int>& labels) override;
  ///@}

  ///@{
  /**
   * Split boundary pixels between sites by their bisectors (default on). Off gives each pixel
   * wholly to the site nearest its centre, as the paper does.
   */
  vtkSetMacro(SplitBoundaryPixels, bool);
  vtkGetMacro(SplitBoundaryPixels, bool);
  vtkBooleanMacro(SplitBoundaryPixels, bool);
  ///@}

protected:
  vtkCVTOpenGLEngine();
  ~vtkCVTOpenGLEngine() override;
  void ReleaseObjects(vtkOpenGLRenderWindow* window) override;
  bool Label(int initialStep) override;
  bool Reduce(cvt::CellSums& sums, double& maximumRadius) override;

private:
  vtkCVTOpenGLEngine(const vtkCVTOpenGLEngine&) = delete;
  void operator=(const vtkCVTOpenGLEngine&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;

  bool ScatterToSlots();
  bool CheckGLError(const char* where);

  cvt::Grid Grid;
  int GridSize[2] = { 0, 0 };       // Grid.Width, Grid.Height, as shader uniforms want them
  float Metric[2] = { 1.0f, 1.0f }; // Grid.Spacing in float
  bool SplitBoundaryPixels = true;
};

#endif
