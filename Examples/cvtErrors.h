// How the `cvt` program reports a failure: one line "cvt: <message>" on stderr and an exit
// status (1, or 2 for usage), whatever part of the program or of VTK found it.
#ifndef cvtErrors_h
#define cvtErrors_h

#include "vtkCommand.h"

#include <string>

class vtkAlgorithm;
class vtkPolyData;

namespace cvtcli
{

/// Prints "cvt: <message>" and exits with `status`.
[[noreturn]] void Fail(const std::string& message, int status = 1);

/// Keeps a filter's last error message, so that the program can fail with it; prints its
/// warnings as "cvt: warning: ..." lines. VTK's own output window is silenced (see main).
class ErrorObserver : public vtkCommand
{
public:
  static ErrorObserver* New() { return new ErrorObserver; }
  void Execute(vtkObject*, unsigned long event, void* data) override;
  std::string Message;
};

/// Runs the filter; fails with its error message when it produced no sites.
void RunOrFail(vtkAlgorithm* filter, vtkPolyData* (*sites)(vtkAlgorithm*));

} // namespace cvtcli

#endif
