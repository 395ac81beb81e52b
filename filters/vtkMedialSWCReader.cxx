#include "vtkMedialSWCReader.h"

#include "MedialSkeletonData.h"

#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <fstream>
#include <sstream>
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

// Parses one non-comment line; returns false when it does not hold the seven SWC fields.
bool parseSwcLine(const std::string& text, SwcRecord& r) {
  std::istringstream in(text);
  std::string fields[7];
  for (std::string& f : fields)
    if (!(in >> f)) return false;
  std::string extra;
  if (in >> extra) return false;
  try {
    size_t used = 0;
    auto wholeInteger = [&](const std::string& s) {
      const long v = std::stol(s, &used);
      if (used != s.size()) throw std::invalid_argument(s);
      return v;
    };
    auto wholeReal = [&](const std::string& s) {
      const double v = std::stod(s, &used);  // accepts "nan" and "inf": validation reports them
      if (used != s.size()) throw std::invalid_argument(s);
      return v;
    };
    r.id = wholeInteger(fields[0]);
    r.type = wholeInteger(fields[1]);
    r.x = wholeReal(fields[2]);
    r.y = wholeReal(fields[3]);
    r.z = wholeReal(fields[4]);
    r.radius = wholeReal(fields[5]);
    r.parent = wholeInteger(fields[6]);
  } catch (const std::exception&) {
    return false;
  }
  return true;
}

}  // namespace

int vtkMedialSWCReader::RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector) {
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  if (this->FileName.empty()) {
    vtkErrorMacro(<< "no file name given");
    return 0;
  }
  std::ifstream file(this->FileName);
  if (!file) {
    vtkErrorMacro(<< this->FileName << ": cannot open the file");
    return 0;
  }

  std::vector<SwcRecord> records;
  std::unordered_map<long, int> indexOfId;
  std::string text;
  for (int lineNumber = 1; std::getline(file, text); ++lineNumber) {
    const size_t first = text.find_first_not_of(" \t\r");
    if (first == std::string::npos || text[first] == '#') continue;
    SwcRecord r;
    if (!parseSwcLine(text, r)) {
      vtkErrorMacro(<< this->FileName << ":" << lineNumber
                    << ": expected 'id type x y z radius parent' (7 numbers), got '" << text << "'");
      return 0;
    }
    r.line = lineNumber;
    if (!indexOfId.emplace(r.id, static_cast<int>(records.size())).second) {
      vtkErrorMacro(<< this->FileName << ":" << lineNumber << ": node id " << r.id << " appears twice");
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
      vtkErrorMacro(<< this->FileName << ":" << r.line << ": node " << r.id << " is its own parent (a self-loop)");
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

  const auto problems = medial::validateSkeleton(skeleton);
  if (!problems.empty()) {
    // Name the file line of the first node concerned, when there is one.
    using Kind = medial::SkeletonProblem::Kind;
    const auto& first = problems.front();
    const bool aboutNode = first.kind == Kind::NonFiniteCoordinate || first.kind == Kind::NonPositiveRadius;
    const int node = aboutNode ? first.index : -1;
    vtkErrorMacro(<< this->FileName
                  << (node >= 0 && node < static_cast<int>(records.size()) ? ":" + std::to_string(records[node].line)
                                                                            : std::string())
                  << ": " << medial::describeProblems(problems));
    return 0;
  }

  output->ShallowCopy(medial::polyDataFromSkeleton(skeleton));
  output->GetPointData()->AddArray(swcType);
  return 1;
}
