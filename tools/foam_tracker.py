"""The same particles through the same OpenFOAM field, tracked by OpenFOAM's
uncoupledKinematicParcelFoam and by slides-track: set-up, runs and readers shared by
tools/compare-foam-tracker and tools/bench/foam-vs-uncoupled.

A solved 3-D impingingJet (foamCases/impingingJet/Allrun -3d; OpenFOAM cannot track in the
wedge) is the input. Under WORK (default CASE/compareFoamTracker) this builds two cases that
share the mesh and the converged U:

  WORK/slides/     constant/slidesProperties (foamField carrier, drag putnam = OpenFOAM's
                   sphereDrag, gravity with buoyancy, all particles injected at t = 0 with no
                   cross-span speed), the latest simpleFoam time; run by slides-track.
  WORK/openfoam/   particleTracking/ dictionaries of the case (kinematicCloudProperties: the
                   same drag, gravity, stick at the plate), 0/U from simpleFoam, uniform p and T
                   giving ρ = 1.1 kg/m³; each parcel injected at the position and with the
                   velocity its particle has in slides-track's first frame (both codes then
                   start from the same state); run by uncoupledKinematicParcelFoam.

Without slides-track (--foam-only) the particles start at t = 0 on a seeded random sample of
the injection disc with the nozzle velocity.
"""

import json
import math
import os
import re
import shutil
import subprocess
import time
import xml.etree.ElementTree as ElementTree
from pathlib import Path

import numpy as np

FOAM_ENV = dict(os.environ, WM_PROJECT_DIR=os.environ.get("WM_PROJECT_DIR", "/usr/share/openfoam"))

# The comparison's particles and gas (those of constant/slidesProperties, analyticSpray's spray).
PARTICLE_DENSITY = 5680.0  # kg/m³
GAS_DENSITY = 1.1  # kg/m³
GAS_VISCOSITY = 25e-6  # m²/s
NOZZLE_VELOCITY = 25.0  # m/s
STANDOFF = 0.06  # m
# Injection disc: 0.1 mm inside the mesh (OpenFOAM cannot inject on the inlet face) and r ≤
# 1.5 mm, inside the potential core, where the gas moves at the nozzle velocity.
INJECTION_PLANE = 1e-4  # m
INJECTION_RADIUS = 1.5e-3  # m
DT = 1e-5  # s, both codes
FRAME_INTERVAL = 2.5e-4  # s, both codes
END_TIME = 0.01  # s

SLIDES_PROPERTIES = """/*--------------------------------*- C++ -*----------------------------------*\\
  SLIDES-track: written by tools/foam_tracker.py for the comparison with
  uncoupledKinematicParcelFoam; the spray of constant/slidesProperties with OpenFOAM's drag law.
\\*---------------------------------------------------------------------------*/
FoamFile {{ version 2.0; format ascii; class dictionary; object slidesProperties; }}

standoff {standoff};

fluid
{{
    density             [1 -3 0 0 0 0 0] {gas_density};
    kinematicViscosity  [0 2 -1 0 0 0 0] {gas_viscosity};
    temperature         [0 0 0 1 0 0 0] 293.15;
}}

nozzle
{{
    centre      ({injection_plane} 0 0);
    axis        (1 0 0);
    radius      {injection_radius};
    crossSpanDirection (0 1 0);
}}

carrier
{{
    type        foamField;
    foamFieldCoeffs {{ time latestTime; interpolation {interpolation}; }}
}}

particles
{{
    count       {count};
    density     {particle_density};
    radiusDistribution {{ type fixed; value {radius}; }}
}}

injection {{ mode allAtStart; crossSpanSpeed 0; seed {seed}; }}

// OpenFOAM's cloud has drag, gravity and buoyancy only: every other term off, not auto.
physics
{{
    drag putnam; gravity (0 -9.81 0); buoyancy on;
    history {{ model none; }} addedMass off; pressureGradient off; lift none; spin off;
    dispersion {{ model none; }} heatTransfer {{ model none; }}
}}
collisions {{ model none; }}

time {{ dt {dt}; endTime {end_time}; stopWhenAllDone yes; integrator exponentialMidpoint; }}

surfaces
{{
    target {{ type plane; point ($:standoff 0 0); normal (-1 0 0); }}
}}

domain {{ min (0 -0.04 -0.04); max (0.06 0.04 0.04); }}

output {{ interval {frame_interval}; carrierResolution (61 41 41); }}
"""


def run_logged(command, cwd, log_name, env=None):
    """Runs command in cwd with its output in cwd/log_name; wall time in seconds."""
    start = time.perf_counter()
    with open(Path(cwd) / log_name, "w") as log:
        result = subprocess.run(command, cwd=cwd, stdout=log, stderr=subprocess.STDOUT, env=env)
    elapsed = time.perf_counter() - start
    if result.returncode != 0:
        tail = (Path(cwd) / log_name).read_text().splitlines()[-20:]
        raise RuntimeError(f"{' '.join(map(str, command))} failed in {cwd}:\n" + "\n".join(tail))
    return elapsed


def latest_time_directory(case):
    times = []
    for entry in Path(case).iterdir():
        try:
            times.append((float(entry.name), entry))
        except ValueError:
            pass
    if not times:
        raise RuntimeError(f"{case} holds no time directory: run its Allrun first")
    return max(times)[1]


def check_three_dimensional(case):
    boundary = (Path(case) / "constant/polyMesh/boundary").read_text()
    if re.search(r"type\s+wedge", boundary):
        raise RuntimeError(f"{case} is the wedge variant: OpenFOAM cannot track particles in "
                           "wedges; solve the 3-D one with ./Allrun -3d")


def link_mesh(case, target):
    (target / "constant").mkdir(parents=True, exist_ok=True)
    mesh = target / "constant/polyMesh"
    if not mesh.exists():
        mesh.symlink_to((Path(case) / "constant/polyMesh").resolve())


def prepare_slides(case, work, count, radius, seed, interpolation="cellPoint"):
    """WORK/slides: the mesh, the latest solution and the comparison's slidesProperties
    (interpolation: the foamFieldCoeffs entry, e.g. "lattice; latticeSpacing 5e-4")."""
    target = work / "slides"
    shutil.rmtree(target, ignore_errors=True)
    link_mesh(case, target)
    latest = latest_time_directory(case)
    shutil.copytree(latest, target / latest.name)
    (target / "constant/slidesProperties").write_text(SLIDES_PROPERTIES.format(
        standoff=STANDOFF, gas_density=GAS_DENSITY, gas_viscosity=GAS_VISCOSITY,
        injection_plane=INJECTION_PLANE, injection_radius=INJECTION_RADIUS, count=count,
        particle_density=PARTICLE_DENSITY, radius=radius, seed=seed, dt=DT, end_time=END_TIME,
        frame_interval=FRAME_INTERVAL, interpolation=interpolation))
    return target


def run_slides(executable, slides_case, threads=1):
    """Runs slides-track; its summary.json."""
    command = [str(executable), str(slides_case), "--threads", str(threads)]
    run_logged(command, slides_case, "log.slides-track")
    return json.loads((slides_case / "slides" / "summary.json").read_text())


def read_slides_frames(output_directory):
    """The frames of particles.pvd: list of (time, {id: (position, velocity, state)})."""
    import vtk  # python3-vtk9; only needed for slides' output
    from vtk.util.numpy_support import vtk_to_numpy

    pvd = ElementTree.parse(Path(output_directory) / "particles.pvd")
    frames = []
    for dataset in pvd.iter("DataSet"):
        reader = vtk.vtkXMLPolyDataReader()
        reader.SetFileName(str(Path(output_directory) / dataset.get("file")))
        reader.Update()
        data = reader.GetOutput()
        particles = {}
        if data.GetNumberOfPoints() > 0:
            points = vtk_to_numpy(data.GetPoints().GetData())
            fields = data.GetPointData()
            ids = vtk_to_numpy(fields.GetArray("id"))
            velocities = vtk_to_numpy(fields.GetArray("velocity"))
            states = vtk_to_numpy(fields.GetArray("state"))
            for k, particle in enumerate(ids):
                particles[int(particle)] = (points[k], velocities[k], int(states[k]))
        frames.append((float(dataset.get("timestep")), particles))
    return frames


def write_foam_field(path, field_class, dimensions, value):
    path.write_text(
        f"FoamFile {{ version 2.0; format ascii; class {field_class}; object {path.name}; }}\n"
        f"dimensions {dimensions};\ninternalField uniform {value};\n"
        f"boundaryField {{ \".*\" {{ type calculated; value uniform {value}; }} }}\n")


def frozen_velocity(source):
    """simpleFoam's U with every patch `calculated` at its solved values (the parcel solver only
    reads U, and its cellPoint interpolation takes the boundary points' values from them): the
    nozzle keeps its 25 m/s, the noSlip plate (no value written) is zero."""
    text = Path(source).read_text()
    start = text.index("boundaryField")
    boundary = re.sub(r"type\s+noSlip;", "type calculated; value uniform (0 0 0);", text[start:])
    return text[:start] + re.sub(r"type\s+\w+;", "type calculated;", boundary)


def write_positions(path, positions):
    lines = "\n".join(f"({p[0]:.12g} {p[1]:.12g} {p[2]:.12g})" for p in positions)
    path.write_text("FoamFile { version 2.0; format ascii; class vectorField; "
                    f"object {path.name}; }}\n{len(positions)}\n(\n{lines}\n)\n")


def injection_models(nozzle, positions, velocities, constant):
    """The template's `nozzle` manualInjection once per particle, each with its own positions
    file and U0 (manualInjection gives all its parcels one U0); origId k is then particle k, as
    parcels are numbered in injection order."""
    models = []
    for k, (position, velocity) in enumerate(zip(positions, velocities)):
        write_positions(constant / f"kinematicCloudPositions.{k}", [position])
        model = re.sub(r'positionsFile\s+"[^"]*";', f'positionsFile   "kinematicCloudPositions.{k}";',
                       nozzle)
        model = re.sub(r"U0\s+\([^)]*\);",
                       "U0              ({:.12g} {:.12g} {:.12g});".format(*velocity), model)
        models.append(model.replace("nozzle", f"particle{k}", 1))
    return "\n".join(models)


def prepare_openfoam(case, work, positions, velocities, start_time, diameter):
    """WORK/openfoam: parcels injected at start_time at the given positions, with one velocity
    for all (a vector: one injection model) or one each (an N × 3 array: one model each)."""
    target = work / "openfoam"
    shutil.rmtree(target, ignore_errors=True)
    template = Path(case) / "particleTracking"
    shutil.copytree(template / "system", target / "system")
    shutil.copytree(template / "constant", target / "constant")
    link_mesh(case, target)
    start = target / f"{start_time:g}"
    start.mkdir()
    (start / "U").write_text(frozen_velocity(latest_time_directory(case) / "U"))
    # ρ = p W/(R T) = 1.1 kg/m³ with W of constant/thermophysicalProperties.
    write_foam_field(start / "p", "volScalarField", "[1 -1 -2 0 0 0 0]", "1e5")
    write_foam_field(start / "T", "volScalarField", "[0 0 0 1 0 0 0]", "293.15")
    cloud = target / "constant/kinematicCloudProperties"
    text = cloud.read_text()
    text = re.sub(r"SOI\s+[^;]+;", f"SOI             {start_time:.12g};", text)
    text = re.sub(r"value\s+160e-6;", f"value   {diameter:.12g};", text)
    velocities = np.asarray(velocities, dtype=float)
    if velocities.ndim == 1:
        write_positions(target / "constant/kinematicCloudPositions", positions)
        text = re.sub(r"U0\s+\([^)]*\);",
                      "U0              ({:.12g} {:.12g} {:.12g});".format(*velocities), text)
    else:
        nozzle = re.search(r"^        nozzle\n        \{\n.*?^        \}\n", text, re.S | re.M).group(0)
        text = text.replace(nozzle, injection_models(nozzle, positions, velocities,
                                                     target / "constant") + "\n")
    cloud.write_text(text)
    control = target / "system/controlDict"
    text = control.read_text()
    text = re.sub(r"startTime\s+[^;]+;", f"startTime       {start_time:.12g};", text)
    control.write_text(text)
    return target


def run_openfoam(foam_case):
    """Runs uncoupledKinematicParcelFoam; (wall time, tracking time, particle-steps)."""
    wall = run_logged(["uncoupledKinematicParcelFoam"], foam_case, "log.uncoupledKinematicParcelFoam",
                      env=FOAM_ENV)
    log = (foam_case / "log.uncoupledKinematicParcelFoam").read_text()
    parcels = [int(n) for n in re.findall(r"Current number of parcels\s*=\s*(\d+)", log)]
    execution = [float(t) for t in re.findall(r"ExecutionTime = ([0-9.eE+-]+) s", log)]
    tracking = execution[-1] - execution[0] if len(execution) > 1 else float("nan")
    return wall, tracking, sum(parcels[1:])


def cloud_list(path):
    """An ASCII lagrangian field file: (count, the text between its outer parentheses), or
    (count, the value) for the compact uniform form `N{value}`."""
    text = Path(path).read_text()
    body = re.sub(r"//.*", "", text[text.index("}") + 1:]).strip()  # after the FoamFile header
    uniform = re.match(r"(\d+)\s*\{\s*(.*?)\s*\}", body, re.S)
    if uniform:
        return int(uniform.group(1)), uniform.group(2)
    listed = re.match(r"(\d+)\s*\((.*)\)\s*$", body, re.S)
    if listed is None:
        raise RuntimeError(f"{path}: not an ASCII list (writeFormat ascii expected)")
    return int(listed.group(1)), listed.group(2)


def read_vectors(path):
    count, body = cloud_list(path)
    vectors = re.findall(r"\(([^()]+)\)", body)
    if len(vectors) == 1 and count > 1:
        vectors *= count
    return np.array([np.array(v.split(), dtype=float) for v in vectors]).reshape(count, 3)


def read_labels(path):
    count, body = cloud_list(path)
    labels = body.split()
    if len(labels) == 1 and count > 1:
        labels *= count
    return [int(label) for label in labels]


def read_openfoam_frames(foam_case):
    """The cloud at each written time: list of (time, {origId: (position, velocity)}); the
    `positions` file holds `(x y z) cell` per parcel."""
    frames = []
    for entry in Path(foam_case).iterdir():
        try:
            when = float(entry.name)
        except ValueError:
            continue
        cloud = entry / "lagrangian/kinematicCloud"
        particles = {}
        if (cloud / "positions").exists():
            positions = read_vectors(cloud / "positions")
            velocities = read_vectors(cloud / "U")
            for k, particle in enumerate(read_labels(cloud / "origId")):
                particles[particle] = (positions[k], velocities[k])
        frames.append((when, particles))
    return sorted(frames, key=lambda frame: frame[0])


def read_openfoam_arrivals(foam_case, start_time):
    """Parcels that hit the plate: {origId: (time, position, velocity)}, from the
    patchPostProcessing records (a `#` header naming the columns, vectors in parentheses);
    the arrival time is the injection time plus the parcel's age."""
    token = re.compile(r"\([^()]*\)|[^\s()]+")

    def column_name(item):  # "(U0 U1 U2)" → "U"
        return re.sub(r"0$", "", item.strip("()").split()[0]) if item.startswith("(") else item

    arrivals = {}
    root = Path(foam_case) / "postProcessing/lagrangian/kinematicCloud/plateArrivals"
    for post in root.glob("*/*.post"):
        names = None
        for line in post.read_text().splitlines():
            if line.startswith("#"):
                names = [column_name(item) for item in token.findall(line.lstrip("#"))]
            elif line.strip() and names:
                record = dict(zip(names, token.findall(line)))
                vector = lambda key: np.array(record[key].strip("()").split(), dtype=float)
                arrivals[int(record["origId"])] = (start_time + float(record["age"]),
                                                   vector("position"), vector("U"))
    return arrivals


def random_disc(count, seed):
    rng = np.random.default_rng(seed)
    r = INJECTION_RADIUS * np.sqrt(rng.random(count))
    theta = 2 * math.pi * rng.random(count)
    return np.column_stack([np.full(count, INJECTION_PLANE), r * np.cos(theta), r * np.sin(theta)])


def first_slides_frame(frames):
    """slides-track's first frame with particles: (time, ids, positions, velocities)."""
    for when, particles in frames:
        moving = {k: v for k, v in particles.items() if v[2] == 0}
        if moving:
            ids = sorted(moving)
            positions = np.array([moving[k][0] for k in ids])
            velocities = np.array([moving[k][1] for k in ids])
            return when, ids, positions, velocities
    raise RuntimeError("slides-track wrote no frame with moving particles")
