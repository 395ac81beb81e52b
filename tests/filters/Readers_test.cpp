// vtkMedialReader: every supported kind of input opened by extension, physical coordinates kept, and
// clear errors on bad files.
#include "TestPaths.h"

#include "MedialErrorCollector.h"
#include "MedialSketchData.h"
#include "vtkMedialMeshTopology.h"
#include "vtkMedialReader.h"

#include <vtkBYUWriter.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkMatrix3x3.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <itkImage.h>
#include <itkGDCMImageIO.h>
#include <itkImageFileWriter.h>
#include <itkImageSeriesWriter.h>
#include <itkMetaDataObject.h>

#include <memory>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>

#include <sys/resource.h>

namespace {

using medial::test::externalPath;
using medial::test::scratchDir;

struct ReadResult {
  vtkSmartPointer<vtkDataObject> data;
  std::string error;
};

ReadResult readFile(const std::string& path) {
  auto reader = vtkSmartPointer<vtkMedialReader>::New();
  auto errors = medial::ErrorCollector::Watch(reader);
  reader->SetFileName(path.c_str());
  reader->Update();
  return {reader->GetOutputDataObject(0), errors->HasErrors() ? reader->GetErrorMessage() : ""};
}

void writeText(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

const char* kCubeOff =
    "OFF\n8 6 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
    "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n";

// A 3-D ITK image with a rotated direction, written to `path` (format by extension).
void writeItkImage(const std::string& path) {
  using Image = itk::Image<short, 3>;
  auto image = Image::New();
  Image::RegionType region;
  region.SetSize({{5, 4, 3}});
  image->SetRegions(region);
  image->Allocate();
  short value = 0;
  for (itk::ImageRegionIterator<Image> it(image, region); !it.IsAtEnd(); ++it) it.Set(value++);
  const double spacing[3] = {0.7, 0.8, 2.5};
  const double origin[3] = {-10.0, 20.0, 3.5};
  image->SetSpacing(spacing);
  image->SetOrigin(origin);
  Image::DirectionType direction;  // a rotation of 90° about z
  direction.Fill(0.0);
  direction(0, 1) = -1.0;
  direction(1, 0) = 1.0;
  direction(2, 2) = 1.0;
  image->SetDirection(direction);
  auto writer = itk::ImageFileWriter<Image>::New();
  writer->SetFileName(path);
  writer->SetInput(image);
  writer->Update();
}

// Reads a volume that must read cleanly and have dimensions nx x ny x nz.
vtkImageData* readVolume(const std::string& path, ReadResult& r, int nx, int ny, int nz) {
  r = readFile(path);
  EXPECT_EQ(r.error, "");
  auto* image = vtkImageData::SafeDownCast(r.data);
  if (!image) return nullptr;
  int dims[3];
  image->GetDimensions(dims);
  EXPECT_EQ(dims[0], nx);
  EXPECT_EQ(dims[1], ny);
  EXPECT_EQ(dims[2], nz);
  return image;
}

long peakResidentKiB() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss;
}

}  // namespace

TEST(Readers, OffQuadMeshKeepsItsPolygons) {
  const std::string path = scratchDir("off-quads") + "/cube.off";
  writeText(path, kCubeOff);
  const ReadResult r = readFile(path);
  ASSERT_EQ(r.error, "");
  auto* mesh = vtkPolyData::SafeDownCast(r.data);
  EXPECT_EQ(mesh->GetNumberOfPoints(), 8);
  EXPECT_EQ(mesh->GetNumberOfPolys(), 6);
  EXPECT_EQ(mesh->GetCell(0)->GetNumberOfPoints(), 4);
}

TEST(Readers, OffVariantsCoffAndNoffAreRead) {
  const std::string dir = scratchDir("off-variants");
  writeText(dir + "/colored.off",
            "COFF\n4 4 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1 0 0 0 255 255\n0 0 1 255 255 255 255\n"
            "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n");
  writeText(dir + "/normals.off",
            "NOFF\n4 4 0\n0 0 0 0 0 -1\n1 0 0 1 0 0\n0 1 0 0 1 0\n0 0 1 0 0 1\n"
            "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n");
  const ReadResult colored = readFile(dir + "/colored.off");
  ASSERT_EQ(colored.error, "");
  auto* mesh = vtkPolyData::SafeDownCast(colored.data);
  EXPECT_EQ(mesh->GetNumberOfPolys(), 4);
  vtkDataArray* colors = mesh->GetPointData()->GetScalars();
  ASSERT_NE(colors, nullptr);
  EXPECT_EQ(colors->GetComponent(1, 1), 255);
  EXPECT_EQ(colors->GetComponent(1, 0), 0);

  const ReadResult normals = readFile(dir + "/normals.off");
  ASSERT_EQ(normals.error, "");
  auto* withNormals = vtkPolyData::SafeDownCast(normals.data);
  ASSERT_NE(withNormals->GetPointData()->GetNormals(), nullptr);
  EXPECT_FLOAT_EQ(withNormals->GetPointData()->GetNormals()->GetComponent(3, 2), 1.0f);

  // Comments before the key word and within the data, as CGAL's tools write them (OpenMesh alone reads
  // none of those files).
  writeText(dir + "/commented.off",
            "# Output of a CGAL tool\n#CBP\n\nOFF\n# counts\n4 4 0\n0 0 0 # first\n1 0 0\n0 1 0\n0 0 1\n"
            "3 0 2 1\n3 0 1 3\n# the last two\n3 1 2 3\n3 0 3 2\n");
  const ReadResult commented = readFile(dir + "/commented.off");
  ASSERT_EQ(commented.error, "");
  EXPECT_EQ(vtkPolyData::SafeDownCast(commented.data)->GetNumberOfPoints(), 4);
  EXPECT_EQ(vtkPolyData::SafeDownCast(commented.data)->GetNumberOfPolys(), 4);
}

TEST(Readers, OffNonManifoldFacesAreKept) {
  // Three triangles on one edge: a half-edge mesh would drop one; Medial's algorithms must see them all.
  const std::string path = scratchDir("off-non-manifold") + "/fin.off";
  writeText(path, "OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n");
  const ReadResult r = readFile(path);
  ASSERT_EQ(r.error, "");
  auto topology = vtkSmartPointer<vtkMedialMeshTopology>::New();
  topology->SetInputData(r.data);
  topology->Update();
  EXPECT_EQ(topology->GetNumberOfFaces(), 3);
  EXPECT_EQ(topology->GetNumberOfNonManifoldEdges(), 1);
}

TEST(Readers, CgalSampleMeshesHaveTheirKnownTopology) {
  struct Known {
    const char* name;
    vtkIdType vertices, genus, borderEdges;
  };
  for (const Known& k :
       {Known{"armadillo", 26002, 0, 0}, Known{"elephant", 2775, 3, 0}, Known{"femur", 3897, 2, 0},
        Known{"knot1", 3200, 1, 0}, Known{"mannequin-devil", 12977, 0, 64}}) {
    const std::string path = externalPath(std::string("cgal/meshes/") + k.name + ".off");
    MEDIAL_REQUIRE_FILE(path);
    const ReadResult r = readFile(path);
    ASSERT_EQ(r.error, "") << k.name;
    auto topology = vtkSmartPointer<vtkMedialMeshTopology>::New();
    topology->SetInputData(r.data);
    topology->Update();
    EXPECT_EQ(vtkPolyData::SafeDownCast(r.data)->GetNumberOfPoints(), k.vertices) << k.name;
    EXPECT_EQ(topology->GetGenus(), k.genus) << k.name;
    EXPECT_EQ(topology->GetNumberOfBorderEdges(), k.borderEdges) << k.name;
    EXPECT_EQ(topology->GetNumberOfComponents(), 1) << k.name;
  }
}

TEST(Readers, BundledMeshesAreClosed) {
  for (const char* name : {"meshes/torus.off", "meshes/capsule.vtp"}) {
    const ReadResult r = readFile(medial::test::dataPath(name));
    ASSERT_EQ(r.error, "") << name;
    auto topology = vtkSmartPointer<vtkMedialMeshTopology>::New();
    topology->SetInputData(r.data);
    topology->Update();
    EXPECT_TRUE(topology->GetClosedManifold()) << name;
  }
}

class ItkFormats : public ::testing::TestWithParam<const char*> {};

TEST_P(ItkFormats, KeepOriginSpacingDirectionAndVoxels) {
  const std::string path = scratchDir(std::string("itk") + GetParam()) + "/image" + GetParam();
  writeItkImage(path);
  ReadResult r;
  vtkImageData* image = readVolume(path, r, 5, 4, 3);
  ASSERT_NE(image, nullptr);
  EXPECT_NEAR(image->GetSpacing()[0], 0.7, 1e-6);
  EXPECT_NEAR(image->GetSpacing()[2], 2.5, 1e-6);
  EXPECT_NEAR(image->GetOrigin()[0], -10.0, 1e-6);
  EXPECT_NEAR(image->GetOrigin()[1], 20.0, 1e-6);
  vtkMatrix3x3* direction = image->GetDirectionMatrix();
  EXPECT_NEAR(direction->GetElement(0, 1), -1.0, 1e-6);
  EXPECT_NEAR(direction->GetElement(1, 0), 1.0, 1e-6);
  EXPECT_NEAR(direction->GetElement(0, 0), 0.0, 1e-6);
  EXPECT_EQ(image->GetScalarType(), VTK_SHORT);
  EXPECT_EQ(image->GetScalarComponentAsDouble(4, 3, 2, 0), 59);  // x fastest: 4 + 5 * (3 + 4 * 2)
  // Physical position of voxel (1, 0, 0): origin + direction * (spacing_x, 0, 0).
  double world[3];
  image->TransformIndexToPhysicalPoint(1, 0, 0, world);
  EXPECT_NEAR(world[0], -10.0, 1e-6);
  EXPECT_NEAR(world[1], 20.7, 1e-6);
}

INSTANTIATE_TEST_SUITE_P(Readers, ItkFormats, ::testing::Values(".nii", ".nii.gz", ".mha", ".nrrd"),
                         [](const ::testing::TestParamInfo<const char*>& info) {
                           std::string name = info.param + 1;
                           for (char& c : name)
                             if (c == '.') c = '_';
                           return name;
                         });

TEST(Readers, InrimageThroughCgal) {
  // A 3 x 2 x 2 unsigned-char INRIMAGE written by hand: a 256-byte header, then the voxels.
  std::string header =
      "#INRIMAGE-4#{\nXDIM=3\nYDIM=2\nZDIM=2\nVDIM=1\nTYPE=unsigned fixed\nPIXSIZE=8 bits\nSCALE=2**0\n"
      "CPU=decm\nVX=0.5\nVY=0.75\nVZ=2\n";
  header += std::string(256 - 4 - header.size(), '\n') + "##}\n";
  ASSERT_EQ(header.size(), 256u);
  const std::string path = scratchDir("inr") + "/tiny.inr";
  {
    std::ofstream out(path, std::ios::binary);
    out << header;
    for (int i = 0; i < 12; ++i) out.put(static_cast<char>(10 * i));
  }
  const ReadResult r = readFile(path);
  ASSERT_EQ(r.error, "");
  auto* image = vtkImageData::SafeDownCast(r.data);
  int dims[3];
  image->GetDimensions(dims);
  EXPECT_EQ(dims[0] * dims[1] * dims[2], 12);
  EXPECT_DOUBLE_EQ(image->GetSpacing()[1], 0.75);
  EXPECT_EQ(image->GetScalarType(), VTK_UNSIGNED_CHAR);
  EXPECT_EQ(image->GetScalarComponentAsDouble(2, 1, 1, 0), 110);
}

TEST(Readers, CgalLiverLabelVolume) {
  const std::string path = externalPath("cgal/images/liver.inr.gz");
  MEDIAL_REQUIRE_FILE(path);
  ReadResult r;
  vtkImageData* image = readVolume(path, r, 438, 353, 165);
  ASSERT_NE(image, nullptr);
  EXPECT_NEAR(image->GetSpacing()[0], 0.617, 1e-3);
  EXPECT_NEAR(image->GetSpacing()[2], 1.333, 1e-3);
  double range[2];
  image->GetScalarRange(range);
  EXPECT_EQ(range[1], 255);
}

TEST(Readers, InVesaliusHeadCt) {
  const std::string path = externalPath("invesalius/Cranium.inv3");
  MEDIAL_REQUIRE_FILE(path);
  ReadResult r;
  vtkImageData* image = readVolume(path, r, 256, 256, 108);
  ASSERT_NE(image, nullptr);
  EXPECT_NEAR(image->GetSpacing()[0], 0.957, 1e-3);
  EXPECT_NEAR(image->GetSpacing()[2], 1.5, 1e-9);
  EXPECT_EQ(image->GetScalarType(), VTK_SHORT);
  double range[2];
  image->GetScalarRange(range);
  EXPECT_EQ(range[0], -1024);  // Hounsfield units
  EXPECT_GT(range[1], 2000);   // dental metal
}

TEST(Readers, ByuMesh) {
  // The capsule written by VTK's BYU writer comes back with its points and triangles (glTF: the GUI test
  // reopens an exported rig).
  const ReadResult capsule = readFile(medial::test::dataPath("meshes/capsule.vtp"));
  auto* mesh = vtkPolyData::SafeDownCast(capsule.data);
  ASSERT_NE(mesh, nullptr);
  const std::string dir = scratchDir("readers-byu-gltf");
  auto byu = vtkSmartPointer<vtkBYUWriter>::New();
  byu->SetInputData(mesh);
  byu->SetGeometryFileName((dir + "/capsule.g").c_str());
  byu->Write();
  const ReadResult fromByu = readFile(dir + "/capsule.g");
  ASSERT_TRUE(fromByu.error.empty()) << fromByu.error;
  EXPECT_EQ(vtkPolyData::SafeDownCast(fromByu.data)->GetNumberOfPoints(), mesh->GetNumberOfPoints());
  EXPECT_EQ(vtkPolyData::SafeDownCast(fromByu.data)->GetNumberOfPolys(), mesh->GetNumberOfPolys());
}

// A sketch goes through the one reader like every other format: strokes as closed line cells with their
// 4x4 placements.
TEST(Readers, SketchTextThroughTheOneReader) {
  const ReadResult r = readFile(medial::test::dataPath("sketches/bird.txt"));
  ASSERT_TRUE(r.error.empty()) << r.error;
  auto* strokes = vtkPolyData::SafeDownCast(r.data);
  ASSERT_TRUE(strokes);
  EXPECT_TRUE(medial::isSketch(strokes));
  EXPECT_EQ(strokes->GetNumberOfLines(), 3) << "body and two wings";
  EXPECT_EQ(strokes->GetNumberOfPolys(), 0);
}

// A 60-byte OFF file announcing 10^7 vertices fails at once, without allocating for them.
TEST(Readers, TruncatedOffFailsAtOnce) {
  const std::string path = scratchDir("truncated-off") + "/truncated.off";
  writeText(path, "OFF\n10000000 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  const long peakKiBBefore = peakResidentKiB();
  const ReadResult r = readFile(path);
  EXPECT_LT(peakResidentKiB() - peakKiBBefore, 64L * 1024) << "10^7 points take 114 MiB as floats";
  EXPECT_NE(r.error.find("ends early"), std::string::npos) << r.error;
}

// Every input of the fuzzers' corpora (tests/fuzz/corpus: the seeds and each input that once crashed a
// reader, scripts/fuzz) reads into a result or a clear error through the one reader.
TEST(Readers, FuzzCorpusGivesAResultOrAnError) {
  const std::string dir = scratchDir("fuzz-corpus");
  int files = 0;
  for (const auto& [kind, extension] :
       {std::make_pair("off", ".off"), std::make_pair("swc", ".swc"), std::make_pair("sketch", ".txt")}) {
    const std::filesystem::path corpus = medial::test::sourceDir() + "/tests/fuzz/corpus/" + kind;
    for (const auto& entry : std::filesystem::directory_iterator(corpus)) {
      const std::string copy = dir + "/" + entry.path().stem().string() + extension;
      std::filesystem::copy_file(entry.path(), copy, std::filesystem::copy_options::overwrite_existing);
      const ReadResult r = readFile(copy);
      auto* polyData = vtkPolyData::SafeDownCast(r.data);
      if (r.error.empty()) {
        EXPECT_TRUE(polyData && polyData->GetNumberOfPoints() > 0) << entry.path();
      }
      ++files;
    }
  }
  EXPECT_GE(files, 7);
  // The .inv3 corpus holds main.plist files: each is packed as InVesalius does, with a 4x4x4 int16 matrix.
  for (const auto& entry :
       std::filesystem::directory_iterator(medial::test::sourceDir() + "/tests/fuzz/corpus/inv3")) {
    const std::string project = dir + "/project";
    std::filesystem::remove_all(project);
    std::filesystem::create_directories(project);
    std::filesystem::copy_file(entry.path(), project + "/main.plist");
    writeText(project + "/matrix.dat", std::string(128, '\1'));
    const std::string inv3 = dir + "/" + entry.path().stem().string() + ".inv3";
    ASSERT_EQ(std::system(("tar -czf " + inv3 + " -C " + project + " main.plist matrix.dat").c_str()), 0);
    const ReadResult r = readFile(inv3);
    auto* image = vtkImageData::SafeDownCast(r.data);
    if (r.error.empty()) {
      EXPECT_TRUE(image && image->GetNumberOfPoints() > 0) << entry.path();
    }
    ++files;
  }
}

// The rig importer's corpus (fuzz_rig_import), read as the GUI reads a rig's skeleton and its mesh: a
// result or one error, never a crash (among them an FBX file that trips Assimp's own assertion, which
// aborted the process, and a glTF skin weighting a vertex its mesh does not have).
TEST(Readers, RigImportCorpusGivesAResultOrAnError) {
  const std::string dir = scratchDir("fuzz-rig-corpus");
  int files = 0;
  for (const auto& entry :
       std::filesystem::directory_iterator(medial::test::sourceDir() + "/tests/fuzz/corpus/rig_import")) {
    std::ifstream in(entry.path(), std::ios::binary);
    char start[4] = {0, 0, 0, 0};
    in.read(start, 4);
    const std::string extension = std::string(start, 4) == "glTF" ? ".glb"
                                  : start[0] == '{'               ? ".gltf"
                                                                  : ".fbx";
    const std::string copy = dir + "/" + entry.path().stem().string() + extension;
    std::filesystem::copy_file(entry.path(), copy, std::filesystem::copy_options::overwrite_existing);
    for (const bool skeleton : {true, false}) {
      auto reader = vtkSmartPointer<vtkMedialReader>::New();
      auto errors = medial::ErrorCollector::Watch(reader);
      reader->SetFileName(copy.c_str());
      reader->SetRigSkeleton(skeleton);
      reader->Update();
      auto* polyData = vtkPolyData::SafeDownCast(reader->GetOutputDataObject(0));
      if (!errors->HasErrors()) {
        EXPECT_TRUE(polyData && polyData->GetNumberOfPoints() > 0) << entry.path();
      } else {
        EXPECT_EQ(errors->GetErrors().size(), 1u) << errors->Joined();
      }
    }
    ++files;
  }
  EXPECT_GE(files, 5);
}

// A volume header that claims more voxels than its file holds, or than any memory, is refused at once,
// before anything is allocated.
TEST(Readers, VolumeHeadersClaimingTooManyVoxelsAreRefused) {
  const std::string dir = scratchDir("huge-volumes");
  const std::string header = "ObjectType = Image\nNDims = 3\nElementType = MET_UCHAR\n";
  writeText(dir + "/4gb.mha",
            header + "DimSize = 2000 2000 1000\nElementDataFile = LOCAL\n" + std::string(100, '\1'));
  writeText(dir + "/petabyte.mha", header + "DimSize = 100000 100000 100000\nElementDataFile = LOCAL\n");
  // The peak resident size, not a time, shows nothing was allocated: a time limit failed on a loaded CI
  // machine (3.2 s under AddressSanitizer beside another test, 9 ms alone).
  const long peakKiBBefore = peakResidentKiB();
  const ReadResult fourGb = readFile(dir + "/4gb.mha");
  EXPECT_NE(fourGb.error.find("the header claims 4.0 GB of voxels, the file holds"), std::string::npos)
      << fourGb.error;
  const ReadResult petabyte = readFile(dir + "/petabyte.mha");
  EXPECT_NE(petabyte.error.find("GB of memory"), std::string::npos) << petabyte.error;
  EXPECT_LT(peakResidentKiB() - peakKiBBefore, 256L * 1024);
}

TEST(Readers, ClearErrorsOnBadFiles) {
  const std::string dir = scratchDir("bad-files");
  writeText(dir + "/garbage.vtp", "this is not XML at all\n");
  writeText(dir + "/garbage.off", "OFF\n3 1 0\n0 0 0\n1 0\n");
  writeText(dir + "/bad-index.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n");
  // A truncated download: 10^7 vertices announced in a 60-byte file (OpenMesh spun for minutes on it).
  writeText(dir + "/truncated.off", "OFF\n10000000 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  writeText(dir + "/huge.off", "OFF\n3 1 0\n# a comment line\n0 0 1e300\n1 0 0\n0 1 0\n3 0 1 2\n");
  writeText(dir + "/negative.off", "OFF\n-3 1 0\n0 0 0\n");
  writeText(dir + "/empty.obj", "# no geometry\n");
  writeText(dir + "/garbage.nii", "not an image");
  writeText(dir + "/garbage.inv3", "not a tar");
  writeText(dir + "/notes.txt", "hello");  // a sketch file whose first line is no stroke point
  writeText(dir + "/notes.docx", "hello");
  struct Case {
    std::string path, expected;
  };
  for (const Case& c :
       {Case{dir + "/missing.off", "no such file"}, Case{dir + "/notes.docx", "unsupported file type"},
        Case{dir + "/notes.txt", "notes.txt:1: expected 'x y'"}, Case{dir + "/garbage.vtp", ""},
        Case{dir + "/garbage.off", "the file ends early (3 vertices and 1 faces announced"},
        Case{dir + "/truncated.off", "the file ends early (10000000 vertices and 1 faces announced"},
        Case{dir + "/huge.off", "huge.off:4: the number 1e300 is not finite or too large"},
        Case{dir + "/negative.off", "announces -3 vertices"},
        Case{dir + "/bad-index.off", "bad-index.off:6: face 0 refers to vertex 7, which does not exist"},
        Case{dir + "/empty.obj", "holds no mesh"}, Case{dir + "/garbage.nii", ""},
        Case{dir + "/garbage.inv3", "not an InVesalius project"}}) {
    const ReadResult r = readFile(c.path);
    EXPECT_FALSE(r.error.empty()) << c.path;
    EXPECT_NE(r.error.find(c.path), std::string::npos) << r.error;
    EXPECT_NE(r.error.find(c.expected), std::string::npos) << r.error;
    EXPECT_EQ(r.error.find("ERROR: In"), std::string::npos) << "VTK's prefix leaked: " << r.error;
  }
}

TEST(Readers, DicomSeriesDirectory) {
  // Writes a 6 x 5 x 4 CT-like volume as four DICOM slices with their positions, then reads the folder.
  using Volume = itk::Image<short, 3>;
  using Slice = itk::Image<short, 2>;
  auto volume = Volume::New();
  Volume::RegionType region;
  region.SetSize({{6, 5, 4}});
  volume->SetRegions(region);
  volume->Allocate();
  short value = -1000;
  for (itk::ImageRegionIterator<Volume> it(volume, region); !it.IsAtEnd(); ++it) it.Set(value += 7);
  const double spacing[3] = {0.7, 0.7, 1.25};
  const double origin[3] = {-20.0, 15.0, 100.0};
  volume->SetSpacing(spacing);
  volume->SetOrigin(origin);

  const std::string dir = scratchDir("dicom-series");
  auto io = itk::GDCMImageIO::New();
  std::vector<std::string> files;
  itk::ImageSeriesWriter<Volume, Slice>::DictionaryArrayType dictionaries;
  std::vector<std::unique_ptr<itk::MetaDataDictionary>> owned;
  for (int z = 0; z < 4; ++z) {
    owned.push_back(std::make_unique<itk::MetaDataDictionary>());
    itk::MetaDataDictionary& d = *owned.back();
    itk::EncapsulateMetaData<std::string>(d, "0008|0060", "CT");
    itk::EncapsulateMetaData<std::string>(d, "0020|000d", "1.2.826.0.1.3680043.2.1125.1");
    itk::EncapsulateMetaData<std::string>(d, "0020|000e", "1.2.826.0.1.3680043.2.1125.1.2");
    itk::EncapsulateMetaData<std::string>(d, "0020|0013", std::to_string(z + 1));
    itk::EncapsulateMetaData<std::string>(d, "0020|0037", "1\\0\\0\\0\\1\\0");
    itk::EncapsulateMetaData<std::string>(d, "0020|0032", "-20\\15\\" + std::to_string(100.0 + 1.25 * z));
    itk::EncapsulateMetaData<std::string>(d, "0028|0030", "0.7\\0.7");
    itk::EncapsulateMetaData<std::string>(d, "0018|0050", "1.25");
    dictionaries.push_back(&d);
    files.push_back(dir + "/slice" + std::to_string(z) + ".dcm");
  }
  auto writer = itk::ImageSeriesWriter<Volume, Slice>::New();
  writer->SetInput(volume);
  writer->SetImageIO(io);
  writer->SetFileNames(files);
  writer->SetMetaDataDictionaryArray(&dictionaries);
  writer->Update();

  ReadResult r;
  vtkImageData* image = readVolume(dir, r, 6, 5, 4);
  ASSERT_NE(image, nullptr);
  EXPECT_NEAR(image->GetSpacing()[0], 0.7, 1e-4);
  EXPECT_NEAR(image->GetSpacing()[2], 1.25, 1e-4);
  EXPECT_NEAR(image->GetOrigin()[0], -20.0, 1e-4);
  EXPECT_NEAR(image->GetOrigin()[2], 100.0, 1e-4);
  EXPECT_EQ(image->GetScalarComponentAsDouble(5, 4, 3, 0), -1000 + 7 * 120);  // the last voxel
}
