#!/usr/bin/python3
"""tools/render_case.py on a run whose last frame is empty (every particle has left), and
without any X display: what it renders, or what it says.

    test_render_case.py frame   the default frame is the last that holds particles; the PNG
                                shows them in the picture band, between title and colour bars
    test_render_case.py nodisplay   no DISPLAY and no xvfb-run: exit 1 with a message (VTK
                                aborted the process with SIGABRT and wrote no picture)
    test_render_case.py nocarrier   with a carrier.vti its slice fills the picture in blues;
                                --no-carrier leaves it out (particles alone)
"""
import os
import subprocess
import sys
import tempfile
from pathlib import Path

TOP = Path(__file__).resolve().parents[2]
RENDER = TOP / "tools" / "render_case.py"
PYTHON = "/usr/bin/python3"


def write_run(directory):
    """particles.pvd with frame 0 (three particles at x = 0, 0.05, 0.1 m) and frame 1 (none)."""
    from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
    from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

    for frame, xs in enumerate([[0.0, 0.05, 0.1], []]):
        points, vertices, speed = vtkPoints(), vtkCellArray(), vtkDoubleArray()
        speed.SetName("speed")
        for k, x in enumerate(xs):
            points.InsertNextPoint(x, 0.0, 0.01 * k)
            vertices.InsertNextCell(1)
            vertices.InsertCellPoint(k)
            speed.InsertNextValue(10.0 + k)
        data = vtkPolyData()
        data.SetPoints(points)
        data.SetVerts(vertices)
        data.GetPointData().AddArray(speed)
        writer = vtkXMLPolyDataWriter()
        writer.SetFileName(str(directory / f"particles_{frame:06d}.vtp"))
        writer.SetInputData(data)
        writer.Write()
    (directory / "particles.pvd").write_text(
        '<?xml version="1.0"?>\n<VTKFile type="Collection" version="0.1">\n<Collection>\n'
        '<DataSet timestep="0" file="particles_000000.vtp"/>\n'
        '<DataSet timestep="0.001" file="particles_000001.vtp"/>\n</Collection>\n</VTKFile>\n')


def write_carrier(directory):
    """carrier.vti: a 3 × 3 × 3 lattice over the particles' box, gas along x (magU 1 to 2)."""
    from vtkmodules.vtkCommonCore import vtkDoubleArray
    from vtkmodules.vtkCommonDataModel import vtkImageData
    from vtkmodules.vtkIOXML import vtkXMLImageDataWriter

    lattice = vtkImageData()
    lattice.SetDimensions(3, 3, 3)
    lattice.SetOrigin(0.0, -0.05, -0.05)
    lattice.SetSpacing(0.05, 0.05, 0.05)
    velocity, speed = vtkDoubleArray(), vtkDoubleArray()
    velocity.SetName("U")
    velocity.SetNumberOfComponents(3)
    speed.SetName("magU")
    for point in range(lattice.GetNumberOfPoints()):
        u = 1.0 + lattice.GetPoint(point)[0] / 0.1
        velocity.InsertNextTuple3(u, 0.0, 0.0)
        speed.InsertNextValue(u)
    lattice.GetPointData().AddArray(velocity)
    lattice.GetPointData().AddArray(speed)
    writer = vtkXMLImageDataWriter()
    writer.SetFileName(str(directory / "carrier.vti"))
    writer.SetInputData(lattice)
    writer.Write()


def render(work, *options):
    """Renders work's run to work/out.png: (result, RGB pixels as rows from the bottom)."""
    png = work / "out.png"
    result = subprocess.run([PYTHON, str(RENDER), str(work), str(png), *options],
                            capture_output=True, text=True,
                            env={k: v for k, v in os.environ.items() if k != "DISPLAY"})
    print(result.stdout, result.stderr)
    if result.returncode != 0:
        return result, None
    from vtkmodules.vtkIOImage import vtkPNGReader
    from vtkmodules.util.numpy_support import vtk_to_numpy
    reader = vtkPNGReader()
    reader.SetFileName(str(png))
    reader.Update()
    width, height, _ = reader.GetOutput().GetDimensions()
    pixels = vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars())
    return result, pixels.reshape(height, width, -1)[:, :, :3]


def frame(work):
    write_run(work)
    result, pixels = render(work)
    if pixels is None:
        return f"render_case.py exited with {result.returncode}"
    if "particles_000000.vtp at t = 0 s" not in result.stdout:
        return "the default frame is not the last one holding particles"
    height = pixels.shape[0]
    # Particle colours are saturated (red to yellow); the labels are grey on white.
    saturated = (pixels.max(axis=2).astype(int) - pixels.min(axis=2)) > 100
    rows = saturated.any(axis=1).nonzero()[0]
    picture = rows[(rows > 0.15 * height) & (rows < 0.93 * height)]
    if len(picture) == 0:
        return "no particle drawn in the picture band"
    return None


def nocarrier(work):
    write_run(work)
    write_carrier(work)
    shares = {}
    for options in ((), ("--no-carrier",)):
        result, pixels = render(work, *options)
        if pixels is None:
            return f"render_case.py {' '.join(options)} exited with {result.returncode}"
        height = pixels.shape[0]
        band = pixels[int(0.2 * height):int(0.9 * height)].astype(int)
        # The backdrop's blues: blue well above red (particles are red to yellow, labels grey).
        shares[options] = ((band[:, :, 2] - band[:, :, 0]) > 60).mean()
    print(f"blue share of the picture band: {shares}")
    if shares[()] < 0.2:
        return "the carrier slice does not fill the picture"
    if shares[("--no-carrier",)] > 0:
        return "--no-carrier still draws the carrier"
    return None


def nodisplay(work):
    write_run(work)
    empty = work / "bin"
    empty.mkdir()
    env = {"PATH": str(empty), "HOME": str(work)}
    result = subprocess.run([PYTHON, str(RENDER), str(work), str(work / "out.png")],
                            capture_output=True, text=True, env=env)
    print(result.stdout, result.stderr)
    expected = ("render_case.py: no X display (DISPLAY is not set) and no xvfb-run to make one: "
                "install xvfb (tools/setup does)\n")
    if result.returncode != 1 or result.stderr != expected:
        return f"exit status {result.returncode}, stderr {result.stderr!r}"
    return None


if __name__ == "__main__":
    with tempfile.TemporaryDirectory() as work:
        failure = {"frame": frame, "nodisplay": nodisplay,
                   "nocarrier": nocarrier}[sys.argv[1]](Path(work))
    if failure:
        sys.exit(f"test_render_case.py {sys.argv[1]}: {failure}")
