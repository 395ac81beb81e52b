#include "sketch/SketchInflation.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <Eigen/SparseCholesky>

#include <cmath>
#include <map>
#include <set>

namespace medial {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Delaunay_mesh_vertex_base_2<Kernel>;
using FaceBase = CGAL::Delaunay_mesh_face_base_2<Kernel>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds>;
using Criteria = CGAL::Delaunay_mesh_size_criteria_2<Cdt>;

// Faces outside the outline: reachable from the infinite face without crossing a constrained edge.
std::set<Cdt::Face_handle> outsideFaces(const Cdt& cdt) {
  std::set<Cdt::Face_handle> outside{cdt.infinite_face()};
  std::vector<Cdt::Face_handle> stack{cdt.infinite_face()};
  auto around = cdt.incident_faces(cdt.infinite_vertex()), done = around;
  do {
    if (outside.insert(around).second) stack.push_back(around);
  } while (++around != done);
  while (!stack.empty()) {
    const Cdt::Face_handle f = stack.back();
    stack.pop_back();
    for (int k = 0; k < 3; ++k) {
      if (cdt.is_constrained(Cdt::Edge(f, k))) continue;
      const Cdt::Face_handle g = f->neighbor(k);
      if (outside.insert(g).second) stack.push_back(g);
    }
  }
  return outside;
}

}  // namespace

bool inflatePolygon(const Polygon2& polygon, const InflationParameters& parameters, TriangleMesh& mesh,
                    std::string& error) {
  if (!(parameters.thickness > 0) || !(parameters.edgeLength > 0)) {
    error = "the inflation thickness and edge length must be > 0";
    return false;
  }
  Cdt cdt;
  std::vector<Cdt::Vertex_handle> outline;
  for (const auto& p : polygon) outline.push_back(cdt.insert(Cdt::Point(p.x(), p.y())));
  for (size_t i = 0; i < outline.size(); ++i)
    cdt.insert_constraint(outline[i], outline[(i + 1) % outline.size()]);
  try {
    CGAL::refine_Delaunay_mesh_2(cdt, Criteria(0.125, parameters.edgeLength));
  } catch (const std::exception& e) {
    error = std::string("triangulation of the outline failed: ") + e.what();
    return false;
  }
  // A chord (an inner edge between two outline vertices) would pinch the surface to z = 0 and give the
  // closed mesh an edge with four faces: split every chord at its midpoint until none is left.
  auto onOutline = [&](Cdt::Vertex_handle v) {
    auto edges = cdt.incident_edges(v), done = edges;
    do {
      if (!cdt.is_infinite(*edges) && cdt.is_constrained(*edges)) return true;
    } while (++edges != done);
    return false;
  };
  for (int round = 0; round < 64; ++round) {
    const auto outside = outsideFaces(cdt);
    std::vector<Cdt::Point> midpoints;
    for (auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e) {
      if (cdt.is_constrained(*e) || outside.count(e->first)) continue;
      const auto a = e->first->vertex(Cdt::cw(e->second)), b = e->first->vertex(Cdt::ccw(e->second));
      const Eigen::Vector2d middle(0.5 * (a->point().x() + b->point().x()),
                                   0.5 * (a->point().y() + b->point().y()));
      if (onOutline(a) && onOutline(b)) midpoints.emplace_back(middle.x(), middle.y());
    }
    if (midpoints.empty()) break;
    for (const auto& p : midpoints) cdt.insert(p);
  }
  // Vertices of the faces inside the outline (marked again: insertions after the mesher leave its marks
  // stale).
  const auto outside = outsideFaces(cdt);
  std::map<Cdt::Vertex_handle, int> index;
  std::vector<Eigen::Vector2d> points;
  std::vector<std::array<int, 3>> triangles;
  std::vector<char> outlineVertex;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (outside.count(f)) continue;
    std::array<int, 3> t;
    for (int k = 0; k < 3; ++k) {
      auto [it, added] = index.emplace(f->vertex(k), int(points.size()));
      if (added) {
        points.emplace_back(f->vertex(k)->point().x(), f->vertex(k)->point().y());
        outlineVertex.push_back(onOutline(f->vertex(k)));
      }
      t[k] = it->second;
    }
    triangles.push_back(t);
  }
  const int n = int(points.size());
  // Interior unknowns of the Poisson system K f = c M 1 (K: cotangent stiffness, M: lumped mass).
  std::vector<int> unknown(n, -1);
  int unknowns = 0;
  for (int v = 0; v < n; ++v)
    if (!outlineVertex[v]) unknown[v] = unknowns++;
  Eigen::VectorXd f = Eigen::VectorXd::Zero(n);
  if (unknowns > 0) {
    std::vector<Eigen::Triplet<double>> entries;
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(unknowns);
    for (const auto& t : triangles) {
      const Eigen::Vector2d& a = points[t[0]];
      const double area = 0.5 * std::abs((points[t[1]] - a).x() * (points[t[2]] - a).y() -
                                         (points[t[1]] - a).y() * (points[t[2]] - a).x());
      for (int k = 0; k < 3; ++k) {
        const int i = t[k], j = t[(k + 1) % 3], o = t[(k + 2) % 3];
        const Eigen::Vector2d u = points[i] - points[o], w = points[j] - points[o];
        const double cotangent = u.dot(w) / std::max(1e-300, std::abs(u.x() * w.y() - u.y() * w.x()));
        const double weight = 0.5 * cotangent;
        if (unknown[i] >= 0) entries.emplace_back(unknown[i], unknown[i], weight);
        if (unknown[j] >= 0) entries.emplace_back(unknown[j], unknown[j], weight);
        if (unknown[i] >= 0 && unknown[j] >= 0) {
          entries.emplace_back(unknown[i], unknown[j], -weight);
          entries.emplace_back(unknown[j], unknown[i], -weight);
        }
        if (unknown[i] >= 0) rhs[unknown[i]] += parameters.thickness * area / 3;
      }
    }
    Eigen::SparseMatrix<double> stiffness(unknowns, unknowns);
    stiffness.setFromTriplets(entries.begin(), entries.end());
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(stiffness);
    if (solver.info() != Eigen::Success) {
      error = "the inflation's Poisson system could not be factorized";
      return false;
    }
    const Eigen::VectorXd interior = solver.solve(rhs);
    for (int v = 0; v < n; ++v)
      if (unknown[v] >= 0) f[v] = interior[unknown[v]];
  }
  // Front vertices 0..n-1 (the outline at z = 0 shared), back copies of the interior ones after them.
  std::vector<int> back(n);
  int vertexCount = n;
  for (int v = 0; v < n; ++v) back[v] = outlineVertex[v] ? v : vertexCount++;
  mesh.vertices.resize(vertexCount, 3);
  for (int v = 0; v < n; ++v) {
    const double h = std::sqrt(std::max(0.0, f[v]));
    mesh.vertices.row(v) << points[v].x(), points[v].y(), h;
    if (back[v] != v) mesh.vertices.row(back[v]) << points[v].x(), points[v].y(), -h;
  }
  mesh.faces.resize(2 * int(triangles.size()), 3);
  for (size_t k = 0; k < triangles.size(); ++k) {
    const auto& t = triangles[k];  // counter-clockwise seen from +z: the front faces up
    mesh.faces.row(2 * k) << t[0], t[1], t[2];
    mesh.faces.row(2 * k + 1) << back[t[0]], back[t[2]], back[t[1]];
  }
  return true;
}

}  // namespace medial
