#include "mesh/MeshDecimation.h"

#include "mesh/EdgeCoarsening.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_simplification/Edge_collapse_visitor_base.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/GarlandHeckbert_plane_policies.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>

#include <array>
#include <cmath>
#include <numeric>

namespace medial {

namespace {

// Fast collapses first above 16 x the budget, to 10 x the budget (EdgeCoarsening.h).
constexpr Eigen::Index kCoarseningAbove = 16;
constexpr int kCoarsenedVertices = 10;

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;
namespace SMS = CGAL::Surface_mesh_simplification;

// Records, after each collapse, that both ends of the edge went into the vertex that is left.
struct CollapseRecord : SMS::Edge_collapse_visitor_base<SurfaceMesh> {
  std::vector<int>* absorbedBy = nullptr;
  void OnCollapsed(const Profile& profile, const SurfaceMesh::Vertex_index& kept) {
    (*absorbedBy)[size_t(profile.v0().idx())] = int(kept.idx());
    (*absorbedBy)[size_t(profile.v1().idx())] = int(kept.idx());
  }
};

// The vertex that holds v now: follows the chain of collapses.
int survivor(const std::vector<int>& absorbedBy, int v) {
  while (absorbedBy[size_t(v)] != v) v = absorbedBy[size_t(v)];
  return v;
}

// Adds the points in order (vertex i is point i) and the triangles; false when a triangle cannot be added
// (a non-manifold edge or vertex, or an orientation clash with a neighbour).
bool buildSurfaceMesh(const std::vector<Kernel::Point_3>& points,
                      const std::vector<std::array<size_t, 3>>& triangles, SurfaceMesh& sm) {
  sm.clear();
  sm.reserve(SurfaceMesh::size_type(points.size()), SurfaceMesh::size_type(3 * triangles.size() / 2),
             SurfaceMesh::size_type(triangles.size()));
  for (const auto& p : points) sm.add_vertex(p);
  for (const auto& t : triangles)
    if (sm.add_face(SurfaceMesh::Vertex_index(SurfaceMesh::size_type(t[0])),
                    SurfaceMesh::Vertex_index(SurfaceMesh::size_type(t[1])),
                    SurfaceMesh::Vertex_index(SurfaceMesh::size_type(t[2]))) == SurfaceMesh::null_face())
      return false;
  return true;
}

DecimatedMesh unchanged(const TriangleMesh& mesh, const std::string& note) {
  DecimatedMesh result;
  result.mesh = mesh;
  result.representative.assign(size_t(mesh.vertices.rows()), -1);
  for (Eigen::Index f = 0; f < mesh.faces.rows(); ++f)
    for (int c = 0; c < 3; ++c) result.representative[size_t(mesh.faces(f, c))] = mesh.faces(f, c);
  result.note = note;
  return result;
}

// Quadric edge collapses down to the budget. `strict`: a mesh a halfedge structure cannot hold as it is
// is not decimated (note set, `decimated` false) instead of being repaired as a soup.
DecimatedMesh collapseEdges(const TriangleMesh& mesh, int targetVertices, bool strict) {
  const Eigen::Index n = mesh.vertices.rows();

  // Decimated in a normalized frame (bounding-box centre at the origin, diagonal 1): CGAL's quadric
  // placement tests singular matrices against absolute thresholds, so the units must not matter.
  const Eigen::RowVector3d centre =
      0.5 * (mesh.vertices.colwise().maxCoeff() + mesh.vertices.colwise().minCoeff());
  const double diagonal = (mesh.vertices.colwise().maxCoeff() - mesh.vertices.colwise().minCoeff()).norm();
  if (!(diagonal > 0) || !std::isfinite(diagonal))
    return unchanged(mesh, "not decimated: the mesh has no extent");
  const Vertices normalized = (mesh.vertices.rowwise() - centre) / diagonal;

  std::vector<Kernel::Point_3> points;
  points.reserve(size_t(n));
  for (Eigen::Index v = 0; v < n; ++v)
    points.emplace_back(normalized(v, 0), normalized(v, 1), normalized(v, 2));
  std::vector<std::array<size_t, 3>> triangles;
  triangles.reserve(size_t(mesh.faces.rows()));
  for (Eigen::Index f = 0; f < mesh.faces.rows(); ++f) {
    const auto corners = mesh.faces.row(f);
    if (corners[0] == corners[1] || corners[1] == corners[2] || corners[2] == corners[0])
      continue;  // no area
    triangles.push_back({size_t(corners[0]), size_t(corners[1]), size_t(corners[2])});
  }
  SurfaceMesh sm;
  if (strict && !buildSurfaceMesh(points, triangles, sm)) return unchanged(mesh, "not a 2-manifold");
  if (!strict && !buildSurfaceMesh(points, triangles, sm)) {
    // Faces oriented against their neighbours, or edges with three faces: CGAL's soup orientation flips
    // faces and duplicates the vertices where the surface is not a disk (the copies come after the input's
    // vertices, whose indices stay). The mesh itself is not changed; only its decimation is built from this.
    CGAL::Polygon_mesh_processing::orient_polygon_soup(points, triangles);
    if (!buildSurfaceMesh(points, triangles, sm))
      return unchanged(mesh, "not decimated: the mesh could not be made a 2-manifold");
  }
  const size_t pointCount = points.size();

  std::vector<int> absorbedBy(pointCount);
  std::iota(absorbedBy.begin(), absorbedBy.end(), 0);
  CollapseRecord record;
  record.absorbedBy = &absorbedBy;
  // Garland-Heckbert plane quadrics: cost and placement.
  SMS::GarlandHeckbert_plane_policies<SurfaceMesh, Kernel> quadrics(sm);
  // About three edges per vertex on a closed triangle mesh (E = 3V - 3 chi).
  SMS::Count_stop_predicate<SurfaceMesh> stop(SurfaceMesh::size_type(3) *
                                              SurfaceMesh::size_type(targetVertices));
  SMS::edge_collapse(sm, stop,
                     CGAL::parameters::get_cost(quadrics.get_cost())
                         .get_placement(quadrics.get_placement())
                         .visitor(record));

  // Compact numbering of the surviving vertices, then the faces that are left.
  DecimatedMesh result;
  result.decimated = true;
  std::vector<int> compact(pointCount, -1);
  int kept = 0;
  for (const auto v : sm.vertices())
    if (!sm.is_isolated(v)) compact[size_t(v.idx())] = kept++;
  result.mesh.vertices.resize(kept, 3);
  for (const auto v : sm.vertices())
    if (compact[size_t(v.idx())] >= 0) {
      const Kernel::Point_3& p = sm.point(v);
      result.mesh.vertices.row(compact[size_t(v.idx())]) =
          Eigen::RowVector3d(p.x(), p.y(), p.z()) * diagonal + centre;
    }
  result.mesh.faces.resize(Eigen::Index(sm.number_of_faces()), 3);
  Eigen::Index row = 0;
  for (const auto f : sm.faces()) {
    int c = 0;
    for (const auto v : CGAL::vertices_around_face(sm.halfedge(f), sm))
      result.mesh.faces(row, c++) = compact[size_t(v.idx())];
    ++row;
  }

  result.representative.assign(static_cast<size_t>(n), -1);
  for (Eigen::Index f = 0; f < mesh.faces.rows(); ++f)
    for (int c = 0; c < 3; ++c) {
      const int v = mesh.faces(f, c);
      result.representative[size_t(v)] = compact[size_t(survivor(absorbedBy, v))];
    }
  return result;
}

}  // namespace

DecimatedMesh decimateMesh(const TriangleMesh& mesh, int targetVertices) {
  const Eigen::Index n = mesh.vertices.rows();
  if (targetVertices <= 0 || n <= targetVertices) return unchanged(mesh, "within the vertex budget");
  if (n <= kCoarseningAbove * Eigen::Index(targetVertices)) return collapseEdges(mesh, targetVertices, false);

  // Large meshes: fast collapses to about kCoarsenedVertices x the budget first (EdgeCoarsening), then the
  // quadric collapses from there. A mesh OpenMesh cannot hold takes the quadric collapses alone.
  CoarsenedMesh coarse = coarsenEdges(mesh, Eigen::Index(kCoarsenedVertices) * targetVertices);
  if (coarse.ok) {
    DecimatedMesh result = collapseEdges(coarse.mesh, targetVertices, true);
    if (result.decimated) {
      std::vector<int> representative(size_t(n), -1);  // input vertex -> coarse vertex -> survivor
      for (size_t v = 0; v < representative.size(); ++v)
        if (const int c = coarse.representative[v]; c >= 0)
          representative[v] = result.representative[size_t(c)];
      result.representative = std::move(representative);
      result.coarsenedVertices = int(coarse.mesh.vertices.rows());
      result.coarsened = std::move(coarse.mesh);
      return result;
    }
  }
  return collapseEdges(mesh, targetVertices, false);
}

}  // namespace medial
