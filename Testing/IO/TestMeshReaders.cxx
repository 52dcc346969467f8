// vtkCVTOFFReader and vtkCVTOBJReader: the OFF and OBJ variants met in public mesh collections
// and exporters read to the same polygons, and every malformed file is a clear error naming its
// line, with an empty output.
#include "vtkCVTOBJReader.h"
#include "vtkCVTOFFReader.h"

#include "vtkCellArray.h"
#include "vtkExecutive.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include "cvtFilterTestSupport.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace
{

/// Writes `text` to a fresh file of that extension and removes it again.
class TextFile
{
public:
  explicit TextFile(const std::string& text, const std::string& extension = "off")
    : Path(testing::TempDir() + "cvt_mesh_" + std::to_string(getpid()) + "_" +
        std::to_string(Count++) + "." + extension)
  {
    std::ofstream(this->Path) << text;
  }
  ~TextFile() { std::remove(this->Path.c_str()); }
  const std::string Path;

private:
  static int Count;
};
int TextFile::Count = 0;

struct Read
{
  vtkSmartPointer<vtkPolyData> Mesh;
  int Status = 0;
  std::string Errors;
};

template<typename Reader>
Read ReadWith(const std::string& path)
{
  vtkNew<Reader> reader;
  vtkNew<cvttest::Messages> messages;
  reader->AddObserver(vtkCommand::ErrorEvent, messages);
  reader->SetFileName(path.c_str());
  Read result;
  result.Status = reader->GetExecutive()->Update();
  result.Mesh = reader->GetOutput();
  result.Errors = messages->Errors;
  return result;
}

Read ReadOff(const std::string& path)
{
  return ReadWith<vtkCVTOFFReader>(path);
}

Read ReadObj(const std::string& path)
{
  return ReadWith<vtkCVTOBJReader>(path);
}

/// The cells of `cells` as lists of point ids.
std::vector<std::vector<vtkIdType>> CellsOf(vtkCellArray* cells)
{
  std::vector<std::vector<vtkIdType>> lists;
  vtkNew<vtkIdList> ids;
  for (cells->InitTraversal(); cells->GetNextCell(ids);)
  {
    lists.emplace_back(ids->begin(), ids->end());
  }
  return lists;
}

// A unit square pyramid: four triangles and a quad.
const std::vector<std::vector<vtkIdType>> PyramidFaces = { { 0, 1, 2, 3 }, { 0, 4, 1 }, { 1, 4, 2 },
  { 2, 4, 3 }, { 3, 4, 0 } };

/// `pointType`: the OFF reader's points are doubles, the OBJ reader's floats (as VTK's).
void ExpectPyramid(const Read& read, int pointType = VTK_DOUBLE)
{
  ASSERT_EQ(read.Status, 1) << read.Errors;
  EXPECT_EQ(read.Errors, "");
  ASSERT_EQ(read.Mesh->GetNumberOfPoints(), 5);
  EXPECT_EQ(read.Mesh->GetNumberOfPolys(), 5);
  EXPECT_EQ(read.Mesh->GetPoints()->GetDataType(), pointType);
  const double expected[5][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 },
    { 0.5, 0.5, 0.7071067811865476 } };
  for (int i = 0; i < 5; ++i)
  {
    double x[3];
    read.Mesh->GetPoint(i, x);
    for (int k = 0; k < 3; ++k)
    {
      EXPECT_EQ(x[k], pointType == VTK_FLOAT ? static_cast<float>(expected[i][k]) : expected[i][k])
        << "point " << i;
    }
  }
  EXPECT_EQ(CellsOf(read.Mesh->GetPolys()), PyramidFaces);
}

/// A malformed file and what its error must say.
struct Case
{
  std::string Text, Expected;
};

/// Each case, a missing file and no file name are refused by Reader with that error and an
/// empty output.
template<typename Reader>
void ExpectRefusals(const std::vector<Case>& cases, const std::string& extension)
{
  for (const Case& c : cases)
  {
    TextFile file(c.Text, extension);
    const Read read = ReadWith<Reader>(file.Path);
    EXPECT_EQ(read.Status, 0) << c.Text;
    EXPECT_NE(read.Errors.find(c.Expected), std::string::npos)
      << "file:\n"
      << c.Text << "\nerror: " << read.Errors;
    EXPECT_EQ(read.Mesh->GetNumberOfPoints(), 0) << c.Text;
    EXPECT_EQ(read.Mesh->GetNumberOfCells(), 0) << c.Text;
  }
  const Read missing = ReadWith<Reader>(testing::TempDir() + "no_such_file." + extension);
  EXPECT_EQ(missing.Status, 0);
  EXPECT_NE(missing.Errors.find("Cannot open"), std::string::npos) << missing.Errors;
  vtkNew<Reader> unnamed;
  vtkNew<cvttest::Messages> messages;
  unnamed->AddObserver(vtkCommand::ErrorEvent, messages);
  EXPECT_EQ(unnamed->GetExecutive()->Update(), 0);
  EXPECT_NE(messages->Errors.find("No FileName"), std::string::npos) << messages->Errors;
}

} // namespace

TEST(OFFReader, ReadsPlainOffWithCommentsAndCountsOnTheirOwnLine)
{
  TextFile file("OFF\n# a pyramid\n\n5 5 8\n0 0 0\n1 0 0\n1 1 0  # corner\n0 1 0\n"
                "0.5 0.5 0.7071067811865476\n4 0 1 2 3\n3 0 4 1\n3 1 4 2\n3 2 4 3\n3 3 4 0\n");
  ExpectPyramid(ReadOff(file.Path));
}

TEST(OFFReader, ReadsCountsOnTheKeywordLineAndSkipsColoursAndNormals)
{
  // CGAL writes "OFF n f e" on one line; COFF and NOFF add numbers per vertex, and faces may
  // carry a colour.
  TextFile counts("OFF 5 5 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 0.5 0.7071067811865476\n"
                  "4 0 1 2 3 255 0 0\n3 0 4 1 0.5 0.5 0.5 1\n3 1 4 2\n3 2 4 3\n3 3 4 0\n");
  ExpectPyramid(ReadOff(counts.Path));
  TextFile cnoff("CNOFF\r\n5 5 8\r\n0 0 0 0 0 -1 255 0 0 255\r\n1 0 0 0 0 -1 0 255 0 255\r\n"
                 "1 1 0 0 0 -1 0 0 255 255\r\n0 1 0 0 0 -1 9 9 9 255\r\n"
                 "0.5 0.5 0.7071067811865476 0 0 1 1 1 1 255\r\n4 0 1 2 3\r\n3 0 4 1\r\n"
                 "3 1 4 2\r\n3 2 4 3\r\n3 3 4 0\r\n");
  ExpectPyramid(ReadOff(cnoff.Path));
  TextFile noKeyword("5 5 8\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 0.5 0.7071067811865476\n"
                     "4 0 1 2 3\n3 0 4 1\n3 1 4 2\n3 2 4 3\n3 3 4 0\n");
  ExpectPyramid(ReadOff(noKeyword.Path));
}

TEST(OFFReader, MalformedFilesAreErrorsNamingTheLine)
{
  const std::string vertices = "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 0.5 0.7\n";
  const std::string faces = "4 0 1 2 3\n3 0 4 1\n3 1 4 2\n3 2 4 3\n3 3 4 0\n";
  const std::vector<Case> cases = {
    { "", "line 0: the file is empty" },
    { "OFF BINARY\n", "binary OFF is not read" },
    { "4OFF\n5 5 0\n", "other than 3 dimensions" },
    { "nOFF\n3\n5 5 0\n", "other than 3 dimensions" },
    { "OFF\n", "counts are missing" },
    { "OFF\nfive 5 0\n", "line 2: expected the vertex and face counts" },
    { "OFF\n5 -1 0\n", "expected the vertex and face counts" },
    { "OFF\n353535235358 6 0\n0 0 0\n", "ends after 1 of its 353535235358 vertices" },
    { "OFF\n5 5 0\n0 0 0\n1 0\n", "line 4: vertex 1 needs three coordinates" },
    { "OFF\n5 5 0\n0 0 0\n1 0 x\n", "vertex 1 needs three coordinates" },
    { "OFF\n5 5 0\n0 0 0\n", "ends after 1 of its 5 vertices" },
    { "OFF\n5 5 0\n" + vertices + "4 0 1 2 3\n", "ends after 1 of its 5 faces" },
    { "OFF\n5 5 0\n" + vertices + "2 0 1\n" + faces, "line 8: face 0 needs a vertex count" },
    { "OFF\n5 5 0\n" + vertices + "4 0 1 2\n" + faces, "face 0 needs a vertex count" },
    { "OFF\n5 5 0\n" + vertices + "4 0 1 2 5\n" + faces, "names vertex '5', which is not one" },
    { "OFF\n5 5 0\n" + vertices + "4 0 -1 2 3\n" + faces, "names vertex '-1'" },
  };
  ExpectRefusals<vtkCVTOFFReader>(cases, "off");
}

TEST(OBJReader, ReadsEveryCornerFormRelativeAndForwardIndicesAndContinuedLines)
{
  // What exporters write: materials and groups (an empty usemtl among them, where VTK's reader
  // stops), texture coordinates and normals, vertex colours, corners ending in a slash (Cura's
  // printer models, on which VTK's reader fails or crashes), a face naming a vertex defined
  // further down, relative indices, a line continued with a backslash, CRLF and tabs.
  TextFile file("# a pyramid\r\nmtllib pyramid.mtl\r\no pyramid\r\nv 0 0 0\r\n"
                "v\t1 0 0\r\nvt 0 0\r\nvn 0 0 1\r\nv 1 1 0 0.5 0.5 0.5\r\nv 0 1 0 # corner\r\n"
                "g side\r\nusemtl\r\ns off\r\nf 1/1 2/ 3/1/1 4//1\r\nf 1 5 2\r\n"
                "v 0.5 0.5 0.7071067811865476\r\nf -4 -1 -3\r\nf 3/1/ \\\r\n  5/ 4\r\n"
                "fo 4 5 1\r\nl 1 2 3\r\np 5\r\n",
    "obj");
  const Read read = ReadObj(file.Path);
  ExpectPyramid(read, VTK_FLOAT);
  const std::vector<std::vector<vtkIdType>> line = { { 0, 1, 2 } }, point = { { 4 } };
  EXPECT_EQ(CellsOf(read.Mesh->GetLines()), line);
  EXPECT_EQ(CellsOf(read.Mesh->GetVerts()), point);
  EXPECT_EQ(read.Mesh->GetPointData()->GetNumberOfArrays(), 0);
}

TEST(OBJReader, MalformedFilesAreErrorsNamingTheLine)
{
  const std::string triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  const std::vector<Case> cases = {
    { "", "line 0: the file has no vertices" },
    { "# only a comment\nvt 0 0\n", "has no vertices" },
    { "v 1 2\n", "line 1: a vertex needs three numbers" },
    { "v 0 0 0\nv 1 2 3.1+e2\n", "line 2: a vertex needs three numbers" },
    { triangle + "f 1 2\n", "line 4: a face needs at least 3 corners, this one has 2" },
    { triangle + "f\n", "a face needs at least 3 corners, this one has 0" },
    { triangle + "f 1 2 0\n", "the face corner '0' is not a vertex index" },
    { triangle + "f 1 2 x/1\n", "the face corner 'x/1' is not a vertex index" },
    { triangle + "f 1 2 3x\n", "the face corner '3x' is not a vertex index" },
    { triangle + "f 1 2 -4\n", "line 4: the face corner '-4' counts back past the first vertex" },
    { triangle + "f 1 2 4\nf 1 2 3\n", "line 4: a corner names vertex 4, but the file has 3" },
    { triangle + "l 1\n", "a line needs at least 2 corners" },
    { triangle + "f 1 2 99999999999999999999\n", "is not a vertex index" },
  };
  ExpectRefusals<vtkCVTOBJReader>(cases, "obj");
}
