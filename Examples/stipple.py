#!/usr/bin/python3
"""Stippling in Python: a picture's darkness as density -> a few thousand sites -> dots, PNG.

    PYTHONPATH=build/lib/python3.11/site-packages /usr/bin/python3 Examples/stipple.py \
        Data/density.png stipple.png 3000

Needs the built `cvt` package and the VTK Python modules it was built against (Debian:
python3-paraview, or python3-vtk9 for a standalone-VTK build)."""
import sys

from vtkmodules.vtkCommonDataModel import vtkDataObject
from vtkmodules.vtkIOImage import vtkPNGReader, vtkPNGWriter
from vtkmodules.vtkImagingCore import vtkImageShiftScale

from cvt.cvtFilters import vtkCVTImageFilter
from cvt.cvtRendering import vtkCVTSceneRenderer


def main(argv):
    if len(argv) < 3:
        print(__doc__)
        return 2
    source, target = argv[1], argv[2]
    sites = int(argv[3]) if len(argv) > 3 else 3000

    reader = vtkPNGReader()
    reader.SetFileName(source)
    darkness = vtkImageShiftScale()  # density = 255 - grey: dark is dense
    darkness.SetInputConnection(reader.GetOutputPort())
    darkness.SetShift(-255.0)
    darkness.SetScale(-1.0)
    darkness.SetOutputScalarTypeToFloat()

    cvt = vtkCVTImageFilter()
    cvt.SetInputConnection(darkness.GetOutputPort())
    cvt.SetInputArrayToProcess(0, 0, 0, vtkDataObject.FIELD_ASSOCIATION_POINTS, "PNGImage")
    cvt.SetNumberOfSites(sites)
    cvt.SetMaximumNumberOfIterations(50)
    cvt.Update()
    dots = cvt.GetSitesOutput()
    if dots.GetNumberOfPoints() == 0:
        print("the CVT failed (see the error above)", file=sys.stderr)
        return 1

    scene = vtkCVTSceneRenderer()
    scene.ShowCellsOff()
    scene.SetPointSize(3.0)
    picture = scene.Render(cvt.GetLabelsOutput(), dots)
    if picture is None:
        print("cannot render: " + scene.GetLastError(), file=sys.stderr)
        return 1
    writer = vtkPNGWriter()
    writer.SetInputData(picture)
    writer.SetFileName(target)
    writer.Write()
    energy = dots.GetFieldData().GetArray("Energy").GetValue(0)
    print(f"wrote {target}: {dots.GetNumberOfPoints()} dots, energy {energy:.6g}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
