/// \file
/// SketchInflation: stage 4 of the sketch skeletonization (Ma et al. 2021, §4.1, after Monster Mash [44]):
/// a simple polygon becomes a closed, rounded 3-D mesh.
///
/// The polygon is triangulated by CGAL's constrained Delaunay triangulation, refined to triangles of at
/// most `edgeLength` (and angles of at least 20.7 degrees). The height field solves the Poisson equation
/// -Laplace(f) = c inside with f = 0 on the outline (cotangent Laplacian, lumped mass, sparse Cholesky),
/// and the surface is z = +-sqrt(f): the front and its mirrored back side share the outline, so the mesh is
/// closed and manifold. The square root (Monster Mash's choice) makes the cross-sections round: a strip of
/// width 2R gets an ellipse of half-height sqrt(c/2) R, a disc of radius R one of sqrt(c)/2 R; the default
/// c = 2 gives round tubes. The result is independent of the drawing's scale.
#pragma once

#include "mesh/TriangleMesh.h"
#include "sketch/SketchStroke.h"

#include <string>

namespace medial {

/// The inflation's parameters (§4.1).
struct InflationParameters {
  double thickness = 2;    ///< c
  double edgeLength = 10;  ///< largest triangle edge of the refined triangulation (polygon units)
};

/// The mesh lies in the polygon's plane z = 0 (front side z > 0). False with `error` on failure.
bool inflatePolygon(const Polygon2& polygon, const InflationParameters& parameters, TriangleMesh& mesh,
                    std::string& error);

}  // namespace medial
