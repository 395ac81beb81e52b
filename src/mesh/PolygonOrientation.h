/// \file
/// PolygonOrientation: makes the faces of a manifold polygon mesh consistently oriented, each connected
/// component outward (positive enclosed volume). The consistent orientation is CGAL's polygon-soup
/// orientation (Polygon_mesh_processing::orient_polygon_soup); the outward choice is the sign of the
/// component's signed volume (divergence theorem over its faces, fanned from their first corner).
#pragma once

#include <Eigen/Core>

#include <vector>

namespace medial {

/// Reorients `faces` in place (the vertex order of a face is reversed, never its vertices changed).
/// Returns the number of faces reversed, or -1 when the mesh is not orientable without duplicating
/// vertices (non-manifold); the faces are then left as they were.
int orientPolygonsOutward(const std::vector<Eigen::Vector3d>& vertices, std::vector<std::vector<int>>& faces);

}  // namespace medial
