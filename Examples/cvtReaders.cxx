#include "cvtReaders.h"

#include "cvtErrors.h"

#include "vtkCVTOBJReader.h"
#include "vtkCVTOFFReader.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkImageExtractComponents.h"
#include "vtkImageReader2.h"
#include "vtkImageReader2Factory.h"
#include "vtkImageShiftScale.h"
#include "vtkNew.h"
#include "vtkPLYReader.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataReader.h"
#include "vtkPolyDataWriter.h"
#include "vtkSTLReader.h"
#include "vtkTrivialProducer.h"
#include "vtkXMLImageDataReader.h"
#include "vtkXMLPolyDataReader.h"

#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <iostream>
#include <iterator>
#include <new>
#include <sys/mman.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace cvtcli
{
namespace
{

/// The probe child's exit status when the reader reported an error (and wrote it to the pipe).
constexpr int ReaderReportedAnError = 3;

std::string Extension(const std::string& path)
{
  const size_t dot = path.find_last_of('.');
  std::string ext = dot == std::string::npos ? "" : path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
  return ext;
}

/// The probe child's exit status when it read the mesh but could not hand it over (out of
/// memory): the parent then reads the file itself.
constexpr int HandOverFailed = 4;

/// An in-memory file that ProbeReader's child writes the mesh it read into, for the parent to
/// read (-1 where there is none); closed with this.
struct HandOverFile
{
  int Descriptor = -1;
  explicit HandOverFile(bool wanted)
    : Descriptor(wanted ? static_cast<int>(memfd_create("cvt-input-mesh", MFD_CLOEXEC)) : -1)
  {
  }
  ~HandOverFile()
  {
    if (this->Descriptor >= 0)
    {
      close(this->Descriptor);
    }
  }
  /// Its path, as readers and writers of files take it.
  std::string Path() const { return "/proc/self/fd/" + std::to_string(this->Descriptor); }
};

/// Some of VTK's readers crash or abort on corrupt files (PNG through libpng's error path,
/// binary legacy VTK and PLY, binary STL with a wrong triangle count). So the file is read once
/// in a child process first: a signal there, or no end within a minute, becomes a clear error
/// here instead of a crash or a hang. A reader that reports an error (a file that is not of its
/// format: VTK's PNG reader then still gives a 1 x 1 image) fails with the reader's message; the
/// child's own stderr is dropped, so that libpng's and the readers' texts do not reach the user.
/// With `handOver` (meshes), the child writes what it read into an in-memory file as binary
/// legacy VTK (lossless: every array with its type, the field data), and what is returned has
/// read that, so the file is parsed once, not twice (bunny00's 75,000 triangles, medians of 3
/// runs: .obj 0.42 -> 0.26 s, .stl 0.25 -> 0.17 s; a compressed .vtp of 1.2 million, 0.91 s
/// either way). Otherwise, or where the child could not (no in-memory file), the reader is
/// returned to read the file again here. Images are read twice: the legacy form would lose an
/// image's extent and direction.
vtkSmartPointer<vtkAlgorithm> ProbeReader(
  vtkSmartPointer<vtkAlgorithm> reader, const std::string& path, bool handOver)
{
  std::cout.flush();
  std::cerr.flush();
  int message[2];
  if (pipe(message) != 0)
  {
    return reader; // no probe possible: read as usual
  }
  const HandOverFile handed(handOver);
  const pid_t child = fork();
  if (child == 0)
  {
    close(message[0]);
    const int quiet = open("/dev/null", O_WRONLY);
    if (quiet >= 0)
    {
      dup2(quiet, STDERR_FILENO);
    }
    alarm(60);
    vtkNew<ErrorObserver> errors;
    reader->AddObserver(vtkCommand::ErrorEvent, errors);
    reader->Update();
    if (!errors->Message.empty())
    {
      // A failed write leaves the parent an empty text: it then says only that reading failed.
      [[maybe_unused]] const ssize_t written =
        write(message[1], errors->Message.data(), errors->Message.size());
      std::_Exit(ReaderReportedAnError);
    }
    if (handed.Descriptor >= 0)
    {
      vtkNew<vtkPolyDataWriter> writer;
      writer->SetInputConnection(reader->GetOutputPort());
      writer->SetFileTypeToBinary();
      writer->SetFileName(handed.Path().c_str());
      std::_Exit(writer->Write() ? 0 : HandOverFailed);
    }
    std::_Exit(0);
  }
  close(message[1]);
  if (child < 0)
  {
    close(message[0]);
    return reader; // no probe possible: read as usual
  }
  std::string text;
  char buffer[512];
  for (ssize_t got; (got = read(message[0], buffer, sizeof(buffer))) > 0;)
  {
    text.append(buffer, static_cast<size_t>(got));
  }
  close(message[0]);
  int status = 0;
  waitpid(child, &status, 0);
  if (WIFEXITED(status) && WEXITSTATUS(status) == ReaderReportedAnError)
  {
    Fail("cannot read --input '" + path + "': " + (text.empty() ? "the reader failed" : text));
  }
  // The child ends with _Exit(0) unless the reader kills it (a signal, or an exit status other
  // than 0, as a sanitizer turns a crash into).
  if (WIFSIGNALED(status) ||
    (WIFEXITED(status) && WEXITSTATUS(status) != 0 && WEXITSTATUS(status) != HandOverFailed))
  {
    std::string why = "the reader crashed on it";
    if (WIFSIGNALED(status))
    {
      why = WTERMSIG(status) == SIGALRM ? std::string("reading it did not end within a minute")
                                        : why + ": " + strsignal(WTERMSIG(status));
    }
    Fail("cannot read --input '" + path + "': the file is corrupt or truncated (" + why + ")");
  }
  if (handed.Descriptor < 0 || WEXITSTATUS(status) == HandOverFailed)
  {
    return reader;
  }
  vtkNew<vtkPolyDataReader> handedOver;
  vtkNew<ErrorObserver> handOverErrors;
  handedOver->AddObserver(vtkCommand::ErrorEvent, handOverErrors);
  handedOver->SetFileName(handed.Path().c_str());
  handedOver->Update();
  if (!handOverErrors->Message.empty())
  {
    return reader; // out of memory in the middle of it: try the file itself
  }
  auto mesh = vtkSmartPointer<vtkTrivialProducer>::New();
  mesh->SetOutput(handedOver->GetOutput());
  return mesh;
}

/// A VTK reader of type Reader for `path`.
template<typename Reader>
vtkSmartPointer<vtkAlgorithm> Open(const std::string& path)
{
  auto reader = vtkSmartPointer<Reader>::New();
  reader->SetFileName(path.c_str());
  return reader;
}

/// The density formats: pictures give the luminance of their colour channels (or their grey
/// channel) over 255, data its one component as it is.
struct DensityFormat
{
  const char* Extension;
  bool Picture;
};
const DensityFormat DensityFormats[] = { { "png", true }, { "jpg", true }, { "jpeg", true },
  { "vti", false }, { "mha", false }, { "mhd", false } };

/// VTK's reader for a density format. vtkImageReader2Factory has the pictures' and MetaImage's
/// readers; .vti is an XML format, which it does not list. It is asked by extension, not by
/// contents (CreateImageReader2), so that a damaged file still reaches its format's reader inside
/// ProbeReader's child, never each reader's header test in this process.
vtkSmartPointer<vtkAlgorithm> ImageReader(const std::string& path, const std::string& ext)
{
  if (ext == "vti")
  {
    return Open<vtkXMLImageDataReader>(path);
  }
  auto reader =
    vtk::TakeSmartPointer(vtkImageReader2Factory::CreateImageReader2FromExtension(ext.c_str()));
  reader->SetFileName(path.c_str());
  return reader;
}

/// Rec. 601 luma (0.299 R + 0.587 G + 0.114 B, alpha ignored) over 255, as floats. By hand:
/// vtkImageLuminance weighs 0.30, 0.59, 0.11 in float, truncates the result to the input's type
/// (8-bit colour gives 256 grey levels) and takes exactly three components (no RGBA); the exact
/// VTK equivalent (a double copy, three vtkImageExtractComponents, vtkImageWeightedSum) holds
/// 56 bytes per RGB pixel, more than the CVT's own 48.
vtkSmartPointer<vtkDataArray> Luminance(vtkDataArray* rgb)
{
  auto luma = vtkSmartPointer<vtkFloatArray>::New();
  if (!luma->SetNumberOfValues(rgb->GetNumberOfTuples()))
  {
    throw std::bad_alloc(); // main reports it as out of memory
  }
  for (vtkIdType p = 0; p < rgb->GetNumberOfTuples(); ++p)
  {
    const double y = 0.299 * rgb->GetComponent(p, 0) + 0.587 * rgb->GetComponent(p, 1) +
      0.114 * rgb->GetComponent(p, 2);
    luma->SetValue(p, static_cast<float>(y * (1.0 / 255.0)));
  }
  return luma;
}

/// (first component of `values` + shift) * scale as floats, computed in double by
/// vtkImageShiftScale on the grid of `grid`.
vtkSmartPointer<vtkDataArray> ShiftScale(
  vtkImageData* grid, vtkDataArray* values, double shift, double scale)
{
  vtkNew<vtkImageData> input;
  input->CopyStructure(grid);
  input->GetPointData()->SetScalars(values);
  vtkNew<vtkImageShiftScale> shiftScale;
  vtkNew<vtkImageExtractComponents> first; // the grey channel of a grey + alpha picture
  if (values->GetNumberOfComponents() > 1)
  {
    first->SetInputData(input);
    first->SetComponents(0);
    shiftScale->SetInputConnection(first->GetOutputPort());
  }
  else
  {
    shiftScale->SetInputData(input);
  }
  shiftScale->SetShift(shift);
  shiftScale->SetScale(scale);
  shiftScale->SetOutputScalarTypeToFloat();
  shiftScale->Update();
  vtkDataArray* result = shiftScale->GetOutput()->GetPointData()->GetScalars();
  if (!result || result->GetNumberOfTuples() != values->GetNumberOfTuples())
  {
    throw std::bad_alloc(); // its only failure: main reports it as out of memory
  }
  return result;
}

/// The mesh formats and their readers: a table, as VTK 9.2 has no factory of polydata readers
/// (vtkImageReader2Factory knows images only; ParaView's vtkSMReaderFactory needs a session).
struct MeshFormat
{
  const char* Extension;
  vtkSmartPointer<vtkAlgorithm> (*Open)(const std::string& path);
  /// Read in a child first (ProbeReader). Our own OBJ and OFF readers are not: the fuzz tests
  /// run them in-process on damaged files and they refuse each with an error, and the probe
  /// would cost a fork and the hand-over.
  bool Probe;
};
const MeshFormat MeshFormats[] = { { "vtp", Open<vtkXMLPolyDataReader>, true },
  { "vtk", Open<vtkPolyDataReader>, true }, { "stl", Open<vtkSTLReader>, true },
  { "ply", Open<vtkPLYReader>, true }, { "obj", Open<vtkCVTOBJReader>, false },
  { "off", Open<vtkCVTOFFReader>, false } };

} // namespace

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
  const auto format = std::find_if(std::begin(DensityFormats), std::end(DensityFormats),
    [&ext](const DensityFormat& f) { return ext == f.Extension; });
  if (format == std::end(DensityFormats))
  {
    Fail("--input '" + options.Input + "' has an unknown type; use .png .jpg .vti .mha");
  }
  vtkSmartPointer<vtkAlgorithm> reader = ImageReader(options.Input, ext);
  ProbeReader(reader, options.Input, false);
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
  const int components = values->GetNumberOfComponents();
  if (!format->Picture && components != 1)
  {
    Fail("the density array has " + std::to_string(components) + " components; it needs one");
  }
  vtkSmartPointer<vtkDataArray> density = format->Picture && components >= 3
    ? Luminance(values)
    : ShiftScale(image, values, 0.0, format->Picture ? 1.0 / 255.0 : 1.0);
  if (options.Invert)
  {
    // top - value as (value - top) * -1 (a value equal to top gives -0, not +0); top is 1 for
    // pictures, else the largest value.
    const double top = format->Picture ? 1.0 : values->GetRange(0)[1];
    density = ShiftScale(image, density, -top, -1.0);
  }
  density->SetName("density");
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

vtkSmartPointer<vtkAlgorithm> MeshReader(const Options& options)
{
  struct stat info;
  if (stat(options.Input.c_str(), &info) != 0)
  {
    Fail("cannot read --input '" + options.Input + "': no such file");
  }
  const std::string ext = Extension(options.Input);
  const auto format = std::find_if(std::begin(MeshFormats), std::end(MeshFormats),
    [&ext](const MeshFormat& f) { return ext == f.Extension; });
  if (format == std::end(MeshFormats))
  {
    Fail("--input '" + options.Input + "' has an unknown type; use .vtp .vtk .stl .ply .obj .off");
  }
  // Our readers would take a UTF-16 file for one without vertices (OBJ) or a bad header (OFF).
  if (ext == "obj" || ext == "off")
  {
    std::ifstream in(options.Input, std::ios::binary);
    unsigned char mark[2] = { 0, 0 };
    in.read(reinterpret_cast<char*>(mark), 2);
    if ((mark[0] == 0xFF && mark[1] == 0xFE) || (mark[0] == 0xFE && mark[1] == 0xFF))
    {
      Fail("cannot read --input '" + options.Input +
        "': it is UTF-16 text; save it as UTF-8 or ASCII");
    }
  }
  vtkSmartPointer<vtkAlgorithm> reader = format->Open(options.Input);
  return format->Probe ? ProbeReader(reader, options.Input, true) : reader;
}

} // namespace cvtcli
