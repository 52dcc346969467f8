"""Seconds of CVT Remesh's stages under pvbatch, alone or under MPI.

    [mpiexec -n N] pvbatch Testing/Benchmark/mpi_remesh_timing.py PLUGIN MESH [SITES [ENGINE]]

MESH: any mesh ParaView reads (.obj .stl .ply .vtp ...), or `torus` for CVT Surface on ENGINE
(CPU, the default, or OpenGL) with the default torus geometry image (1024 x 512); SITES (default
5000). Prints one line with the number of ranks sharing the cell sums, the whole update's
seconds, the optimisation's and the remesh's seconds (the filter's own clocks; nan where the
filter keeps none) and the energy. VTK_SMP_BACKEND_IN_USE=
Sequential gives one thread per rank."""
import sys
import time

from paraview import servermanager
from paraview.simple import LoadPlugin, OpenDataFile

plugin, mesh = sys.argv[1], sys.argv[2]
sites = int(sys.argv[3]) if len(sys.argv) > 3 else 5000
engine = sys.argv[4] if len(sys.argv) > 4 else "CPU"
LoadPlugin(plugin, remote=False, ns=globals())
if mesh == "torus":
    remesh = CVTSurface(Input=CVTGeometryImage(), NumberOfSites=sites, Engine=engine)
else:
    source = OpenDataFile(mesh)
    source.UpdatePipeline()
    remesh = CVTRemesh(Input=source, NumberOfSites=sites)
start = time.time()
remesh.UpdatePipeline()
update = time.time() - start
fields = servermanager.Fetch(remesh).GetFieldData()
value = lambda name: fields.GetArray(name).GetValue(0) if fields.GetArray(name) else float("nan")
print("%s, %d sites, %d rank(s) sharing: update %.2f s, optimise %.2f s, remesh %.2f s, "
      "energy %.12g" % (mesh.rsplit("/", 1)[-1], sites, value("EngineRanks"), update,
                        value("OptimizeSeconds"), value("RemeshSeconds"), value("Energy")))
