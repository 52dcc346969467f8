#include "vtkCVTMeshGeometryImage.h"

#include "cvtParameterization.h"
#include "vtkCVTOutputHelpers.h"

#include "vtkCellArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>

vtkStandardNewMacro(vtkCVTMeshGeometryImage);

//------------------------------------------------------------------------------
vtkCVTMeshGeometryImage::vtkCVTMeshGeometryImage()
{
  this->SetNumberOfInputPorts(1);
}

//------------------------------------------------------------------------------
int vtkCVTMeshGeometryImage::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

//------------------------------------------------------------------------------
int vtkCVTMeshGeometryImage::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  const int extent[6] = { 0, std::max(this->Resolution[0], 1) - 1, 0,
    std::max(this->Resolution[1], 1) - 1, 0, 0 };
  outputVector->GetInformationObject(0)->Set(
    vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  return 1;
}

//------------------------------------------------------------------------------
int vtkCVTMeshGeometryImage::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkImageData* output = vtkImageData::GetData(outputVector, 0);
  output->Initialize();
  if (!input || input->GetNumberOfPolys() == 0)
  {
    vtkErrorMacro("The mesh has no triangles; give a triangle mesh of disk topology.");
    return 0;
  }
  if (this->Resolution[0] < 2 || this->Resolution[1] < 2)
  {
    vtkErrorMacro("The resolution must be at least 2 x 2.");
    return 0;
  }
  if (input->GetNumberOfVerts() + input->GetNumberOfLines() + input->GetNumberOfStrips() > 0)
  {
    vtkErrorMacro(
      "The mesh has vertices, lines or strips; give triangles only (vtkTriangleFilter).");
    return 0;
  }
  cvt::TriangleMesh mesh;
  mesh.Points.resize(3 * static_cast<size_t>(input->GetNumberOfPoints()));
  for (vtkIdType p = 0; p < input->GetNumberOfPoints(); ++p)
  {
    input->GetPoint(p, &mesh.Points[3 * p]);
  }
  vtkIdType npts;
  const vtkIdType* ids;
  vtkCellArray* polys = input->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(npts, ids);)
  {
    if (npts != 3)
    {
      vtkErrorMacro(
        "The mesh has a cell with " << npts << " points; give triangles only (vtkTriangleFilter).");
      return 0;
    }
    mesh.Triangles.push_back(
      { static_cast<int>(ids[0]), static_cast<int>(ids[1]), static_cast<int>(ids[2]) });
  }
  const std::string problem = cvt::CheckDiskMesh(mesh);
  if (!problem.empty())
  {
    vtkErrorMacro("Bad mesh: " << problem << ".");
    return 0;
  }
  std::vector<double> uv;
  std::string error;
  if (!cvt::ParameterizeDisk(mesh, uv, error))
  {
    vtkErrorMacro("The mesh could not be parameterised: " << error << ".");
    return 0;
  }
  cvtvtk::WriteGeometryImage(
    cvt::ResampleMesh(mesh, uv, this->Resolution[0], this->Resolution[1]), output);
  return 1;
}

//------------------------------------------------------------------------------
void vtkCVTMeshGeometryImage::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Resolution: " << this->Resolution[0] << " x " << this->Resolution[1] << "\n";
}
