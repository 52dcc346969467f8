#include "vtkCVTOBJReader.h"

#include "vtkCellArray.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <cerrno>
#include <cstdlib>
#include <istream>
#include <string>

vtkStandardNewMacro(vtkCVTOBJReader);

namespace
{

bool IsSpace(char c)
{
  return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

const char* SkipSpaces(const char* p)
{
  while (IsSpace(*p))
  {
    ++p;
  }
  return p;
}

const char* WordEnd(const char* p)
{
  while (*p != '\0' && !IsSpace(*p))
  {
    ++p;
  }
  return p;
}

/// Cells as offsets and connectivity, appended to one at a time.
struct CellList
{
  vtkNew<vtkIdTypeArray> Offsets;
  vtkNew<vtkIdTypeArray> Connectivity;
  CellList() { this->Offsets->InsertNextValue(0); }
  void Close() { this->Offsets->InsertNextValue(this->Connectivity->GetNumberOfTuples()); }
  vtkIdType Count() const { return this->Offsets->GetNumberOfTuples() - 1; }
  void MoveTo(vtkCellArray* cells) { cells->SetData(this->Offsets, this->Connectivity); }
};

/// One statement of the file (a line, with the lines a backslash continued it onto) and what it
/// adds to the mesh. Returns an empty text, or what is wrong with it.
class Statements
{
public:
  vtkNew<vtkPoints> Points;
  CellList Faces, Lines, Vertices;
  /// The largest vertex index met (from 0) and its statement's line: a face may name vertices
  /// defined further down, so indices are checked against the count at the end.
  long long LargestIndex = -1;
  long long LargestIndexLine = 0;

  // Single precision, as vtkOBJReader stores them: the same points, so the same merges.
  Statements() { this->Points->SetDataTypeToFloat(); }

  std::string Read(const char* p, long long line)
  {
    p = SkipSpaces(p);
    const char* end = WordEnd(p);
    const std::string keyword(p, end);
    if (keyword == "v")
    {
      return this->Vertex(end);
    }
    if (keyword == "f" || keyword == "fo") // "fo": the face of OBJ's first versions
    {
      return this->Cell(end, line, 3, "face", this->Faces);
    }
    if (keyword == "l")
    {
      return this->Cell(end, line, 2, "line", this->Lines);
    }
    if (keyword == "p")
    {
      return this->Cell(end, line, 1, "point", this->Vertices);
    }
    return {}; // not geometry: vt, vn, g, o, s, mtllib, usemtl, curves and surfaces
  }

private:
  std::string Vertex(const char* p)
  {
    double x[3];
    for (double& coordinate : x)
    {
      p = SkipSpaces(p);
      char* end = nullptr;
      coordinate = std::strtod(p, &end);
      if (end == p || !(*end == '\0' || IsSpace(*end)))
      {
        return "a vertex needs three numbers (v x y z).";
      }
      p = end;
    }
    this->Points->InsertNextPoint(x);
    return {};
  }

  /// A face, line or point statement: its corners' vertex indices (the number before the first
  /// slash), at least `fewest` of them.
  std::string Cell(
    const char* p, long long line, int fewest, const std::string& what, CellList& cells)
  {
    const long long count = this->Points->GetNumberOfPoints();
    int corners = 0;
    for (p = SkipSpaces(p); *p != '\0'; p = SkipSpaces(p))
    {
      const char* end = WordEnd(p);
      const auto corner = [p, end]() { return std::string(p, end); }; // for the errors alone
      errno = 0;
      char* after = nullptr;
      const long long index = std::strtoll(p, &after, 10);
      if (after == p || errno != 0 || !(after == end || *after == '/') || index == 0)
      {
        return "the " + what + " corner '" + corner() +
          "' is not a vertex index (1 is the first vertex, -1 the last one so far).";
      }
      const long long vertex = index > 0 ? index - 1 : count + index;
      if (vertex < 0)
      {
        return "the " + what + " corner '" + corner() + "' counts back past the first vertex (" +
          std::to_string(count) + " so far).";
      }
      if (vertex > this->LargestIndex)
      {
        this->LargestIndex = vertex;
        this->LargestIndexLine = line;
      }
      cells.Connectivity->InsertNextValue(static_cast<vtkIdType>(vertex));
      ++corners;
      p = end;
    }
    if (corners < fewest)
    {
      return "a " + what + " needs at least " + std::to_string(fewest) + " corner" +
        (fewest > 1 ? "s" : "") + ", this one has " + std::to_string(corners) + ".";
    }
    cells.Close();
    return {};
  }
};

} // namespace

bool vtkCVTOBJReader::ReadMesh(std::istream& in, vtkPolyData* output)
{
  Statements mesh;
  std::string text, statement;
  long long number = 0, first = 0; // the line read last, and the statement's first line
  while (std::getline(in, text))
  {
    ++number;
    const size_t hash = text.find('#');
    if (hash != std::string::npos)
    {
      text.erase(hash);
    }
    while (!text.empty() && IsSpace(text.back()))
    {
      text.pop_back();
    }
    if (statement.empty())
    {
      first = number;
    }
    statement += text;
    if (!statement.empty() && statement.back() == '\\')
    {
      statement.back() = ' '; // continued on the next line
      continue;
    }
    const std::string problem = mesh.Read(statement.c_str(), first);
    if (!problem.empty())
    {
      return this->LineError(first, problem);
    }
    statement.clear();
  }
  const std::string problem = mesh.Read(statement.c_str(), first); // ended on a backslash
  if (!problem.empty())
  {
    return this->LineError(first, problem);
  }
  const long long count = mesh.Points->GetNumberOfPoints();
  if (count == 0)
  {
    return this->LineError(
      number, "the file has no vertices (lines 'v x y z'); is it an OBJ file?");
  }
  if (mesh.LargestIndex >= count)
  {
    return this->LineError(mesh.LargestIndexLine,
      "a corner names vertex " + std::to_string(mesh.LargestIndex + 1) + ", but the file has " +
        std::to_string(count) + ".");
  }
  output->SetPoints(mesh.Points);
  const std::pair<CellList*, void (vtkPolyData::*)(vtkCellArray*)> kinds[] = {
    { &mesh.Faces, &vtkPolyData::SetPolys }, { &mesh.Lines, &vtkPolyData::SetLines },
    { &mesh.Vertices, &vtkPolyData::SetVerts }
  };
  for (const auto& [cells, set] : kinds)
  {
    if (cells->Count() > 0)
    {
      vtkNew<vtkCellArray> array;
      cells->MoveTo(array);
      (output->*set)(array);
    }
  }
  return true;
}
