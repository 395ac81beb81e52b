#include "vtkMedialSWCWriter.h"

#include "MedialFileNames.h"
#include "MedialSkeletonData.h"

#include <vtkDataArray.h>
#include <vtkErrorCode.h>
#include <vtkInformation.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <cstdio>
#include <fstream>
#include <iomanip>
#include <queue>

vtkStandardNewMacro(vtkMedialSWCWriter);

void vtkMedialSWCWriter::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << this->FileName << "\n";
  os << indent << "DefaultType: " << this->DefaultType << "\n";
}

int vtkMedialSWCWriter::FillInputPortInformation(int, vtkInformation* info) {
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

namespace {

// Breadth-first order and parent of every node, one tree per component. Returns false on a cycle.
bool orderAsForest(const medial::Skeleton& skeleton, std::vector<int>& order, std::vector<int>& parent) {
  const int n = skeleton.nodeCount();
  std::vector<std::vector<int>> neighbours(n);
  for (const auto& [a, b] : skeleton.edges) {
    neighbours[a].push_back(b);
    neighbours[b].push_back(a);
  }
  parent.assign(n, -2);  // -2: not reached yet
  order.clear();
  auto growFrom = [&](int root) {
    std::queue<int> queue;
    queue.push(root);
    parent[root] = -1;
    while (!queue.empty()) {
      const int v = queue.front();
      queue.pop();
      order.push_back(v);
      for (int w : neighbours[v]) {
        if (w == parent[v]) continue;  // the tree edge back (a repeated edge would reach here twice)
        if (parent[w] != -2) return false;
        parent[w] = v;
        queue.push(w);
      }
    }
    return true;
  };
  if (skeleton.root >= 0 && !growFrom(skeleton.root)) return false;
  for (int v = 0; v < n; ++v)
    if (parent[v] == -2 && !growFrom(v)) return false;
  return true;
}

}  // namespace

void vtkMedialSWCWriter::WriteData() {
  this->SetErrorCode(this->WriteSkeleton() ? vtkErrorCode::NoError : vtkErrorCode::UserError);
}

bool vtkMedialSWCWriter::WriteSkeleton() {
  vtkPolyData* input = vtkPolyData::SafeDownCast(this->GetInput());
  if (this->FileName.empty()) {
    vtkErrorMacro(<< "no file name given");
    return false;
  }
  medial::Skeleton skeleton;
  std::string error;
  if (!input || !medial::skeletonFromPolyData(input, skeleton, error)) {
    vtkErrorMacro(<< this->FileName << ": " << (input ? error : "no input"));
    return false;
  }
  if (skeleton.radii.empty()) {
    vtkErrorMacro(<< this->FileName << ": the skeleton has no Radius array, which SWC requires");
    return false;
  }
  if (const auto problems = medial::validateSkeleton(skeleton); !problems.empty()) {
    vtkErrorMacro(<< this->FileName << ": invalid skeleton: " << medial::describeProblems(problems));
    return false;
  }
  std::vector<int> order, parent;
  if (!orderAsForest(skeleton, order, parent)) {
    vtkErrorMacro(<< this->FileName
                  << ": the skeleton has a cycle; SWC stores only trees (write VTP instead)");
    return false;
  }

  vtkDataArray* swcType = input->GetPointData()->GetArray("SWCType");
  std::vector<int> swcId(skeleton.nodeCount());
  for (size_t k = 0; k < order.size(); ++k) swcId[order[k]] = static_cast<int>(k) + 1;

  const auto write = [&](const std::string& temporary, std::string& why) {
    std::ofstream out(temporary);
    if (!out) {
      why = "cannot write to this location";
      return false;
    }
    out << "# SWC written by Medial: id type x y z radius parent\n" << std::setprecision(17);
    for (int v : order) {
      const auto& p = skeleton.nodes[v];
      const int type = swcType ? static_cast<int>(swcType->GetComponent(v, 0)) : this->DefaultType;
      out << swcId[v] << ' ' << type << ' ' << p.x() << ' ' << p.y() << ' ' << p.z() << ' '
          << skeleton.radii[v] << ' ' << (parent[v] < 0 ? -1 : swcId[parent[v]]) << '\n';
    }
    if (!out.flush()) {
      why = "write failed (disk full?)";
      return false;
    }
    return true;
  };
  if (!medial::writeAtomically(this->FileName, write, error)) {
    vtkErrorMacro(<< this->FileName << ": " << error);
    return false;
  }
  return true;
}
