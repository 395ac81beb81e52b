/// \file
/// TubularClusters: phase I of the TSK centerline paper (WSCG 2008, section 3, "Information structuring").
/// The PDF text is garbled; this is our reading of it, step by step:
///  1. P0: the given seed, or the structure's voxel of lowest z - the rectum end of a colon. Beyond the
///     paper: when that voxel is no end of the structure (a U standing on its bend), the lower of the
///     structure's two geodesic ends is taken instead.
///  2. Layers: every voxel is labelled with its Manhattan distance to P0 measured inside the structure
///     (6-connected breadth-first steps); a layer is the set of voxels with one label.
///     Border distance: for every voxel, the distance (mm) to the nearest voxel outside the structure
///     along the six main directions (the volume's edge counts as outside).
///  3. Primitive centerline: from the chosen point P_i (a member of layer L_i), the section takes the next
///     layers L_i+1, L_i+2, ... until h^3 > 4V/pi (eq. 1: h > 2r for a cylinder of volume V = pi r^2 h),
///     with h the number of layers taken and V the number of voxels taken; the next chosen point P_i+1 is
///     the voxel of the last layer taken farthest from the border. The sequence P_0 ... P_n is the
///     primitive centerline (the last point ends the last section, whether or not it met eq. 1).
///  4. Clusters: the membership of voxel i to vertex j is mu_ij = Dm_j / D_ij, D_ij the Euclidean distance
///     from the voxel to P_j and Dm_j the smallest such distance over the voxels other than P_j (the
///     nearest voxel). A voxel joins the cluster of greatest membership, ties to the earlier vertex. Chosen
///     here: the candidates are the vertices that bound the voxel's section and the sections next to it,
///     so that a colon folding back on itself does not give a voxel to a vertex behind the wall.
///  5. Order: clusters in vertex order; inside a cluster, voxels by relative membership mu_next - mu_prev
///     (from the previous cluster's side to the next one's).
#pragma once

#include "common/Error.h"
#include "centerline/BinaryVolume.h"

#include <functional>
#include <string>
#include <vector>

namespace medial {

/// Phase I's result: the primitive centerline, the clusters and the total order of the voxels.
struct TubularClusters {
  std::vector<int64_t> primitive;              ///< the chosen points P_0 ... P_n (voxel indices)
  std::vector<float> primitiveBorderDistance;  ///< of each chosen point (mm; step 2b, six directions)
  std::vector<int> primitiveLayer;             ///< the layer of each chosen point
  std::vector<int64_t> orderedVoxels;          ///< every reached voxel, in the total order of step 5
  std::vector<int> orderedCluster;             ///< the cluster (vertex index) of each ordered voxel
  int64_t unreachedVoxels = 0;                 ///< structure voxels not 6-connected to P0
  Error error;                                 ///< why phase I failed; empty on success
  /// True when phase I succeeded.
  bool ok() const { return error.empty(); }
};

/// `seed`: a voxel index inside the structure, or -1 for the lowest-z voxel.
TubularClusters structureTube(const BinaryVolume& volume, int64_t seed = -1,
                              const std::function<bool(double)>& progress = {});

/// Step 2a on its own: the Manhattan layers from `seed` (6-connected breadth-first steps inside the
/// structure): the voxels of each layer; `layer` gets every voxel's layer (-1 where unreached).
std::vector<std::vector<int64_t>> manhattanLayers(const BinaryVolume& volume, int64_t seed,
                                                  std::vector<int>& layer);

/// Step 2b: the distance (mm) from an inside voxel to the nearest outside voxel along the six main
/// directions (the volume's edge counts as outside); never less than the Euclidean distance.
float sixDirectionBorderDistance(const BinaryVolume& volume, int64_t voxel);

/// The structure's voxel of lowest physical z (-1 when it is empty).
int64_t lowestVoxel(const BinaryVolume& volume);

}  // namespace medial
