// vtkCVTOFFReader: the OFF variants met in public mesh collections read to the same polygons,
// and every malformed file is a clear error naming its line, with an empty output.
#include "vtkCVTOFFReader.h"

#include "vtkCellArray.h"
#include "vtkExecutive.h"
#include "vtkIdList.h"
#include "vtkNew.h"
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

/// Writes `text` to a fresh file and removes it again.
class OffFile
{
public:
  explicit OffFile(const std::string& text)
    : Path(testing::TempDir() + "cvt_off_" + std::to_string(getpid()) + "_" +
        std::to_string(Count++) + ".off")
  {
    std::ofstream(this->Path) << text;
  }
  ~OffFile() { std::remove(this->Path.c_str()); }
  const std::string Path;

private:
  static int Count;
};
int OffFile::Count = 0;

struct Read
{
  vtkSmartPointer<vtkPolyData> Mesh;
  int Status = 0;
  std::string Errors;
};

Read ReadOff(const std::string& path)
{
  vtkNew<vtkCVTOFFReader> reader;
  vtkNew<cvttest::Messages> messages;
  reader->AddObserver(vtkCommand::ErrorEvent, messages);
  reader->SetFileName(path.c_str());
  Read result;
  result.Status = reader->GetExecutive()->Update();
  result.Mesh = reader->GetOutput();
  result.Errors = messages->Errors;
  return result;
}

/// The faces of a mesh as lists of point ids.
std::vector<std::vector<vtkIdType>> Faces(vtkPolyData* mesh)
{
  std::vector<std::vector<vtkIdType>> faces;
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    mesh->GetCellPoints(c, ids);
    faces.emplace_back(ids->begin(), ids->end());
  }
  return faces;
}

// A unit square pyramid: four triangles and a quad.
const std::vector<std::vector<vtkIdType>> PyramidFaces = { { 0, 1, 2, 3 }, { 0, 4, 1 }, { 1, 4, 2 },
  { 2, 4, 3 }, { 3, 4, 0 } };

void ExpectPyramid(const Read& read)
{
  ASSERT_EQ(read.Status, 1) << read.Errors;
  EXPECT_EQ(read.Errors, "");
  ASSERT_EQ(read.Mesh->GetNumberOfPoints(), 5);
  EXPECT_EQ(read.Mesh->GetNumberOfPolys(), 5);
  EXPECT_EQ(read.Mesh->GetPoints()->GetDataType(), VTK_DOUBLE);
  const double expected[5][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 },
    { 0.5, 0.5, 0.7071067811865476 } };
  for (int i = 0; i < 5; ++i)
  {
    double x[3];
    read.Mesh->GetPoint(i, x);
    for (int k = 0; k < 3; ++k)
    {
      EXPECT_EQ(x[k], expected[i][k]) << "point " << i;
    }
  }
  EXPECT_EQ(Faces(read.Mesh), PyramidFaces);
}

} // namespace

TEST(OFFReader, ReadsPlainOffWithCommentsAndCountsOnTheirOwnLine)
{
  OffFile file("OFF\n# a pyramid\n\n5 5 8\n0 0 0\n1 0 0\n1 1 0  # corner\n0 1 0\n"
               "0.5 0.5 0.7071067811865476\n4 0 1 2 3\n3 0 4 1\n3 1 4 2\n3 2 4 3\n3 3 4 0\n");
  ExpectPyramid(ReadOff(file.Path));
}

TEST(OFFReader, ReadsCountsOnTheKeywordLineAndSkipsColoursAndNormals)
{
  // CGAL writes "OFF n f e" on one line; COFF and NOFF add numbers per vertex, and faces may
  // carry a colour.
  OffFile counts("OFF 5 5 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 0.5 0.7071067811865476\n"
                 "4 0 1 2 3 255 0 0\n3 0 4 1 0.5 0.5 0.5 1\n3 1 4 2\n3 2 4 3\n3 3 4 0\n");
  ExpectPyramid(ReadOff(counts.Path));
  OffFile cnoff("CNOFF\r\n5 5 8\r\n0 0 0 0 0 -1 255 0 0 255\r\n1 0 0 0 0 -1 0 255 0 255\r\n"
                "1 1 0 0 0 -1 0 0 255 255\r\n0 1 0 0 0 -1 9 9 9 255\r\n"
                "0.5 0.5 0.7071067811865476 0 0 1 1 1 1 255\r\n4 0 1 2 3\r\n3 0 4 1\r\n"
                "3 1 4 2\r\n3 2 4 3\r\n3 3 4 0\r\n");
  ExpectPyramid(ReadOff(cnoff.Path));
  OffFile noKeyword("5 5 8\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 0.5 0.7071067811865476\n"
                    "4 0 1 2 3\n3 0 4 1\n3 1 4 2\n3 2 4 3\n3 3 4 0\n");
  ExpectPyramid(ReadOff(noKeyword.Path));
}

TEST(OFFReader, MalformedFilesAreErrorsNamingTheLine)
{
  const std::string vertices = "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 0.5 0.7\n";
  const std::string faces = "4 0 1 2 3\n3 0 4 1\n3 1 4 2\n3 2 4 3\n3 3 4 0\n";
  struct Case
  {
    std::string Text, Expected;
  };
  const Case cases[] = {
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
  for (const Case& c : cases)
  {
    OffFile file(c.Text);
    const Read read = ReadOff(file.Path);
    EXPECT_EQ(read.Status, 0) << c.Text;
    EXPECT_NE(read.Errors.find(c.Expected), std::string::npos)
      << "file:\n"
      << c.Text << "\nerror: " << read.Errors;
    EXPECT_EQ(read.Mesh->GetNumberOfPoints(), 0) << c.Text;
    EXPECT_EQ(read.Mesh->GetNumberOfCells(), 0) << c.Text;
  }
  const Read missing = ReadOff(testing::TempDir() + "no_such_file.off");
  EXPECT_EQ(missing.Status, 0);
  EXPECT_NE(missing.Errors.find("Cannot open"), std::string::npos) << missing.Errors;
  vtkNew<vtkCVTOFFReader> unnamed;
  vtkNew<cvttest::Messages> messages;
  unnamed->AddObserver(vtkCommand::ErrorEvent, messages);
  EXPECT_EQ(unnamed->GetExecutive()->Update(), 0);
  EXPECT_NE(messages->Errors.find("No FileName"), std::string::npos) << messages->Errors;
}
