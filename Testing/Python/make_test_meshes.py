#!/usr/bin/python3
"""Writes the surface test meshes into a folder (no downloads: VTK sources and marching cubes
of implicit surfaces, made here). Each is a kind of input the remesher must handle:
  sphere.vtp        closed, genus 0 (VTK's UV sphere: pole fans, uneven triangles)
  noisy.vtp         the same with 1% radial noise, as a scan (no sharp features to keep)
  torus.vtp         closed, genus 1, as a parametric grid with duplicated seam points
  genus2.vtp        closed, genus 2 (marching cubes: many thin triangles)
  genus3.vtp        closed, genus 3
  dumbbell.vtp      closed, genus 0, not star-shaped about its centroid (two balls, a bar)
  holes.vtp         a sphere with four holes (four boundary loops)
  twoparts.vtp      two disjoint closed parts
  pieces.vtp        an assembly of 25 parts: a ball, 20 small spheres, 4 small rings (genus 1)
  box.vtp           a box with sharp edges, quads triangulated and subdivided
  cube.vtp          a cube of 12 triangles (CAD-like faces, each meeting hundreds of cells)
  plate.vtp         a plate thinner than the cells at 1000 sites (cells reach both sides)
  dirty.vtp         a disk with duplicated points, zero-area and duplicate triangles
  disk.vtp          an open disk (one boundary loop)
Usage: make_test_meshes.py OUTPUT_DIR"""
import os
import sys

import numpy as np
import vtk
from vtk.util.numpy_support import numpy_to_vtk


def write(mesh, path):
    w = vtk.vtkXMLPolyDataWriter()
    w.SetDataModeToBinary()
    w.SetInputData(mesh)
    w.SetFileName(path)
    w.Write()


def output(algorithm):
    algorithm.Update()
    out = vtk.vtkPolyData()
    out.ShallowCopy(algorithm.GetOutput())
    return out


def implicit_surface(function, bounds, n=96):
    """Marching cubes of function(x, y, z) = 0 over a box, as triangles."""
    lo, hi = np.array(bounds[0::2]), np.array(bounds[1::2])
    axes = [np.linspace(lo[k], hi[k], n) for k in range(3)]
    z, y, x = np.meshgrid(axes[2], axes[1], axes[0], indexing='ij')
    values = function(x, y, z).astype(np.float64).ravel()
    image = vtk.vtkImageData()
    image.SetDimensions(n, n, n)
    image.SetOrigin(*lo)
    image.SetSpacing(*((hi - lo) / (n - 1)))
    array = numpy_to_vtk(values, deep=True)
    array.SetName('f')
    image.GetPointData().SetScalars(array)
    contour = vtk.vtkMarchingCubes()
    contour.SetInputData(image)
    contour.SetValue(0, 0.0)
    contour.ComputeNormalsOff()
    contour.ComputeScalarsOff()
    return output(contour)


def torus_field(x, y, z, R=1.0, r=0.4):
    return (np.sqrt(x * x + y * y) - R) ** 2 + z * z - r * r


def main():
    folder = sys.argv[1]
    os.makedirs(folder, exist_ok=True)

    sphere = vtk.vtkSphereSource()
    sphere.SetThetaResolution(80)
    sphere.SetPhiResolution(60)
    write(output(sphere), os.path.join(folder, 'sphere.vtp'))
    noisy = output(sphere)
    rng = np.random.default_rng(1)
    points = noisy.GetPoints()
    for i in range(points.GetNumberOfPoints()):
        scale = 1.0 + 0.01 * (rng.random() - 0.5)
        points.SetPoint(i, *[scale * x for x in points.GetPoint(i)])
    write(noisy, os.path.join(folder, 'noisy.vtp'))

    torus = vtk.vtkParametricTorus()
    torus.SetRingRadius(1.0)
    torus.SetCrossSectionRadius(0.4)
    source = vtk.vtkParametricFunctionSource()
    source.SetParametricFunction(torus)
    source.SetUResolution(120)
    source.SetVResolution(60)
    source.GenerateTextureCoordinatesOff()
    write(output(source), os.path.join(folder, 'torus.vtp'))

    # Genus 2 and 3: unions of tori along x (the product of the fields is zero on each torus).
    def tori(count):
        def f(x, y, z):
            value = np.ones_like(x)
            for k in range(count):
                cx = (k - (count - 1) / 2.0) * 1.6
                value = np.minimum(value, torus_field(x - cx, y, z, 1.0, 0.35))
            return value
        return f
    write(implicit_surface(tori(2), (-2.8, 2.8, -1.6, 1.6, -0.6, 0.6), 110),
          os.path.join(folder, 'genus2.vtp'))
    write(implicit_surface(tori(3), (-3.6, 3.6, -1.6, 1.6, -0.6, 0.6), 120),
          os.path.join(folder, 'genus3.vtp'))

    def dumbbell(x, y, z):
        ball = np.minimum(np.sqrt((x - 1.2) ** 2 + y * y + z * z), np.sqrt((x + 1.2) ** 2 + y * y + z * z)) - 0.7
        bar = np.maximum(np.sqrt(y * y + z * z) - 0.25, np.abs(x) - 1.2)
        return np.minimum(ball, bar)
    write(implicit_surface(dumbbell, (-2.1, 2.1, -0.9, 0.9, -0.9, 0.9), 100),
          os.path.join(folder, 'dumbbell.vtp'))

    # A sphere with four round holes.
    fine = vtk.vtkSphereSource()
    fine.SetThetaResolution(90)
    fine.SetPhiResolution(70)
    ball = output(fine)
    centres = vtk.vtkCellCenters()
    centres.SetInputData(ball)
    centres.Update()
    keep = vtk.vtkCellArray()
    directions = [(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, 0, 1)]
    for c in range(ball.GetNumberOfCells()):
        p = np.array(centres.GetOutput().GetPoint(c))
        p /= np.linalg.norm(p)
        if all(np.dot(p, d) < 0.93 for d in directions):
            keep.InsertNextCell(ball.GetCell(c).GetPointIds())
    holes = vtk.vtkPolyData()
    holes.SetPoints(ball.GetPoints())
    holes.SetPolys(keep)
    clean = vtk.vtkCleanPolyData()
    clean.SetInputData(holes)
    write(output(clean), os.path.join(folder, 'holes.vtp'))

    # Two parts.
    a = vtk.vtkSphereSource()
    a.SetThetaResolution(60)
    a.SetPhiResolution(40)
    b = vtk.vtkSphereSource()
    b.SetCenter(1.5, 0.0, 0.0)
    b.SetRadius(0.35)
    b.SetThetaResolution(40)
    b.SetPhiResolution(30)
    both = vtk.vtkAppendPolyData()
    both.AddInputConnection(a.GetOutputPort())
    both.AddInputConnection(b.GetOutputPort())
    write(output(both), os.path.join(folder, 'twoparts.vtp'))

    # An assembly: one ball, 20 small balls and 4 small rings around it.
    parts = vtk.vtkAppendPolyData()
    big = vtk.vtkSphereSource()
    big.SetThetaResolution(60)
    big.SetPhiResolution(40)
    parts.AddInputConnection(big.GetOutputPort())
    for k in range(20):
        angle = 2 * np.pi * k / 20
        small = vtk.vtkSphereSource()
        small.SetRadius(0.03 + 0.004 * k)
        small.SetCenter(0.9 * np.cos(angle), 0.9 * np.sin(angle), 0.2 * ((k % 3) - 1))
        small.SetThetaResolution(16)
        small.SetPhiResolution(12)
        parts.AddInputConnection(small.GetOutputPort())
    for k in range(4):
        ring = implicit_surface(lambda x, y, z: torus_field(x, y, z, 0.12, 0.04),
                                (-0.2, 0.2, -0.2, 0.2, -0.06, 0.06), 40)
        move = vtk.vtkTransform()
        move.Translate(1.3 * np.cos(np.pi * k / 2 + 0.3), 1.3 * np.sin(np.pi * k / 2 + 0.3), 0.0)
        moved = vtk.vtkTransformPolyDataFilter()
        moved.SetTransform(move)
        moved.SetInputData(ring)
        parts.AddInputConnection(moved.GetOutputPort())
    write(output(parts), os.path.join(folder, 'pieces.vtp'))

    def box_mesh(x, y, z, subdivisions):
        """A box: quads with points repeated per face, merged, triangulated, subdivided."""
        cube = vtk.vtkCubeSource()
        cube.SetXLength(x)
        cube.SetYLength(y)
        cube.SetZLength(z)
        merge = vtk.vtkCleanPolyData()
        merge.SetInputConnection(cube.GetOutputPort())
        tri = vtk.vtkTriangleFilter()
        tri.SetInputConnection(merge.GetOutputPort())
        last = tri
        if subdivisions:
            last = vtk.vtkLinearSubdivisionFilter()
            last.SetInputConnection(tri.GetOutputPort())
            last.SetNumberOfSubdivisions(subdivisions)
        mesh = output(last)
        mesh.GetPointData().Initialize()
        return mesh

    # A box with sharp edges; a cube of 12 triangles; a plate 2% thick (at 1000 sites a cell
    # reaches both sides).
    write(box_mesh(2.0, 1.0, 0.6, 5), os.path.join(folder, 'box.vtp'))
    write(box_mesh(1.0, 1.0, 1.0, 0), os.path.join(folder, 'cube.vtp'))
    write(box_mesh(1.0, 1.0, 0.02, 3), os.path.join(folder, 'plate.vtp'))

    # An open disk, and a dirty copy of it.
    disk = vtk.vtkDiskSource()
    disk.SetInnerRadius(0.0)
    disk.SetOuterRadius(1.0)
    disk.SetRadialResolution(30)
    disk.SetCircumferentialResolution(120)
    dtri = vtk.vtkTriangleFilter()
    dtri.SetInputConnection(disk.GetOutputPort())
    clean_disk = vtk.vtkCleanPolyData()
    clean_disk.SetInputConnection(dtri.GetOutputPort())
    flat = output(clean_disk)
    write(flat, os.path.join(folder, 'disk.vtp'))
    # Dirty: every triangle with its own points, one duplicate and two zero-area triangles.
    points = vtk.vtkPoints()
    polys = vtk.vtkCellArray()
    for c in range(flat.GetNumberOfCells()):
        ids = flat.GetCell(c).GetPointIds()
        polys.InsertNextCell(3)
        for k in range(3):
            polys.InsertCellPoint(points.InsertNextPoint(flat.GetPoint(ids.GetId(k))))
    ids = flat.GetCell(0).GetPointIds()
    polys.InsertNextCell(3)
    for k in range(3):
        polys.InsertCellPoint(points.InsertNextPoint(flat.GetPoint(ids.GetId(k))))
    for c in range(2):
        polys.InsertNextCell(3)
        p = points.InsertNextPoint(flat.GetPoint(c))
        polys.InsertCellPoint(p)
        polys.InsertCellPoint(p)
        polys.InsertCellPoint(points.InsertNextPoint(flat.GetPoint(c + 1)))
    dirty = vtk.vtkPolyData()
    dirty.SetPoints(points)
    dirty.SetPolys(polys)
    write(dirty, os.path.join(folder, 'dirty.vtp'))


main()
