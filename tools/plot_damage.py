#!/usr/bin/env python3
"""Plots an eroding surface's damage (surfaces/erosion_grid.h, Section 5.2 of the reference):
the accumulated damage on the layer's surface and on a section through its centre (read from
the last damage_<surface>_NNNNNN.vti of a run), and σ_eq on the centre line impact by impact at
three depths (from damage.h5).

    python3 tools/plot_damage.py RUN_DIRECTORY out.png [--surface layer]
"""
import glob
import os

from tool_startup import run_output_arguments, system_python_or_exit

try:
    import h5py
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOXML import vtkXMLImageDataReader
except ImportError as error:
    system_python_or_exit(error, "python3-vtk9 python3-matplotlib python3-h5py")


def main():
    parser = run_output_arguments(__doc__)
    parser.add_argument("--surface", default="layer")
    args = parser.parse_args()
    frames = sorted(glob.glob(os.path.join(args.output_directory, f"damage_{args.surface}_*.vti")))
    reader = vtkXMLImageDataReader()
    reader.SetFileName(frames[-1])
    reader.Update()
    image = reader.GetOutput()
    nx, ny, nz = image.GetDimensions()
    spacing = image.GetSpacing()
    damage = vtk_to_numpy(image.GetPointData().GetArray("damage")).reshape(nz, ny, nx)
    width, thickness = (nx - 1) * spacing[0] * 1e3, (nz - 1) * spacing[2] * 1e3

    fig, axes = plt.subplots(1, 3, figsize=(13, 3.8))
    shown = axes[0].imshow(damage[0], origin="lower", cmap="inferno",
                           extent=[-width / 2, width / 2, -width / 2, width / 2])
    axes[0].set_title("accumulated damage, surface")
    axes[0].set_xlabel("mm")
    fig.colorbar(shown, ax=axes[0], label="impacts with Σ > 0")
    shown = axes[1].imshow(damage[:, ny // 2, :], origin="upper", cmap="inferno", aspect="auto",
                           extent=[-width / 2, width / 2, thickness, 0])
    axes[1].set_title("section through the centre")
    axes[1].set_xlabel("mm")
    axes[1].set_ylabel("depth [mm]")
    fig.colorbar(shown, ax=axes[1])

    with h5py.File(os.path.join(args.output_directory, "damage.h5"), "r") as h5:
        time = h5[f"{args.surface}/centreLineTime"][:]
        stress = h5[f"{args.surface}/centreLineSigmaEq"][:]
    for k in (1, nz // 2, nz - 1):
        axes[2].plot(time * 1e3, stress[:, k] / 1e6, ".", ms=2,
                     label=f"depth {k * spacing[2] * 1e3:.3g} mm")
    axes[2].set_yscale("log")
    axes[2].set_xlabel("t [ms]")
    axes[2].set_ylabel("σ_eq [MPa]")
    axes[2].set_title("σ_eq on the centre line, per impact")
    axes[2].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(args.png, dpi=90)


if __name__ == "__main__":
    main()
