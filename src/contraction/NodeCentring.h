// NodeCentring (beyond the paper, issue 26): after the refinement of III.C - which moves each node to the
// centroid of the mesh vertices it absorbed, a centre of the surface, not of the volume: on a bent limb or
// where one side of a part is more finely meshed it sits off the axis - every node of one or two edges
// moves to the area centroid of the mesh's cross-section through it (the plane normal to the skeleton's
// direction there, over five edges each way; the smallest closed loop around the node: CrossSections).
// The move is kept only when
// the centroid lies inside the mesh, within the section's equivalent radius (farther, the loop is not this
// part's: a junction, a fold) and when every edge of the node stays inside the mesh. Branch nodes stay.
// Two passes: the directions change as the neighbours move. MCF's answer (CGAL) is a medial attraction
// term during the flow, towards the Voronoi poles; this one measures and centres the result directly.
#pragma once

#include "contraction/ConnectivitySurgery.h"
#include "contraction/CrossSections.h"
#include "mesh/InsideTest.h"

namespace medial {

// Returns the number of node moves made (over both passes).
int centreNodes(CurveSkeleton& skeleton, const CrossSections& sections, const InsideTest& inside,
                int passes = 2);

}  // namespace medial
