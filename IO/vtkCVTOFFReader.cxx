#include "vtkCVTOFFReader.h"

#include "vtkCellArray.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <istream>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkCVTOFFReader);

namespace
{

/// The file's meaningful lines ("#" comments and blank lines dropped), each with its number.
class OffLines
{
public:
  explicit OffLines(std::istream& in)
    : In(in)
  {
  }

  /// The next meaningful line in `line` (comment cut off); false at the end of the file.
  bool Next(std::string& line)
  {
    while (std::getline(this->In, line))
    {
      ++this->Number;
      const size_t hash = line.find('#');
      if (hash != std::string::npos)
      {
        line.erase(hash);
      }
      if (line.find_first_not_of(" \t\r\f\v") != std::string::npos)
      {
        return true;
      }
    }
    return false;
  }

  int LineNumber() const { return this->Number; }

private:
  std::istream& In;
  int Number = 0;
};

/// The whitespace-separated words of a line.
std::vector<std::string> Words(const std::string& line)
{
  std::istringstream in(line);
  std::vector<std::string> words;
  for (std::string word; in >> word;)
  {
    words.push_back(word);
  }
  return words;
}

bool ParseInteger(const std::string& word, long long& value)
{
  errno = 0;
  char* end = nullptr;
  value = std::strtoll(word.c_str(), &end, 10);
  return errno == 0 && end != word.c_str() && *end == '\0';
}

bool ParseReal(const std::string& word, double& value)
{
  char* end = nullptr;
  value = std::strtod(word.c_str(), &end);
  return end != word.c_str() && *end == '\0';
}

/// Whether `word` is the header keyword [ST][C][N][4][n]OFF (Geomview's spelling; "off" too).
/// `otherDimension` is set when it says the points are 4-dimensional (4) or n-dimensional (n).
bool IsKeyword(const std::string& word, bool& otherDimension)
{
  otherDimension = false;
  if (word == "off")
  {
    return true;
  }
  if (word.size() < 3 || word.compare(word.size() - 3, 3, "OFF") != 0)
  {
    return false;
  }
  const std::string prefix = word.substr(0, word.size() - 3);
  size_t i = prefix.compare(0, 2, "ST") == 0 ? 2 : 0;
  for (const char optional : { 'C', 'N', '4', 'n' })
  {
    if (i < prefix.size() && prefix[i] == optional)
    {
      otherDimension = otherDimension || optional == '4' || optional == 'n';
      ++i;
    }
  }
  return i == prefix.size();
}

} // namespace

bool vtkCVTOFFReader::ReadMesh(std::istream& in, vtkPolyData* output)
{
  // Each vertex line holds at least 6 characters ("0 0 0\n") and each face line 8: a wrong
  // header must not size the arrays beyond what the file can hold (it fails further down).
  in.seekg(0, std::ios::end);
  const long long fileSize = std::max<long long>(0, static_cast<long long>(in.tellg()));
  in.seekg(0);
  OffLines lines(in);
  std::string line;
  const auto fail = [&](const std::string& what)
  { return this->LineError(lines.LineNumber(), what); };
  if (!lines.Next(line))
  {
    return fail("the file is empty; an OFF file starts with OFF and the vertex and face counts.");
  }

  // Header: an optional keyword, then the vertex, face and edge counts on the same line or the
  // next one.
  std::vector<std::string> words = Words(line);
  bool dimensions = false;
  if (IsKeyword(words[0], dimensions))
  {
    const std::string keyword = words[0];
    if (dimensions)
    {
      return fail("'" + keyword + "' has points of other than 3 dimensions; only 3D OFF is read.");
    }
    words.erase(words.begin());
    if (!words.empty() && (words[0] == "BINARY" || words[0] == "binary"))
    {
      return fail("binary OFF is not read; save the mesh as ASCII OFF (or .ply, .obj, .stl).");
    }
    if (words.empty())
    {
      if (!lines.Next(line))
      {
        return fail("the vertex and face counts are missing after '" + keyword + "'.");
      }
      words = Words(line);
    }
  }
  long long vertexCount = -1, faceCount = -1;
  if (words.size() < 2 || !ParseInteger(words[0], vertexCount) ||
    !ParseInteger(words[1], faceCount) || vertexCount < 0 || faceCount < 0)
  {
    return fail("expected the vertex and face counts (two integers, then the edge count), got '" +
      line + "'.");
  }

  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->Allocate(static_cast<vtkIdType>(std::min(vertexCount, fileSize / 6)));
  for (long long v = 0; v < vertexCount; ++v)
  {
    if (!lines.Next(line))
    {
      return fail("the file ends after " + std::to_string(v) + " of its " +
        std::to_string(vertexCount) + " vertices.");
    }
    words = Words(line);
    double x[3];
    if (words.size() < 3 || !ParseReal(words[0], x[0]) || !ParseReal(words[1], x[1]) ||
      !ParseReal(words[2], x[2]))
    {
      return fail("vertex " + std::to_string(v) + " needs three coordinates, got '" + line + "'.");
    }
    points->InsertNextPoint(x);
  }

  vtkNew<vtkIdTypeArray> offsets;
  vtkNew<vtkIdTypeArray> connectivity;
  offsets->Allocate(std::min(faceCount, fileSize / 8) + 1);
  connectivity->Allocate(3 * std::min(faceCount, fileSize / 8));
  offsets->InsertNextValue(0);
  for (long long f = 0; f < faceCount; ++f)
  {
    if (!lines.Next(line))
    {
      return fail("the file ends after " + std::to_string(f) + " of its " +
        std::to_string(faceCount) + " faces.");
    }
    words = Words(line);
    long long corners = 0;
    if (!ParseInteger(words[0], corners) || corners < 3 ||
      static_cast<long long>(words.size()) < corners + 1)
    {
      return fail("face " + std::to_string(f) +
        " needs a vertex count of at least 3 and that many vertex indices, got '" + line + "'.");
    }
    for (long long k = 1; k <= corners; ++k)
    {
      long long index = -1;
      if (!ParseInteger(words[k], index) || index < 0 || index >= vertexCount)
      {
        return fail("face " + std::to_string(f) + " names vertex '" + words[k] +
          "', which is not one of the " + std::to_string(vertexCount) + " vertices.");
      }
      connectivity->InsertNextValue(static_cast<vtkIdType>(index));
    }
    offsets->InsertNextValue(connectivity->GetNumberOfTuples());
  }
  vtkNew<vtkCellArray> polygons;
  polygons->SetData(offsets, connectivity);
  output->SetPoints(points);
  output->SetPolys(polygons);
  return true;
}
