#!/usr/bin/python3
"""Reads a run's particles.h5 (layout: src/slides/io/hdf5_particles.h) with h5py and plots
what a spray engineer looks at first: the deposition map on the target (where the particles
arrived, in the target plane) and the distribution of impact speeds.

    tools/plot_hdf5.py foamCases/analyticSpray/slides/particles.h5 deposition.png

Needs Debian's python3-h5py and python3-matplotlib (installed by tools/setup)."""
import argparse
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def in_plane_axes(positions):
    """The two coordinates spanning the target plane: the axes along which arrivals spread
    (the plane's normal is the axis along which they barely vary)."""
    spread = positions.std(axis=0)
    normal = int(np.argmin(spread))
    return [axis for axis in range(3) if axis != normal], normal


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("file", help="particles.h5 of a finished run")
    parser.add_argument("png", help="image to write")
    parser.add_argument("--surface", type=int, default=0, help="surface index (default 0)")
    arguments = parser.parse_args()

    with h5py.File(arguments.file, "r") as h5:
        arrivals = h5["arrivals"]
        chosen = arrivals["surface"][:] == arguments.surface
        positions = arrivals["position"][:][chosen]
        velocities = arrivals["velocity"][:][chosen]
        diameters = arrivals["diameter"][:][chosen]
        last = sorted(h5["frames"])[-1]
        end_time = h5["frames"][last].attrs["time"]
        case = h5.attrs["case"]
        case = case.decode() if isinstance(case, bytes) else case
    if len(positions) == 0:
        sys.exit(f"{arguments.file}: no particle arrived at surface {arguments.surface}")

    (a, b), normal = in_plane_axes(positions)
    names = "xyz"
    speeds = np.linalg.norm(velocities, axis=1)
    figure, (deposit, histogram) = plt.subplots(1, 2, figsize=(11, 4.6))
    counts, a_edges, b_edges = np.histogram2d(positions[:, a] * 1e3, positions[:, b] * 1e3, bins=60)
    image = deposit.imshow(counts.T, origin="lower", cmap="viridis", aspect="equal",
                           extent=(a_edges[0], a_edges[-1], b_edges[0], b_edges[-1]))
    figure.colorbar(image, ax=deposit, label="particles per bin")
    deposit.set_xlabel(f"{names[a]} [mm]")
    deposit.set_ylabel(f"{names[b]} [mm]")
    deposit.set_title(f"deposition map ({len(positions)} particles, "
                      f"plane {names[normal]} = {positions[:, normal].mean() * 1e3:.3g} mm)")
    histogram.hist(speeds, bins=50, color="tab:orange", edgecolor="black", linewidth=0.3)
    histogram.axvline(speeds.mean(), color="black", linestyle="--",
                      label=f"mean {speeds.mean():.3g} m/s")
    histogram.set_xlabel("impact speed [m/s]")
    histogram.set_ylabel("particles")
    histogram.set_title(f"impact speeds (mean diameter {diameters.mean() * 1e6:.3g} µm)")
    histogram.legend()
    figure.suptitle(f"{case}   (t = {end_time:.4g} s)", fontsize=9)
    figure.tight_layout()
    figure.savefig(arguments.png, dpi=110)
    print(f"wrote {arguments.png}: {len(positions)} arrivals, impact speed "
          f"{speeds.mean():.4g} ± {speeds.std():.3g} m/s")


if __name__ == "__main__":
    main()
