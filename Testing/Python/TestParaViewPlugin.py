"""pvpython test of the ParaView plugin (run under X: Testing/xvfb.sh): loads the plugin, runs every
proxy with its default properties on bundled data, checks the outputs numerically, compares a
screenshot with a baseline, and checks that bad input leaves an error and an empty output while
the session keeps working.

    Testing/xvfb.sh run STATE_DIR pvpython TestParaViewPlugin.py PLUGIN DATA_DIR OUTPUT_DIR
Set CVT_UPDATE_BASELINES=1 to rewrite the baseline."""
import os
import sys

from paraview import servermanager
from paraview.simple import (ColorBy, CreateView, Delete, GetActiveViewOrCreate,
                             GetColorTransferFunction, LoadPlugin, OutputPort, PNGSeriesReader,
                             Render, ResetCamera, SaveScreenshot, Show, Wavelet)
from vtkmodules.vtkCommonCore import vtkOutputWindow, vtkStringOutputWindow
from vtkmodules.vtkImagingCore import vtkImageDifference
from vtkmodules.vtkIOImage import vtkPNGReader

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAILED: " + message)


def field(data, name):
    return data.GetFieldData().GetArray(name).GetValue(0)


def main(plugin, data_dir, output_dir):
    LoadPlugin(plugin, remote=False, ns=globals())

    # Default properties on the bundled picture: 1000 sites, L-BFGS, 100 iterations.
    picture = PNGSeriesReader(FileNames=[os.path.join(data_dir, "density.png")])
    cvt = CVTImage(Input=picture)
    check(cvt.Method == "L-BFGS" and cvt.NumberOfSites == 1000 and cvt.NumberOfCorrections == 7,
          "defaults are L-BFGS, 1000 sites, 7 corrections")
    check(cvt.Density[1] == "Uniform density", "uniform density by default")
    cvt.UpdatePipeline()
    sites = servermanager.Fetch(cvt, idx=0)
    labels = servermanager.Fetch(cvt, idx=1)
    dual = servermanager.Fetch(cvt, idx=2)
    history = servermanager.Fetch(cvt, idx=3)
    check(sites.GetNumberOfPoints() == 1000, "1000 sites")
    check(labels.GetDimensions() == (256, 256, 1), "labels have the picture's 256x256 pixels")
    check(labels.GetPointData().GetArray("SiteId") is not None, "labels carry SiteId")
    check(dual.GetNumberOfPolys() > 1500, "dual triangulation has triangles")
    check(history.GetNumberOfRows() > 10, "history has rows")
    first = history.GetValueByName(0, "energy").ToDouble()
    last = history.GetValueByName(history.GetNumberOfRows() - 1, "energy").ToDouble()
    check(last < 0.8 * first, "energy falls: %g -> %g" % (first, last))
    check(abs(field(sites, "Energy") - last) <= 1e-9 * last, "reported energy is the last one")
    check(field(sites, "HexagonalFraction") > 0.5, "mostly hexagonal cells")
    total_mass = sum(sites.GetPointData().GetArray("Mass").GetValue(i) for i in range(1000))
    check(abs(total_mass - 256 * 256) < 1.0, "masses add up to the domain area: %g" % total_mass)

    # Screenshot against the baseline.
    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = [300, 300]
    view.OrientationAxesVisibility = 0
    display = Show(OutputPort(cvt, 1), view)
    ColorBy(display, ("POINTS", "SiteId"))
    ResetCamera(view)
    view.CameraParallelProjection = 1
    Render(view)
    shot = os.path.join(output_dir, "paraview_cvt.png")
    SaveScreenshot(shot, view, ImageResolution=[300, 300])
    baseline = os.path.join(data_dir, "Baseline", "paraview_cvt.png")
    if os.environ.get("CVT_UPDATE_BASELINES") == "1":
        os.replace(shot, baseline)
        print("baseline rewritten: " + baseline)
    else:
        readers = []
        for name in (shot, baseline):
            reader = vtkPNGReader()
            reader.SetFileName(name)
            reader.Update()
            readers.append(reader)
        difference = vtkImageDifference()
        difference.SetInputConnection(readers[0].GetOutputPort())
        difference.SetImageConnection(readers[1].GetOutputPort())
        difference.Update()
        error = difference.GetThresholdedError()
        print("screenshot thresholded error: %g" % error)
        check(error < 20.0, "screenshot matches the baseline (error %g)" % error)

    # The surface proxies with their defaults: a 1024 x 512 torus, 1000 sites, L-BFGS.
    torus = CVTGeometryImage()
    surface = CVTSurface(Input=torus)
    check(list(torus.Resolution) == [1024, 512] and surface.NumberOfSites == 1000,
          "surface defaults: 1024 x 512, 1000 sites")
    # Both filters with an OpenGL engine inherit its properties (abstract CVTGPUAlgorithm), and
    # they reach the filter.
    for proxy in (surface, CVTImage(Input=torus)):
        names = proxy.ListProperties()
        check("Engine" in names and "AdaptiveJumpFlooding" in names,
              "%s has Engine and AdaptiveJumpFlooding" % proxy.GetXMLName())
        proxy.AdaptiveJumpFlooding = 0
        proxy.UpdateVTKObjects()
        check("AdaptiveJumpFlooding: 0" in str(proxy.GetClientSideObject()),  # its PrintSelf
              "%s: AdaptiveJumpFlooding reaches the filter" % proxy.GetXMLName())
        proxy.AdaptiveJumpFlooding = 1
    surface.UpdatePipeline()
    remesh = servermanager.Fetch(surface, idx=2)
    edges = set()
    for c in range(remesh.GetNumberOfCells()):
        ids = [remesh.GetCell(c).GetPointId(k) for k in range(3)]
        for k in range(3):
            edges.add(tuple(sorted((ids[k], ids[(k + 1) % 3]))))
    euler = remesh.GetNumberOfPoints() - len(edges) + remesh.GetNumberOfCells()
    check(remesh.GetNumberOfPoints() == 1000, "remesh has the 1000 sites as vertices")
    check(euler == 0, "torus remesh has Euler characteristic 0 (got %d)" % euler)
    valence6 = remesh.GetFieldData().GetArray("Valence6Fraction").GetValue(0)
    print("surface: valence 6 %.1f%%, smallest angle %.1f" %
          (100 * valence6, remesh.GetFieldData().GetArray("MinimumAngle").GetValue(0)))
    check(valence6 > 0.6, "mostly valence 6")

    # A bundled mesh through the mesh geometry image proxy.
    from paraview.simple import XMLPolyDataReader
    mesh = XMLPolyDataReader(FileName=[os.path.join(data_dir, "hemisphere.vtp")])
    mesh_image = CVTMeshGeometryImage(Input=mesh, Resolution=[128, 128])
    mesh_cvt = CVTSurface(Input=mesh_image, NumberOfSites=100, MaximumNumberOfIterations=10)
    mesh_cvt.UpdatePipeline()
    check(mesh_cvt.GetDataInformation(2).GetNumberOfPoints() == 100, "mesh remesh has 100 vertices")
    # A mesh's point array, carried onto the pixels, is a density the surface proxy offers.
    from paraview.simple import Calculator
    weighted = Calculator(Input=mesh, ResultArrayName="rho", Function="1 + 9 * (coordsX > 0)")
    weighted_image = CVTMeshGeometryImage(Input=weighted, Resolution=[128, 128])
    weighted_image.UpdatePipeline()
    weighted_cvt = CVTSurface(Input=weighted_image, NumberOfSites=100, MaximumNumberOfIterations=10)
    check(weighted_cvt.Density == "Uniform density", "surface: uniform density by default")
    check("rho" in weighted_cvt.GetProperty("DensityArray").Available,
          "surface: the mesh's array is offered as density")
    weighted_cvt.Density = "rho"
    weighted_cvt.UpdatePipeline()
    dense_sites = servermanager.Fetch(weighted_cvt, idx=0)
    positive = sum(1 for i in range(dense_sites.GetNumberOfPoints())
                   if dense_sites.GetPoint(i)[0] > 0)
    check(positive > 60, "surface density draws the sites where it is larger (%d of 100)" % positive)

    # Any mesh becomes an atlas, which CVT Surface follows across its seams on either engine
    # (here Auto: the CPU without a GPU): a sphere's remesh is closed, a vertex per site.
    from paraview.simple import Sphere
    ball = Sphere(ThetaResolution=32, PhiResolution=16)
    atlas_image = CVTMeshGeometryImage(Input=ball, Resolution=[128, 128], Parameterization="Atlas")
    atlas_cvt = CVTSurface(Input=atlas_image, NumberOfSites=80, MaximumNumberOfIterations=10)
    atlas_cvt.UpdatePipeline()
    atlas_remesh = servermanager.Fetch(atlas_cvt, idx=2)
    check(atlas_remesh.GetNumberOfPoints() == 80 and atlas_remesh.GetNumberOfPolys() == 2 * 80 - 4,
          "sphere atlas remesh: %d vertices, %d triangles (80, 156)" %
          (atlas_remesh.GetNumberOfPoints(), atlas_remesh.GetNumberOfPolys()))

    # File > Open of an OFF mesh picks the plugin's reader; its octahedron remeshes closed.
    from paraview.simple import OpenDataFile
    octahedron = os.path.join(output_dir, "octahedron.off")
    with open(octahedron, "w") as off:
        off.write("OFF 6 8 12\n1 0 0\n-1 0 0\n0 1 0\n0 -1 0\n0 0 1\n0 0 -1\n"
                  "3 0 2 4\n3 2 1 4\n3 1 3 4\n3 3 0 4\n3 2 0 5\n3 1 2 5\n3 3 1 5\n3 0 3 5\n")
    off_reader = OpenDataFile(octahedron)
    check(off_reader is not None and off_reader.GetXMLName() == "CVTOFFReader",
          "File > Open of .off uses CVTOFFReader, not %s" %
          (off_reader.GetXMLName() if off_reader else None))
    if off_reader is not None:
        off_remesh = CVTRemesh(Input=off_reader, NumberOfSites=60, MaximumNumberOfIterations=10)
        off_remesh.UpdatePipeline()
        info = off_remesh.GetDataInformation(2)
        check(info.GetNumberOfPoints() == 60 and info.GetNumberOfCells() == 2 * 60 - 4,
              "the OFF octahedron remeshes to a closed genus-0 mesh of 60 vertices (%d, %d)" %
              (info.GetNumberOfPoints(), info.GetNumberOfCells()))
    # CollapseForValence (on for meshes, off for geometry images) reaches both filters.
    collapsing = [(surface, 0)] + ([(off_remesh, 1)] if off_reader is not None else [])
    for proxy, default in collapsing:
        check(proxy.CollapseForValence == default,
              "%s: CollapseForValence defaults to %d" % (proxy.GetXMLName(), default))
        proxy.CollapseForValence = 1 - default
        proxy.UpdateVTKObjects()
        check("CollapseForValence: %s" % ("on" if default == 0 else "off")
              in str(proxy.GetClientSideObject()),
              "%s: CollapseForValence reaches the filter" % proxy.GetXMLName())
        proxy.CollapseForValence = default
        proxy.UpdateVTKObjects()

    # The remesh's SiteIterationBudget (fewer iterations at many sites) reaches the filter.
    if off_reader is not None:
        check(off_remesh.SiteIterationBudget == 250000,
              "CVTRemesh: SiteIterationBudget defaults to 250000, not %d" %
              off_remesh.SiteIterationBudget)
        off_remesh.SiteIterationBudget = 0
        off_remesh.UpdateVTKObjects()
        check("SiteIterationBudget: 0" in str(off_remesh.GetClientSideObject()),
              "CVTRemesh: SiteIterationBudget reaches the filter")

    # The first picture of Show(), as pvpython gives it: the plugin's display hints.
    first_view = CreateView("RenderView")
    shown = {
        "image sites": Show(OutputPort(cvt, 0), first_view),
        "image labels": Show(OutputPort(cvt, 1), first_view),
        "image dual": Show(OutputPort(cvt, 2), first_view),
        "surface sites": Show(OutputPort(surface, 0), first_view),
        "remesh": Show(OutputPort(surface, 2), first_view),
    }
    expected = {"image sites": "Point Gaussian", "image labels": "Slice",
                "image dual": "Wireframe", "surface sites": "Point Gaussian",
                "remesh": "Surface With Edges"}
    for name, display in shown.items():
        check(display.Representation == expected[name], "%s shown as %s, not %s" %
              (name, expected[name], display.Representation))
    # Site dots a fifth of the site spacing in radius, flat circles lifted off the image plane
    # (ParaView's default, 0.5% of the extent, makes specks); other sites keep the defaults.
    dots = shown["image sites"]
    info = cvt.GetDataInformation(0)
    bounds = info.GetBounds()
    spacing = ((bounds[1] - bounds[0]) * (bounds[3] - bounds[2]) / info.GetNumberOfPoints()) ** 0.5
    check(abs(dots.GaussianRadius - 0.2 * spacing) < 1e-6 * spacing,
          "image site dots of radius 0.2 x spacing %g, not %g" % (spacing, dots.GaussianRadius))
    check(dots.ShaderPreset == "Plain circle", "image site dots drawn as plain circles")
    check(list(dots.Position) == [0.0, 0.0, dots.GaussianRadius], "dots lifted off the image")
    check(shown["surface sites"].ShaderPreset != "Plain circle", "surface sites keep the defaults")
    check(shown["image labels"].ColorArrayName[1] == "SiteId", "labels coloured by SiteId")
    site_colours = GetColorTransferFunction("SiteId").RGBPoints
    check(list(site_colours[1:4]) == [0.27, 0.0, 0.33],
          "SiteId has the plugin's many-hue colour map, not Cool to Warm: %s" % site_colours[:4])
    controller = servermanager.vtkSMParaViewPipelineControllerWithRendering()
    for proxy, port, view_type, icon in [(cvt, 1, "RenderView", "GEOMETRY"),
                                         (cvt, 2, "None", "GEOMETRY"),
                                         (cvt, 3, "None", "SpreadSheetView"),
                                         (surface, 1, "None", "GEOMETRY"),
                                         (surface, 2, "RenderView", "GEOMETRY"),
                                         (torus, 0, "None", "GEOMETRY")]:
        name = "%s port %d" % (proxy.GetXMLLabel(), port)
        check(controller.GetPreferredViewType(proxy.SMProxy, port) == view_type,
              "%s opens in %s on Apply" % (name, view_type))
        check(controller.GetPipelineIcon(proxy.SMProxy, port) == icon,
              "%s has the pipeline icon %s" % (name, icon))
    Delete(first_view)

    # Bad input: more sites than pixels. An error, once, an empty output; the session goes on.
    messages = vtkStringOutputWindow()
    previous = vtkOutputWindow.GetInstance()
    vtkOutputWindow.SetInstance(messages)
    small = Wavelet(WholeExtent=[0, 7, 0, 7, 0, 0])
    bad = CVTImage(Input=small, NumberOfSites=100)
    bad.UpdatePipeline()
    for port in range(4):
        bad.UpdatePipeline()
        bad.GetDataInformation(port)
    vtkOutputWindow.SetInstance(previous)
    check(messages.GetOutput().count("exceeds the 64 pixels") == 1,
          "the error names the problem, once: %s" % messages.GetOutput())
    check("returned failure" not in messages.GetOutput(), "no pipeline failure lines")
    check(bad.GetDataInformation(0).GetNumberOfPoints() == 0, "bad input leaves an empty output")
    bad.NumberOfSites = 10
    bad.UpdatePipeline()
    check(bad.GetDataInformation(0).GetNumberOfPoints() == 10, "the session keeps working")

    print("plugin test: " + ("FAILED" if failures else "ok"))
    return 1 if failures else 0


status = main(sys.argv[1], sys.argv[2], sys.argv[3])
if status:
    sys.exit(status)  # only on failure: sys.exit after rendering trips an X error in pvpython
