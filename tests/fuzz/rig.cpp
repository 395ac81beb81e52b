// Fuzz target: vtkMedialRigWriter's checks of what it is given. The input describes a skeleton (nodes,
// radii, edges, root) and the skinning weights of a tetrahedron's four vertices; the writer must refuse
// what is invalid with an error, write the rest, and never crash.
#include "vtkMedialRigWriter.h"

#include <fuzzer/FuzzedDataProvider.h>
#include <unistd.h>

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkObject.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <array>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  vtkObject::GlobalWarningDisplayOff();
  FuzzedDataProvider in(data, size);
  // The skeleton: up to 12 nodes, up to 16 edges (any ids, also out of range), radii and a root.
  auto skeleton = vtkSmartPointer<vtkPolyData>::New();
  auto nodes = vtkSmartPointer<vtkPoints>::New();
  auto radius = vtkSmartPointer<vtkDoubleArray>::New();
  radius->SetName("Radius");
  const int nodeCount = in.ConsumeIntegralInRange(0, 12);
  for (int i = 0; i < nodeCount; ++i) {
    nodes->InsertNextPoint(in.ConsumeFloatingPoint<double>(), in.ConsumeFloatingPoint<double>(),
                           in.ConsumeFloatingPoint<double>());
    radius->InsertNextValue(in.ConsumeFloatingPoint<double>());
  }
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  const int edgeCount = in.ConsumeIntegralInRange(0, 16);
  for (int e = 0; e < edgeCount; ++e) {
    const vtkIdType ids[2] = {in.ConsumeIntegralInRange<vtkIdType>(-1, 13),
                              in.ConsumeIntegralInRange<vtkIdType>(-1, 13)};
    lines->InsertNextCell(2, ids);
  }
  skeleton->SetPoints(nodes);
  skeleton->SetLines(lines);
  if (in.ConsumeBool()) skeleton->GetPointData()->AddArray(radius);
  if (in.ConsumeBool()) {
    auto root = vtkSmartPointer<vtkIntArray>::New();
    root->SetName("Root");
    root->InsertNextValue(in.ConsumeIntegralInRange(-2, 14));
    skeleton->GetFieldData()->AddArray(root);
  }
  // The mesh: a tetrahedron with SkinWeights of any number of components and any values.
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  auto corners = vtkSmartPointer<vtkPoints>::New();
  for (const auto& p : {std::array<double, 3>{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}})
    corners->InsertNextPoint(p.data());
  auto faces = vtkSmartPointer<vtkCellArray>::New();
  for (auto f : {std::array<vtkIdType, 3>{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}})
    faces->InsertNextCell(3, f.data());
  mesh->SetPoints(corners);
  mesh->SetPolys(faces);
  auto weights = vtkSmartPointer<vtkDoubleArray>::New();
  weights->SetName("SkinWeights");
  weights->SetNumberOfComponents(in.ConsumeIntegralInRange(1, 18));
  weights->SetNumberOfTuples(in.ConsumeBool() ? 4 : in.ConsumeIntegralInRange(0, 6));
  for (vtkIdType v = 0; v < weights->GetNumberOfTuples(); ++v)
    for (int c = 0; c < weights->GetNumberOfComponents(); ++c)
      weights->SetComponent(v, c, in.ConsumeFloatingPoint<double>());
  mesh->GetPointData()->AddArray(weights);

  const std::string path =
      "/tmp/medial-fuzz-" + std::to_string(::getpid()) + (in.ConsumeBool() ? ".glb" : ".fbx");
  auto writer = vtkSmartPointer<vtkMedialRigWriter>::New();
  writer->SetFileName(path.c_str());
  writer->SetInputData(0, mesh);
  writer->SetSkeletonData(skeleton);
  writer->SetMaxInfluences(in.ConsumeIntegralInRange(1, 8));
  writer->Write();
  return 0;
}
