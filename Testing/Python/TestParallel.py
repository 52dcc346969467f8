"""CVT filters under MPI: `mpiexec -n 2 pvbatch TestParallel.py PLUGIN`.

Every rank runs the same CVT and keeps its share of each output, so the pieces together hold
each site, triangle and history row once, and the same numbers as one process computing alone
(the filters run here in this process, through the Python modules, as the reference). On the
CPU engine the ranks share the cell integrals: of the image's cells, of the input mesh's
triangles for the remesh and of the geometry image's triangles for CVT Surface; on the OpenGL
engine the reductions over bands of the image's rows."""
import sys

from paraview import servermanager
from paraview.simple import LoadPlugin, Sphere, Wavelet

from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
from vtkmodules.vtkFiltersSources import vtkSphereSource
from cvt.cvtFilters import (vtkCVTGeometryImageSource, vtkCVTImageFilter, vtkCVTRemeshFilter,
                            vtkCVTSurfaceFilter)

failures = []


def check(what, ok):
    print(("ok      " if ok else "FAILED  ") + what)
    if not ok:
        failures.append(what)


def check_same(what, ours, alone):
    check("%s: %d in all ranks' pieces (alone %d)" % (what, ours, alone), ours == alone)


def counts(proxy, port):
    info = proxy.GetDataInformation(port)
    return info.GetNumberOfPoints(), info.GetNumberOfCells(), info.GetNumberOfRows()


def run_alone(algorithm, source, sites):
    """The filter on one process, as the reference: 10 iterations, like the proxies below."""
    algorithm.SetInputConnection(source.GetOutputPort())
    algorithm.SetNumberOfSites(sites)
    algorithm.SetMaximumNumberOfIterations(10)
    algorithm.Update()
    return algorithm


def site_ids(proxy):
    data = servermanager.Fetch(proxy)  # all ranks' pieces of port 0, appended
    ids = data.GetPointData().GetArray("SiteId")
    return [int(ids.GetValue(i)) for i in range(ids.GetNumberOfTuples())]


def check_shared_sums(what, proxy, alone, ranks, tolerance):
    """The cell sums shared by all ranks, and the energy within `tolerance` (relative) of one
    process's."""
    fields = servermanager.Fetch(proxy).GetFieldData()
    shared = fields.GetArray("EngineRanks").GetValue(0)
    check("%s: cell sums shared by %d ranks" % (what, shared), shared == ranks)
    energy = fields.GetArray("Energy").GetValue(0)
    reference = alone.GetSitesOutput().GetFieldData().GetArray("Energy").GetValue(0)
    check("%s: energy %.17g (alone %.17g)" % (what, energy, reference),
          abs(energy - reference) <= tolerance * abs(reference))


def check_shared_remesh(what, proxy, alone, sites, ranks):
    """Sites and remesh triangles once in all pieces, and cell sums shared by all ranks: each
    clips its share of the triangles and the sums are added across ranks, in another order than
    one process adds them (the last bits differ, not the result)."""
    check_same(what + ": sites", counts(proxy, 0)[0], sites)
    ids = site_ids(proxy)
    check(what + ": each site once", sorted(ids) == list(range(sites)))
    check_same(what + ": remesh triangles", counts(proxy, 2)[1],
               alone.GetRemeshOutput().GetNumberOfCells())
    check_shared_sums(what, proxy, alone, ranks, 1e-9)


def check_shared_opengl(what, proxy, alone, sites, ranks):
    """Each site once and the reductions shared by all ranks on the OpenGL engine: every rank
    labels the whole image and reduces its band of rows; the bands' float sums are added in
    another order than one process's blending adds them, so the energy agrees to float
    accuracy, not to the bit (the runs use Lloyd's method: L-BFGS's line search turns such
    differences into other steps, 2.7e-5 of the energy after 10 on the torus)."""
    check(what + ": each site once", sorted(site_ids(proxy)) == list(range(sites)))
    check_shared_sums(what, proxy, alone, ranks, 1e-6)


def main(argv):
    LoadPlugin(argv[1], remote=False, ns=globals())
    ranks = servermanager.ActiveConnection.GetNumberOfDataPartitions()
    check("more than one rank (%d)" % ranks, ranks > 1)

    # CVT Image on a distributed Wavelet (each rank's source makes only its piece).
    extent = [-50, 50, -50, 50, 0, 0]
    image = CVTImage(Input=Wavelet(WholeExtent=extent), Density=["POINTS", "RTData"],
                     NumberOfSites=300, MaximumNumberOfIterations=10, Engine="CPU")
    image.UpdatePipeline()
    source = vtkRTAnalyticSource()
    source.SetWholeExtent(*extent)
    alone = vtkCVTImageFilter()
    alone.SetInputArrayToProcess(0, 0, 0, 0, "RTData")
    alone.SetEngineToCPU()
    run_alone(alone, source, 300)
    check_same("image: sites", counts(image, 0)[0], 300)
    ids = site_ids(image)
    check("image: each site once (%d distinct ids of %d)" % (len(set(ids)), len(ids)),
          sorted(ids) == list(range(300)))
    labels, _, _ = counts(image, 1)
    # Pieces of an image share one layer of points: 101 x 101 points, plus one shared row.
    check("image: labels in pieces (%d points; whole image 10201)" % labels,
          10201 <= labels <= 10201 + 101 * (ranks - 1))
    check_same("image: dual triangles", counts(image, 2)[1],
               alone.GetDualOutput().GetNumberOfCells())
    check_same("image: history rows", counts(image, 3)[2], alone.GetHistoryOutput().GetNumberOfRows())
    # The ranks share the cell integrals; each cell is integrated by one rank, so the sites and
    # energy are those of one process, to the bit.
    check_shared_sums("image", image, alone, ranks, 0.0)

    # The same on the OpenGL engine, each rank reducing its band of rows.
    image = CVTImage(Input=Wavelet(WholeExtent=extent), Density=["POINTS", "RTData"],
                     NumberOfSites=300, MaximumNumberOfIterations=10, Engine="OpenGL", Method=0)
    image.UpdatePipeline()
    alone = vtkCVTImageFilter()
    alone.SetInputArrayToProcess(0, 0, 0, 0, "RTData")
    alone.SetEngineToOpenGL()
    alone.SetMethodToLloyd()
    run_alone(alone, source, 300)
    check_shared_opengl("image OpenGL", image, alone, 300, ranks)

    # CVT Remesh of a distributed sphere (the source makes one piece per rank).
    remesh = CVTRemesh(Input=Sphere(ThetaResolution=40, PhiResolution=40), NumberOfSites=200,
                       MaximumNumberOfIterations=10)
    remesh.UpdatePipeline()
    sphere = vtkSphereSource()
    sphere.SetThetaResolution(40)
    sphere.SetPhiResolution(40)
    alone = run_alone(vtkCVTRemeshFilter(), sphere, 200)
    check_shared_remesh("remesh", remesh, alone, 200, ranks)
    check_same("remesh: labelled input triangles", counts(remesh, 1)[1],
               alone.GetLabelsOutput().GetNumberOfCells())

    # CVT Surface on the CPU engine: a remesh of the geometry image's triangles inside the filter,
    # whose ranks share the clipping as CVT Remesh's do.
    surface = CVTSurface(Input=CVTGeometryImage(Resolution=[128, 64]), NumberOfSites=200,
                         MaximumNumberOfIterations=10, Engine="CPU")
    surface.UpdatePipeline()
    torus = vtkCVTGeometryImageSource()
    torus.SetResolution(128, 64)
    alone = vtkCVTSurfaceFilter()
    alone.SetEngineToCPU()
    run_alone(alone, torus, 200)
    check_shared_remesh("surface", surface, alone, 200, ranks)

    # CVT Surface on the OpenGL engine: each rank reduces and looks for constrained centroids in
    # its band of the geometry image's rows.
    surface = CVTSurface(Input=CVTGeometryImage(Resolution=[128, 64]), NumberOfSites=200,
                         MaximumNumberOfIterations=10, Engine="OpenGL", Method=0)
    surface.UpdatePipeline()
    alone = vtkCVTSurfaceFilter()
    alone.SetEngineToOpenGL()
    alone.SetMethodToLloyd()
    run_alone(alone, torus, 200)
    check_shared_opengl("surface OpenGL", surface, alone, 200, ranks)

    print("parallel: %s" % ("ok" if not failures else "FAILED (%d)" % len(failures)))


if __name__ == "__main__":
    main(sys.argv)
    # No sys.exit on success: pvbatch then stops the other ranks' service loops itself.
    if failures:
        sys.exit(1)
