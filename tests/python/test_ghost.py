"""vtkMedialGhostPass from Python: a sphere inside a box shows through the box once it is of interest."""
import os
import sys
import unittest

import vtk
import medial


def actor(source, rgb):
    source.Update()
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputData(source.GetOutput())
    result = vtk.vtkActor()
    result.SetMapper(mapper)
    result.GetProperty().SetColor(*rgb)
    return result


def red_pixels(window):
    grab = vtk.vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.Update()
    scalars = grab.GetOutput().GetPointData().GetScalars()
    count = 0
    for i in range(scalars.GetNumberOfTuples()):
        r, g, b = scalars.GetTuple3(i)[:3]
        count += r > 120 and r > 1.6 * g and r > 1.6 * b
    return count / scalars.GetNumberOfTuples()


class GhostPassFromPython(unittest.TestCase):
    def test_sphere_inside_a_box_shows_when_of_interest(self):
        box = vtk.vtkCubeSource()
        box.SetXLength(4), box.SetYLength(4), box.SetZLength(4)
        sphere = vtk.vtkSphereSource()
        sphere.SetRadius(1.0)
        renderer = vtk.vtkRenderer()
        renderer.AddActor(actor(box, (0.9, 0.85, 0.7)))
        interest = actor(sphere, (0.9, 0.1, 0.1))
        renderer.AddActor(interest)
        ghost = medial.vtkMedialGhostPass()
        renderer.SetPass(ghost)
        window = vtk.vtkRenderWindow()
        window.SetOffScreenRendering(1)
        window.SetSize(200, 150)
        window.AddRenderer(renderer)
        renderer.ResetCamera()

        window.Render()
        hidden = red_pixels(window)
        medial.vtkMedialGhostPass.SetImportance(interest, 1.0)
        window.Render()
        shown = red_pixels(window)
        ghost.SetModeToCutaway()
        window.Render()
        cut = red_pixels(window)
        window.Finalize()
        self.assertLess(hidden, 0.001, "the box hides the sphere")
        self.assertGreater(shown, 0.02, "ghosted, the box lets the sphere through")
        self.assertGreater(cut, 0.02, "cut away, too")
        self.assertEqual(ghost.GetLastInterestCount(), 1)
        self.assertEqual(interest.GetPropertyKeys().Get(medial.vtkMedialGhostPass.IMPORTANCE()), 1.0)


if __name__ == "__main__":
    if not os.environ.get("DISPLAY"):
        print("no X display: run under xvfb-run -a")
        sys.exit(77)  # CTest SKIP_RETURN_CODE
    unittest.main()
