/// \file
/// NodeRadii: the sphere radius of each skeleton node, so that the skeleton feeds SQM tube meshing.
/// Radius_k = the median distance from node k to the original positions of the mesh vertices it absorbed
/// (robust to the few far vertices a junction collects); the distance to the surface when a node absorbed
/// fewer than 3 vertices; never below 1e-6 of the bounding-box diagonal.
#pragma once

#include "contraction/ConnectivitySurgery.h"
#include "mesh/InsideTest.h"

#include <vector>

namespace medial {

/// The radius of each node of `skeleton` (see the file); `originalVertices` are the input mesh's
/// vertices, `surface` its inside test.
std::vector<double> nodeRadii(const CurveSkeleton& skeleton, const Vertices& originalVertices,
                              const InsideTest& surface);

}  // namespace medial
