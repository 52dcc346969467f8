// cvt: centroidal Voronoi tessellations on the GPU from the command line.
//   cvt image [options]     CVT of a 2D image domain (density from an image, or uniform)
//   cvt surface [options]   constrained CVT on a surface (a torus) and its remesh
// Run `cvt --help` for the options. Errors go to stderr with exit status 1 (2 for usage).
#include "cvtCommandLine.h"
#include "vtkCVTGeometryImageSource.h"
#include "vtkCVTImageFilter.h"
#include "vtkCVTMeshGeometryImage.h"
#include "vtkCVTRemeshFilter.h"
#include "vtkCVTSceneRenderer.h"
#include "vtkCVTSurfaceFilter.h"
#include "vtkLogger.h"
#include "vtkOutputWindow.h"

#include "vtkAbstractPolyDataReader.h"
#include "vtkCleanPolyData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkErrorCode.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkImageReader2.h"
#include "vtkJPEGReader.h"
#include "vtkMetaImageReader.h"
#include "vtkNew.h"
#include "vtkOBJReader.h"
#include "vtkPLYReader.h"
#include "vtkPNGReader.h"
#include "vtkPNGWriter.h"
#include "vtkParametricTorus.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataReader.h"
#include "vtkSTLReader.h"
#include "vtkSmartPointer.h"
#include "vtkTable.h"
#include "vtkXMLImageDataReader.h"
#include "vtkXMLImageDataWriter.h"
#include "vtkXMLPolyDataReader.h"
#include "vtkXMLPolyDataWriter.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace
{
using cvtcli::Options;

[[noreturn]] void Fail(const std::string& message, int status = 1)
{
  std::cerr << "cvt: " << message << "\n";
  std::exit(status);
}

std::string Extension(const std::string& path)
{
  const size_t dot = path.find_last_of('.');
  std::string ext = dot == std::string::npos ? "" : path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
  return ext;
}

/// Some of VTK's readers crash or abort on corrupt files (PNG through libpng's error path,
/// binary legacy VTK and PLY, binary STL with a wrong triangle count). So the file is read once
/// in a child process first: a signal there, or no end within a minute, becomes a clear error
/// here instead of a crash or a hang.
void ProbeReader(vtkAlgorithm* reader, const std::string& path)
{
  std::cout.flush();
  std::cerr.flush();
  const pid_t child = fork();
  if (child == 0)
  {
    alarm(60);
    reader->Update();
    std::_Exit(0);
  }
  if (child < 0)
  {
    return; // no probe possible: read as usual
  }
  int status = 0;
  waitpid(child, &status, 0);
  // The child ends with _Exit(0) unless the reader kills it (a signal, or an exit status other
  // than 0, as a sanitizer turns a crash into).
  if (WIFSIGNALED(status) || (WIFEXITED(status) && WEXITSTATUS(status) != 0))
  {
    std::string why = "the reader crashed on it";
    if (WIFSIGNALED(status))
    {
      why = WTERMSIG(status) == SIGALRM ? std::string("reading it did not end within a minute")
                                        : why + ": " + strsignal(WTERMSIG(status));
    }
    Fail("cannot read --input '" + path + "': the file is corrupt or truncated (" + why + ")");
  }
}

/// Reads the density image and leaves a one-component float array "density" as its scalars.
vtkSmartPointer<vtkImageData> ReadDensityImage(const Options& options)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  if (options.Input.empty())
  {
    const int n = options.Resolution;
    image->SetDimensions(n, n, 1);
    image->SetSpacing((options.Domain[1] - options.Domain[0]) / n,
      (options.Domain[3] - options.Domain[2]) / n, 1.0);
    image->SetOrigin(options.Domain[0] + 0.5 * image->GetSpacing()[0],
      options.Domain[2] + 0.5 * image->GetSpacing()[1], 0.0);
    return image; // no density array: uniform
  }
  struct stat info;
  if (stat(options.Input.c_str(), &info) != 0)
  {
    Fail("cannot read --input '" + options.Input + "': no such file");
  }
  const std::string ext = Extension(options.Input);
  vtkSmartPointer<vtkAlgorithm> reader;
  bool isPicture = false;
  if (ext == "png")
  {
    auto r = vtkSmartPointer<vtkPNGReader>::New();
    r->SetFileName(options.Input.c_str());
    reader = r;
    isPicture = true;
  }
  else if (ext == "jpg" || ext == "jpeg")
  {
    auto r = vtkSmartPointer<vtkJPEGReader>::New();
    r->SetFileName(options.Input.c_str());
    reader = r;
    isPicture = true;
  }
  else if (ext == "vti")
  {
    auto r = vtkSmartPointer<vtkXMLImageDataReader>::New();
    r->SetFileName(options.Input.c_str());
    reader = r;
  }
  else if (ext == "mha" || ext == "mhd")
  {
    auto r = vtkSmartPointer<vtkMetaImageReader>::New();
    r->SetFileName(options.Input.c_str());
    reader = r;
  }
  else
  {
    Fail("--input '" + options.Input + "' has an unknown type; use .png .jpg .vti .mha");
  }
  ProbeReader(reader, options.Input);
  reader->Update();
  vtkImageData* read = vtkImageData::SafeDownCast(reader->GetOutputDataObject(0));
  if (!read || read->GetNumberOfPoints() == 0)
  {
    Fail("could not read an image from '" + options.Input + "'");
  }
  image->ShallowCopy(read);
  vtkDataArray* values = options.Array.empty()
    ? image->GetPointData()->GetScalars()
    : image->GetPointData()->GetArray(options.Array.c_str());
  if (!values)
  {
    Fail(options.Array.empty()
        ? "'" + options.Input + "' has no scalar array; choose one with --array"
        : "'" + options.Input + "' has no point array '" + options.Array + "'");
  }
  // Pictures: luminance of the colour channels (alpha ignored), scaled to [0, 1].
  const int components = values->GetNumberOfComponents();
  if (!isPicture && components != 1)
  {
    Fail("the density array has " + std::to_string(components) + " components; it needs one");
  }
  vtkNew<vtkFloatArray> density;
  density->SetName("density");
  density->SetNumberOfValues(values->GetNumberOfTuples());
  const double scale = isPicture ? 1.0 / 255.0 : 1.0;
  double maximum = -std::numeric_limits<double>::infinity();
  for (vtkIdType p = 0; p < values->GetNumberOfTuples(); ++p)
  {
    double v = values->GetComponent(p, 0);
    if (isPicture && components >= 3)
    {
      v = 0.299 * values->GetComponent(p, 0) + 0.587 * values->GetComponent(p, 1) +
        0.114 * values->GetComponent(p, 2);
    }
    v *= scale;
    density->SetValue(p, static_cast<float>(v));
    maximum = std::max(maximum, v);
  }
  if (options.Invert)
  {
    const double top = isPicture ? 1.0 : maximum;
    for (vtkIdType p = 0; p < density->GetNumberOfValues(); ++p)
    {
      density->SetValue(p, static_cast<float>(top - density->GetValue(p)));
    }
  }
  image->GetPointData()->Initialize();
  image->GetPointData()->SetScalars(density);
  if (options.HaveDomain)
  {
    int dims[3];
    image->GetDimensions(dims);
    image->SetExtent(0, dims[0] - 1, 0, dims[1] - 1, 0, dims[2] - 1);
    const double sx = (options.Domain[1] - options.Domain[0]) / dims[0];
    const double sy = (options.Domain[3] - options.Domain[2]) / dims[1];
    image->SetSpacing(sx, sy, 1.0);
    image->SetOrigin(options.Domain[0] + 0.5 * sx, options.Domain[2] + 0.5 * sy, 0.0);
  }
  return image;
}

vtkSmartPointer<vtkPolyData> ReadSitesCsv(const std::string& path)
{
  std::ifstream in(path);
  if (!in)
  {
    Fail("cannot read --initial-sites '" + path + "'");
  }
  std::vector<double> xy;
  try
  {
    xy = cvtcli::ParseSitesCsv(in, path);
  }
  catch (const cvtcli::UsageError& error)
  {
    Fail(error.what());
  }
  vtkNew<vtkPoints> points;
  for (size_t i = 0; i + 1 < xy.size(); i += 2)
  {
    points->InsertNextPoint(xy[i], xy[i + 1], 0.0);
  }
  auto sites = vtkSmartPointer<vtkPolyData>::New();
  sites->SetPoints(points);
  return sites;
}

/// The files of one run, written under temporary names in the output folder and renamed into
/// place together once all are written: a full disk, a file-size limit or a folder that turns
/// read-only leaves the previous results or nothing, never a truncated file under a real name.
/// Errors throw (main reports them), so that the destructor removes the temporary files.
class OutputFiles
{
public:
  explicit OutputFiles(const std::string& folder)
    : Folder(folder + "/")
  {
  }
  ~OutputFiles()
  {
    for (const std::string& name : this->Pending)
    {
      std::remove(this->Temporary(name).c_str());
    }
  }
  OutputFiles(const OutputFiles&) = delete;
  OutputFiles& operator=(const OutputFiles&) = delete;

  /// Where to write `name` for now.
  std::string Add(const std::string& name)
  {
    this->Pending.push_back(name);
    return this->Temporary(name);
  }
  /// The complaint for a file that could not be written.
  [[noreturn]] void Failed(const std::string& name, const std::string& why) const
  {
    throw std::runtime_error("cannot write '" + this->Folder + name + "'" +
      (why.empty() ? std::string() : " (" + why + ")") +
      "; check the free space and permissions of the --output directory");
  }
  /// Renames every written file into place.
  void Commit()
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

private:
  std::string Temporary(const std::string& name) const
  {
    return this->Folder + "." + name + ".partial";
  }
  std::string Folder;
  std::vector<std::string> Pending;
};

template<typename Writer>
void Write(vtkDataObject* data, OutputFiles& files, const std::string& name)
{
  vtkNew<Writer> writer;
  // Inline base64, not appended raw data: Debian 12's expat rejects the raw appended section,
  // so VTK and ParaView there could not read the files back.
  writer->SetDataModeToBinary();
  writer->SetCompressorTypeToNone(); // zlib took longer than the whole remesh of small meshes
  writer->SetHeaderTypeToUInt64();   // 32-bit block headers fail past 4 GB (32768^2 labels)
  writer->SetInputData(data);
  writer->SetFileName(files.Add(name).c_str());
  if (writer->Write() != 1 || writer->GetErrorCode() != vtkErrorCode::NoError)
  {
    files.Failed(name, vtkErrorCode::GetStringFromErrorCode(writer->GetErrorCode()));
  }
}

/// Keeps a filter's last error message, so that the program can fail with it.
class ErrorObserver : public vtkCommand
{
public:
  static ErrorObserver* New() { return new ErrorObserver; }
  void Execute(vtkObject*, unsigned long event, void* data) override
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
      if ((static_cast<unsigned char>(ch) < 32 && ch != '\n') ||
        static_cast<unsigned char>(ch) > 126)
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
  std::string Message;
};

/// Runs the filter; fails with its error message when it produced no sites.
void Run(vtkAlgorithm* filter, vtkPolyData* (*sites)(vtkAlgorithm*))
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

/// Creates the --output folder and checks that files can be made there, before any work.
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

/// sites.csv (x,y or x,y,z per line: the --initial-sites format) and history.csv.
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

/// Whether cvt.png was written (the summary lists only the files that were).
bool PictureWritten = false;

void WritePicture(vtkImageData* picture, const std::string& error, OutputFiles& files)
{
  PictureWritten = picture != nullptr;
  if (!picture)
  {
    // The results are written; only the picture needs OpenGL (the CPU engine does not).
    std::cerr << "cvt: warning: cvt.png not written: " << error << "\n";
    return;
  }
  vtkNew<vtkPNGWriter> png;
  png->SetInputData(picture);
  png->SetFileName(files.Add("cvt.png").c_str());
  png->Write();
  if (png->GetErrorCode() != vtkErrorCode::NoError)
  {
    files.Failed("cvt.png", vtkErrorCode::GetStringFromErrorCode(png->GetErrorCode()));
  }
}

double Field(vtkDataObject* data, const char* name)
{
  return data->GetFieldData()->GetArray(name)->GetTuple1(0);
}

void PrintSummary(
  const Options& options, vtkPolyData* sites, const std::string& context, const char* files)
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
    << (PictureWritten ? std::string(files)
                       : std::regex_replace(files, std::regex(" cvt\\.png"), ""))
    << " in " << options.Output << "\n";
}

template<typename Filter>
void SetOptimizer(const Options& options, Filter* filter)
{
  filter->SetNumberOfSites(options.Sites);
  filter->SetRandomSeed(static_cast<int>(options.Seed));
  filter->SetMaximumNumberOfIterations(options.Iterations);
  filter->SetTolerance(options.Tolerance);
  filter->SetGradientTolerance(options.GradientTolerance);
  filter->SetNumberOfCorrections(options.Corrections);
  if (options.Method == "lloyd")
  {
    filter->SetMethodToLloyd();
  }
  else
  {
    filter->SetMethodToLBFGS();
  }
}

int RunImage(const Options& options)
{
  OutputFolder(options); // before any work: a folder that cannot be written fails now
  vtkSmartPointer<vtkImageData> image = ReadDensityImage(options);
  vtkNew<vtkCVTImageFilter> cvt;
  cvt->SetInputData(image);
  if (image->GetPointData()->GetArray("density"))
  {
    cvt->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "density");
  }
  if (!options.InitialSites.empty())
  {
    cvt->SetInitialSitesData(ReadSitesCsv(options.InitialSites));
  }
  SetOptimizer(options, cvt.Get());
  cvt->SetComputeExactEnergy(options.Report);
  cvt->SetEngine(options.Engine == "opengl" ? vtkCVTImageFilter::OPENGL
      : options.Engine == "cpu"             ? vtkCVTImageFilter::CPU
                                            : vtkCVTImageFilter::AUTO);
  Run(cvt, [](vtkAlgorithm* f) { return static_cast<vtkCVTImageFilter*>(f)->GetSitesOutput(); });

  OutputFiles files(OutputFolder(options));
  vtkPolyData* sites = cvt->GetSitesOutput();
  Write<vtkXMLPolyDataWriter>(sites, files, "sites.vtp");
  Write<vtkXMLImageDataWriter>(cvt->GetLabelsOutput(), files, "labels.vti");
  Write<vtkXMLPolyDataWriter>(cvt->GetDualOutput(), files, "dual.vtp");
  WriteCsv(sites, cvt->GetHistoryOutput(), 2, files);
  vtkNew<vtkCVTSceneRenderer> scene;
  WritePicture(scene->Render(cvt->GetLabelsOutput(), sites), scene->GetLastError(), files);
  files.Commit();

  if (options.Report)
  {
    std::cout << std::setprecision(6) << "report:\n"
              << "  method                      " << options.Method << "\n"
              << "  iterations / evaluations    " << Field(sites, "Iterations") << " / "
              << Field(sites, "Evaluations") << "\n"
              << "  energy F (engine)           " << Field(sites, "Energy") << "\n"
              << "  energy F (exact, CPU)       " << Field(sites, "ExactEnergy") << "\n"
              << "  relative difference         "
              << 100.0 * Field(sites, "EnergyRelativeDifference") << " %\n"
              << "  |grad F|                    " << Field(sites, "GradientNorm") << "\n"
              << "  hexagonal interior cells    " << 100.0 * Field(sites, "HexagonalFraction")
              << " %\n"
              << "  stdev cell radius r_i       " << Field(sites, "RadiusStandardDeviation") << "\n"
              << "  stdev nearest neighbour d_i "
              << Field(sites, "NearestNeighborStandardDeviation") << "\n"
              << "  stdev cell area a_i         " << Field(sites, "AreaStandardDeviation") << "\n";
  }
  PrintSummary(options, sites, cvt->GetContextDescription(),
    "sites.vtp sites.csv labels.vti dual.vtp history.csv cvt.png");
  return 0;
}

/// A reader for the --input mesh, by extension.
vtkSmartPointer<vtkAlgorithm> MeshReader(const Options& options)
{
  struct stat info;
  if (stat(options.Input.c_str(), &info) != 0)
  {
    Fail("cannot read --input '" + options.Input + "': no such file");
  }
  const std::string ext = Extension(options.Input);
  vtkSmartPointer<vtkAlgorithm> reader;
  if (ext == "vtp")
  {
    auto r = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    r->SetFileName(options.Input.c_str());
    reader = r;
  }
  else if (ext == "vtk")
  {
    auto r = vtkSmartPointer<vtkPolyDataReader>::New();
    r->SetFileName(options.Input.c_str());
    reader = r;
  }
  else if (ext == "stl" || ext == "ply" || ext == "obj")
  {
    vtkSmartPointer<vtkAbstractPolyDataReader> r;
    if (ext == "stl")
      r = vtkSmartPointer<vtkSTLReader>::New();
    else if (ext == "ply")
      r = vtkSmartPointer<vtkPLYReader>::New();
    else
      r = vtkSmartPointer<vtkOBJReader>::New();
    r->SetFileName(options.Input.c_str());
    reader = r;
  }
  else
  {
    Fail("--input '" + options.Input + "' has an unknown type; use .vtp .vtk .stl .ply .obj");
  }
  return reader;
}

/// The surface's geometry image: a torus, or a mesh read from --input and parameterised.
vtkSmartPointer<vtkAlgorithm> SurfaceGeometryImage(const Options& options)
{
  if (options.Input.empty())
  {
    vtkNew<vtkParametricTorus> torus;
    torus->SetRingRadius(options.Torus[0]);
    torus->SetCrossSectionRadius(options.Torus[1]);
    auto source = vtkSmartPointer<vtkCVTGeometryImageSource>::New();
    source->SetParametricFunction(torus);
    source->SetResolution(options.GIResolution[0], options.GIResolution[1]);
    return source;
  }
  vtkSmartPointer<vtkAlgorithm> reader = MeshReader(options);
  ProbeReader(reader, options.Input);
  vtkNew<vtkCleanPolyData> merge;
  merge->SetInputConnection(reader->GetOutputPort());
  auto parameterise = vtkSmartPointer<vtkCVTMeshGeometryImage>::New();
  parameterise->SetInputConnection(merge->GetOutputPort());
  parameterise->SetResolution(options.GIResolution[0], options.GIResolution[1]);
  return parameterise;
}

/// cvt surface --input MESH on the CPU engine: restricted Voronoi cells on the mesh itself.
int RunRemesh(const Options& options)
{
  using Clock = std::chrono::steady_clock;
  const auto seconds = [](Clock::time_point from)
  { return std::chrono::duration<double>(Clock::now() - from).count(); };
  const Clock::time_point start = Clock::now();
  OutputFolder(options); // before any work: a folder that cannot be written fails now
  vtkSmartPointer<vtkAlgorithm> reader = MeshReader(options);
  ProbeReader(reader, options.Input);
  vtkNew<ErrorObserver> readErrors;
  reader->AddObserver(vtkCommand::ErrorEvent, readErrors);
  reader->Update();
  if (!readErrors->Message.empty())
  {
    Fail("cannot read --input '" + options.Input + "': " + readErrors->Message);
  }
  const double readSeconds = seconds(start);
  vtkNew<vtkCVTRemeshFilter> cvt;
  cvt->SetInputConnection(reader->GetOutputPort());
  cvt->SetDensityArray(options.Array.c_str());
  SetOptimizer(options, cvt.Get());
  const Clock::time_point optimise = Clock::now();
  Run(cvt, [](vtkAlgorithm* f) { return static_cast<vtkCVTRemeshFilter*>(f)->GetSitesOutput(); });
  const double cvtSeconds = seconds(optimise);

  const Clock::time_point write = Clock::now();
  OutputFiles files(OutputFolder(options));
  vtkPolyData* sites = cvt->GetSitesOutput();
  vtkPolyData* remesh = cvt->GetRemeshOutput();
  Write<vtkXMLPolyDataWriter>(sites, files, "sites.vtp");
  Write<vtkXMLPolyDataWriter>(cvt->GetLabelsOutput(), files, "labels.vtp");
  Write<vtkXMLPolyDataWriter>(remesh, files, "remesh.vtp");
  WriteCsv(sites, cvt->GetHistoryOutput(), 3, files);
  const double writeSeconds = seconds(write);
  vtkNew<vtkCVTSceneRenderer> scene;
  WritePicture(scene->RenderMesh(remesh), scene->GetLastError(), files);
  files.Commit();
  if (options.Report)
  {
    vtkFieldData* in = sites->GetFieldData();
    vtkFieldData* out = remesh->GetFieldData();
    const auto topology = [](vtkDataObject* data, const std::string& prefix)
    {
      std::ostringstream text;
      text << Field(data, (prefix + "Components").c_str()) << " parts, genus "
           << Field(data, (prefix + "Genus").c_str()) << ", "
           << Field(data, (prefix + "BoundaryLoops").c_str()) << " boundary loops";
      return text.str();
    };
    std::cout << std::setprecision(6) << "report:\n"
              << "  engine                      CPU: "
              << in->GetAbstractArray("EngineReason")->GetVariantValue(0).ToString() << "\n"
              << "  method                      " << options.Method << "\n"
              << "  iterations / evaluations    " << Field(sites, "Iterations") << " / "
              << Field(sites, "Evaluations") << "\n"
              << "  energy F                    " << Field(sites, "Energy") << "\n"
              << "  normalised F n / A^2        "
              << Field(sites, "Energy") * sites->GetNumberOfPoints() /
        (Field(sites, "SurfaceArea") * Field(sites, "SurfaceArea"))
              << "\n"
              << "  |grad F|                    " << Field(sites, "GradientNorm") << "\n"
              << "  surface area                " << Field(sites, "SurfaceArea") << "\n"
              << "  input topology              " << topology(sites, "Input") << "\n"
              << "  remesh topology             " << topology(remesh, "") << "\n"
              << "  remesh: " << remesh->GetNumberOfPoints() << " vertices, "
              << remesh->GetNumberOfPolys() << " triangles (" << Field(remesh, "RemovedTriangles")
              << " dropped as non-manifold, " << Field(remesh, "FilledHoles") << " holes closed, "
              << Field(remesh, "SplitVertices") << " pinched vertices split, "
              << Field(remesh, "FlippedEdges") << " edges flipped for angles, "
              << Field(remesh, "ValenceFlips") << " for valence, " << Field(remesh, "MovedVertices")
              << " vertices moved)\n"
              << "  valence 6                   " << 100.0 * Field(remesh, "Valence6Fraction")
              << " %\n"
              << "  smallest / largest angle    " << Field(remesh, "MinimumAngle") << " / "
              << Field(remesh, "MaximumAngle") << " degrees\n"
              << "  seconds: read " << readSeconds << ", prepare " << Field(sites, "PrepareSeconds")
              << ", optimise " << Field(sites, "OptimizeSeconds") << ", remesh "
              << Field(sites, "RemeshSeconds") << " (CVT filter " << cvtSeconds << "), write "
              << writeSeconds << "\n";
    (void)out;
  }
  PrintSummary(options, sites, "", "sites.vtp sites.csv labels.vtp remesh.vtp history.csv cvt.png");
  return 0;
}

int RunSurface(const Options& options)
{
  if (!options.Input.empty() && options.Engine != "opengl")
  {
    return RunRemesh(options);
  }
  OutputFolder(options); // before any work: a folder that cannot be written fails now
  vtkSmartPointer<vtkAlgorithm> geometryImage = SurfaceGeometryImage(options);
  vtkNew<ErrorObserver> meshErrors;
  geometryImage->AddObserver(vtkCommand::ErrorEvent, meshErrors);
  geometryImage->Update();
  if (!meshErrors->Message.empty())
  {
    Fail(meshErrors->Message);
  }
  vtkNew<vtkCVTSurfaceFilter> cvt;
  cvt->SetInputConnection(geometryImage->GetOutputPort());
  SetOptimizer(options, cvt.Get());
  cvt->SetEngine(options.Engine == "opengl" ? vtkCVTSurfaceFilter::OPENGL
      : options.Engine == "cpu"             ? vtkCVTSurfaceFilter::CPU
                                            : vtkCVTSurfaceFilter::AUTO);
  Run(cvt, [](vtkAlgorithm* f) { return static_cast<vtkCVTSurfaceFilter*>(f)->GetSitesOutput(); });

  OutputFiles files(OutputFolder(options));
  vtkPolyData* sites = cvt->GetSitesOutput();
  vtkPolyData* remesh = cvt->GetRemeshOutput();
  Write<vtkXMLPolyDataWriter>(sites, files, "sites.vtp");
  Write<vtkXMLImageDataWriter>(cvt->GetLabelsOutput(), files, "labels.vti");
  Write<vtkXMLPolyDataWriter>(remesh, files, "remesh.vtp");
  WriteCsv(sites, cvt->GetHistoryOutput(), 3, files);
  vtkNew<vtkCVTSceneRenderer> scene;
  WritePicture(scene->RenderMesh(remesh), scene->GetLastError(), files);
  files.Commit();

  if (options.Report)
  {
    vtkFieldData* mesh = remesh->GetFieldData();
    std::cout << std::setprecision(6) << "report:\n"
              << "  method                      " << options.Method << "\n"
              << "  iterations / evaluations    " << Field(sites, "Iterations") << " / "
              << Field(sites, "Evaluations") << "\n"
              << "  energy F                    " << Field(sites, "Energy") << "\n"
              << "  |grad F| (tangential)       " << Field(sites, "GradientNorm") << "\n"
              << "  surface area                " << Field(sites, "SurfaceArea") << "\n"
              << "  area weights min / max      " << Field(sites, "MinimumAreaWeight") << " / "
              << Field(sites, "MaximumAreaWeight") << "\n"
              << "  remesh: " << remesh->GetNumberOfPoints() << " vertices, "
              << remesh->GetNumberOfPolys() << " triangles\n"
              << "  valence 6                   " << 100.0 * Field(remesh, "Valence6Fraction")
              << " %\n"
              << "  smallest / largest angle    " << Field(remesh, "MinimumAngle") << " / "
              << Field(remesh, "MaximumAngle") << " degrees\n"
              << "  valence histogram          ";
    vtkDataArray* valence = mesh->GetArray("ValenceHistogram");
    for (vtkIdType v = 0; v < valence->GetNumberOfTuples(); ++v)
    {
      if (valence->GetTuple1(v) > 0)
      {
        std::cout << " " << v << ":" << valence->GetTuple1(v);
      }
    }
    std::cout << "\n  angle histogram (10 deg)   ";
    vtkDataArray* angles = mesh->GetArray("AngleHistogram");
    for (vtkIdType b = 0; b < angles->GetNumberOfTuples(); ++b)
    {
      if (angles->GetTuple1(b) > 0)
      {
        std::cout << " " << 10 * b << "-" << 10 * (b + 1) << ":" << angles->GetTuple1(b);
      }
    }
    std::cout << "\n";
  }
  PrintSummary(options, sites, cvt->GetContextDescription(),
    "sites.vtp sites.csv labels.vti remesh.vtp history.csv cvt.png");
  return 0;
}
}

int main(int argc, char* argv[])
{
  // Past a file-size limit (ulimit -f), writes fail with EFBIG and are reported; the default
  // action would kill the program.
  std::signal(SIGXFSZ, SIG_IGN);
  Options options;
  try
  {
    options = cvtcli::ParseArguments(std::vector<std::string>(argv + 1, argv + argc));
  }
  catch (const cvtcli::UsageError& error)
  {
    Fail(error.what(), 2);
  }
  if (options.Help)
  {
    std::cout << cvtcli::Usage;
    return options.HelpStatus;
  }
  // Errors and warnings reach the user once, through the filters' observers ("cvt: ..."),
  // without VTK's pipeline dumps.
  vtkOutputWindow::GetInstance()->SetDisplayModeToNever();
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  try
  {
    return options.Command == "surface" ? RunSurface(options) : RunImage(options);
  }
  catch (const std::bad_alloc&)
  {
    Fail("out of memory: the input is too large for this machine, or corrupt");
  }
  catch (const std::exception& failure)
  {
    Fail(failure.what());
  }
}
