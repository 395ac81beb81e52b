// CrossSections and NodeCentring (issue 26): the off-centre measure on a tube whose axis is known and the
// splits of edges across bends. The centring measured on sample meshes, against CGAL's skeleton and
// against the nodes the selection came from, is in NodeCentringPeer_test.cpp.
#include "TestPaths.h"

#include "contraction/CrossSections.h"
#include "contraction/NodeCentring.h"
#include "contraction/SkeletonByContraction.h"
#include "mesh/InsideTest.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

namespace {

// A closed tube of radius r along x from 0 to length (rings of `sides` vertices, flat caps fanned).
medial::TriangleMesh tube(double r, double length, int rings = 40, int sides = 48) {
  std::vector<Eigen::Vector3d> points;
  std::vector<Eigen::Vector3i> faces;
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < sides; ++j) {
      const double a = 2 * M_PI * j / sides;
      points.emplace_back(length * i / (rings - 1), r * std::cos(a), r * std::sin(a));
    }
  auto at = [&](int i, int j) { return i * sides + (j % sides); };
  for (int i = 0; i + 1 < rings; ++i)
    for (int j = 0; j < sides; ++j) {
      faces.emplace_back(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      faces.emplace_back(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  const int start = int(points.size()), end = start + 1;
  points.emplace_back(0, 0, 0);
  points.emplace_back(length, 0, 0);
  for (int j = 0; j < sides; ++j) {
    faces.emplace_back(start, at(0, j + 1), at(0, j));
    faces.emplace_back(end, at(rings - 1, j), at(rings - 1, j + 1));
  }
  medial::TriangleMesh mesh;
  mesh.vertices.resize(Eigen::Index(points.size()), 3);
  for (size_t k = 0; k < points.size(); ++k) mesh.vertices.row(Eigen::Index(k)) = points[k];
  mesh.faces.resize(Eigen::Index(faces.size()), 3);
  for (size_t k = 0; k < faces.size(); ++k) mesh.faces.row(Eigen::Index(k)) = faces[k];
  return mesh;
}

}  // namespace

TEST(CrossSections, ATubesSectionIsItsDiscAndTheRatioIsTheDistanceFromTheAxisInRadii) {
  const medial::CrossSections sections(tube(2.0, 20.0));
  const medial::CrossSection onAxis = sections.around({10, 0, 0}, {1, 0, 0});
  ASSERT_TRUE(onAxis.found);
  EXPECT_NEAR(onAxis.area, M_PI * 4, 0.02 * M_PI * 4);  // the 48-gon's area
  EXPECT_NEAR(onAxis.offCentre({10, 0, 0}), 0.0, 1e-6);
  const medial::CrossSection halfway = sections.around({7, 1, 0}, {1, 0, 0});
  ASSERT_TRUE(halfway.found);
  EXPECT_NEAR(halfway.offCentre({7, 1, 0}), 0.5, 0.01);
  EXPECT_NEAR(halfway.centroid.y(), 0.0, 1e-6);
  // Outside the tube no loop winds around the point.
  EXPECT_FALSE(sections.around({7, 3, 0}, {1, 0, 0}).found);
  // A skeleton on the axis is centred; one half a radius off is off by 0.5.
  medial::Skeleton axis;
  axis.nodes = {{2, 0, 0}, {18, 0, 0}};
  axis.edges = {{0, 1}};
  EXPECT_NEAR(medial::offCentre(axis, sections).median(), 0.0, 1e-6);
  axis.nodes = {{2, 1, 0}, {18, 1, 0}};
  const auto off = medial::offCentre(axis, sections);
  EXPECT_EQ(off.outside, 0);
  EXPECT_NEAR(off.median(), 0.5, 0.01);
}

// The centring's splits: a straight tube's axis is left as it is; a skeleton of one straight edge across a
// bent tube gets nodes where the edge's middle is off its section's centroid, and ends up more centred.
TEST(NodeCentring, AnEdgeAcrossABendIsSplitOntoTheAxis) {
  medial::TriangleMesh straight = tube(1.0, 10.0);
  const medial::CrossSections straightSections(straight);
  const medial::InsideTest straightInside(straight);
  medial::CurveSkeleton axis;
  axis.nodes.resize(2, 3);
  axis.nodes << 1, 0, 0, 9, 0, 0;
  axis.edges = {{0, 1}};
  axis.vertexToNode.assign(size_t(straight.vertices.rows()), 0);
  EXPECT_EQ(medial::splitOffCentreEdges(axis, straight.vertices, straightSections, straightInside), 0);

  // An arc: a tube bent around the z axis by 90 degrees (radius of the bend 6, of the tube 1).
  medial::TriangleMesh arc = tube(1.0, 1.0, 40, 32);
  for (Eigen::Index v = 0; v < arc.vertices.rows(); ++v) {
    const double angle = arc.vertices(v, 0) * M_PI / 2, radial = 6 + arc.vertices(v, 1);
    arc.vertices.row(v) << radial * std::cos(angle), radial * std::sin(angle), arc.vertices(v, 2);
  }
  const medial::CrossSections sections(arc);
  const medial::InsideTest inside(arc);
  medial::CurveSkeleton chord;
  chord.nodes.resize(2, 3);
  const double a0 = 0.3 * M_PI / 2, a1 = 0.7 * M_PI / 2;  // a chord 0.29 radii off the axis at its middle
  chord.nodes << 6 * std::cos(a0), 6 * std::sin(a0), 0, 6 * std::cos(a1), 6 * std::sin(a1), 0;
  chord.edges = {{0, 1}};
  chord.vertexToNode.assign(size_t(arc.vertices.rows()), 0);
  const double before = medial::offCentre(medial::skeletonOf(chord), sections).median();
  const int added = medial::splitOffCentreEdges(chord, arc.vertices, sections, inside);
  const auto after = medial::offCentre(medial::skeletonOf(chord), sections);
  std::printf("chord across the bend: %d nodes added, off-centre median %.3f -> %.3f\n", added, before,
              after.median());
  EXPECT_GT(added, 0);
  EXPECT_EQ(int(chord.edges.size()), 1 + added);
  EXPECT_EQ(after.outside, 0);
  EXPECT_LT(after.median(), 0.5 * before);
  for (Eigen::Index k = 0; k < chord.nodes.rows(); ++k)
    EXPECT_TRUE(inside.contains(chord.nodes.row(k).transpose()));
}
