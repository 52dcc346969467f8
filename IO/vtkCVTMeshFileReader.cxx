#include "vtkCVTMeshFileReader.h"

#include "vtkInformationVector.h"
#include "vtkPolyData.h"

#include <fstream>

vtkCVTMeshFileReader::vtkCVTMeshFileReader()
{
  this->SetNumberOfInputPorts(0);
}

int vtkCVTMeshFileReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  output->Initialize();
  if (this->FileName.empty())
  {
    vtkErrorMacro("No FileName: set the " << this->GetExtension() << " file to read.");
    return 0;
  }
  std::ifstream in(this->FileName, std::ios::binary);
  if (!in)
  {
    vtkErrorMacro("Cannot open '" << this->FileName << "': no such file or no permission.");
    return 0;
  }
  if (!this->ReadMesh(in, output))
  {
    output->Initialize();
    return 0;
  }
  return 1;
}

bool vtkCVTMeshFileReader::LineError(long long line, const std::string& what)
{
  vtkErrorMacro("'" << this->FileName << "' line " << line << ": " << what);
  return false;
}

void vtkCVTMeshFileReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName.empty() ? "(none)" : this->FileName) << "\n";
}
