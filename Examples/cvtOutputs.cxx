#include "cvtOutputs.h"

#include "cvtErrors.h"

#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkPNGWriter.h"
#include "vtkPolyData.h"
#include "vtkTable.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <regex>
#include <stdexcept>
#include <sys/stat.h>

namespace cvtcli
{

std::string OutputFolder(const Options& options)
{
  if (mkdir(options.Output.c_str(), 0777) != 0 && errno != EEXIST)
  {
    Fail(
      "cannot create --output directory '" + options.Output + "' (" + std::strerror(errno) + ")");
  }
  const std::string probe = options.Output + "/.cvt-write-test";
  std::FILE* file = std::fopen(probe.c_str(), "w");
  if (!file)
  {
    Fail(
      "cannot write in --output directory '" + options.Output + "' (" + std::strerror(errno) + ")");
  }
  std::fclose(file);
  std::remove(probe.c_str());
  return options.Output;
}

OutputFiles::OutputFiles(const std::string& folder)
  : Folder(folder + "/")
{
}

OutputFiles::~OutputFiles()
{
  for (const std::string& name : this->Pending)
  {
    std::remove(this->Temporary(name).c_str());
  }
}

std::string OutputFiles::Add(const std::string& name)
{
  this->Pending.push_back(name);
  return this->Temporary(name);
}

void OutputFiles::Failed(const std::string& name, const std::string& why) const
{
  throw std::runtime_error("cannot write '" + this->Folder + name + "'" +
    (why.empty() ? std::string() : " (" + why + ")") +
    "; check the free space and permissions of the --output directory");
}

void OutputFiles::Commit()
{
  for (const std::string& name : this->Pending)
  {
    if (std::rename(this->Temporary(name).c_str(), (this->Folder + name).c_str()) != 0)
    {
      this->Failed(name, std::strerror(errno));
    }
  }
  this->Pending.clear();
}

std::string OutputFiles::Temporary(const std::string& name) const
{
  return this->Folder + "." + name + ".partial";
}

void WriteCsv(vtkPolyData* sites, vtkTable* history, int dimensions, OutputFiles& files)
{
  std::ofstream csv(files.Add("sites.csv"));
  csv << std::setprecision(17);
  for (vtkIdType i = 0; i < sites->GetNumberOfPoints(); ++i)
  {
    double p[3];
    sites->GetPoint(i, p);
    csv << p[0] << "," << p[1];
    if (dimensions == 3)
    {
      csv << "," << p[2];
    }
    csv << "\n";
  }
  std::ofstream out(files.Add("history.csv"));
  out << "iteration,evaluations,energy,gradient_norm,seconds\n" << std::setprecision(12);
  for (vtkIdType r = 0; r < history->GetNumberOfRows(); ++r)
  {
    out << history->GetValueByName(r, "iteration").ToInt() << ","
        << history->GetValueByName(r, "evaluations").ToInt() << ","
        << history->GetValueByName(r, "energy").ToDouble() << ","
        << history->GetValueByName(r, "gradient_norm").ToDouble() << ","
        << history->GetValueByName(r, "seconds").ToDouble() << "\n";
  }
  for (auto [stream, name] : { std::make_pair(&csv, "sites.csv"), { &out, "history.csv" } })
  {
    stream->close();
    if (stream->fail())
    {
      files.Failed(name, std::strerror(errno));
    }
  }
}

bool WritePicture(vtkImageData* picture, const std::string& error, OutputFiles& files)
{
  if (!picture)
  {
    // The results are written; the picture is only a view of them (nothing to draw).
    std::cerr << "cvt: warning: cvt.png not written: " << error << "\n";
    return false;
  }
  vtkNew<vtkPNGWriter> png;
  png->SetInputData(picture);
  png->SetFileName(files.Add("cvt.png").c_str());
  png->Write();
  if (png->GetErrorCode() != vtkErrorCode::NoError)
  {
    files.Failed("cvt.png", vtkErrorCode::GetStringFromErrorCode(png->GetErrorCode()));
  }
  return true;
}

double Field(vtkDataObject* data, const char* name)
{
  return data->GetFieldData()->GetArray(name)->GetTuple1(0);
}

void PrintSummary(const Options& options, vtkPolyData* sites, const std::string& context,
  const char* files, bool pictureWritten)
{
  if (options.Quiet)
  {
    return;
  }
  std::cout
    << "cvt " << options.Command << ": " << sites->GetNumberOfPoints() << " sites, "
    << Field(sites, "Iterations") << " iterations ("
    << sites->GetFieldData()->GetAbstractArray("StopReason")->GetVariantValue(0).ToString()
    << "), energy " << std::setprecision(8) << Field(sites, "Energy") << ", |grad F| "
    << Field(sites, "GradientNorm") << "\n"
    << "  engine: "
    << sites->GetFieldData()->GetAbstractArray("Engine")->GetVariantValue(0).ToString() << " ("
    << sites->GetFieldData()->GetAbstractArray("EngineReason")->GetVariantValue(0).ToString() << ")"
    << (context.empty() ? "" : "; OpenGL: " + context) << "\n"
    << "  wrote "
    << (pictureWritten ? std::string(files)
                       : std::regex_replace(files, std::regex(" cvt\\.png"), ""))
    << " in " << options.Output << "\n";
}

} // namespace cvtcli
