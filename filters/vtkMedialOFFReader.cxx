#include "vtkMedialOFFReader.h"

#include "MedialTextFile.h"

#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>

#include <OpenMesh/Core/IO/IOManager.hh>
#include <OpenMesh/Core/IO/importer/BaseImporter.hh>

#include <unistd.h>

#include <cctype>
#include <cmath>
#include <cstdint>
#include <limits>
#include <filesystem>
#include <iterator>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkMedialOFFReader);

vtkMedialOFFReader::vtkMedialOFFReader() { this->SetNumberOfInputPorts(0); }

void vtkMedialOFFReader::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << this->FileName << "\n";
}

namespace {

using namespace OpenMesh;

// An OpenMesh importer that records the polygon soup as read, instead of a half-edge mesh (which would
// drop non-manifold faces). Only the calls OFF reading makes do anything.
class PolygonSoupImporter : public IO::BaseImporter {
 public:
  std::vector<Vec3d> points;
  std::vector<Vec3uc> colors;
  std::vector<Vec3f> normals;
  std::vector<std::vector<int>> faces;
  bool badFace = false;
  size_t facesSeen = 0;  // bad ones included

  VertexHandle add_vertex(const Vec3f& p) override { return add_vertex(Vec3d(p[0], p[1], p[2])); }
  VertexHandle add_vertex(const Vec3d& p) override {
    points.push_back(p);
    return VertexHandle(static_cast<int>(points.size()) - 1);
  }
  VertexHandle add_vertex() override { return add_vertex(Vec3d(0, 0, 0)); }
  FaceHandle add_face(const VHandles& handles) override {
    ++facesSeen;
    std::vector<int> face;
    for (const VertexHandle& h : handles) {
      if (!h.is_valid() || h.idx() >= static_cast<int>(points.size())) {
        badFace = true;
        return FaceHandle();
      }
      face.push_back(h.idx());
    }
    faces.push_back(std::move(face));
    return FaceHandle(static_cast<int>(faces.size()) - 1);
  }
  void set_point(VertexHandle v, const Vec3f& p) override { points.at(v.idx()) = Vec3d(p[0], p[1], p[2]); }
  void set_normal(VertexHandle v, const Vec3f& n) override { normalAt(v) = n; }
  void set_normal(VertexHandle v, const Vec3d& n) override { normalAt(v) = Vec3f(n[0], n[1], n[2]); }
  void set_color(VertexHandle v, const Vec3uc& c) override { colorAt(v) = c; }
  void set_color(VertexHandle v, const Vec4uc& c) override { colorAt(v) = Vec3uc(c[0], c[1], c[2]); }
  void set_color(VertexHandle v, const Vec3f& c) override { colorAt(v) = toBytes(c[0], c[1], c[2]); }
  void set_color(VertexHandle v, const Vec4f& c) override { colorAt(v) = toBytes(c[0], c[1], c[2]); }

  // Everything below is not produced by OFF files (or not kept by Medial).
  HalfedgeHandle add_edge(VertexHandle, VertexHandle) override { return HalfedgeHandle(); }
  FaceHandle add_face(HalfedgeHandle) override { return FaceHandle(); }
  void add_face_texcoords(FaceHandle, VertexHandle, const std::vector<Vec2f>&) override {}
  void add_face_texcoords(FaceHandle, VertexHandle, const std::vector<Vec3f>&) override {}
  void set_face_texindex(FaceHandle, int) override {}
  void set_halfedge(VertexHandle, HalfedgeHandle) override {}
  void set_texcoord(VertexHandle, const Vec2f&) override {}
  void set_status(VertexHandle, const Attributes::StatusInfo&) override {}
  void set_next(HalfedgeHandle, HalfedgeHandle) override {}
  void set_face(HalfedgeHandle, FaceHandle) override {}
  void request_face_texcoords2D() override {}
  void set_texcoord(HalfedgeHandle, const Vec2f&) override {}
  void set_texcoord(VertexHandle, const Vec3f&) override {}
  void set_texcoord(HalfedgeHandle, const Vec3f&) override {}
  void set_status(HalfedgeHandle, const Attributes::StatusInfo&) override {}
  void set_color(EdgeHandle, const Vec3uc&) override {}
  void set_color(EdgeHandle, const Vec4uc&) override {}
  void set_color(EdgeHandle, const Vec3f&) override {}
  void set_color(EdgeHandle, const Vec4f&) override {}
  void set_status(EdgeHandle, const Attributes::StatusInfo&) override {}
  void set_normal(FaceHandle, const Vec3f&) override {}
  void set_normal(FaceHandle, const Vec3d&) override {}
  void set_color(FaceHandle, const Vec3uc&) override {}
  void set_color(FaceHandle, const Vec4uc&) override {}
  void set_color(FaceHandle, const Vec3f&) override {}
  void set_color(FaceHandle, const Vec4f&) override {}
  void set_status(FaceHandle, const Attributes::StatusInfo&) override {}
  void add_texture_information(int, std::string) override {}
  size_t n_vertices() const override { return points.size(); }
  size_t n_faces() const override { return faces.size(); }
  size_t n_edges() const override { return 0; }

 private:
  static Vec3uc toBytes(float r, float g, float b) {
    auto byte = [](float x) { return static_cast<unsigned char>(std::clamp(x, 0.f, 1.f) * 255.f + 0.5f); };
    return Vec3uc(byte(r), byte(g), byte(b));
  }
  Vec3uc& colorAt(VertexHandle v) {
    colors.resize(points.size(), Vec3uc(255, 255, 255));
    return colors.at(v.idx());
  }
  Vec3f& normalAt(VertexHandle v) {
    normals.resize(points.size(), Vec3f(0, 0, 0));
    return normals.at(v.idx());
  }
};

// An ASCII OFF file's text without its comments ('#' to the end of a line) and blank lines: OpenMesh reads
// none of CGAL's OFF files that open with a comment block (cube_poly, sphere966, mesh_with_colors...).
// `lines` gets the file's line number of each line kept.
std::string withoutComments(medial::TextFile& file, std::vector<int>& lines) {
  std::string text;
  for (std::string line; file.nextLine(line);) {
    if (medial::isBlank(line)) continue;
    text += line + "\n";
    lines.push_back(file.lineNumber());
  }
  return text;
}

// What OpenMesh cannot be trusted with in an ASCII OFF text, checked line by line before it reads (one
// vertex and one face per line, as every OFF writer does): counts that are not whole numbers or are
// negative, fewer lines than the counts announce (OpenMesh then loops over the missing ones: a truncated
// download announcing 10^7 vertices took minutes), coordinates that do not fit the single precision
// OpenMesh reads them in (it then loses its place and blames the faces), and faces whose size or indices
// are wrong (a face announcing 10^9 corners made it allocate gigabytes). Empty when the text is fit to
// read; otherwise the problem, with the file's line.
std::string checkAsciiOff(const std::string& text, const std::vector<int>& lineNumbers,
                          const std::string& fileName, long long& vertices, long long& faces,
                          std::string& canonical) {
  std::vector<std::vector<std::string>> lines;
  std::vector<int> numbers;  // the file's line of each (lines of other whitespace, \f or \v, drop out here)
  std::istringstream in(text);
  size_t index = 0;
  for (std::string line; std::getline(in, line); ++index) {
    std::istringstream words(line);
    std::vector<std::string> tokens{std::istream_iterator<std::string>(words),
                                    std::istream_iterator<std::string>()};
    if (tokens.empty()) continue;  // fuzz_off under UBSan: a line of \v indexed an empty list
    lines.push_back(std::move(tokens));
    numbers.push_back(lineNumbers[index]);
  }
  const auto at = [&](size_t line) { return fileName + ":" + std::to_string(numbers[line]) + ": "; };
  const auto whole = [](const std::string& word, long long& value) {
    char* end = nullptr;
    value = std::strtoll(word.c_str(), &end, 10);
    return end != word.c_str() && *end == '\0';
  };
  // The key word, then the counts "V F [E]" on its line or the next.
  if (lines.empty() || lines[0].empty()) return fileName + ": the file is empty";
  if (lines[0][0].find("OFF") == std::string::npos) return at(0) + "the file does not start with OFF";
  if (lines[0][0].find('n') != std::string::npos)
    return at(0) + "nOFF (points of any dimension) is not supported; write the mesh as OFF, PLY or STL";
  size_t line = 0, word = 1;
  if (lines[0].size() == 1) line = 1, word = 0;
  if (line >= lines.size() || lines[line].size() < word + 2 || !whole(lines[line][word], vertices) ||
      !whole(lines[line][word + 1], faces))
    return at(std::min(line, lines.size() - 1)) + "the header's vertex and face counts are not whole numbers";
  if (vertices < 0 || faces < 0)
    return at(line) + "the header announces " + std::to_string(vertices) + " vertices and " +
           std::to_string(faces) + " faces";
  const size_t first = line + 1;
  if (double(lines.size() - first) < double(vertices) + double(faces))
    return fileName + ": the file ends early (" + std::to_string(vertices) + " vertices and " +
           std::to_string(faces) + " faces announced, " + std::to_string(lines.size() - first) +
           " lines follow the header)";
  for (long long v = 0; v < vertices; ++v) {
    const size_t l = first + size_t(v);
    for (size_t k = 0; k < 3; ++k) {
      char* end = nullptr;
      const bool present = k < lines[l].size();
      const double value = present ? std::strtod(lines[l][k].c_str(), &end) : 0;
      if (!present || end == lines[l][k].c_str() || *end != '\0')
        return at(l) + "vertex " + std::to_string(v) + " needs three coordinates";
      if (!(std::abs(value) <= std::numeric_limits<float>::max()))
        return at(l) + "the number " + lines[l][k] + " is not finite or too large for OFF's single precision";
    }
  }
  for (long long f = 0; f < faces; ++f) {
    const size_t l = first + size_t(vertices + f);
    long long corners = 0;
    if (!whole(lines[l][0], corners) || corners < 1 || size_t(corners) >= lines[l].size())
      return at(l) + "face " + std::to_string(f) + " does not list the " + lines[l][0] +
             " corners it announces";
    for (size_t k = 1; k <= size_t(corners); ++k) {
      long long index = 0;
      if (!whole(lines[l][k], index) || index < 0 || index >= vertices)
        return at(l) + "face " + std::to_string(f) + " refers to vertex " + lines[l][k] +
               ", which does not exist";
    }
  }
  // What OpenMesh reads: the key word alone, the counts alone, then exactly the lines they announce, a
  // face as its corners only (it misreads anything else: fuzz_off found a counts line ending in "0FF" and
  // a face followed by 8888830, which it took for colour data, that made it loop; face colours are not
  // kept anyway).
  std::ostringstream out;
  out << lines[0][0] << "\n" << vertices << " " << faces << " 0\n";
  for (size_t l = first; l < first + size_t(vertices + faces); ++l) {
    const bool face = l >= first + size_t(vertices);
    const size_t words = face ? size_t(std::stoll(lines[l][0])) + 1 : lines[l].size();
    for (size_t w = 0; w < words; ++w) out << (w ? " " : "") << lines[l][w];
    out << "\n";
  }
  canonical = out.str();
  return std::string();
}

// Binary OFF ("OFF BINARY" and its variants) is refused: OpenMesh's binary reader trusts the counts it
// reads, without checking for the end of the file, and reads them in an order of bytes that does not
// match the big-endian files of the format's description (fuzz_off found files that hang it). A file is
// binary when its first line, as written or without its comment, says BINARY (fuzz_off: a comment hid it from
// one of the two).
bool isBinaryOff(const std::string& path, const std::string& text) {
  std::ifstream in(path, std::ios::binary);
  std::string firstLine;
  std::getline(in, firstLine);
  return firstLine.find("BINARY") != std::string::npos ||
         text.substr(0, text.find('\n')).find("BINARY") != std::string::npos;
}

}  // namespace

int vtkMedialOFFReader::RequestData(vtkInformation*, vtkInformationVector**,
                                    vtkInformationVector* outputVector) {
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  medial::TextFile file;
  std::string error;
  if (!file.open(this->FileName, error)) {
    vtkErrorMacro(<< error);
    return 0;
  }

  PolygonSoupImporter soup;
  IO::Options options = IO::Options::VertexColor | IO::Options::VertexNormal;
  omerr().disable();  // OpenMesh would print its own complaints; ours name the file
  std::vector<int> lines;
  const std::string text = withoutComments(file, lines);
  long long vertices = 0, faces = 0;
  const bool ascii = !isBinaryOff(this->FileName, text);
  std::string canonical;
  error = ascii ? checkAsciiOff(text, lines, this->FileName, vertices, faces, canonical)
                : this->FileName + ": binary OFF is not supported; write the mesh as ASCII OFF, PLY or STL";
  if (!error.empty()) {
    omerr().enable();
    vtkErrorMacro(<< error);
    return 0;
  }
  // An ASCII file is read from its canonical copy (OpenMesh reads colours and normals only from a file,
  // not from a stream).
  std::string path = this->FileName;
  if (ascii) {
    path = (std::filesystem::temp_directory_path() /
            ("medial-off-" + std::to_string(::getpid()) + "-" + std::to_string(uintptr_t(this)) + ".off"))
               .string();
    std::ofstream(path) << canonical;
  }
  const bool ok = IO::IOManager().read(path, soup, options);
  if (path != this->FileName) std::filesystem::remove(path);
  omerr().enable();
  if (!ok) {
    vtkErrorMacro(<< this->FileName << ": not a readable OFF file");
    return 0;
  }
  // OpenMesh reads a file that ends early without complaint, and what it makes of the missing numbers
  // is whatever was in memory: hold it to the counts the header announced.
  if (ascii && ((long long)soup.points.size() < vertices || (long long)soup.facesSeen < faces)) {
    vtkErrorMacro(<< this->FileName << ": the file ends early (" << vertices << " vertices and " << faces
                  << " faces announced, " << soup.points.size() << " and " << soup.facesSeen << " read)");
    return 0;
  }
  if (soup.badFace) {
    vtkErrorMacro(<< this->FileName << ": a face refers to a vertex that does not exist");
    return 0;
  }
  if (soup.points.empty()) {
    vtkErrorMacro(<< this->FileName << ": the mesh has no vertices");
    return 0;
  }
  this->UpdateProgress(0.7);

  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(soup.points.size()));
  for (size_t i = 0; i < soup.points.size(); ++i) points->SetPoint(i, soup.points[i].data());

  auto polys = vtkSmartPointer<vtkCellArray>::New();
  polys->AllocateEstimate(static_cast<vtkIdType>(soup.faces.size()), 3);
  std::vector<vtkIdType> ids;
  for (const auto& face : soup.faces) {
    ids.assign(face.begin(), face.end());
    polys->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
  }
  output->SetPoints(points);
  output->SetPolys(polys);

  if (options.vertex_has_color() && soup.colors.size() == soup.points.size()) {
    auto colors = vtkSmartPointer<vtkUnsignedCharArray>::New();
    colors->SetName("Colors");
    colors->SetNumberOfComponents(3);
    colors->SetNumberOfTuples(static_cast<vtkIdType>(soup.colors.size()));
    for (size_t i = 0; i < soup.colors.size(); ++i)
      for (int c = 0; c < 3; ++c) colors->SetComponent(i, c, soup.colors[i][c]);
    output->GetPointData()->SetScalars(colors);
  }
  if (options.vertex_has_normal() && soup.normals.size() == soup.points.size()) {
    auto normals = vtkSmartPointer<vtkFloatArray>::New();
    normals->SetName("Normals");
    normals->SetNumberOfComponents(3);
    normals->SetNumberOfTuples(static_cast<vtkIdType>(soup.normals.size()));
    for (size_t i = 0; i < soup.normals.size(); ++i) normals->SetTypedTuple(i, soup.normals[i].data());
    output->GetPointData()->SetNormals(normals);
  }
  this->UpdateProgress(1.0);
  return 1;
}
