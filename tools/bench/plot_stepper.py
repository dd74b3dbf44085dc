#!/usr/bin/python3
"""Plots the stepper benchmark: particle-steps per second against particle count, one line per
integrator, from one run of build/tools/bench/bench_stepper (all points measured together).

    /usr/bin/python3 tools/bench/plot_stepper.py [out.png]     (default build/bench_stepper.png)

Also writes the figures as CSV beside the PNG. Uses Debian's python3-matplotlib.
"""
import csv
import json
import os
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

top = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
bench = os.path.join(top, "build", "tools", "bench", "bench_stepper")
png = sys.argv[1] if len(sys.argv) > 1 else os.path.join(top, "build", "bench_stepper.png")
if not os.access(bench, os.X_OK):
    sys.exit(f"plot_stepper.py: {bench} is not built; run tools/setup first")

report = json.loads(subprocess.run([bench, "--benchmark_format=json"], check=True,
                                   capture_output=True, text=True).stdout)
rows = []
for run in report["benchmarks"]:
    arguments = dict(part.split(":") for part in run["run_name"].split("/")[1:] if ":" in part)
    rows.append({"integrator": run["label"], "particles": int(arguments["particles"]),
                 "particleStepsPerSecond": run["items_per_second"]})

with open(os.path.splitext(png)[0] + ".csv", "w", newline="") as table:
    writer = csv.DictWriter(table, fieldnames=["integrator", "particles", "particleStepsPerSecond"])
    writer.writeheader()
    writer.writerows(rows)

figure, axes = plt.subplots(figsize=(7, 4.5))
for integrator in dict.fromkeys(row["integrator"] for row in rows):
    points = sorted((row["particles"], row["particleStepsPerSecond"]) for row in rows
                    if row["integrator"] == integrator)
    axes.plot([p for p, _ in points], [s / 1e6 for _, s in points], "o-", label=integrator)
context = report["context"]
axes.set_xscale("log")
axes.set_xlabel("particles in flight")
axes.set_ylabel("million particle-steps per second")
axes.set_ylim(bottom=0)
axes.set_title(f"stepper, drag + gravity on the analytic jet "
               f"({context['num_cpus']} CPUs, {context['date'][:10]})", fontsize=10)
axes.grid(True, which="both", alpha=0.3)
axes.legend()
figure.tight_layout()
figure.savefig(png, dpi=110)
print(f"{png} and {os.path.splitext(png)[0]}.csv")
