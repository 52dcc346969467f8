"""/usr/bin/python3 test of the wrapped modules: import, a pipeline, bad input.
Needs PYTHONPATH to the built package and the vtkmodules it was built against."""
import sys

from vtkmodules.vtkCommonCore import vtkOutputWindow, vtkStringOutputWindow
from vtkmodules.vtkCommonDataModel import vtkDataObject
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource

from cvt.cvtFilters import vtkCVTImageFilter
from cvt.cvtIO import vtkCVTOBJReader, vtkCVTOFFReader
from cvt.cvtRendering import vtkCVTOpenGLEngine, vtkCVTSceneRenderer

source = vtkRTAnalyticSource()
source.SetWholeExtent(-32, 31, -32, 31, 0, 0)
cvt = vtkCVTImageFilter()
cvt.SetInputConnection(source.GetOutputPort())
cvt.SetInputArrayToProcess(0, 0, 0, vtkDataObject.FIELD_ASSOCIATION_POINTS, "RTData")
cvt.SetNumberOfSites(30)
cvt.SetMaximumNumberOfIterations(20)
cvt.Update()
sites = cvt.GetSitesOutput()
assert sites.GetNumberOfPoints() == 30, sites.GetNumberOfPoints()
energy = sites.GetFieldData().GetArray("Energy").GetValue(0)
history = cvt.GetHistoryOutput()
assert history.GetNumberOfRows() > 2
assert energy < history.GetValueByName(0, "energy").ToDouble()
assert cvt.GetLabelsOutput().GetPointData().GetArray("SiteId").GetRange()[1] <= 29

picture = vtkCVTSceneRenderer().Render(cvt.GetLabelsOutput(), sites)
assert picture is not None and picture.GetDimensions()[0] == 800
assert "Context" in str(vtkCVTOpenGLEngine())
assert "FileName: (none)" in str(vtkCVTOFFReader())
assert "FileName: (none)" in str(vtkCVTOBJReader())

messages = vtkStringOutputWindow()
vtkOutputWindow.SetInstance(messages)
cvt.SetNumberOfSites(0)
cvt.Update()
assert cvt.GetSitesOutput().GetNumberOfPoints() == 0
assert "at least one site" in messages.GetOutput(), messages.GetOutput()
print("python modules: ok, energy %g" % energy)
