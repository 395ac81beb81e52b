"""Skeleton, skinning weights and a Blender rig of a mesh, with a picture of the weights.

    python3 examples/skeleton_and_rig.py [MESH] [OUTDIR]
"""
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import medial

mesh = sys.argv[1] if len(sys.argv) > 1 else "data/external/cgal/meshes/elephant.off"
out = sys.argv[2] if len(sys.argv) > 2 else "out/examples"
os.makedirs(out, exist_ok=True)

skeleton = medial.skeletonize(mesh, nodes=25, weights=True)
print(skeleton)
skeleton.save(os.path.join(out, "skeleton.vtp"))
print("wrote", medial.rig(skeleton, path=os.path.join(out, "rig.glb")))

# Each vertex coloured by the bone that moves it most; the skeleton's bones on top. The mesh is y-up (as
# the rig's default up_axis): matplotlib's up is z, so x, z, y are drawn.
vertices, bone = skeleton.mesh.points[:, [0, 2, 1]], skeleton.weights.argmax(axis=1)
axes = plt.figure(figsize=(6, 5)).add_subplot(projection="3d")
axes.scatter(*vertices.T, c=bone, cmap="tab20", s=2, alpha=0.5)
for a, b in skeleton.edges:
    axes.plot(*skeleton.nodes[[a, b]][:, [0, 2, 1]].T, color="black", linewidth=2)
axes.set_box_aspect(vertices.max(axis=0) - vertices.min(axis=0))
axes.view_init(elev=10, azim=-30)
axes.set_axis_off()
plt.savefig(os.path.join(out, "skeleton_and_rig.png"), dpi=120, bbox_inches="tight")
print("wrote", os.path.join(out, "skeleton_and_rig.png"))
