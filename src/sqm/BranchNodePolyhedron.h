/// \file
/// BranchNodePolyhedron: steps 1 and 2 of SQM for one branch node, in the bind pose (thesis chapter,
/// sections "BNP generation" and "BNP refinement"; CESCG 2014 section 4).
///
/// Generation: one intersection vertex where each edge of the node leaves its sphere; their convex hull
/// on the sphere (a closed "pillow" of two fans when they are coplanar, as with three edges), with Steiner
/// points added where a hull face leaves a cap wider than 75 degrees (beyond the papers: both sides of a
/// pillow, the far side of three arms); each triangle
/// split in six (a vertex at its centre and at each edge's middle); the new vertices projected onto the
/// sphere along a ray: an edge's middle along the mean normal of its two triangles (radially when those
/// cancel, as on a pillow's rim), a centre along the normal of the triangle of its three projected edge
/// middles - the thesis's fix for obtuse triangles, used for every triangle since it equals the face
/// normal on regular ones.
///
/// Refinement: a Link Intersection Edge (LIE) of two intersection vertices a, b is the chain of edges whose
/// ends are neighbours of both; splitting one of its edges adds one neighbour to a and to b. The valence of
/// every intersection vertex is raised to what its path needs (see SqmMesher), splitting the LIE's
/// representative (first) edge each time, and the LIE is smoothed after each split.
#pragma once

#include <Eigen/Core>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <string>
#include <vector>

namespace medial {

/// OpenMesh traits of the polyhedra: double-precision points and normals.
struct SqmMeshTraits : public OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;   ///< double precision
  using Normal = OpenMesh::Vec3d;  ///< double precision
};
/// A branch node polyhedron's triangle mesh.
using BnpMesh = OpenMesh::TriMesh_ArrayKernelT<SqmMeshTraits>;

/// The smoothing after each LIE split (thesis, "Smoothing schemes"): averaging, quaternion
/// (default), area- or valency-weighted Laplacian.
enum class LieSmoothing { Averaging, Quaternion, AreaLaplacian, ValencyLaplacian };
/// The scheme's name as the command line spells it ("quaternion", "area-laplacian", ...).
const char* lieSmoothingName(LieSmoothing smoothing);
/// The scheme named `name`; false, leaving `smoothing` alone, for an unknown name.
bool parseLieSmoothing(const std::string& name, LieSmoothing& smoothing);
/// Every scheme's name (the one list the filter, the command line and the GUI offer).
std::vector<std::string> lieSmoothingNames();

/// The polyhedron of one branch node (SQM stage 2): the convex hull of the points where its
/// edges leave its sphere, refined by LIE splits and projected onto the sphere.
struct BranchNodePolyhedron {
  int node = -1;                                    ///< the skeleton node
  Eigen::Vector3d centre;                           ///< the node's position (bind pose)
  double radius = 0;                                ///< the node's radius: the sphere the polyhedron lies on
  BnpMesh mesh;                                     ///< the hull, refined
  std::vector<int> neighbourNodes;                  ///< skeleton node each intersection vertex points to
  std::vector<BnpMesh::VertexHandle> intersection;  ///< one per neighbour node, same order
  std::vector<BnpMesh::VertexHandle> steiner;       ///< hull points in caps no edge leaves through
  std::vector<int> lieSplits;                       ///< per hull edge (index into hullEdges): splits so far
  /// Pairs of hull points joined by a LIE: intersection vertices 0..n-1, then Steiner points n, n+1, ...
  std::vector<std::pair<int, int>> hullEdges;

  /// Hull point i: intersection vertex i, or Steiner point i - intersection.size().
  BnpMesh::VertexHandle hullVertex(int i) const {
    return i < int(intersection.size()) ? intersection[size_t(i)] : steiner[size_t(i) - intersection.size()];
  }

  /// The number of edges at intersection vertex i.
  int valence(int i) const { return int(mesh.valence(intersection[size_t(i)])); }
  /// The neighbours of intersection vertex i in counter-clockwise order seen from outside (about the
  /// outward direction from the centre through it).
  std::vector<BnpMesh::VertexHandle> orderedRing(int i) const;
};

/// Builds the subdivided BNP of a node at `centre` with `radius` whose edges point to `neighbourPositions`
/// (bind pose). Returns false with `error` when two edges leave in the same direction.
bool generateBnp(int node, const Eigen::Vector3d& centre, double radius,
                 const std::vector<int>& neighbourNodes,
                 const std::vector<Eigen::Vector3d>& neighbourPositions, BranchNodePolyhedron& bnp,
                 std::string& error);

/// Raises the valence of the intersection vertices: exact[i] = true requires valence == target[i] (the
/// parent's vertex, fixed by the parent's BNP), false requires valence >= target[i]. Vertices are served
/// in order: exact ones first. Returns false with `error` when a requirement cannot be met.
bool refineBnp(BranchNodePolyhedron& bnp, const std::vector<int>& target, const std::vector<bool>& exact,
               LieSmoothing smoothing, std::string& error);

}  // namespace medial
