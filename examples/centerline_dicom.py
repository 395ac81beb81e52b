"""Centerline and diameter profile of a colon in a CT series (DICOM folder, .nrrd, .nii, .mha).

    python3 examples/centerline_dicom.py [CT|phantom] [OUTDIR]

With `phantom` (the default), medial-make-colon-phantom makes a synthetic colon CT as a DICOM series.
"""
import os
import shutil
import subprocess
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import medial

out = sys.argv[2] if len(sys.argv) > 2 else "out/examples"
os.makedirs(out, exist_ok=True)
ct = sys.argv[1] if len(sys.argv) > 1 else "phantom"
if ct == "phantom":
    ct = os.path.join(out, "colon-dicom")
    maker = os.environ.get("MEDIAL_COLON_PHANTOM") or shutil.which("medial-make-colon-phantom") or \
        "build/bin/medial-make-colon-phantom"  # the installed one, else the build tree's
    subprocess.run([maker, ct], check=True, stdout=subprocess.DEVNULL)

colon = medial.centerline(ct, threshold=(-1024, -600), sections=True, surface=True)
print(colon, *colon.notes, sep="\n  ")
colon.save(os.path.join(out, "colon-centerline.vtp"))
colon.surface.save(os.path.join(out, "colon-lumen.stl"))

profile = colon.sections
plt.figure(figsize=(7, 3))
plt.fill_between(profile["ArcLength"], profile["MinDiameter"], profile["MaxDiameter"], alpha=0.4,
                 label="min to max diameter")
plt.plot(profile["ArcLength"], profile["MinDiameter"], label="min diameter")
plt.xlabel("arc length along the centerline (mm)"), plt.ylabel("diameter (mm)"), plt.legend()
plt.savefig(os.path.join(out, "centerline_dicom.png"), dpi=120, bbox_inches="tight")
print("wrote", os.path.join(out, "centerline_dicom.png"))
