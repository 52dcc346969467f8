"""GPU centroidal Voronoi tessellations for VTK and ParaView.

    from cvt.cvtFilters import vtkCVTImageFilter
    from cvt.cvtRendering import vtkCVTSceneRenderer

The modules need the Python modules (vtkmodules) of the VTK they were built against: ParaView's
(Debian: python3-paraview) for the default build, the standalone VTK's (Debian: python3-vtk9)
for a build with CVT_USE_STANDALONE_VTK."""
