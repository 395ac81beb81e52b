/// \file
/// NodeCentring (beyond the paper, issue 26): after the refinement of III.C - which moves each node to the
/// centroid of the mesh vertices it absorbed, a centre of the surface, not of the volume: on a bent limb or
/// where one side of a part is more finely meshed it sits off the axis - nodes move to the area centroid of
/// the mesh's cross-section through them (the plane normal to the skeleton's direction there, over five
/// edges each way; the smallest closed loop around the node: CrossSections). A node of one or two edges
/// takes the direction through it; a branch node, when asked (`branchNodes`), the direction of its
/// straightest pair of edges (the axis the branches leave from). The move is kept only when the centroid
/// lies inside the mesh, within the section's equivalent radius (farther, the loop is not this part's: a
/// junction, a fold) and when every edge of the node, to where its neighbour moves, stays inside the mesh.
/// All of a pass's targets are found on the same skeleton (Jacobi, not Gauss-Seidel: the targets do not
/// depend on the nodes' numbering). Two passes: the directions change as
/// the neighbours move.
///
/// MCF's answer (CGAL) is a medial attraction term during the flow, towards the Voronoi poles. Tried in
/// Medial's contraction (each vertex attracted to its inner pole with w_M W_H, w_M 0.3-2, poles of the
/// contracted or of the input mesh): the off-centre medians moved both ways by up to 0.3 from mesh to mesh,
/// no better on the whole; so Medial measures the sections and centres on them directly.
#pragma once

#include "contraction/ConnectivitySurgery.h"
#include "contraction/CrossSections.h"
#include "mesh/InsideTest.h"

#include <vector>

namespace medial {

/// Returns the number of node moves made (over both passes).
/// `directions`, when given, replaces the skeleton's own direction at each node where it is not zero.
int centreNodes(CurveSkeleton& skeleton, const CrossSections& sections, const InsideTest& inside,
                bool branchNodes = false, int passes = 2,
                const std::vector<Eigen::Vector3d>* directions = nullptr);

/// The skeleton's direction at every node as centreNodes finds it: over five edges each way, at a branch
/// node along its straightest pair of edges; zero at a node without edges.
std::vector<Eigen::Vector3d> nodeDirections(const CurveSkeleton& skeleton);

/// The off-centre ratio at every node (|node - section centroid| / the section's equivalent radius), the
/// section cut normal to the node's direction; NaN where the direction is zero or no closed loop winds
/// around the node (outside).
std::vector<double> nodeOffCentre(const Vertices& nodes, const std::vector<Eigen::Vector3d>& directions,
                                  const CrossSections& sections);

/// An edge whose middle is off its cross-section's centroid by more than `threshold` times the section's
/// equivalent radius (the plane normal to the edge; the measure) gets a node at that centroid, when
/// the centroid lies inside, both halves stay inside and the edge bends there by at most 45 degrees (more:
/// the plane was too oblique to the part's axis, a thick body cut at a slant, and the skeleton would
/// zigzag); the halves are tried again, up to `maxDepth` times (splitSkeletonEdges). The surgery leaves one
/// straight edge along a whole bent limb or body: a straight edge cannot follow a bent axis. Returns the
/// number of nodes added.
int splitOffCentreEdges(CurveSkeleton& skeleton, const Vertices& originalVertices,
                        const CrossSections& sections, const InsideTest& inside, double threshold = 0.1,
                        int maxDepth = 6);

}  // namespace medial
