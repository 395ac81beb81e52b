/// \file
/// UnionCutting: stages 1 and 2 of SqmUnion. The SQM mesh as an exact CGAL surface of triangles (fanned
/// from each polygon's first vertex), cut along every intersection curve by CGAL's autorefinement.
///
/// Only the region where faces cut each other is cut (issue 46: on the dense tree refined twice CGAL spent
/// 2.5 s on the whole mesh, much of it pairing the boxes of faces that meet nothing): the polygons of the
/// cutting pairs, in clusters joined by the pairs, each cluster a surface of its own, cut on every core.
/// Outside the clusters no face changes, so the cut clusters and the other polygons join into the same
/// closed surface as cutting the whole mesh would give; should a cut reach a cluster's border (a new
/// vertex on an edge the cluster shares with a polygon outside), the whole mesh is cut instead.
#pragma once

#include "sqm/SqmMesh.h"

#include "mesh/StableBoxIds.h"  // before CGAL's Polygon_mesh_processing headers

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Surface_mesh.h>

#include <memory>
#include <string>
#include <vector>

namespace medial {

/// Exact kernel and surface of the union's cutting.
using ExactKernel = CGAL::Exact_predicates_exact_constructions_kernel;
/// A surface of triangles with exact points.
using ExactMesh = CGAL::Surface_mesh<ExactKernel::Point_3>;

/// Marks every triangle the autorefinement cuts, and gives each piece the polygon of the triangle it came
/// from. CGAL copies the visitor: the state is shared.
struct CutTracker : CGAL::Polygon_mesh_processing::Corefinement::Default_visitor<ExactMesh> {
  ExactMesh::Property_map<ExactMesh::Face_index, int> polygon;  ///< the SQM polygon of each triangle
  ExactMesh::Property_map<ExactMesh::Face_index, bool> cut;     ///< whether the triangle was cut
  std::shared_ptr<int> current = std::make_shared<int>(-1);     ///< the polygon being cut
  /// CGAL's call before a face is split: its polygon becomes the current one.
  void before_subface_creations(ExactMesh::Face_index old, ExactMesh&) {
    *current = polygon[old];
    cut[old] = true;
  }
  /// CGAL's call for each piece of the face being split.
  void after_subface_created(ExactMesh::Face_index piece, ExactMesh&) {
    polygon[piece] = *current;
    cut[piece] = true;
  }
};

/// The SQM mesh's polygons as triangles of an exact surface, each knowing its polygon and each vertex its
/// index in the SQM mesh.
struct ExactSurface {
  ExactMesh surface;                                             ///< the triangles
  ExactMesh::Property_map<ExactMesh::Vertex_index, int> source;  ///< SQM vertex; -1 on a curve
  ExactMesh::Property_map<ExactMesh::Edge_index, bool> curve;    ///< edge on an intersection curve
  std::vector<ExactMesh::Vertex_index> handles;                  ///< of the SQM mesh's vertices
  CutTracker tracker;                                            ///< polygon and cut flag per triangle
};

/// Builds `exact` from `mesh` and cuts it along every intersection curve of the faces in `cutting` (pairs
/// of polygons that cut each other, from intersectingFaces()), so that no two triangles cut each other any
/// more; curve edges are marked.
/// \return false with `error` set where the mesh is not a closed manifold of polygons.
bool cutAlongIntersections(const SqmMesh& mesh, const std::vector<std::pair<int, int>>& cutting,
                           ExactSurface& exact, std::string& error);

}  // namespace medial
