"""Writes Data/density.png, the bundled default input of `cvt image`: a 256x256 grey picture
(dark = dense with --invert) of a few soft blobs and a ring. Run with Debian's python3 and
python3-paraview: /usr/bin/python3 Data/make_density.py"""
import math
import os

from vtkmodules.vtkCommonCore import vtkUnsignedCharArray
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkIOImage import vtkPNGWriter

N = 256
image = vtkImageData()
image.SetDimensions(N, N, 1)
values = vtkUnsignedCharArray()
values.SetNumberOfValues(N * N)
blobs = [(-0.45, 0.35, 0.18), (0.4, 0.45, 0.12), (0.1, -0.4, 0.25)]
for j in range(N):
    y = -1.0 + (j + 0.5) * 2.0 / N
    for i in range(N):
        x = -1.0 + (i + 0.5) * 2.0 / N
        darkness = 0.08
        for (cx, cy, r) in blobs:
            darkness += 0.8 * math.exp(-((x - cx) ** 2 + (y - cy) ** 2) / (2 * r * r))
        ring = math.hypot(x - 0.35, y + 0.05)
        darkness += 0.5 * math.exp(-((ring - 0.3) ** 2) / 0.002)
        values.SetValue(j * N + i, int(round(255 * (1.0 - min(darkness, 1.0)))))
image.GetPointData().SetScalars(values)
writer = vtkPNGWriter()
writer.SetInputData(image)
writer.SetFileName(os.path.join(os.path.dirname(os.path.abspath(__file__)), "density.png"))
writer.Write()
