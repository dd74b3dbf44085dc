"""Start-up shared by the plotting and rendering tools (render_case.py, render_packing.py,
plot_deposit.py, plot_damage.py): a display for VTK, Debian's python3 when the one running
lacks its packages, and the command line every one of them opens with (a run's output
directory and the image to write).
"""
import argparse
import os
import shutil
import sys

TOOL = os.path.basename(sys.argv[0])


def ensure_display():
    """Debian's VTK renders through X even off screen: without a display, runs the tool again
    under a virtual one (without either, VTK aborts the process when it opens the window)."""
    if os.environ.get("DISPLAY"):
        return
    if not shutil.which("xvfb-run"):
        sys.exit(f"{TOOL}: no X display (DISPLAY is not set) and no xvfb-run to make one: "
                 "install xvfb (tools/setup does)")
    os.execvp("xvfb-run", ["xvfb-run", "-a", sys.executable, *sys.argv])


def system_python_or_exit(error, packages):
    """After an ImportError: a pyenv or venv python3 does not see Debian's packages, so runs the
    tool again with the system one; exits naming the packages if that is the one running."""
    if sys.executable != "/usr/bin/python3" and os.path.exists("/usr/bin/python3"):
        os.execv("/usr/bin/python3", ["/usr/bin/python3", *sys.argv])
    sys.exit(f"{TOOL}: {error} (Debian: apt-get install {packages})")


def run_output_arguments(doc):
    """A parser described by the first line of doc, for OUTPUT_DIRECTORY PNG [options]."""
    parser = argparse.ArgumentParser(description=doc.splitlines()[0])
    parser.add_argument("output_directory", help="the run's output, e.g. CASE/slides")
    parser.add_argument("png", help="image to write")
    return parser
