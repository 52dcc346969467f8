"""Time per Lloyd iteration of CVT Image under pvbatch, alone or under MPI.

    [mpiexec -n N] pvbatch Testing/Benchmark/mpi_timing.py PLUGIN [SIZE SITES ITERATIONS DENSITY
        ENGINE]

SIZE x SIZE Wavelet (default 4096), SITES sites (100000), ITERATIONS Lloyd iterations (5),
DENSITY 1 for the density |RTData| + 1, 0 for a uniform one (0), ENGINE CPU or OpenGL (CPU).
Prints one line with the number of ranks sharing the cell sums, the whole update's seconds, the
median seconds per iteration (from the history's clock) and the energy. VTK_SMP_BACKEND_IN_USE=Sequential gives one thread
per rank."""
import statistics
import sys
import time

from paraview import servermanager
from paraview.simple import Calculator, LoadPlugin, Wavelet

args = sys.argv[1:] + ["4096", "100000", "5", "0", "CPU"][len(sys.argv) - 2:]
plugin, size, sites, iterations, density = args[0], int(args[1]), int(args[2]), int(args[3]), args[4] == "1"
engine = args[5]
LoadPlugin(plugin, remote=False, ns=globals())
source = Wavelet(WholeExtent=[0, size - 1, 0, size - 1, 0, 0])
if density:
    source = Calculator(Input=source, ResultArrayName="density", Function="abs(RTData)+1")
source.UpdatePipeline()
cvt = CVTImage(Input=source, Density=["POINTS", "density" if density else "Uniform density"],
               NumberOfSites=sites, MaximumNumberOfIterations=iterations, Method="Lloyd",
               Tolerance=0, Engine=engine)
start = time.time()
cvt.UpdatePipeline()
update = time.time() - start
clock = servermanager.Fetch(cvt, None, None, 3).GetColumnByName("seconds")
seconds = [clock.GetValue(i) for i in range(clock.GetNumberOfTuples())]
steps = [b - a for a, b in zip(seconds, seconds[1:])]
fields = servermanager.Fetch(cvt).GetFieldData()
print("%s: %d x %d, %d sites, %s density, %d rank(s) sharing: update %.2f s, %.3f s per iteration "
      "(median of %d), energy %.12g" % (engine, size, size, sites, "a" if density else "uniform",
                                        fields.GetArray("EngineRanks").GetValue(0), update,
                                        statistics.median(steps), len(steps),
                                        fields.GetArray("Energy").GetValue(0)))
