"""The same pipeline in ParaView (pvpython or pvbatch; rendering needs an X server, e.g.
`xvfb-run -a`):

    xvfb-run -a pvpython Examples/paraview_pipeline.py build/lib/paraview-plugins/CVTPlugin/CVTPlugin.so \
        Data/density.png paraview_cvt.png

Loads the plugin, reads the picture, inverts it into a density, runs "CVT Image" (menu
Filters > CVT in the GUI) and saves a screenshot of the cells with the sites on top; then
remeshes a torus with "CVT Geometry Image" and "CVT Surface" and saves a screenshot of the
remesh next to the first (name_surface.png)."""
import sys

from paraview.simple import (Calculator, ColorBy, CreateView, GetActiveViewOrCreate,
                             LoadPlugin, OutputPort, PNGSeriesReader, Render, ResetCamera,
                             SaveScreenshot, Show)


def main(argv):
    if len(argv) < 4:
        print(__doc__)
        return 2
    plugin, picture, screenshot = argv[1], argv[2], argv[3]
    LoadPlugin(plugin, remote=False, ns=globals())
    image = PNGSeriesReader(FileNames=[picture])  # point data "PNGImage", one pixel per point
    density = Calculator(Input=image, ResultArrayName="darkness", Function="255 - PNGImage")
    cvt = CVTImage(Input=density, Density=["POINTS", "darkness"], NumberOfSites=500,
                   MaximumNumberOfIterations=50)
    cvt.UpdatePipeline()
    sites = cvt.GetDataInformation(0).GetNumberOfPoints()

    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = [500, 500]
    view.OrientationAxesVisibility = 0
    labels = Show(OutputPort(cvt, 1), view)
    ColorBy(labels, ("POINTS", "SiteId"))
    labels.LookupTable.ApplyPreset("Rainbow Uniform", True)
    dots = Show(OutputPort(cvt, 0), view)
    dots.SetRepresentationType("Points")
    dots.PointSize = 4
    dots.AmbientColor = dots.DiffuseColor = [0.0, 0.0, 0.0]
    dots.ColorArrayName = ["POINTS", ""]
    ResetCamera(view)
    view.CameraPosition = [view.CameraFocalPoint[0], view.CameraFocalPoint[1], 1000.0]
    view.CameraParallelProjection = 1
    ResetCamera(view)
    Render(view)
    SaveScreenshot(screenshot, view, ImageResolution=[500, 500])
    print(f"wrote {screenshot}: {sites} sites")

    # Surface remeshing: a torus geometry image -> constrained CVT -> dual triangulation.
    torus = CVTGeometryImage(Resolution=[256, 128])
    surface = CVTSurface(Input=torus, NumberOfSites=300, MaximumNumberOfIterations=50)
    surface_view = CreateView("RenderView")
    surface_view.ViewSize = [500, 400]
    surface_view.OrientationAxesVisibility = 0
    mesh = Show(OutputPort(surface, 2), surface_view)
    mesh.SetRepresentationType("Surface With Edges")
    surface_view.CameraPosition = [0.0, -4.0, 3.0]
    surface_view.CameraViewUp = [0.0, 0.0, 1.0]
    ResetCamera(surface_view)
    Render(surface_view)
    surface_shot = screenshot.rsplit(".", 1)[0] + "_surface.png"
    SaveScreenshot(surface_shot, surface_view, ImageResolution=[500, 400])
    vertices = surface.GetDataInformation(2).GetNumberOfPoints()
    print(f"wrote {surface_shot}: remesh with {vertices} vertices")
    return 0


if __name__ == "__main__":
    # Only exit explicitly on failure: pvpython's sys.exit() after rendering trips an X error
    # (GLXBadContext) while ParaView tears its windows down.
    status = main(sys.argv)
    if status:
        sys.exit(status)
