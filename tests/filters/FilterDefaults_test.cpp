// Every filter's defaults are its algorithm's, in both directions: a fresh filter's getters give the
// default parameters struct of src/ (docs/ARCHITECTURE.md §3), and MakeParameters() carries every setting
// back into the struct (a fresh filter's gives the defaults, a changed one's the changed values). Each test
// also reads the filter's header: a setter that no check here covers fails it, so a new parameter cannot be
// forgotten in the constructor, in MakeParameters() or here.
#include "centerline/TskCenterline.h"
#include "contraction/SkeletonByContraction.h"
#include "sketch/SketchSkeleton.h"
#include "sqm/SqmMesher.h"
#include "vtkMedialContractionSkeleton.h"
#include "vtkMedialSQM.h"
#include "vtkMedialSketchSkeleton.h"
#include "vtkMedialTskCenterline.h"

#include "TestPaths.h"

#include <vtkSmartPointer.h>

#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

// The names of the parameters `header` declares a setter for (vtkSet*Macro and hand-written Set*).
std::set<std::string> settersIn(const std::string& header) {
  std::ifstream file(medial::test::sourceDir() + "/filters/" + header);
  std::stringstream text;
  text << file.rdbuf();
  const std::string all = text.str();
  std::set<std::string> names;
  const std::regex setter(R"((?:vtkSet\w*Macro\(|void Set)(\w+))");
  for (auto it = std::sregex_iterator(all.begin(), all.end(), setter); it != std::sregex_iterator(); ++it)
    names.insert((*it)[1].str());
  EXPECT_FALSE(names.empty()) << "no setter found in " << header;
  return names;
}

// One filter's checks: each parameter() call checks the fresh filter against the defaults, sets another
// value on a second filter and records what its MakeParameters() must hold.
template <class Filter, class Parameters>
class Coverage {
 public:
  const vtkSmartPointer<Filter> fresh = vtkSmartPointer<Filter>::New();
  const vtkSmartPointer<Filter> changed = vtkSmartPointer<Filter>::New();
  const Parameters defaults{};

  // `name`: the setter's name; `startsAsDefault`: the fresh filter's getter equals the default;
  // `set`: gives `changed` another value; `holds(p, changed)`: p holds the changed value (changed true)
  // or the default (false).
  void parameter(const std::string& name, bool startsAsDefault, const std::function<void(Filter*)>& set,
                 const std::function<bool(const Parameters&, bool)>& holds) {
    EXPECT_TRUE(startsAsDefault) << name << " does not start at the algorithm's default";
    EXPECT_TRUE(holds(defaults, false)) << name << ": the check does not recognise the default";
    set(changed);
    names_.insert(name);
    holds_.emplace_back(name, holds);
  }
  // A setter no MakeParameters() field stands for, with the reason.
  void notAParameter(const std::string& name) { names_.insert(name); }

  void verify(const std::string& header) {
    const Parameters made = fresh->MakeParameters(), madeChanged = changed->MakeParameters();
    for (const auto& [name, holds] : holds_) {
      EXPECT_TRUE(holds(made, false)) << name << ": a fresh filter's MakeParameters() is not the default";
      EXPECT_TRUE(holds(madeChanged, true)) << name << ": MakeParameters() does not carry the setting";
    }
    for (const std::string& setter : settersIn(header))
      EXPECT_TRUE(names_.count(setter)) << header << " declares Set" << setter << ", which no check covers";
  }

 private:
  std::set<std::string> names_;
  std::vector<std::pair<std::string, std::function<bool(const Parameters&, bool)>>> holds_;
};

// A parameter whose getter, setter and struct field share one type: FIELD is reached from a Parameters p.
#define MEDIAL_PARAMETER(coverage, Name, field, other)                          \
  do {                                                                          \
    const auto changedValue = decltype(coverage.defaults.field)(other);         \
    coverage.parameter(                                                         \
        #Name, coverage.fresh->Get##Name() == coverage.defaults.field,          \
        [changedValue](auto* f) { f->Set##Name(changedValue); },                \
        [d = coverage.defaults, changedValue](const auto& p, bool changed) {    \
          return p.field == (changed ? changedValue : d.field);                 \
        });                                                                     \
    EXPECT_NE(changedValue, coverage.defaults.field) << #Name ": not a change"; \
  } while (false)

}  // namespace

TEST(FilterDefaults, ContractionSkeletonCarriesEverySkeletonByContractionParameter) {
  Coverage<vtkMedialContractionSkeleton, medial::SkeletonByContractionParameters> c;
  MEDIAL_PARAMETER(c, TargetNodes, targetNodes, 12);
  MEDIAL_PARAMETER(c, ContractionVertices, contractionVertices, 2500);
  MEDIAL_PARAMETER(c, ReferenceVertices, contraction.referenceVertices, 3000);
  MEDIAL_PARAMETER(c, InitialContractionFactor, contraction.initialContractionFactor, 2e-3);
  MEDIAL_PARAMETER(c, ContractionScale, contraction.contractionScale, 3.0);
  MEDIAL_PARAMETER(c, InitialAttractionWeight, contraction.initialAttraction, 2.0);
  MEDIAL_PARAMETER(c, MaxContractionWeight, contraction.maxContractionWeight, 1024.0);
  MEDIAL_PARAMETER(c, MaxAttractionWeight, contraction.maxAttractionWeight, 5000.0);
  MEDIAL_PARAMETER(c, MaxIterations, contraction.maxIterations, 20);
  MEDIAL_PARAMETER(c, ShapeWeight, surgery.shapeWeight, 0.5);
  MEDIAL_PARAMETER(c, SamplingWeight, surgery.samplingWeight, 0.2);
  MEDIAL_PARAMETER(c, CollapseLengthFraction, surgery.deltaFraction, 2e-3);
  MEDIAL_PARAMETER(c, RefineEmbedding, refineEmbedding, false);
  MEDIAL_PARAMETER(c, RestoreCycles, restoreCycles, false);
  MEDIAL_PARAMETER(c, CenterNodes, centerNodes, false);
  MEDIAL_PARAMETER(c, ComputeWeights, computeWeights, true);
  MEDIAL_PARAMETER(c, HeatConstant, weights.heatConstant, 2.0);
  MEDIAL_PARAMETER(c, RecordStages, recordStages, true);
  c.parameter(
      "Solver", c.fresh->GetSolver() == medial::sparseSolverName(c.defaults.contraction.solver),
      [](auto* f) { f->SetSolver("cholmod-amd"); },
      [d = c.defaults](const auto& p, bool changed) {
        medial::SparseSolverKind want = d.contraction.solver;
        if (changed) medial::parseSparseSolverKind("cholmod-amd", want);
        return p.contraction.solver == want && p.weights.solver == want;  // one solver for both systems
      });
  c.notAParameter("CentreNodes");  // the deprecated British alias of SetCenterNodes (tested below)
  c.verify("vtkMedialContractionSkeleton.h");
}

// The British spelling stays for one release, as an alias.
TEST(FilterDefaults, CentreNodesIsAnAliasOfCenterNodes) {
  const auto f = vtkSmartPointer<vtkMedialContractionSkeleton>::New();
  f->SetCentreNodes(false);
  EXPECT_FALSE(f->GetCenterNodes());
  f->CentreNodesOn();
  EXPECT_TRUE(f->GetCenterNodes());
  f->CentreNodesOff();
  EXPECT_FALSE(f->GetCentreNodes());
}

TEST(FilterDefaults, SqmCarriesEverySqmParameter) {
  Coverage<vtkMedialSQM, medial::SqmParameters> c;
  c.parameter(
      "Smoothing", c.fresh->GetSmoothing() == medial::lieSmoothingName(c.defaults.smoothing),
      [](auto* f) { f->SetSmoothing("averaging"); },
      [d = c.defaults](const auto& p, bool changed) {
        return changed ? medial::lieSmoothingName(p.smoothing) == std::string("averaging")
                       : p.smoothing == d.smoothing;
      });
  c.parameter(
      "Pairing", c.fresh->GetPairing() == medial::ringPairingName(c.defaults.pairing),
      [](auto* f) { f->SetPairing("angle"); },
      [d = c.defaults](const auto& p, bool changed) {
        return changed ? p.pairing == medial::RingPairing::MinimalAngle : p.pairing == d.pairing;
      });
  MEDIAL_PARAMETER(c, LinearRingVertices, linearRingVertices, 12);
  MEDIAL_PARAMETER(c, PairTriangles, pairTriangles, false);
  MEDIAL_PARAMETER(c, Capsules, capsules, true);
  MEDIAL_PARAMETER(c, CapsuleSteps, capsuleSteps, 7);
  MEDIAL_PARAMETER(c, SubdivisionLevels, subdivisionLevels, 2);
  MEDIAL_PARAMETER(c, SharpScaling, sharpScaling.enabled, true);
  MEDIAL_PARAMETER(c, SharpMinimumScale, sharpScaling.minimumScale, 0.5);
  MEDIAL_PARAMETER(c, FoldRepair, foldRepair, false);
  MEDIAL_PARAMETER(c, Union, unite, true);
  MEDIAL_PARAMETER(c, CountOverlaps, countOverlaps, true);
  MEDIAL_PARAMETER(c, MergeNodes, mergeNodes, false);
  MEDIAL_PARAMETER(c, RecordStages, recordStages, true);
  c.verify("vtkMedialSQM.h");
}

TEST(FilterDefaults, SketchSkeletonCarriesEverySketchParameter) {
  Coverage<vtkMedialSketchSkeleton, medial::SketchParameters> c;
  MEDIAL_PARAMETER(c, SimplificationThreshold, thresholds.simplification, 0.3);
  MEDIAL_PARAMETER(c, MergingThreshold, thresholds.merging, 0.3);
  MEDIAL_PARAMETER(c, PruningThreshold, thresholds.pruning, 0.3);
  MEDIAL_PARAMETER(c, CollapsingThreshold, thresholds.collapsing, 0.3);
  MEDIAL_PARAMETER(c, UnitLength, unitLength, 0.5);
  MEDIAL_PARAMETER(c, ResampleStep, resampleStep, 5.0);
  MEDIAL_PARAMETER(c, PolygonTolerance, polygonTolerance, 1.0);
  MEDIAL_PARAMETER(c, ShapeWeight, shapeWeight, 0.5);
  MEDIAL_PARAMETER(c, Thickness, thickness, 1.5);
  MEDIAL_PARAMETER(c, MeshEdgeLength, meshEdgeLength, 5.0);
  MEDIAL_PARAMETER(c, Inflate, inflate, false);
  MEDIAL_PARAMETER(c, MergeParts, mergeParts, false);
  MEDIAL_PARAMETER(c, RecordStages, recordStages, true);
  // Per-part settings: RequestData applies them to each part's stroke, not to SketchParameters.
  c.notAParameter("PartThresholds");
  c.notAParameter("BranchSimplification");
  c.verify("vtkMedialSketchSkeleton.h");
}

TEST(FilterDefaults, TskCenterlineCarriesEveryTskCenterlineParameter) {
  Coverage<vtkMedialTskCenterline, medial::TskCenterlineParameters> c;
  EXPECT_STREQ(c.fresh->GetSelectionName(), "automatic");
  EXPECT_EQ(c.defaults.selection, medial::VoxelSelection::Automatic);
  c.parameter(
      "Label", c.fresh->GetLabel() == c.defaults.label, [](auto* f) { f->SetLabel(3); },
      [d = c.defaults](const auto& p, bool changed) { return p.label == (changed ? 3 : d.label); });
  // SetThreshold after SetLabel: the last selection given is the one used.
  c.parameter(
      "Threshold",
      c.fresh->GetThresholdLow() == c.defaults.thresholdLow &&
          c.fresh->GetThresholdHigh() == c.defaults.thresholdHigh,
      [](auto* f) { f->SetThreshold(-900, -500); },
      [d = c.defaults](const auto& p, bool changed) {
        return changed ? p.selection == medial::VoxelSelection::Threshold && p.thresholdLow == -900 &&
                             p.thresholdHigh == -500
                       : p.selection == d.selection && p.thresholdLow == d.thresholdLow &&
                             p.thresholdHigh == d.thresholdHigh;
      });
  c.parameter(
      "Seed", !c.fresh->MakeParameters().seed, [](auto* f) { f->SetSeed(1, 2, 3); },
      [](const auto& p, bool changed) {
        return changed ? p.seed && *p.seed == Eigen::Vector3d(1, 2, 3) : !p.seed;
      });
  c.parameter(
      "BorderParts", c.fresh->GetBorderParts() == int(c.defaults.borderParts),
      [](auto* f) { f->SetBorderParts(vtkMedialTskCenterline::BORDER_PARTS_KEEP); },
      [d = c.defaults](const auto& p, bool changed) {
        return p.borderParts == (changed ? medial::BorderParts::Keep : d.borderParts);
      });
  MEDIAL_PARAMETER(c, FillHoles, fillHoles, true);
  MEDIAL_PARAMETER(c, MaxGap, maxGap, 20.0);
  MEDIAL_PARAMETER(c, MinimumPartVolume, minimumPartVolume, 500.0);
  MEDIAL_PARAMETER(c, AntecedentWidth, tsk.antecedentWidth, c.defaults.tsk.antecedentWidth + 2);
  MEDIAL_PARAMETER(c, DetectBranches, detectBranches, true);
  MEDIAL_PARAMETER(c, MinimumBranchLength, minimumBranchLength, 5.0);
  MEDIAL_PARAMETER(c, CenteringIterations, tsk.centeringIterations, c.defaults.tsk.centeringIterations + 1);
  MEDIAL_PARAMETER(c, SampleSpacing, tsk.sampleSpacing, 0.5);
  MEDIAL_PARAMETER(c, ComputeSections, computeSections, true);
  MEDIAL_PARAMETER(c, SectionSpacing, sections.spacing, c.defaults.sections.spacing * 2);
  MEDIAL_PARAMETER(c, SectionRays, sections.rays, c.defaults.sections.rays * 2);
  MEDIAL_PARAMETER(c, RecordStages, recordStages, true);
  MEDIAL_PARAMETER(c, ComputeSurface, keepStructure, true);
  // The lumen surface's own settings (medial::LumenSurfaceParameters, applied by the filter).
  c.notAParameter("SurfaceTriangles");
  c.notAParameter("SurfaceSmoothing");
  c.verify("vtkMedialTskCenterline.h");
}

// The selection modes without values reach the parameters as well.
TEST(FilterDefaults, SelectionModesReachTheParameters) {
  const auto f = vtkSmartPointer<vtkMedialTskCenterline>::New();
  f->SelectNonZero();
  EXPECT_EQ(f->MakeParameters().selection, medial::VoxelSelection::NonZero);
  EXPECT_STREQ(f->GetSelectionName(), "non-zero");
  f->SelectAutomatically();
  EXPECT_EQ(f->MakeParameters().selection, medial::VoxelSelection::Automatic);
  EXPECT_STREQ(f->GetSelectionName(), "automatic");
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
