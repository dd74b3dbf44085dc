#!/usr/bin/env python3
"""Plots a run's deposit: the height map over the target and a side view of the stuck particles.

    python3 tools/plot_deposit.py CASE/slides out.png [--surface NAME]

Reads deposit_<surface>.vti (the height map of surfaces/deposit_map.h, in the target plane's
own axes u, v) and deposit.vtp (every stuck particle), and writes a PNG with the height map
(in µm, axes in mm from the map's corner) beside the deposit's profile (height of each stuck
particle's centre against its in-plane distance from the deposit's centroid), with Eq. 5.12's
n_dep and h_dep from summary.json in the title. Needs python3-vtk9, python3-matplotlib.
"""
import json
import os
import sys

from tool_startup import run_output_arguments, system_python_or_exit

try:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOXML import vtkXMLImageDataReader, vtkXMLPolyDataReader
except ImportError as error:
    system_python_or_exit(error, "python3-vtk9 python3-matplotlib")


def main():
    parser = run_output_arguments(__doc__)
    parser.add_argument("--surface", help="deposit surface (default: the first deposit_*.vti)")
    args = parser.parse_args()
    directory = args.output_directory
    maps = sorted(f for f in os.listdir(directory) if f.startswith("deposit_") and f.endswith(".vti"))
    if args.surface:
        maps = [f"deposit_{args.surface}.vti"]
    if not maps or not os.path.exists(os.path.join(directory, maps[0])):
        sys.exit(f"plot_deposit.py: no deposit map in {directory} (no particle stuck, or no "
                 "surface with interaction deposit)")
    surface = maps[0][len("deposit_"):-len(".vti")]

    reader = vtkXMLImageDataReader()
    reader.SetFileName(os.path.join(directory, maps[0]))
    reader.Update()
    image = reader.GetOutput()
    columns, rows, _ = image.GetDimensions()
    pixel = image.GetSpacing()[0]
    height = vtk_to_numpy(image.GetPointData().GetArray("height")).reshape(rows, columns)
    direction = np.array([image.GetDirectionMatrix().GetElement(r, c) for r in range(3)
                          for c in range(3)]).reshape(3, 3)
    origin = np.array(image.GetOrigin())
    normal = direction[:, 2]

    points = vtkXMLPolyDataReader()
    points.SetFileName(os.path.join(directory, "deposit.vtp"))
    points.Update()
    centres = vtk_to_numpy(points.GetOutput().GetPoints().GetData())
    offsets = centres - origin
    heights = offsets @ normal
    inPlane = offsets @ direction[:, :2]
    radial = np.linalg.norm(inPlane - inPlane.mean(axis=0), axis=1)

    title = f"deposit on {surface}"
    summary = os.path.join(directory, "summary.json")
    if os.path.exists(summary):
        with open(summary) as f:
            deposit = json.load(f).get("deposition", {}).get(surface)
        if deposit:
            title += (f": {deposit['stuck']} stuck, n_dep = {deposit['depositedFraction']:.3f}, "
                      f"h_dep = {deposit['depositHeight'] * 1e3:.3f} mm (Eq. 5.12)")

    figure, (left, right) = plt.subplots(1, 2, figsize=(12, 5.2))
    extent = [0, columns * pixel * 1e3, 0, rows * pixel * 1e3]
    shown = left.imshow(height * 1e6, origin="lower", extent=extent, cmap="viridis")
    # Frame the bulk of the deposit (the middle 96 % of the particles in each direction, with a
    # margin): a few particles that stuck far out would otherwise shrink it to a dot.
    u = (centres - origin) @ direction[:, 0] * 1e3
    v = (centres - origin) @ direction[:, 1] * 1e3
    for axis, values in ((left.set_xlim, u), (left.set_ylim, v)):
        low, high = np.percentile(values, [2, 98])
        margin = 0.5 * (high - low) + 0.5
        axis(max(0, low - margin), high + margin)
    figure.colorbar(shown, ax=left, label="deposit height [µm]")
    left.set_xlabel("u [mm]")
    left.set_ylabel("v [mm]")
    left.set_title("height over the target plane")
    right.scatter(radial * 1e3, heights * 1e6, s=2)
    right.set_xlabel("distance from the deposit's centroid in the plane [mm]")
    right.set_ylabel("centre height above the plane [µm]")
    right.set_title("stuck particles")
    figure.suptitle(title)
    figure.tight_layout()
    figure.savefig(args.png, dpi=110)
    print(f"wrote {args.png}")


if __name__ == "__main__":
    main()
