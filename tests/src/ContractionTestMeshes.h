// Procedural triangle meshes with known skeletons for the contraction tests.
#pragma once

#include "mesh/MeshTopology.h"
#include "mesh/TriangleMesh.h"

#include <cmath>
#include <cstdint>
#include <vector>

namespace medial::testing {

// Torus around the z axis: major radius R, minor radius r; its skeleton is the circle of radius R.
inline TriangleMesh torusMesh(double R, double r, int rings = 48, int sides = 16) {
  TriangleMesh mesh;
  mesh.vertices.resize(rings * sides, 3);
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < sides; ++j) {
      const double u = 2 * M_PI * i / rings, v = 2 * M_PI * j / sides;
      mesh.vertices.row(i * sides + j) << (R + r * std::cos(v)) * std::cos(u),
          (R + r * std::cos(v)) * std::sin(u), r * std::sin(v);
    }
  mesh.faces.resize(2 * rings * sides, 3);
  int f = 0;
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < sides; ++j) {
      const int a = i * sides + j, b = ((i + 1) % rings) * sides + j,
                c = ((i + 1) % rings) * sides + (j + 1) % sides, d = i * sides + (j + 1) % sides;
      mesh.faces.row(f++) << a, b, c;
      mesh.faces.row(f++) << a, c, d;
    }
  return mesh;
}

// Closed capsule-like tube along x from -length/2 to length/2 with radius r (a cylinder closed by fans).
inline TriangleMesh tubeMesh(double length, double r, int rings = 40, int sides = 16) {
  TriangleMesh mesh;
  mesh.vertices.resize(rings * sides + 2, 3);
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < sides; ++j) {
      const double x = -length / 2 + length * i / (rings - 1), v = 2 * M_PI * j / sides;
      mesh.vertices.row(i * sides + j) << x, r * std::cos(v), r * std::sin(v);
    }
  const int left = rings * sides, right = left + 1;
  mesh.vertices.row(left) << -length / 2 - r, 0, 0;
  mesh.vertices.row(right) << length / 2 + r, 0, 0;
  mesh.faces.resize(2 * (rings - 1) * sides + 2 * sides, 3);
  int f = 0;
  for (int i = 0; i + 1 < rings; ++i)
    for (int j = 0; j < sides; ++j) {
      const int a = i * sides + j, b = (i + 1) * sides + j, c = (i + 1) * sides + (j + 1) % sides,
                d = i * sides + (j + 1) % sides;
      mesh.faces.row(f++) << a, c, b;
      mesh.faces.row(f++) << a, d, c;
    }
  for (int j = 0; j < sides; ++j) {
    mesh.faces.row(f++) << left, (j + 1) % sides, j;  // oriented as the side faces
    const int last = (rings - 1) * sides;
    mesh.faces.row(f++) << right, last + j, last + (j + 1) % sides;
  }
  return mesh;
}

inline TriangleMesh appendMesh(const TriangleMesh& a, const TriangleMesh& b,
                               const Eigen::RowVector3d& shift) {
  TriangleMesh m;
  m.vertices.resize(a.vertices.rows() + b.vertices.rows(), 3);
  m.vertices << a.vertices, (b.vertices.rowwise() + shift);
  m.faces.resize(a.faces.rows() + b.faces.rows(), 3);
  m.faces << a.faces, (b.faces.array() + int(a.vertices.rows())).matrix();
  return m;
}

// The topology (MeshTopology) of a triangle mesh.
inline MeshTopology topologyOf(const TriangleMesh& mesh) {
  std::vector<std::vector<int64_t>> faces;
  for (Eigen::Index f = 0; f < mesh.faces.rows(); ++f)
    faces.push_back({mesh.faces(f, 0), mesh.faces(f, 1), mesh.faces(f, 2)});
  return computeMeshTopology(mesh.vertices.rows(), faces);
}

// The mesh with a third face on the edge of its first face: a fin, an edge no halfedge structure can hold.
inline TriangleMesh withFin(TriangleMesh mesh) {
  const int a = mesh.faces(0, 0), b = mesh.faces(0, 1);
  mesh.vertices.conservativeResize(mesh.vertices.rows() + 1, 3);
  mesh.vertices.row(mesh.vertices.rows() - 1) << 0, 0, 3;
  mesh.faces.conservativeResize(mesh.faces.rows() + 1, 3);
  mesh.faces.row(mesh.faces.rows() - 1) << a, b, int(mesh.vertices.rows() - 1);
  return mesh;
}

}  // namespace medial::testing
