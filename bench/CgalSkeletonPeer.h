// CGAL's Mean_curvature_flow_skeletonization as the contraction's peer, shared by
// medial_bench_contraction and the centring test (tests/src/NodeCentring_test.cpp): a CGAL surface mesh as
// Medial's TriangleMesh, and CGAL's skeleton as a medial::Skeleton.
#pragma once

#include "mesh/TriangleMesh.h"
#include "skeleton/Skeleton.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mean_curvature_flow_skeletonization.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/extract_mean_curvature_flow_skeleton.h>

namespace medial::peer {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Skeletonization = CGAL::Mean_curvature_flow_skeletonization<SurfaceMesh>;

inline TriangleMesh toTriangleMesh(const SurfaceMesh& sm) {
  TriangleMesh mesh;
  mesh.vertices.resize(Eigen::Index(sm.number_of_vertices()), 3);
  for (auto v : sm.vertices()) {
    const auto& p = sm.point(v);
    mesh.vertices.row(Eigen::Index(v.idx())) << p.x(), p.y(), p.z();
  }
  mesh.faces.resize(Eigen::Index(sm.number_of_faces()), 3);
  Eigen::Index f = 0;
  for (auto face : sm.faces()) {
    int c = 0;
    for (auto v : CGAL::vertices_around_face(sm.halfedge(face), sm)) mesh.faces(f, c++) = int(v.idx());
    ++f;
  }
  return mesh;
}

// CGAL's skeleton (its vertices and edges), for the centring measure.
inline Skeleton cgalSkeleton(const SurfaceMesh& input) {
  Skeletonization::Skeleton graph;
  CGAL::extract_mean_curvature_flow_skeleton(input, graph);
  Skeleton s;
  for (auto v : CGAL::make_range(vertices(graph))) {
    const auto& p = graph[v].point;
    s.nodes.emplace_back(p.x(), p.y(), p.z());
  }
  for (auto e : CGAL::make_range(edges(graph)))
    s.edges.push_back({int(source(e, graph)), int(target(e, graph))});
  return s;
}

}  // namespace medial::peer
