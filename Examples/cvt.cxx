// cvt: centroidal Voronoi tessellations on the GPU from the command line.
//   cvt image [options]     CVT of a 2D image domain (density from an image, or uniform)
//   cvt surface [options]   constrained CVT on a surface (a torus) and its remesh
// Run `cvt --help` for the options. Errors go to stderr with exit status 1 (2 for usage).
// The parts: options (cvtCommandLine), inputs (cvtReaders), outputs (cvtOutputs), error
// reporting (cvtErrors) and the two commands (cvtImageCommand, cvtSurfaceCommand).
#include "cvtCommandLine.h"
#include "cvtCommands.h"
#include "cvtErrors.h"

#include "vtkLogger.h"
#include "vtkOutputWindow.h"

#include <csignal>
#include <exception>
#include <iostream>
#include <malloc.h>
#include <new>
#include <string>
#include <vector>

int main(int argc, char* argv[])
{
  using namespace cvtcli;
  // Past a file-size limit (ulimit -f), writes fail with EFBIG and are reported; the default
  // action would kill the program.
  std::signal(SIGXFSZ, SIG_IGN);
  // Memory freed by one stage stays with the process for the next: the stages allocate and free
  // arrays of tens of megabytes (edge tables, Voronoi pieces), which glibc by default maps
  // afresh and unmaps each time, and a fresh page costs its first touch, 6 to 11 us on these
  // virtual machines (1.2 million triangles at 1000 sites, with EdgeTable's 32-bit indices:
  // 372,000 page faults -> 208,000, 14.3 -> 12.4 s end to end, medians of 3). The program runs
  // one job and exits, so nothing needs returning.
  mallopt(M_MMAP_THRESHOLD, 1 << 30);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
  Options options;
  try
  {
    options = ParseArguments(std::vector<std::string>(argv + 1, argv + argc));
  }
  catch (const UsageError& error)
  {
    Fail(error.what(), 2);
  }
  if (options.Help)
  {
    std::cout << Usage;
    return options.HelpStatus;
  }
  // Errors and warnings reach the user once, through the filters' observers ("cvt: ..."),
  // without VTK's pipeline dumps.
  vtkOutputWindow::GetInstance()->SetDisplayModeToNever();
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  try
  {
    return options.Command == "surface" ? RunSurface(options) : RunImage(options);
  }
  catch (const std::bad_alloc&)
  {
    Fail("out of memory: the input is too large for this machine, or corrupt");
  }
  catch (const std::exception& failure)
  {
    Fail(failure.what());
  }
}
