"""CVT filters under MPI: `mpiexec -n 2 pvbatch TestParallel.py PLUGIN`.

Every rank computes the same CVT and keeps its share of each output, so the pieces together hold
each site, triangle and history row once, and the same numbers as one process computing alone
(the filters run here in this process, through the Python modules, as the reference)."""
import sys

from paraview import servermanager
from paraview.simple import LoadPlugin, Sphere, Wavelet

from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
from vtkmodules.vtkFiltersSources import vtkSphereSource
from cvt.cvtFilters import vtkCVTImageFilter, vtkCVTRemeshFilter

failures = []


def check(what, ok):
    print(("ok      " if ok else "FAILED  ") + what)
    if not ok:
        failures.append(what)


def counts(proxy, port):
    info = proxy.GetDataInformation(port)
    return info.GetNumberOfPoints(), info.GetNumberOfCells(), info.GetNumberOfRows()


def site_ids(proxy):
    data = servermanager.Fetch(proxy)  # all ranks' pieces of port 0, appended
    ids = data.GetPointData().GetArray("SiteId")
    return [int(ids.GetValue(i)) for i in range(ids.GetNumberOfTuples())]


def main(argv):
    LoadPlugin(argv[1], remote=False, ns=globals())
    ranks = servermanager.ActiveConnection.GetNumberOfDataPartitions()
    check("more than one rank (%d)" % ranks, ranks > 1)

    # CVT Image on a distributed Wavelet (each rank's source makes only its piece).
    extent = [-50, 50, -50, 50, 0, 0]
    image = CVTImage(Input=Wavelet(WholeExtent=extent), Density=["POINTS", "RTData"],
                     NumberOfSites=300, MaximumNumberOfIterations=10)
    image.UpdatePipeline()
    source = vtkRTAnalyticSource()
    source.SetWholeExtent(*extent)
    alone = vtkCVTImageFilter()
    alone.SetInputConnection(source.GetOutputPort())
    alone.SetInputArrayToProcess(0, 0, 0, 0, "RTData")
    alone.SetNumberOfSites(300)
    alone.SetMaximumNumberOfIterations(10)
    alone.Update()
    sites, _, _ = counts(image, 0)
    check("image: %d sites in all ranks' pieces (alone: 300)" % sites, sites == 300)
    ids = site_ids(image)
    check("image: each site once (%d distinct ids of %d)" % (len(set(ids)), len(ids)),
          sorted(ids) == list(range(300)))
    labels, _, _ = counts(image, 1)
    # Pieces of an image share one layer of points: 101 x 101 points, plus one shared row.
    check("image: labels in pieces (%d points; whole image 10201)" % labels,
          10201 <= labels <= 10201 + 101 * (ranks - 1))
    _, triangles, _ = counts(image, 2)
    reference = alone.GetDualOutput().GetNumberOfCells()
    check("image: dual triangles %d (alone %d)" % (triangles, reference), triangles == reference)
    _, _, rows = counts(image, 3)
    reference = alone.GetHistoryOutput().GetNumberOfRows()
    check("image: history rows %d (alone %d)" % (rows, reference), rows == reference)
    energy = servermanager.Fetch(image).GetFieldData().GetArray("Energy").GetValue(0)
    reference = alone.GetSitesOutput().GetFieldData().GetArray("Energy").GetValue(0)
    check("image: energy %.9g (alone %.9g)" % (energy, reference),
          abs(energy - reference) <= 1e-12 * abs(reference))

    # CVT Remesh of a distributed sphere (the source makes one piece per rank).
    remesh = CVTRemesh(Input=Sphere(ThetaResolution=40, PhiResolution=40), NumberOfSites=200,
                       MaximumNumberOfIterations=10)
    remesh.UpdatePipeline()
    sphere = vtkSphereSource()
    sphere.SetThetaResolution(40)
    sphere.SetPhiResolution(40)
    alone = vtkCVTRemeshFilter()
    alone.SetInputConnection(sphere.GetOutputPort())
    alone.SetNumberOfSites(200)
    alone.SetMaximumNumberOfIterations(10)
    alone.Update()
    sites, _, _ = counts(remesh, 0)
    check("remesh: %d sites (alone 200)" % sites, sites == 200)
    ids = site_ids(remesh)
    check("remesh: each site once", sorted(ids) == list(range(200)))
    _, triangles, _ = counts(remesh, 2)
    reference = alone.GetRemeshOutput().GetNumberOfCells()
    check("remesh: %d triangles (alone %d)" % (triangles, reference), triangles == reference)
    _, cells, _ = counts(remesh, 1)
    reference = alone.GetLabelsOutput().GetNumberOfCells()
    check("remesh: labelled input %d triangles (alone %d)" % (cells, reference), cells == reference)

    print("parallel: %s" % ("ok" if not failures else "FAILED (%d)" % len(failures)))


if __name__ == "__main__":
    main(sys.argv)
    # No sys.exit on success: pvbatch then stops the other ranks' service loops itself.
    if failures:
        sys.exit(1)
