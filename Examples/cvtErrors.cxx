#include "cvtErrors.h"

#include "vtkAlgorithm.h"
#include "vtkNew.h"
#include "vtkPolyData.h"

#include <cstdlib>
#include <iostream>

namespace cvtcli
{

void Fail(const std::string& message, int status)
{
  std::cerr << "cvt: " << message << "\n";
  std::exit(status);
}

void ErrorObserver::Execute(vtkObject*, unsigned long event, void* data)
{
  // VTK's text is "ERROR: In FILE, line N\nvtkClass (0x...): message"; keep the message.
  std::string text = static_cast<const char*>(data);
  const size_t line = text.find('\n');
  const size_t header = text.find("): ", line == std::string::npos ? 0 : line);
  if ((text.rfind("ERROR: In ", 0) == 0 || text.rfind("Warning: In ", 0) == 0) &&
    header != std::string::npos)
  {
    text = text.substr(header + 3);
  }
  while (!text.empty() && (text.back() == '\n' || text.back() == ' '))
  {
    text.pop_back();
  }
  // Readers quote corrupt files' bytes: keep the terminal sane.
  for (char& ch : text)
  {
    if ((static_cast<unsigned char>(ch) < 32 && ch != '\n') || static_cast<unsigned char>(ch) > 126)
    {
      ch = '?';
    }
  }
  if (event == vtkCommand::WarningEvent)
  {
    std::cerr << "cvt: warning: " << text << "\n";
    return;
  }
  this->Message = text;
}

void RunOrFail(vtkAlgorithm* filter, vtkPolyData* (*sites)(vtkAlgorithm*))
{
  vtkNew<ErrorObserver> errors;
  filter->AddObserver(vtkCommand::ErrorEvent, errors);
  filter->AddObserver(vtkCommand::WarningEvent, errors);
  filter->Update();
  if (!errors->Message.empty() || sites(filter)->GetNumberOfPoints() == 0)
  {
    Fail(errors->Message.empty() ? "the CVT produced no sites" : errors->Message);
  }
}

} // namespace cvtcli
