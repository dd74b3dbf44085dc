#!/usr/bin/env python3
"""Renders a packed ensemble (an injector of model ensemble, integrate/ensemble.h) as spheres.

    python3 tools/render_packing.py CASE/slides out.png [--cut x|y|z]

Takes the first frame of particles.pvd that holds particles (an ensemble starts at rest, all
at once), draws each particle as a sphere of its diameter coloured by it, and cuts the packing
in half by the plane through its centre normal to --cut (default x), so the inside shows.
Renders off screen; without a display, under xvfb-run (Debian: python3-vtk9, xvfb).
"""

import os
import sys
import xml.etree.ElementTree as ElementTree

from tool_startup import ensure_display, run_output_arguments, system_python_or_exit

ensure_display()
try:
    import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the render window implementation)
except ImportError as error:
    system_python_or_exit(error, "python3-vtk9")

from vtkmodules.vtkCommonDataModel import vtkPlane
from vtkmodules.vtkFiltersCore import vtkGlyph3D
from vtkmodules.vtkFiltersPoints import vtkExtractPoints
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
from vtkmodules.vtkRenderingCore import (
    vtkActor,
    vtkPolyDataMapper,
    vtkRenderer,
    vtkRenderWindow,
    vtkWindowToImageFilter,
)


def first_frame_with_particles(run):
    """The output of the first frame of run/particles.pvd that holds particles."""
    for entry in ElementTree.parse(os.path.join(run, "particles.pvd")).getroot().iter("DataSet"):
        reader = vtkXMLPolyDataReader()
        reader.SetFileName(os.path.join(run, entry.get("file")))
        reader.Update()
        if reader.GetOutput().GetNumberOfPoints() > 0:
            return reader.GetOutput()
    sys.exit(f"render_packing.py: no frame of {run}/particles.pvd holds particles")


def main():
    parser = run_output_arguments(__doc__)
    parser.add_argument("--cut", choices="xyz", default="x")
    arguments = parser.parse_args()

    particles = first_frame_with_particles(arguments.output_directory)
    bounds = particles.GetBounds()
    centre = [(bounds[2 * a] + bounds[2 * a + 1]) / 2 for a in range(3)]
    axis = "xyz".index(arguments.cut)
    normal = [0.0, 0.0, 0.0]
    normal[axis] = 1.0
    plane = vtkPlane()
    plane.SetOrigin(centre)
    plane.SetNormal(normal)
    behind = vtkExtractPoints()  # the half on the plane's negative side
    behind.SetInputData(particles)
    behind.SetImplicitFunction(plane)
    behind.ExtractInsideOn()
    behind.Update()
    behind.GetOutput().GetPointData().SetActiveScalars("diameter")

    sphere = vtkSphereSource()
    sphere.SetRadius(0.5)
    sphere.SetThetaResolution(16)
    sphere.SetPhiResolution(12)
    glyphs = vtkGlyph3D()
    glyphs.SetInputConnection(behind.GetOutputPort())
    glyphs.SetSourceConnection(sphere.GetOutputPort())
    glyphs.SetScaleModeToScaleByScalar()
    glyphs.SetScaleFactor(1.0)
    glyphs.SetColorModeToColorByScalar()
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(glyphs.GetOutputPort())
    mapper.SetScalarRange(behind.GetOutput().GetPointData().GetArray("diameter").GetRange())
    actor = vtkActor()
    actor.SetMapper(mapper)

    renderer = vtkRenderer()
    renderer.AddActor(actor)
    renderer.SetBackground(1, 1, 1)
    camera = renderer.GetActiveCamera()
    camera.SetFocalPoint(centre)
    position = list(centre)
    position[axis] += 1.0  # looking at the cut face
    camera.SetPosition(position)
    camera.SetViewUp([0.0, 0.0, 1.0] if axis != 2 else [0.0, 1.0, 0.0])
    camera.Elevation(20)
    renderer.ResetCamera()
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(800, 800)
    window.AddRenderer(renderer)
    window.Render()
    image = vtkWindowToImageFilter()
    image.SetInput(window)
    writer = vtkPNGWriter()
    writer.SetFileName(arguments.png)
    writer.SetInputConnection(image.GetOutputPort())
    writer.Write()


if __name__ == "__main__":
    main()
