"""The same pipeline in ParaView (pvpython or pvbatch; rendering needs an X server, e.g.
`xvfb-run -a`):

    xvfb-run -a pvpython Examples/paraview_pipeline.py build/lib/paraview-plugins/CVTPlugin/CVTPlugin.so \
        Data/density.png paraview_cvt.png

Loads the plugin, reads the picture, inverts it into a density, runs "CVT Image" (menu
Filters > CVT in the GUI) and saves a screenshot of the cells with the sites on top."""
import sys

from paraview.simple import (Calculator, ColorBy, GetActiveViewOrCreate, LoadPlugin,
                             OutputPort, PNGSeriesReader, Render, ResetCamera, SaveScreenshot,
                             Show)


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
    return 0


if __name__ == "__main__":
    # Only exit explicitly on failure: pvpython's sys.exit() after rendering trips an X error
    # (GLXBadContext) while ParaView tears its windows down.
    status = main(sys.argv)
    if status:
        sys.exit(status)
