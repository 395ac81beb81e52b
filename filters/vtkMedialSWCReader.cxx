#include "vtkMedialSWCReader.h"

#include "MedialSkeletonData.h"
#include "MedialTextFile.h"

#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <cmath>
#include <unordered_map>

vtkStandardNewMacro(vtkMedialSWCReader);

vtkMedialSWCReader::vtkMedialSWCReader() { this->SetNumberOfInputPorts(0); }

void vtkMedialSWCReader::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << this->FileName << "\n";
}

namespace {

struct SwcRecord {
  long id, type;
  double x, y, z, radius;
  long parent;
  int line;
};

// Parses one non-comment line; returns false when it does not hold the seven SWC fields (id, type and
// parent whole numbers).
bool parseSwcLine(const std::string& text, SwcRecord& r) {
  std::vector<double> f;
  if (!medial::parseNumbers(text, f) || f.size() != 7) return false;
  for (int whole : {0, 1, 6})
    if (!(std::abs(f[size_t(whole)]) < 1e15) || f[size_t(whole)] != std::floor(f[size_t(whole)]))
      return false;
  r = {long(f[0]), long(f[1]), f[2], f[3], f[4], f[5], long(f[6]), 0};
  return true;
}

}  // namespace

int vtkMedialSWCReader::RequestData(vtkInformation*, vtkInformationVector**,
                                    vtkInformationVector* outputVector) {
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  medial::TextFile file;
  std::string error;
  if (!file.open(this->FileName, error)) {
    vtkErrorMacro(<< error);
    return 0;
  }

  std::vector<SwcRecord> records;
  std::unordered_map<long, int> indexOfId;
  std::string text;
  while (file.nextLine(text)) {
    if (medial::isBlank(text)) continue;
    SwcRecord r;
    if (!parseSwcLine(text, r)) {
      vtkErrorMacro(<< file.where() << "expected 'id type x y z radius parent' (7 numbers), got '" << text
                    << "'");
      return 0;
    }
    r.line = file.lineNumber();
    if (!indexOfId.emplace(r.id, static_cast<int>(records.size())).second) {
      vtkErrorMacro(<< file.where() << "node id " << r.id << " appears twice");
      return 0;
    }
    records.push_back(r);
  }
  if (records.empty()) {
    vtkErrorMacro(<< this->FileName << ": no nodes (an SWC file needs 'id type x y z radius parent' lines)");
    return 0;
  }

  medial::Skeleton skeleton;
  auto swcType = vtkSmartPointer<vtkIntArray>::New();
  swcType->SetName("SWCType");
  for (const SwcRecord& r : records) {
    const int index = static_cast<int>(skeleton.nodes.size());
    skeleton.nodes.emplace_back(r.x, r.y, r.z);
    skeleton.radii.push_back(r.radius);
    swcType->InsertNextValue(static_cast<int>(r.type));
    if (r.parent == -1) {
      if (skeleton.root < 0) skeleton.root = index;
      continue;
    }
    if (r.parent == r.id) {
      vtkErrorMacro(<< this->FileName << ":" << r.line << ": node " << r.id
                    << " is its own parent (a self-loop)");
      return 0;
    }
    const auto parent = indexOfId.find(r.parent);
    if (parent == indexOfId.end()) {
      vtkErrorMacro(<< this->FileName << ":" << r.line << ": parent " << r.parent << " of node " << r.id
                    << " is not a node of the file");
      return 0;
    }
    skeleton.edges.push_back({parent->second, index});
  }

  // SWC describes trees: following parents from any node must reach a root (parent -1). A chain that comes
  // back to itself is a cycle, which the format cannot mean.
  std::vector<int> parentOf(records.size(), -1), state(records.size(), 0);  // 0 new, 1 on the path, 2 done
  for (size_t i = 0; i < records.size(); ++i)
    if (records[i].parent != -1) parentOf[i] = indexOfId.at(records[i].parent);
  for (size_t start = 0; start < records.size(); ++start) {
    std::vector<int> path;
    int k = int(start);
    while (k >= 0 && state[size_t(k)] == 0) {
      state[size_t(k)] = 1;
      path.push_back(k);
      k = parentOf[size_t(k)];
    }
    if (k >= 0 && state[size_t(k)] == 1) {
      vtkErrorMacro(<< this->FileName << ":" << records[size_t(k)].line << ": the parents of node "
                    << records[size_t(k)].id << " lead back to it (a cycle; SWC describes trees)");
      return 0;
    }
    for (int v : path) state[size_t(v)] = 2;
  }

  const auto problems = medial::validateSkeleton(skeleton);
  if (!problems.empty()) {
    // Name the file line of the first node concerned, when there is one.
    using Kind = medial::SkeletonProblem::Kind;
    const auto& first = problems.front();
    const bool aboutNode = first.kind == Kind::NonFiniteCoordinate || first.kind == Kind::NonPositiveRadius;
    const int node = aboutNode ? first.index : -1;
    vtkErrorMacro(<< this->FileName
                  << (node >= 0 && node < static_cast<int>(records.size())
                          ? ":" + std::to_string(records[node].line)
                          : std::string())
                  << ": " << medial::describeProblems(problems));
    return 0;
  }

  output->ShallowCopy(medial::polyDataFromSkeleton(skeleton));
  output->GetPointData()->AddArray(swcType);
  return 1;
}
