"""A skeleton seen through its mesh: VTK's own rendering with Medial's ghost pass (importance map).

    xvfb-run -a python3 examples/ghost_view.py [MESH] [OUTDIR]
"""
import os
import sys

import vtk
import medial

mesh = sys.argv[1] if len(sys.argv) > 1 else "data/meshes/capsule.vtp"
out = sys.argv[2] if len(sys.argv) > 2 else "out/examples"
os.makedirs(out, exist_ok=True)
if not os.environ.get("DISPLAY"):
    print("ghost_view: VTK needs an X display here: run under xvfb-run -a")
    sys.exit(77)  # CTest's SKIP_RETURN_CODE
skeleton = medial.skeletonize(mesh, nodes=25)


def actor(polydata, rgb):
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputData(polydata)
    result = vtk.vtkActor()
    result.SetMapper(mapper)
    result.GetProperty().SetColor(*rgb)
    return result


tubes = vtk.vtkTubeFilter()
tubes.SetInputData(skeleton.polydata)
tubes.SetRadius(0.008 * skeleton.mesh.polydata.GetLength())
tubes.SetNumberOfSides(12)
tubes.Update()
bones = actor(tubes.GetOutput(), (0.85, 0.15, 0.1))
renderer = vtk.vtkRenderer()
renderer.AddActor(actor(skeleton.mesh.polydata, (0.9, 0.85, 0.7)))
renderer.AddActor(bones)
renderer.SetBackground(1, 1, 1)
ghost = medial.vtkMedialGhostPass()
medial.vtkMedialGhostPass.SetImportance(bones, 1.0)  # the bones show through whatever hides them
renderer.SetPass(ghost)
window = vtk.vtkRenderWindow()
window.SetOffScreenRendering(1)
window.SetSize(640, 480)
window.AddRenderer(renderer)
renderer.GetActiveCamera().Azimuth(30)  # a three-quarter view of a y-up mesh
renderer.ResetCamera()
window.Render()

grab = vtk.vtkWindowToImageFilter()
grab.SetInput(window)
png = vtk.vtkPNGWriter()
png.SetInputConnection(grab.GetOutputPort())
png.SetFileName(os.path.join(out, "ghost_view.png"))
png.Write()
print("wrote", png.GetFileName())
