#include "vtkMedialSQM.h"

#include "MedialProgress.h"
#include "MedialSkeletonData.h"
#include "MedialMeshData.h"
#include "common/NameList.h"
#include "sqm/SqmMesher.h"

#include <vtkCellArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

vtkStandardNewMacro(vtkMedialSQM);

void vtkMedialSQM::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Smoothing: " << this->Smoothing << "\n";
  os << indent << "Pairing: " << this->Pairing << "\n";
  os << indent << "LinearRingVertices: " << this->LinearRingVertices << "\n";
  os << indent << "Capsules: " << this->Capsules << "\n";
  os << indent << "CapsuleSteps: " << this->CapsuleSteps << "\n";
  os << indent << "PairTriangles: " << this->PairTriangles << "\n";
  os << indent << "SubdivisionLevels: " << this->SubdivisionLevels << "\n";
  os << indent << "SharpScaling: " << this->SharpScaling << "\n";
  os << indent << "SharpMinimumScale: " << this->SharpMinimumScale << "\n";
  os << indent << "FoldRepair: " << this->FoldRepair << "\n";
  os << indent << "RecordStages: " << this->RecordStages << "\n";
  os << indent << "MergeNodes: " << this->MergeNodes << "\n";
  os << indent << "Union: " << this->Union << "\n";
  os << indent << "CountOverlaps: " << this->CountOverlaps << "\n";
}

vtkMedialSQM::vtkMedialSQM() {
  const medial::SqmParameters defaults;
  this->Smoothing = medial::lieSmoothingName(defaults.smoothing);
  this->Pairing = medial::ringPairingName(defaults.pairing);
  this->LinearRingVertices = defaults.linearRingVertices;
  this->Capsules = defaults.capsules;
  this->CapsuleSteps = defaults.capsuleSteps;
  this->PairTriangles = defaults.pairTriangles;
  this->SubdivisionLevels = defaults.subdivisionLevels;
  this->SharpScaling = defaults.sharpScaling.enabled;
  this->SharpMinimumScale = defaults.sharpScaling.minimumScale;
  this->FoldRepair = defaults.foldRepair;
  this->MergeNodes = defaults.mergeNodes;
  this->Union = defaults.unite;
  this->CountOverlaps = defaults.countOverlaps;
  this->Seconds.assign(GetStageNames().size(), 0.0);
  this->Stages.clear();
}

std::vector<std::string> vtkMedialSQM::GetStageNames() {
  return {"straightening", "generation",  "refinement", "joining",
          "skinning",      "subdivision", "repairs",    "union"};
}

double vtkMedialSQM::GetStageSeconds(const std::string& stage) const {
  const std::vector<std::string> names = GetStageNames();
  for (size_t s = 0; s < names.size(); ++s)
    if (names[s] == stage) return this->Seconds[s];
  return 0;
}

medial::SqmParameters vtkMedialSQM::MakeParameters() const {
  medial::SqmParameters p;
  medial::parseLieSmoothing(this->Smoothing, p.smoothing);  // the setters accept known names only
  medial::parseRingPairing(this->Pairing, p.pairing);
  p.linearRingVertices = this->LinearRingVertices;
  p.capsules = this->Capsules;
  p.capsuleSteps = this->CapsuleSteps;
  p.pairTriangles = this->PairTriangles;
  p.subdivisionLevels = this->SubdivisionLevels;
  p.sharpScaling.enabled = this->SharpScaling;
  p.sharpScaling.minimumScale = this->SharpMinimumScale;
  p.foldRepair = this->FoldRepair;
  p.mergeNodes = this->MergeNodes;
  p.unite = this->Union;
  p.countOverlaps = this->CountOverlaps;
  p.recordStages = this->RecordStages;
  return p;
}

std::string vtkMedialSQM::GetSmoothingNames() { return medial::joinNames(medial::lieSmoothingNames()); }
std::string vtkMedialSQM::GetPairingNames() { return medial::joinNames(medial::ringPairingNames()); }

void vtkMedialSQM::SetSmoothing(const std::string& name) {
  medial::LieSmoothing smoothing;
  if (!medial::parseLieSmoothing(name, smoothing)) {
    vtkErrorMacro(<< "unknown smoothing '" << name << "' (" << GetSmoothingNames() << ")");
    return;
  }
  if (name != this->Smoothing) {
    this->Smoothing = name;
    this->Modified();
  }
}

void vtkMedialSQM::SetPairing(const std::string& name) {
  medial::RingPairing pairing;
  if (!medial::parseRingPairing(name, pairing)) {
    vtkErrorMacro(<< "unknown pairing '" << name << "' (" << GetPairingNames() << ")");
    return;
  }
  if (name != this->Pairing) {
    this->Pairing = name;
    this->Modified();
  }
}

int vtkMedialSQM::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                              vtkInformationVector* outputVector) {
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  medial::Skeleton skeleton;
  std::string error;
  if (!input || !medial::skeletonFromPolyData(input, skeleton, error)) {
    vtkErrorMacro(<< (input ? error : std::string("no input skeleton")));
    return 0;
  }
  this->MergedNodes = this->FoldRepairedVertices = 0;
  this->BranchNodes = this->ConnectionNodes = this->LeafNodes = this->IrregularVertices = 0;
  this->Quads = this->Triangles = 0;
  this->OverlappingFacePairs = this->OverlappingNodePairs = this->UnionCutPolygons =
      this->UnionRemovedPolygons = 0;
  this->OverlapCountComplete = true;
  this->Seconds.assign(GetStageNames().size(), 0.0);
  this->Stages.clear();
  const medial::SqmResult result =
      medial::sqmMesh(skeleton, this->MakeParameters(), medial::progressOf(this));
  this->OverlappingFacePairs = result.overlaps.facePairs;
  this->OverlappingNodePairs = result.overlaps.nodePairs;
  this->OverlapCountComplete = result.overlaps.complete;
  if (!result.ok()) {
    medial::reportError(this, result.error);
    return 0;
  }
  this->UnionCutPolygons = result.unionResult.cutPolygons;
  this->UnionRemovedPolygons = result.unionResult.removedPolygons;
  this->MergedNodes = result.mergedNodes;
  this->FoldRepairedVertices = result.foldRepairedVertices;
  this->BranchNodes = result.branchNodes;
  this->ConnectionNodes = result.connectionNodes;
  this->LeafNodes = result.leafNodes;
  this->IrregularVertices = result.irregularVertices;
  this->Quads = result.mesh.quadCount();
  this->Triangles = result.mesh.triangleCount();
  this->Seconds = {result.straighteningSeconds, result.generationSeconds, result.refinementSeconds,
                   result.joiningSeconds,       result.placementSeconds,  result.subdivisionSeconds,
                   result.repairSeconds,        result.unionSeconds};
  // Points and polygons only: the field data the pipeline passed on from the input (`Root`) stays.
  const vtkSmartPointer<vtkPolyData> mesh =
      medial::polyDataFromPolygons(result.mesh.vertices, result.mesh.faces);
  output->SetPoints(mesh->GetPoints());
  output->SetPolys(mesh->GetPolys());
  output->GetPointData()->AddArray(medial::intArray("SkeletonNode", result.mesh.vertexNode));
  if (this->RecordStages) {
    const medial::SqmMesh* stages[] = {&result.polyhedra, &result.refinedPolyhedra, &result.baseMesh};
    for (size_t k = 0; k < GetStageMeshNames().size(); ++k) {
      vtkSmartPointer<vtkPolyData> stage =
          medial::polyDataFromPolygons(stages[k]->vertices, stages[k]->faces);
      stage->GetPointData()->AddArray(medial::intArray("SkeletonNode", stages[k]->vertexNode));
      this->Stages[GetStageMeshNames()[k]] = stage;
    }
  }
  return 1;
}

vtkPolyData* vtkMedialSQM::GetStageMesh(const std::string& name) const {
  const auto found = this->Stages.find(name);
  return found != this->Stages.end() ? found->second.Get() : nullptr;
}
