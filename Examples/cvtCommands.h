// The two commands of the `cvt` program: `cvt image` (cvtImageCommand.cxx) and `cvt surface`
// (cvtSurfaceCommand.cxx). Each reads its input, runs its CVT filter, writes the --output files
// and returns the exit status; errors end the program with a "cvt: ..." line.
#ifndef cvtCommands_h
#define cvtCommands_h

#include "cvtCommandLine.h"
#include "vtkCVTAlgorithm.h"
#include "vtkCVTGPUAlgorithm.h"

namespace cvtcli
{

int RunImage(const Options& options);
int RunSurface(const Options& options);

/// The optimiser options that the image, surface and remesh filters share.
inline void SetOptimizer(const Options& options, vtkCVTAlgorithm* filter)
{
  filter->SetNumberOfSites(options.Sites);
  filter->SetRandomSeed(static_cast<int>(options.Seed));
  filter->SetMaximumNumberOfIterations(options.Iterations);
  filter->SetTolerance(options.Tolerance);
  filter->SetGradientTolerance(options.GradientTolerance);
  filter->SetNumberOfCorrections(options.Corrections);
  if (options.Method == "lloyd")
  {
    filter->SetMethodToLloyd();
  }
  else
  {
    filter->SetMethodToLBFGS();
  }
}

/// --engine auto|opengl|cpu on the image and surface filters.
inline void SetEngine(const Options& options, vtkCVTGPUAlgorithm* filter)
{
  filter->SetEngine(options.Engine == "opengl" ? vtkCVTGPUAlgorithm::OPENGL
      : options.Engine == "cpu"                ? vtkCVTGPUAlgorithm::CPU
                                               : vtkCVTGPUAlgorithm::AUTO);
}

} // namespace cvtcli

#endif
