#!/usr/bin/env python3
"""Renders a run's output to a PNG, for checking a run without opening ParaView.

    python3 tools/render_case.py CASE/slides out.png [--time T] [--normal x|y|z] [--no-carrier]

Shows the last frame of particles.pvd that holds particles (points coloured by speed) in front
of a slice of carrier.vti through the jet (coloured by magU; --no-carrier leaves it out, e.g.
for an unsteady carrier, whose carrier.vti holds time 0), seen from the side with a parallel
camera; the slice is the lattice plane through the fastest gas, moved behind the particles as a
backdrop. The title and colour bars have their own bands above and below the picture.
The jet axis is the lattice axis of the largest mean |U| component; the view looks along the
other axis with the smaller mean |U| component (the extrusion axis of a planar jet), or --normal.
Needs VTK's Python bindings (Debian: python3-vtk9); renders off screen, without a display
under xvfb-run (Debian: xvfb; tools/setup installs both).
"""
import os
import re
import sys
import xml.etree.ElementTree as ElementTree

from tool_startup import ensure_display, run_output_arguments, system_python_or_exit

ensure_display()
try:
    from vtkmodules.util.numpy_support import vtk_to_numpy
except ImportError as error:
    system_python_or_exit(error, "python3-vtk9 python3-numpy")

import vtkmodules.vtkRenderingFreeType  # noqa: F401 (text rendering)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the render window implementation)
from vtkmodules.vtkImagingCore import vtkExtractVOI
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkIOXML import vtkXMLImageDataReader, vtkXMLPolyDataReader
from vtkmodules.vtkRenderingAnnotation import vtkScalarBarActor
from vtkmodules.vtkRenderingCore import (
    vtkActor,
    vtkDataSetMapper,
    vtkPolyDataMapper,
    vtkRenderer,
    vtkRenderWindow,
    vtkTextActor,
    vtkWindowToImageFilter,
)
from vtkmodules.vtkCommonCore import vtkLookupTable

AXES = "xyz"
# Fractions of the window height: colour bars below the picture, the title above it.
BAR_BAND = 0.15
TITLE_BAND = 0.07
WINDOW_SIZE = (1000, 600)


def point_count(vtp):
    """NumberOfPoints of a .vtp file, read from its XML head (the data may be appended raw)."""
    with open(vtp, "rb") as file:
        head = file.read(4096)
    found = re.search(rb'NumberOfPoints="(\d+)"', head)
    return int(found.group(1)) if found else 0


def choose_frame(pvd, time):
    """(time, path) of the DataSet in the .pvd nearest to time; without a time the last one that
    holds particles (once every particle has arrived or left, the last frames are empty), or
    the last one when none does."""
    data_sets = ElementTree.parse(pvd).getroot().findall("./Collection/DataSet")
    if not data_sets:
        sys.exit(f"render_case.py: {pvd} lists no frames")
    path = lambda data_set: os.path.join(os.path.dirname(pvd), data_set.get("file"))
    if time is None:
        holding = [data_set for data_set in data_sets if point_count(path(data_set)) > 0]
        chosen = (holding or data_sets)[-1]
    else:
        chosen = min(data_sets, key=lambda data_set: abs(float(data_set.get("timestep")) - time))
    return float(chosen.get("timestep")), path(chosen)


def read(reader_class, path):
    reader = reader_class()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def lookup_table(value_range, hue_range, saturation_range, value_range_hsv):
    table = vtkLookupTable()
    table.SetTableRange(value_range[0], max(value_range[1], value_range[0] + 1e-12))
    table.SetHueRange(*hue_range)
    table.SetSaturationRange(*saturation_range)
    table.SetValueRange(*value_range_hsv)
    table.Build()
    return table


def label(text, x_position, y_position, size):
    """Dark text whose top left corner is at the given fractions of the window."""
    actor = vtkTextActor()
    actor.SetInput(text)
    actor.GetTextProperty().SetColor(0.1, 0.1, 0.1)
    actor.GetTextProperty().SetFontSize(size)
    actor.GetTextProperty().SetVerticalJustificationToTop()
    actor.GetPositionCoordinate().SetCoordinateSystemToNormalizedViewport()
    actor.SetPosition(x_position, y_position)
    return actor


def scalar_bar(table, title, x_position):
    """A horizontal colour bar in the band below the picture: its title above it, its labels
    below it (VTK's own title would sit among the labels)."""
    bar = vtkScalarBarActor()
    bar.SetLookupTable(table)
    bar.SetNumberOfLabels(5)
    bar.SetLabelFormat("%.3g")
    bar.SetOrientationToHorizontal()
    bar.SetPosition(x_position, 0.005)
    bar.SetWidth(0.4)
    bar.SetHeight(BAR_BAND - 0.05)
    bar.SetTextPositionToPrecedeScalarBar()
    bar.UnconstrainedFontSizeOn()  # the size below, not one grown to the bar's height
    text = bar.GetLabelTextProperty()
    text.SetColor(0.1, 0.1, 0.1)
    text.SetFontSize(14)
    text.BoldOff()
    text.ShadowOff()
    text.ItalicOff()
    return bar, label(title, x_position + 0.01, BAR_BAND - 0.005, 15)


def side_view(carrier, normal_option):
    """(jet axis, view normal, up axis, camera side ±1 along the normal), axes as indices.
    Without a carrier (a scene without gas) the view is along y (or --normal) with z up."""
    if carrier is None:
        normal = AXES.index(normal_option) if normal_option else 1
        up = 2 if normal != 2 else 1
        jet_axis = 3 - normal - up
        return jet_axis, normal, up, (-1 if up == (normal + 1) % 3 else 1)
    mean_component = abs(vtk_to_numpy(carrier.GetPointData().GetArray("U"))).mean(axis=0)
    jet_axis = int(mean_component.argmax())
    if normal_option:
        normal = AXES.index(normal_option)
    else:
        normal = min((axis for axis in range(3) if axis != jet_axis),
                     key=lambda axis: mean_component[axis])
    up = 3 - jet_axis - normal
    # The jet points right when (view direction × up) = e_jet; e_normal × e_up = e_jet exactly
    # when (normal, up, jet) is cyclic, so then the camera looks along +normal.
    side = -1 if up == (normal + 1) % 3 else 1
    return jet_axis, normal, up, side


def carrier_backdrop(carrier, normal, side):
    """The lattice plane through the fastest gas (exact lattice values, no interpolation),
    coloured by magU, and its lookup table."""
    speed = vtk_to_numpy(carrier.GetPointData().GetArray("magU"))
    dimensions = carrier.GetDimensions()
    fastest = [0, 0, 0]
    carrier.ComputeStructuredCoordinates(carrier.GetPoint(int(speed.argmax())), fastest, [0.0] * 3)
    extent = [0, dimensions[0] - 1, 0, dimensions[1] - 1, 0, dimensions[2] - 1]
    extent[2 * normal] = extent[2 * normal + 1] = fastest[normal]
    plane = vtkExtractVOI()
    plane.SetInputData(carrier)
    plane.SetVOI(extent)
    plane.Update()

    table = lookup_table(carrier.GetPointData().GetArray("magU").GetRange(),
                         (0.62, 0.55), (0.9, 0.15), (0.45, 1.0))
    mapper = vtkDataSetMapper()
    mapper.SetInputConnection(plane.GetOutputPort())
    mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectColorArray("magU")
    mapper.SetLookupTable(table)
    mapper.UseLookupTableScalarRangeOn()
    actor = vtkActor()
    actor.SetMapper(mapper)
    # Moved to the lattice face away from the camera, so no particle hides behind it.
    far_face = carrier.GetBounds()[2 * normal + (1 if side < 0 else 0)]
    offset = [0.0, 0.0, 0.0]
    offset[normal] = far_face - plane.GetOutput().GetBounds()[2 * normal]
    actor.SetPosition(offset)
    return actor, table


def particle_actor(particles):
    speed_range = (particles.GetPointData().GetArray("speed").GetRange()
                   if particles.GetNumberOfPoints() else (0.0, 1.0))
    table = lookup_table(speed_range, (0.0, 0.17), (1.0, 1.0), (0.55, 1.0))
    mapper = vtkPolyDataMapper()
    mapper.SetInputData(particles)
    mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectColorArray("speed")
    mapper.SetLookupTable(table)
    mapper.UseLookupTableScalarRangeOn()
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetPointSize(4)
    actor.GetProperty().RenderPointsAsSpheresOn()
    return actor, table


def main():
    parser = run_output_arguments(__doc__)
    parser.add_argument("--normal", choices=AXES, help="view along this axis")
    parser.add_argument("--no-carrier", action="store_true",
                        help="particles alone, without carrier.vti: an unsteady carrier's "
                        "carrier.vti is its state at time 0, not at the frame's time")
    parser.add_argument("--time", type=float, help="show the frame nearest this time [s] "
                        "(default: the last frame)")
    arguments = parser.parse_args()

    time, frame_file = choose_frame(os.path.join(arguments.output_directory, "particles.pvd"),
                                    arguments.time)
    particles = read(vtkXMLPolyDataReader, frame_file)
    carrier_file = os.path.join(arguments.output_directory, "carrier.vti")
    # No carrier.vti (a run without gas, carrier none) or --no-carrier: particles alone.
    carrier = (read(vtkXMLImageDataReader, carrier_file)
               if os.path.exists(carrier_file) and not arguments.no_carrier else None)

    # The picture in the middle band; title and colour bars in a renderer of their own over
    # the whole window, so they never cover the picture.
    renderer = vtkRenderer()
    renderer.SetBackground(1, 1, 1)
    renderer.SetViewport(0, BAR_BAND, 1, 1 - TITLE_BAND)
    labels = vtkRenderer()
    labels.SetBackground(1, 1, 1)
    jet_axis, normal, up, side = side_view(carrier, arguments.normal)
    dots, speed_table = particle_actor(particles)
    renderer.AddActor(dots)
    for actor in scalar_bar(speed_table, "particle speed [m/s]", 0.05):
        labels.AddActor2D(actor)
    if carrier is not None:
        backdrop, gas_table = carrier_backdrop(carrier, normal, side)
        renderer.AddActor(backdrop)
        for actor in scalar_bar(gas_table, "carrier magU [m/s]", 0.55):
            labels.AddActor2D(actor)
    labels.AddActor2D(label(f"{os.path.basename(frame_file)}   t = {time:.6g} s   "
                            f"{particles.GetNumberOfPoints()} particles", 0.012, 0.985, 18))

    # From the side: along the view normal, jet axis pointing right, parallel projection.
    camera = renderer.GetActiveCamera()
    camera.ParallelProjectionOn()
    bounds = (carrier if carrier is not None else particles).GetBounds()
    centre = [(bounds[2 * axis] + bounds[2 * axis + 1]) / 2 for axis in range(3)]
    position = list(centre)
    position[normal] += side * (10 * (bounds[2 * normal + 1] - bounds[2 * normal]) + 1.0)
    view_up = [0.0, 0.0, 0.0]
    view_up[up] = 1.0
    camera.SetFocalPoint(centre)
    camera.SetPosition(position)
    camera.SetViewUp(view_up)
    renderer.ResetCamera()
    # Fill the picture band: the half height that shows both the up and the jet extent.
    aspect = (1 - BAR_BAND - TITLE_BAND) * WINDOW_SIZE[1] / WINDOW_SIZE[0]
    jet_half = (bounds[2 * jet_axis + 1] - bounds[2 * jet_axis]) / 2
    up_half = (bounds[2 * up + 1] - bounds[2 * up]) / 2
    camera.SetParallelScale(1.05 * max(up_half, jet_half * aspect, 1e-9))

    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(*WINDOW_SIZE)
    window.AddRenderer(labels)
    window.AddRenderer(renderer)
    window.Render()
    image = vtkWindowToImageFilter()
    image.SetInput(window)
    image.Update()
    writer = vtkPNGWriter()
    writer.SetFileName(arguments.png)
    writer.SetInputConnection(image.GetOutputPort())
    writer.Write()
    print(f"{arguments.png}: {os.path.basename(frame_file)} at t = {time:.6g} s")


if __name__ == "__main__":
    main()
