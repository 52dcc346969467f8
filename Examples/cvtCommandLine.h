// The `cvt` program's own parsers: its command line and the --initial-sites CSV. Kept apart
// from the program so that the test suite can feed them any input
// (Testing/CommandLine/TestFuzz.cxx).
#ifndef cvtCommandLine_h
#define cvtCommandLine_h

#include <istream>
#include <stdexcept>
#include <string>
#include <vector>

namespace cvtcli
{

/// The options of `cvt image` and `cvt surface` (see Usage).
struct Options
{
  bool Help = false; // --help: print Usage and exit with HelpStatus
  int HelpStatus = 0;
  std::string Command;
  std::string Input, Array, InitialSites, Output = "cvt-output", Method = "lbfgs";
  bool Invert = false, HaveDomain = false, Quiet = false, Report = false;
  int Corrections = 7;
  double GradientTolerance = 0.0;
  double Domain[4] = { -1.0, 1.0, -1.0, 1.0 };
  int Resolution = 512, Sites = 1000, Iterations = 100;
  bool IterationsGiven = false; // --iterations given: a remesh then keeps that cap at any count
  double Torus[2] = { 1.0, 0.4 };
  int GIResolution[2] = { 1024, 512 };
  bool GIResolutionGiven = false; // else a mesh's atlas is sized from --sites
  bool HaveTorus = false, HaveImageOption = false;
  bool KeepEverySite = false; // --keep-every-site: no remesh collapses for valence 6
  std::string Engine = "auto";
  long long Seed = 1;
  double Tolerance = 1e-6;
};

/// What a wrong command line or sites file is, in one sentence for the user.
struct UsageError : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

extern const char* const Usage;

/// Parses the arguments after the program name; throws UsageError naming what is wrong.
/// No arguments, --help or -h: Help is set (HelpStatus 2 for none, 0 for --help).
Options ParseArguments(const std::vector<std::string>& args);

/// Reads sites, one "x,y" or "x,y,z" per line (z ignored; blank lines and a header line are
/// skipped) as flat x, y pairs; throws UsageError naming `name` and the line that is wrong.
std::vector<double> ParseSitesCsv(std::istream& in, const std::string& name);

} // namespace cvtcli

#endif
