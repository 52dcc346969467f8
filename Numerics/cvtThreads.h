// Private to CVT::Numerics: the CPU engines run their loops with vtkSMPTools. ParaView's VTK
// defaults to the Sequential backend although it ships STDThread; use the threads unless the
// user chose a backend (VTK_SMP_BACKEND_IN_USE).
#ifndef cvtThreads_h
#define cvtThreads_h

#include "vtkSMPTools.h"

#include <cstdlib>
#include <string>

namespace cvt
{
inline void UseThreads()
{
  const char* backend = vtkSMPTools::GetBackend();
  if (backend && std::string(backend) == "Sequential" && !std::getenv("VTK_SMP_BACKEND_IN_USE"))
  {
    vtkSMPTools::SetBackend("STDThread");
  }
}
}

#endif
