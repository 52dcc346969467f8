// The CPU engines' parallel loops. They take their thread count and backend from vtkSMPTools
// (vtkSMPTools::Initialize, VTK_SMP_MAX_THREADS, VTK_SMP_BACKEND_IN_USE) and cut the range into
// the same chunks as vtkSMPTools::For, but run the chunks on oneTBB's worker threads, which
// stay from one loop to the next: the STDThread backend of ParaView 5.11's VTK (9.2) starts
// and joins its threads in every loop (`cvtBenchmark cpu` on these 2-core machines: 0.14 to
// 0.19 ms a loop, against 8 to 12 us), and an optimisation runs three loops per evaluation,
// some 400 in a remesh at 1000 sites.
#ifndef cvtThreads_h
#define cvtThreads_h

#include "cvtNumericsModule.h" // for export macro
#include "vtkType.h"           // for vtkIdType

#include <functional>

namespace cvt
{
/// ParaView's VTK defaults to the Sequential backend although it ships STDThread; use the
/// threads unless the user chose a backend (VTK_SMP_BACKEND_IN_USE).
CVTNUMERICS_EXPORT void UseThreads();

/// Runs chunk(begin, end) over [first, last) as vtkSMPTools::For(first, last, grain, chunk)
/// does: chunks of `grain` items (0: a quarter of the range per thread), all of it at once
/// when it is one chunk or when a loop runs already (loops in a loop's body are serial, as
/// vtkSMPTools has them unless nesting is turned on), in order on one thread under the
/// Sequential backend. The chunks, and so the results, do not depend on the threads' timing.
CVTNUMERICS_EXPORT void ForChunks(vtkIdType first, vtkIdType last, vtkIdType grain,
  const std::function<void(vtkIdType, vtkIdType)>& chunk);

/// ForChunks with vtkSMPTools::For's signature, for any functor of (begin, end).
template<class Functor>
void For(vtkIdType first, vtkIdType last, vtkIdType grain, const Functor& chunk)
{
  ForChunks(first, last, grain, [&chunk](vtkIdType begin, vtkIdType end) { chunk(begin, end); });
}

template<class Functor>
void For(vtkIdType first, vtkIdType last, const Functor& chunk)
{
  For(first, last, 0, chunk);
}
}

#endif
