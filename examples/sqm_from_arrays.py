"""A quad-dominant tube mesh (SQM) of a skeleton given as numpy arrays: a star of five limbs.

    python3 examples/sqm_from_arrays.py [OUTDIR]
"""
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
from mpl_toolkits.mplot3d.art3d import Poly3DCollection
import numpy as np
import medial

out = sys.argv[1] if len(sys.argv) > 1 else "out/examples"
os.makedirs(out, exist_ok=True)

# A centre node, five limbs of three nodes each, thinning towards the tips.
angles = np.linspace(0, 2 * np.pi, 5, endpoint=False)
limbs = [[(r * np.cos(a), r * np.sin(a), 0.3 * r) for r in (1.0, 2.0, 3.0)] for a in angles]
nodes = np.vstack([[(0, 0, 0)], np.reshape(limbs, (-1, 3))])
edges = [(0 if k == 0 else 1 + 3 * limb + k - 1, 1 + 3 * limb + k) for limb in range(5) for k in range(3)]
radius = np.hstack([[0.6], np.tile([0.45, 0.35, 0.25], 5)])

tube = medial.sqm((nodes, edges, radius), subdivide=2, capsule=True)  # rounded tips
print(tube, "closed" if tube.is_closed() else "OPEN")
print("wrote", tube.save(os.path.join(out, "star.obj")))

axes = plt.figure(figsize=(6, 5)).add_subplot(projection="3d")
axes.add_collection3d(Poly3DCollection([tube.points[p] for p in tube.polygons], facecolor="#d9c8a0",
                                       edgecolor="#555555", linewidths=0.2))
axes.set_xlim(-3.3, 3.3), axes.set_ylim(-3.3, 3.3), axes.set_zlim(-0.7, 1.6)
axes.set_box_aspect((6.6, 6.6, 2.3)), axes.view_init(elev=35, azim=-60)
axes.set_axis_off()
plt.savefig(os.path.join(out, "sqm_from_arrays.png"), dpi=120, bbox_inches="tight")
print("wrote", os.path.join(out, "sqm_from_arrays.png"))
