// The centring on sample meshes (issue 26): against CGAL's mean curvature flow skeleton, measured in the
// same run, and the selected nodes against the nodes they came from. A test executable of its own
// (medial_peer_tests): CGAL's skeletonization costs minutes to compile under the sanitizers, and these
// tests measure quality, which the sanitizer build does not need to repeat (scripts/sanitize).
#include "CgalSkeletonPeer.h"
#include "TestPaths.h"

#include "contraction/CrossSections.h"
#include "contraction/NodeCentring.h"
#include "contraction/SkeletonByContraction.h"

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

using medial::peer::SurfaceMesh;

// The goal on three sample meshes: with --nodes 0 the median off-centre ratio is at most CGAL's
// (measured here, in the same run), the 90th percentile at most CGAL's + 0.1 on two of them (on the cow
// the udder's and the junctions' samples keep it higher: 1.11 against CGAL's 0.75-0.82), and centring
// lowers the median against no centring. The elephant (0.313) sits inside the spread of CGAL's own median
// from run to run (0.31-0.42: its flow is not deterministic), so it is held to its measured figure instead.
TEST(NodeCentring, UnselectedSkeletonsAreAsCentredAsCgalsOnThreeSamples) {
  struct Sample {
    const char* name;
    bool percentile;     // the 90th percentile is asserted against CGAL's too
    double fixedMedian;  // > 0: held to this median instead of CGAL's
  };
  for (const Sample sample : {Sample{"knot1", true, 0}, Sample{"hand", true, 0}, Sample{"cow", false, 0},
                              Sample{"elephant", false, 0.33}}) {
    const std::string path = medial::test::externalPath(std::string("cgal/meshes/") + sample.name + ".off");
    if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " missing: run scripts/fetch-samples";
    SurfaceMesh sm;
    ASSERT_TRUE(CGAL::IO::read_polygon_mesh(path, sm));
    const medial::TriangleMesh mesh = medial::peer::toTriangleMesh(sm);
    const medial::CrossSections sections(mesh);
    medial::SkeletonByContractionParameters p;
    p.targetNodes = 0;
    const auto centred = medial::skeletonByContraction(mesh, p);
    p.centerNodes = false;
    const auto uncentred = medial::skeletonByContraction(mesh, p);
    ASSERT_TRUE(centred.ok() && uncentred.ok());
    const auto ours = medial::offCentre(centred.skeleton, sections);
    const auto before = medial::offCentre(uncentred.skeleton, sections);
    EXPECT_EQ(ours.outside, 0) << sample.name;
    EXPECT_LT(ours.median(), before.median()) << sample.name;
    if (sample.fixedMedian > 0) {
      std::printf(
          "%s: off-centre median / 90th percentile: Medial %.3f / %.3f (without centring %.3f / %.3f)\n",
          sample.name, ours.median(), ours.percentile90(), before.median(), before.percentile90());
      EXPECT_LE(ours.median(), sample.fixedMedian) << sample.name;
      continue;
    }
    const auto cgal = medial::offCentre(medial::peer::cgalSkeleton(sm), sections);
    std::printf(
        "%s: off-centre median / 90th percentile: Medial %.3f / %.3f (without centring %.3f / %.3f), "
        "CGAL %.3f / %.3f\n",
        sample.name, ours.median(), ours.percentile90(), before.median(), before.percentile90(),
        cgal.median(), cgal.percentile90());
    EXPECT_LE(ours.median(), cgal.median()) << sample.name;
    if (sample.percentile) {
      EXPECT_LE(ours.percentile90(), cgal.percentile90() + 0.1) << sample.name;
    }
  }
}

// The goal for the selection: every selected node as centred as the node it came from. On three
// sample meshes each of the default skeleton's nodes is compared with its source in the unselected
// skeleton, centred (measureSelectionCentring): at most one in ten more than 0.1 further off, and the
// medians no worse. (With the selected nodes cut across their own chords: knot1 5 of 30, cow 12 of 38.)
TEST(NodeCentring, SelectedNodesAreAsCentredAsTheNodesTheyCameFrom) {
  for (const char* name : {"knot1", "hand", "cow"}) {
    const std::string path = medial::test::externalPath(std::string("cgal/meshes/") + name + ".off");
    if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " missing: run scripts/fetch-samples";
    SurfaceMesh sm;
    ASSERT_TRUE(CGAL::IO::read_polygon_mesh(path, sm));
    const medial::TriangleMesh mesh = medial::peer::toTriangleMesh(sm);
    medial::SkeletonByContractionParameters p;
    p.recordStages = true;
    const auto run = medial::skeletonByContraction(mesh, p);
    ASSERT_TRUE(run.ok()) << name;
    ASSERT_EQ(run.selectedFrom.size(), run.skeleton.nodes.size()) << name;
    medial::SkeletonByContractionResult unrecorded = run;
    unrecorded.unselectedSkeleton = {};
    EXPECT_TRUE(medial::measureSelectionCentring(unrecorded, mesh).selected.ratios.empty());
    const medial::SelectionCentring nodes = medial::measureSelectionCentring(run, mesh);
    std::printf("%s: selected nodes' median off-centre %.3f, their sources' %.3f, %d of %zu further off\n",
                name, nodes.selected.median(), nodes.source.median(), nodes.worse,
                nodes.selected.ratios.size());
    EXPECT_GE(nodes.selected.ratios.size(), run.skeleton.nodes.size() * 3 / 4) << name;
    EXPECT_LE(10 * nodes.worse, int(nodes.selected.ratios.size())) << name;
    EXPECT_LE(nodes.selected.median(), nodes.source.median() + 0.01) << name;
  }
}
