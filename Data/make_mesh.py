"""Writes Data/hemisphere.vtp, the bundled mesh for `cvt surface --input`: the upper half of a
sphere of radius 0.5 (a triangle mesh of disk topology). Run with Debian's python3 and
python3-paraview: /usr/bin/python3 Data/make_mesh.py"""
import os

from vtkmodules.vtkFiltersCore import vtkCleanPolyData
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

sphere = vtkSphereSource()
sphere.SetRadius(0.5)
sphere.SetThetaResolution(64)
sphere.SetPhiResolution(32)
sphere.SetEndPhi(90.0)
clean = vtkCleanPolyData()
clean.SetInputConnection(sphere.GetOutputPort())
writer = vtkXMLPolyDataWriter()
writer.SetInputConnection(clean.GetOutputPort())
writer.SetDataModeToBinary()  # inline base64: Debian 12's expat rejects appended raw data
writer.SetFileName(os.path.join(os.path.dirname(os.path.abspath(__file__)), "hemisphere.vtp"))
writer.Write()
