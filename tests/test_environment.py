"""The machine can do what the course needs: VTK renders off screen (through EGL on Linux)."""
import subprocess
import sys

RENDER = """
from course_lib.draw import configure_offscreen_vtk
configure_offscreen_vtk()
import numpy as np, pyvista as pv
plotter = pv.Plotter(off_screen=True, window_size=(160, 120))
plotter.add_mesh(pv.Sphere(), color="orange")
image = plotter.screenshot(return_img=True)
plotter.close()
print(image.shape, int(np.unique(image.reshape(-1, image.shape[-1]), axis=0).shape[0]))
"""


def test_vtk_renders_off_screen():
    """Run in a subprocess: without GL libraries VTK crashes the process instead of raising."""
    done = subprocess.run([sys.executable, "-c", RENDER], capture_output=True, text=True,
                          timeout=120)
    assert done.returncode == 0, (
        f"VTK could not render off screen (exit code {done.returncode}). On Debian install "
        f"libegl1 and libgl1-mesa-dri (scripts/system-packages does).\n{done.stderr[-2000:]}")
    shape, colours = done.stdout.split(")")
    assert shape.strip() == "(120, 160, 3"
    assert int(colours) > 10, "the rendered image is (nearly) one colour: nothing was drawn"
    assert "bad X server" not in done.stderr
