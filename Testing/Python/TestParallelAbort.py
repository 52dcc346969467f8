"""Ranks that do not all run the same way end together: `mpiexec -n 2 pvbatch --symmetric
TestParallelAbort.py`. Each rank runs the CVT Image filter for its piece; on the CPU engine the
ranks share the cell sums, one reduction per evaluation, so a rank that stopped alone would
leave the others waiting in the next reduction (a hang, caught by the test's timeout).
1. Rank 1 alone sets AbortExecute at its fifth progress event, as ParaView's abort button does
   on the rank that sees it: every rank stops after the same iteration, "aborted".
2. Rank 1 runs the OpenGL engine, rank 0 the CPU engine (Auto on nodes with and without a
   GPU): they agree not to share, and each computes alone."""
from vtkmodules.vtkCommonCore import vtkIntArray
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
from vtkmodules.vtkParallelCore import vtkMultiProcessController
from cvt.cvtFilters import vtkCVTImageFilter

controller = vtkMultiProcessController.GetGlobalController()
rank, ranks = controller.GetLocalProcessId(), controller.GetNumberOfProcesses()
failures = []


def run(opengl_on_rank_one, abort_on_rank_one):
    source = vtkRTAnalyticSource()
    source.SetWholeExtent(-50, 50, -50, 50, 0, 0)
    cvt = vtkCVTImageFilter()
    cvt.SetInputConnection(source.GetOutputPort())
    cvt.SetInputArrayToProcess(0, 0, 0, 0, "RTData")
    if opengl_on_rank_one and rank == 1:
        cvt.SetEngineToOpenGL()
    else:
        cvt.SetEngineToCPU()
    cvt.SetNumberOfSites(300)
    cvt.SetMaximumNumberOfIterations(20)
    cvt.SetTolerance(0)
    cvt.FailPipelineOnErrorOff()
    events = [0]

    def progress(algorithm, event):
        events[0] += 1
        if abort_on_rank_one and rank == 1 and events[0] == 5:
            algorithm.SetAbortExecute(1)

    cvt.AddObserver("ProgressEvent", progress)
    cvt.UpdatePiece(rank, ranks, 0)
    fields = cvt.GetSitesOutput().GetFieldData()
    value = lambda name, default: fields.GetArray(name).GetValue(0) if fields.GetArray(name) else default
    reason = fields.GetAbstractArray("StopReason")
    # Every rank's iteration count, gathered on all of them.
    mine, everyone = vtkIntArray(), vtkIntArray()
    mine.InsertNextValue(int(value("Iterations", -1)))
    controller.AllGather(mine, everyone)
    counts = [everyone.GetValue(i) for i in range(everyone.GetNumberOfTuples())]
    return int(value("EngineRanks", 0)), reason.GetValue(0) if reason else "", counts


def check(what, ok):
    print("rank %d: %s %s" % (rank, "ok     " if ok else "FAILED ", what), flush=True)
    if not ok:
        failures.append(what)


shared, reason, counts = run(False, True)
check("abort on rank 1: %d ranks sharing, stop '%s', iterations on every rank %s"
      % (shared, reason, counts),
      ranks > 1 and shared == ranks and reason == "aborted" and len(set(counts)) == 1
      and 0 <= counts[0] < 20)
shared, reason, counts = run(True, False)
check("OpenGL on rank 1 only: %d ranks sharing, stop '%s'" % (shared, reason),
      shared == 1 if rank == 0 else shared in (0, 1))
if rank == 0:
    print("parallel abort: " + ("ok" if not failures else "FAILED"), flush=True)
