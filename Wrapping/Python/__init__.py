"""GPU centroidal Voronoi tessellations for VTK and ParaView.

    from cvt.cvtFilters import vtkCVTImageFilter
    from cvt.cvtRendering import vtkCVTSceneRenderer

The modules need ParaView's VTK Python modules (Debian: python3-paraview)."""
