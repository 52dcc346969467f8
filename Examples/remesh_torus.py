#!/usr/bin/python3
"""Surface remeshing in Python: a torus as a geometry image -> constrained CVT on the GPU ->
the dual triangulation as a new mesh, saved as .vtp and rendered to a PNG.

    PYTHONPATH=build/lib/python3.11/site-packages /usr/bin/python3 Examples/remesh_torus.py \
        remesh.vtp remesh.png [SITES] [W H]

Needs the built `cvt` package and the VTK Python modules it was built against (Debian:
python3-paraview, or python3-vtk9 for a standalone-VTK build)."""
import sys

from vtkmodules.vtkCommonComputationalGeometry import vtkParametricTorus
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

from cvt.cvtFilters import vtkCVTGeometryImageSource, vtkCVTSurfaceFilter
from cvt.cvtRendering import vtkCVTSceneRenderer


def main(argv):
    if len(argv) < 3:
        print(__doc__)
        return 2
    mesh_file, picture_file = argv[1], argv[2]
    sites = int(argv[3]) if len(argv) > 3 else 1000
    width, height = (int(argv[4]), int(argv[5])) if len(argv) > 5 else (1024, 512)

    torus = vtkParametricTorus()
    torus.SetRingRadius(1.0)
    torus.SetCrossSectionRadius(0.4)
    geometry_image = vtkCVTGeometryImageSource()
    geometry_image.SetParametricFunction(torus)
    geometry_image.SetResolution(width, height)

    cvt = vtkCVTSurfaceFilter()
    cvt.SetInputConnection(geometry_image.GetOutputPort())
    cvt.SetNumberOfSites(sites)
    cvt.SetMaximumNumberOfIterations(100)
    cvt.Update()
    remesh = cvt.GetRemeshOutput()
    if remesh.GetNumberOfPolys() == 0:
        print("the CVT failed (see the error above)", file=sys.stderr)
        return 1

    writer = vtkXMLPolyDataWriter()
    writer.SetInputData(remesh)
    writer.SetDataModeToBinary()  # inline base64: Debian 12's expat rejects appended raw data
    writer.SetFileName(mesh_file)
    writer.Write()
    picture = vtkCVTSceneRenderer().RenderMesh(remesh)
    png = vtkPNGWriter()
    png.SetInputData(picture)
    png.SetFileName(picture_file)
    png.Write()
    fields = remesh.GetFieldData()
    print(f"wrote {mesh_file} and {picture_file}: {remesh.GetNumberOfPoints()} vertices, "
          f"{remesh.GetNumberOfPolys()} triangles, valence 6: "
          f"{100 * fields.GetArray('Valence6Fraction').GetValue(0):.1f}%, smallest angle "
          f"{fields.GetArray('MinimumAngle').GetValue(0):.1f} degrees")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
