// The `cvt` program's command line and sites-file parsers (see cvtCommandLine.h).
#include "cvtCommandLine.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>

namespace cvtcli
{

const char* const Usage = R"(usage: cvt image [options]
       cvt surface [options]

Computes a centroidal Voronoi tessellation (CVT) on the GPU (headless: EGL, no display needed):
of a 2D image domain (image), or a constrained CVT of a surface with its remesh (surface).

Input:
  --input FILE            density image: .png .jpg .jpeg .vti .mha .mhd (default: none, a
                          uniform density on --domain at --resolution)
  --array NAME            density array of a .vti/.mha input (default: its active scalars)
  --invert                dark = dense (for stippling): density = max - value
  --domain XMIN XMAX YMIN YMAX
                          physical extent of the image domain (default: the image's own
                          geometry; with no --input, [-1,1]^2)
  --resolution N          grid size when there is no --input (default 512)
  --engine auto|cpu|opengl
                          image: opengl runs on the GPU; cpu integrates exact Voronoi polygons
                          in parallel; auto (default) takes cpu when the only OpenGL is a
                          software renderer (llvmpipe) or there is none, and on a hardware GPU
                          the engine that is faster on a calibration job
Surface (cvt surface):
  --torus R r             a torus of ring radius R and tube radius r (default 1 0.4)
  --gi-resolution W H     geometry image size (default 1024 512)
  --input MESH            a surface mesh (.vtp .vtk .stl .ply .obj .off): any
                          orientable manifold (genus, boundaries, several parts); cleaned
                          (merged points, triangulated, degenerate triangles dropped,
                          oriented) and remeshed
  --array NAME            with --input: a point array used as density (denser where larger)
  --keep-every-site       with --input: every site keeps its remesh vertex (by default edges
                          are collapsed where that brings valences closer to 6)
  --engine auto|cpu|opengl
                          with --input: cpu (and auto) computes exact restricted Voronoi cells
                          on the mesh, multi-threaded; opengl maps it into a geometry
                          image (one chart for a disk or a star-shaped closed mesh, else an
                          atlas of charts joined by seams) and runs on the GPU (default auto)
Sites:
  --sites N               number of sites (default 1000)
  --initial-sites FILE    CSV of initial sites, one "x,y" per line (overrides --sites)
  --seed S                seed of the initial site sampling (default 1)
Optimiser:
  --method lloyd|lbfgs    optimiser (default lbfgs)
  --iterations N          iteration cap (default 100; for the cpu engine's remesh of an --input
                          with more than 2500 sites, unless given: 250000/sites, at least 50)
  --tolerance T           stop when the relative energy decrease falls below T (Lloyd: or
                          when no pixel changes site); 0 runs every iteration (default 1e-6)
  --gradient-tolerance G  stop when |grad F| falls below G times its initial value (default 0)
  --corrections M         L-BFGS corrections kept (default 7)
  --report                image: energy, |grad F|, the GPU energy against the exact CPU energy
                          of the result, quality measures (Rong et al. Table 6); surface:
                          energy, |grad F|, remesh valence and angle histograms
Output:
  --output DIR            writes sites.vtp, sites.csv, labels.vti, dual.vtp (image) or
                          remesh.vtp (surface), history.csv and cvt.png (default: ./cvt-output)
  --quiet                 print nothing but errors
  --help                  this text
)";

namespace
{
[[noreturn]] void Fail(const std::string& message, int /*status*/)
{
  throw UsageError(message);
}

double ParseNumber(const std::string& option, const char* text)
{
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(text, &end);
  if (end == text || *end != '\0' || errno != 0 || !std::isfinite(value))
  {
    Fail(option + " expects a number, got '" + text + "'", 2);
  }
  return value;
}

long long ParseInteger(const std::string& option, const char* text)
{
  char* end = nullptr;
  errno = 0;
  const long long value = std::strtoll(text, &end, 10);
  if (end == text || *end != '\0' || errno != 0)
  {
    Fail(option + " expects an integer, got '" + text + "'", 2);
  }
  return value;
}

int ParseInt(const std::string& option, const char* text)
{
  const long long value = ParseInteger(option, text);
  if (value < std::numeric_limits<int>::min() || value > std::numeric_limits<int>::max())
  {
    Fail(option + " is out of range: '" + text + "'", 2);
  }
  return static_cast<int>(value);
}

} // namespace

Options ParseArguments(const std::vector<std::string>& args)
{
  Options options;
  if (args.empty() || args[0] == "--help" || args[0] == "-h")
  {
    options.Help = true;
    options.HelpStatus = args.empty() ? 2 : 0;
    return options;
  }
  options.Command = args[0];
  if (options.Command != "image" && options.Command != "surface")
  {
    Fail("unknown command '" + options.Command +
        "'; use 'cvt image' or 'cvt surface' (see cvt --help)",
      2);
  }
  for (size_t k = 1; k < args.size(); ++k)
  {
    const std::string& a = args[k];
    auto value = [&](int count = 1) -> const char*
    {
      if (k + count > args.size() - 1)
      {
        Fail(a + " needs " + std::to_string(count) + " value(s)", 2);
      }
      return args[++k].c_str();
    };
    if (a == "--help" || a == "-h")
    {
      options.Help = true;
      return options;
    }
    else if (a == "--input")
      options.Input = value();
    else if (a == "--array")
      options.Array = value();
    else if (a == "--keep-every-site")
      options.KeepEverySite = true;
    else if (a == "--engine")
      options.Engine = value();
    else if (a == "--invert")
    {
      options.Invert = true;
      options.HaveImageOption = true;
    }
    else if (a == "--torus")
    {
      if (k + 2 > args.size() - 1)
      {
        Fail("--torus needs 2 values: R r", 2);
      }
      options.Torus[0] = ParseNumber(a, args[++k].c_str());
      options.Torus[1] = ParseNumber(a, args[++k].c_str());
      options.HaveTorus = true;
      if (!(options.Torus[0] > 0.0) || !(options.Torus[1] > 0.0) ||
        !(options.Torus[1] < options.Torus[0]))
      {
        Fail("--torus needs 0 < r < R", 2);
      }
    }
    else if (a == "--gi-resolution")
    {
      if (k + 2 > args.size() - 1)
      {
        Fail("--gi-resolution needs 2 values: W H", 2);
      }
      options.GIResolutionGiven = true;
      for (int& r : options.GIResolution)
      {
        r = ParseInt(a, args[++k].c_str());
        if (r < 2 || r > 65536)
        {
          Fail("--gi-resolution needs sizes between 2 and 65536", 2);
        }
      }
    }
    else if (a == "--quiet")
      options.Quiet = true;
    else if (a == "--report")
      options.Report = true;
    else if (a == "--corrections")
      options.Corrections = ParseInt(a, value());
    else if (a == "--gradient-tolerance")
      options.GradientTolerance = ParseNumber(a, value());
    else if (a == "--domain")
    {
      if (k + 4 > args.size() - 1)
      {
        Fail("--domain needs 4 values: XMIN XMAX YMIN YMAX", 2);
      }
      for (double& d : options.Domain)
      {
        d = ParseNumber(a, args[++k].c_str());
      }
      options.HaveDomain = true;
      options.HaveImageOption = true;
      if (!(options.Domain[1] > options.Domain[0]) || !(options.Domain[3] > options.Domain[2]))
      {
        Fail("--domain needs XMIN < XMAX and YMIN < YMAX", 2);
      }
    }
    else if (a == "--resolution")
    {
      options.Resolution = ParseInt(a, value());
      options.HaveImageOption = true;
    }
    else if (a == "--sites")
      options.Sites = ParseInt(a, value());
    else if (a == "--initial-sites")
    {
      options.InitialSites = value();
      options.HaveImageOption = true;
    }
    else if (a == "--seed")
      options.Seed = ParseInteger(a, value());
    else if (a == "--method")
      options.Method = value();
    else if (a == "--iterations")
    {
      options.Iterations = ParseInt(a, value());
      options.IterationsGiven = true;
    }
    else if (a == "--tolerance")
      options.Tolerance = ParseNumber(a, value());
    else if (a == "--output")
      options.Output = value();
    else
      Fail("unknown option '" + a + "' (see cvt --help)", 2);
  }
  if (options.Command == "surface" && options.HaveImageOption)
  {
    Fail("--invert, --domain, --resolution and --initial-sites are options of "
         "'cvt image', not of 'cvt surface'",
      2);
  }
  if (options.Engine != "auto" && options.Engine != "cpu" && options.Engine != "opengl")
  {
    Fail("--engine must be auto, cpu or opengl, got '" + options.Engine + "'", 2);
  }
  if (options.Command == "surface" && !options.Array.empty() && options.Input.empty())
  {
    Fail("--array with 'cvt surface' names a point array of the --input mesh", 2);
  }
  if (options.KeepEverySite && (options.Command != "surface" || options.Input.empty()))
  {
    Fail("--keep-every-site is an option of 'cvt surface --input' (the remesh of a mesh)", 2);
  }
  if (options.Command == "image" && options.HaveTorus)
  {
    Fail("--torus is an option of 'cvt surface'", 2);
  }
  if (options.Command == "surface" && !options.Input.empty() && options.HaveTorus)
  {
    Fail("give either --input MESH or --torus R r, not both", 2);
  }
  if (options.Method != "lloyd" && options.Method != "lbfgs")
  {
    Fail("--method must be lloyd or lbfgs, got '" + options.Method + "'", 2);
  }
  if (options.Resolution < 1 || options.Resolution > 65536)
  {
    Fail("--resolution must be between 1 and 65536", 2);
  }
  if (options.Iterations < 0)
  {
    Fail("--iterations must be >= 0", 2);
  }
  if (!(options.Tolerance >= 0.0))
  {
    Fail("--tolerance must be >= 0", 2);
  }
  if (options.Corrections < 1 || options.Corrections > 100)
  {
    Fail("--corrections must be between 1 and 100", 2);
  }
  if (!(options.GradientTolerance >= 0.0 && options.GradientTolerance <= 1.0))
  {
    Fail("--gradient-tolerance must be between 0 and 1", 2);
  }
  if (options.Sites < 0)
  {
    Fail("--sites must be >= 0", 2);
  }
  return options;
}

std::vector<double> ParseSitesCsv(std::istream& in, const std::string& name)
{
  std::vector<double> sites;
  std::string line;
  int lineNumber = 0;
  while (std::getline(in, line))
  {
    ++lineNumber;
    if (line.find_first_not_of(" \t\r") == std::string::npos)
    {
      continue;
    }
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream fields(line);
    double x, y;
    if (!(fields >> x >> y) || !std::isfinite(x) || !std::isfinite(y))
    {
      if (lineNumber == 1)
      {
        continue; // a header line
      }
      throw UsageError("--initial-sites '" + name + "' line " + std::to_string(lineNumber) +
        " is not 'x,y' or 'x,y,z' with finite numbers");
    }
    sites.push_back(x);
    sites.push_back(y);
  }
  if (in.bad())
  {
    throw UsageError("cannot read --initial-sites '" + name + "'");
  }
  return sites;
}

} // namespace cvtcli
