// Every filter's defaults are its algorithm's: a fresh filter gives back the default parameters struct of
// src/ (docs/ARCHITECTURE.md §3), and its setters keep to their ranges.
#include "centerline/TskCenterline.h"
#include "contraction/SkeletonByContraction.h"
#include "sketch/SketchSkeleton.h"
#include "sqm/SqmMesher.h"
#include "vtkMedialContractionSkeleton.h"
#include "vtkMedialSQM.h"
#include "vtkMedialSketchSkeleton.h"
#include "vtkMedialTskCenterline.h"

#include <vtkSmartPointer.h>

#include <gtest/gtest.h>

TEST(FilterDefaults, ContractionSkeletonTakesSkeletonByContractionParameters) {
  const medial::SkeletonByContractionParameters p;
  const auto f = vtkSmartPointer<vtkMedialContractionSkeleton>::New();
  EXPECT_EQ(f->GetTargetNodes(), p.targetNodes);
  EXPECT_EQ(f->GetContractionVertices(), p.contractionVertices);
  EXPECT_EQ(f->GetReferenceVertices(), p.contraction.referenceVertices);
  EXPECT_EQ(f->GetInitialContractionFactor(), p.contraction.initialContractionFactor);
  EXPECT_EQ(f->GetContractionScale(), p.contraction.contractionScale);
  EXPECT_EQ(f->GetMaxContractionWeight(), p.contraction.maxContractionWeight);
  EXPECT_EQ(f->GetMaxAttractionWeight(), p.contraction.maxAttractionWeight);
  EXPECT_EQ(f->GetMaxIterations(), p.contraction.maxIterations);
  EXPECT_EQ(f->GetShapeWeight(), p.surgery.shapeWeight);
  EXPECT_EQ(f->GetSamplingWeight(), p.surgery.samplingWeight);
  EXPECT_EQ(f->GetRefineEmbedding(), p.refineEmbedding);
  EXPECT_EQ(f->GetRestoreCycles(), p.restoreCycles);
  EXPECT_EQ(f->GetCentreNodes(), p.centreNodes);
  EXPECT_EQ(f->GetComputeWeights(), p.computeWeights);
  EXPECT_EQ(f->GetHeatConstant(), p.weights.heatConstant);
  EXPECT_EQ(f->GetSolver(), medial::sparseSolverName(p.contraction.solver));
}

TEST(FilterDefaults, SqmTakesSqmParameters) {
  const medial::SqmParameters p;
  const auto f = vtkSmartPointer<vtkMedialSQM>::New();
  EXPECT_EQ(f->GetSmoothing(), medial::lieSmoothingName(p.smoothing));
  EXPECT_EQ(f->GetPairing(), medial::ringPairingName(p.pairing));
  EXPECT_EQ(f->GetLinearRingVertices(), p.linearRingVertices);
  EXPECT_EQ(f->GetCapsules(), p.capsules);
  EXPECT_EQ(f->GetPairTriangles(), p.pairTriangles);
  EXPECT_EQ(f->GetSubdivisionLevels(), p.subdivisionLevels);
  EXPECT_EQ(f->GetSharpScaling(), p.sharpScaling.enabled);
  EXPECT_EQ(f->GetSharpMinimumScale(), p.sharpScaling.minimumScale);
  EXPECT_EQ(f->GetFoldRepair(), p.foldRepair);
  EXPECT_EQ(f->GetMergeNodes(), p.mergeNodes);
}

TEST(FilterDefaults, SketchSkeletonTakesSketchParameters) {
  const medial::SketchParameters p;
  const auto f = vtkSmartPointer<vtkMedialSketchSkeleton>::New();
  EXPECT_EQ(f->GetSimplificationThreshold(), p.thresholds.simplification);
  EXPECT_EQ(f->GetMergingThreshold(), p.thresholds.merging);
  EXPECT_EQ(f->GetPruningThreshold(), p.thresholds.pruning);
  EXPECT_EQ(f->GetCollapsingThreshold(), p.thresholds.collapsing);
  EXPECT_EQ(f->GetUnitLength(), p.unitLength);
  EXPECT_EQ(f->GetResampleStep(), p.resampleStep);
  EXPECT_EQ(f->GetPolygonTolerance(), p.polygonTolerance);
  EXPECT_EQ(f->GetShapeWeight(), p.shapeWeight);
  EXPECT_EQ(f->GetThickness(), p.thickness);
  EXPECT_EQ(f->GetMeshEdgeLength(), p.meshEdgeLength);
  EXPECT_EQ(f->GetInflate(), p.inflate);
}

TEST(FilterDefaults, TskCenterlineTakesTskCenterlineParameters) {
  const medial::TskCenterlineParameters p;
  const auto f = vtkSmartPointer<vtkMedialTskCenterline>::New();
  EXPECT_STREQ(f->GetSelectionName(), "non-zero");
  EXPECT_EQ(p.selection, medial::VoxelSelection::NonZero);
  EXPECT_EQ(f->GetLabel(), p.label);
  EXPECT_EQ(f->GetThresholdLow(), p.thresholdLow);
  EXPECT_EQ(f->GetThresholdHigh(), p.thresholdHigh);
  EXPECT_EQ(f->GetBorderParts(), int(p.borderParts));
  EXPECT_EQ(f->GetFillHoles(), p.fillHoles);
  EXPECT_EQ(f->GetAntecedentWidth(), p.tsk.antecedentWidth);
  EXPECT_EQ(f->GetSampleSpacing(), p.tsk.sampleSpacing);
  EXPECT_EQ(f->GetCenteringIterations(), p.tsk.centeringIterations);
  EXPECT_EQ(f->GetDetectBranches(), p.detectBranches);
  EXPECT_EQ(f->GetMinimumBranchLength(), p.minimumBranchLength);
  EXPECT_EQ(f->GetComputeSections(), p.computeSections);
  EXPECT_EQ(f->GetSectionSpacing(), p.sections.spacing);
  EXPECT_EQ(f->GetSectionRays(), p.sections.rays);
}

// A setter changes only its own parameter: choosing a threshold does not decide about border parts.
TEST(FilterDefaults, SettersChangeOnlyTheirOwnParameter) {
  const auto f = vtkSmartPointer<vtkMedialTskCenterline>::New();
  f->SetBorderParts(vtkMedialTskCenterline::BORDER_PARTS_KEEP);
  f->SetThreshold(-1024, -600);
  EXPECT_EQ(f->GetBorderParts(), vtkMedialTskCenterline::BORDER_PARTS_KEEP);
  EXPECT_FALSE(f->GetDropBorderParts());
  f->SetBorderParts(vtkMedialTskCenterline::BORDER_PARTS_AUTOMATIC);
  EXPECT_TRUE(f->GetDropBorderParts()) << "automatic: dropped for a threshold";
  f->SetLabel(1);
  EXPECT_FALSE(f->GetDropBorderParts()) << "automatic: kept for a label";
  // Names: an unknown one is refused and the old one stays.
  const auto sqm = vtkSmartPointer<vtkMedialSQM>::New();
  sqm->GlobalWarningDisplayOff();
  sqm->SetSmoothing("median");
  EXPECT_EQ(sqm->GetSmoothing(), "quaternion");
  sqm->GlobalWarningDisplayOn();
}
