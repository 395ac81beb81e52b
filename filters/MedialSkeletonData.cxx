#include "MedialSkeletonData.h"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>

namespace medial {

bool looksLikeSkeleton(vtkPolyData* polyData) {
  return polyData && polyData->GetNumberOfLines() > 0 && polyData->GetNumberOfPolys() == 0 &&
         polyData->GetNumberOfStrips() == 0;
}

bool skeletonFromPolyData(vtkPolyData* polyData, Skeleton& skeleton, std::string& error) {
  skeleton = Skeleton();
  if (!polyData) {
    error = "no skeleton given";
    return false;
  }
  if (polyData->GetNumberOfPolys() > 0 || polyData->GetNumberOfStrips() > 0) {
    error = "the polydata holds polygons; a skeleton has only line cells";
    return false;
  }
  const vtkIdType n = polyData->GetNumberOfPoints();
  skeleton.nodes.resize(n);
  for (vtkIdType i = 0; i < n; ++i) polyData->GetPoint(i, skeleton.nodes[i].data());

  vtkCellArray* lines = polyData->GetLines();
  auto ids = vtkSmartPointer<vtkIdList>::New();
  for (lines->InitTraversal(); lines->GetNextCell(ids);) {
    for (vtkIdType k = 0; k + 1 < ids->GetNumberOfIds(); ++k)
      skeleton.edges.push_back({static_cast<int>(ids->GetId(k)), static_cast<int>(ids->GetId(k + 1))});
    if (ids->GetNumberOfIds() == 1) {
      error = "a line cell has a single point; skeleton edges join two nodes";
      return false;
    }
  }

  if (vtkDataArray* radius = polyData->GetPointData()->GetArray(kRadiusArray)) {
    if (radius->GetNumberOfComponents() != 1) {
      error = "the Radius array has " + std::to_string(radius->GetNumberOfComponents()) +
              " components instead of 1";
      return false;
    }
    skeleton.radii.resize(n);
    for (vtkIdType i = 0; i < n; ++i) skeleton.radii[i] = radius->GetComponent(i, 0);
  }
  if (vtkDataArray* axes = polyData->GetPointData()->GetArray(kEllipsoidAxesArray)) {
    if (axes->GetNumberOfComponents() != 9) {
      error = "the EllipsoidAxes array has " + std::to_string(axes->GetNumberOfComponents()) +
              " components instead of 9";
      return false;
    }
    skeleton.ellipsoidAxes.resize(n);
    for (vtkIdType i = 0; i < n; ++i)
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) skeleton.ellipsoidAxes[i](r, c) = axes->GetComponent(i, 3 * r + c);
  }
  if (vtkDataArray* root = polyData->GetFieldData()->GetArray(kRootField)) {
    if (root->GetNumberOfTuples() > 0) skeleton.root = static_cast<int>(root->GetComponent(0, 0));
  }
  return true;
}

vtkSmartPointer<vtkPolyData> polyDataFromSkeleton(const Skeleton& skeleton) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(skeleton.nodeCount());
  for (int i = 0; i < skeleton.nodeCount(); ++i) points->SetPoint(i, skeleton.nodes[i].data());

  auto lines = vtkSmartPointer<vtkCellArray>::New();
  for (const auto& [a, b] : skeleton.edges) {
    const vtkIdType ids[2] = {a, b};
    lines->InsertNextCell(2, ids);
  }

  auto polyData = vtkSmartPointer<vtkPolyData>::New();
  polyData->SetPoints(points);
  polyData->SetLines(lines);

  if (!skeleton.radii.empty()) {
    auto radius = vtkSmartPointer<vtkDoubleArray>::New();
    radius->SetName(kRadiusArray);
    radius->SetNumberOfValues(skeleton.nodeCount());
    for (int i = 0; i < skeleton.nodeCount(); ++i) radius->SetValue(i, skeleton.radii[i]);
    polyData->GetPointData()->AddArray(radius);
  }
  if (!skeleton.ellipsoidAxes.empty()) {
    auto axes = vtkSmartPointer<vtkDoubleArray>::New();
    axes->SetName(kEllipsoidAxesArray);
    axes->SetNumberOfComponents(9);
    axes->SetNumberOfTuples(skeleton.nodeCount());
    for (int i = 0; i < skeleton.nodeCount(); ++i)
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) axes->SetComponent(i, 3 * r + c, skeleton.ellipsoidAxes[i](r, c));
    polyData->GetPointData()->AddArray(axes);
  }
  auto nodeType = vtkSmartPointer<vtkUnsignedCharArray>::New();
  nodeType->SetName(kNodeTypeArray);
  const std::vector<NodeType> types = classifyNodes(skeleton);
  nodeType->SetNumberOfValues(static_cast<vtkIdType>(types.size()));
  for (size_t i = 0; i < types.size(); ++i) nodeType->SetValue(i, static_cast<unsigned char>(types[i]));
  polyData->GetPointData()->AddArray(nodeType);

  if (skeleton.root >= 0) {
    auto root = vtkSmartPointer<vtkIntArray>::New();
    root->SetName(kRootField);
    root->InsertNextValue(skeleton.root);
    polyData->GetFieldData()->AddArray(root);
  }
  return polyData;
}

std::string describeProblems(const std::vector<SkeletonProblem>& problems) {
  constexpr size_t shown = 3;
  std::string text;
  for (size_t i = 0; i < problems.size() && i < shown; ++i) text += (i ? "; " : "") + problems[i].message;
  if (problems.size() > shown) text += "; and " + std::to_string(problems.size() - shown) + " more";
  return text;
}

}  // namespace medial
