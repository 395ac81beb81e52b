/// \file
/// SkinBinding: binds any mesh to any skeleton with the heat-diffusion weights of rig/HeatWeights.h (the
/// contraction paper's §III.E, Baran and Popović 2007) - not only the contraction's own mesh and skeleton but
/// a sketch's inflated mesh and its skeleton, an SQM mesh and the skeleton it was swept from, or a mesh and
/// a skeleton drawn by hand.
///
/// The rig needs one root. A skeleton that names none gets the body centre of rig/RigRoot.h: the branch
/// node nearest the mesh's volume centroid among the nodes central along the skeleton - the hips of a
/// figure, the middle of a fish - where a rigger puts the root so that posing a limb never drags the body.
#pragma once

#include "common/Error.h"
#include "rig/HeatWeights.h"
#include "rig/RigRoot.h"

namespace medial {

/// The weights of bindSkin() and what it met.
struct SkinBindingResult {
  Eigen::MatrixXd weights;    ///< (mesh vertices x skeleton edges), rows summing to 1
  int root = -1;              ///< the skeleton's root, or its body centre when it had none
  int nodesOutside = 0;       ///< skeleton nodes outside the mesh (a bone there sees no vertex from inside)
  int invisibleVertices = 0;  ///< vertices their nearest bone does not see (weighted by diffusion only)
  Error error;                ///< why the work failed; empty on success
  /// True when the work succeeded (no error).
  bool ok() const { return error.empty(); }
};

/// Heat-diffusion weights of every mesh vertex for every skeleton edge \cite au2008 \cite baran2007.
/// \pre `skeleton` lies in `mesh`'s frame and units (its nodes inside the mesh, as a rig's bones are)
/// \param mesh the skin: a triangle mesh, several components allowed
/// \param skeleton nodes and edges (the bones); a root is chosen at the body's centre when it has none
/// \param parameters the heat constant, Blender's minimum weight, the solver (HeatWeightParameters)
/// \param progress called with the fraction done; returning false stops the work (error: Error::cancelled())
/// \return one weight per vertex and bone, rows summing to 1, or an error: no bones, no faces, a skeleton
///         entirely outside the mesh's bounding box (another unit or frame), solver failure, cancelled
SkinBindingResult bindSkin(const TriangleMesh& mesh, const Skeleton& skeleton,
                           const HeatWeightParameters& parameters = {},
                           const std::function<bool(double)>& progress = {});

}  // namespace medial
