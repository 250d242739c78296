"""ParaView state for an arksph run: particles coloured by speed in a 2D view.

Use it from the ParaView GUI:
    paraview --script=paraview/arksph_state.py              # run directory from $ARKSPH_RUN,
    ARKSPH_RUN=/tmp/myrun paraview --script=paraview/arksph_state.py   # default runs/default
or, with ParaView open: View > Python Shell > Run Script, and pick this file (set ARKSPH_RUN
before starting ParaView, or edit RUN below).

What it builds (Pipeline Browser):
    particles.pvd  (PVD reader: every output frame, the time steps drive the animation toolbar)
      speed        (Calculator: speed = mag(velocity), a point array)
shown as points (spheres, one particle spacing wide), coloured by speed with a colour bar, in a
2D view (parallel projection, looking down -z, fitted to the particles), on white.

Switching fields (GUI): select "speed" in the Pipeline Browser and pick another array in the
colouring combo box of the toolbar: pressure, density, phase, velocity (Magnitude / X / Y),
mass, id. Click "Rescale to data range" (or "Rescale over all timesteps") after a change of time.
Switching fields (Python Shell), e.g. pressure:
    ColorBy(GetDisplayProperties(FindSource("speed")), ("POINTS", "pressure"))
    GetDisplayProperties(FindSource("speed")).RescaleTransferFunctionToDataRange(False, True)
    Render()
or the x velocity:  ColorBy(GetDisplayProperties(FindSource("speed")), ("POINTS", "velocity", "X"))
For batch pictures of any field at given times use paraview/render.py (see paraview/README.md).
"""

import math
import os

from paraview.simple import (Calculator, ColorBy, GetActiveViewOrCreate, GetAnimationScene,
                             GetColorTransferFunction, GetScalarBar, PVDReader, Render,
                             ResetCamera, SetActiveSource, Show)

# The run to open: $ARKSPH_RUN (a run directory or its particles.pvd), else runs/default relative
# to the current directory, else relative to the repository this script lives in.
RUN = os.environ.get("ARKSPH_RUN", "runs/default")


def _find_pvd(run):
    candidates = [run]
    if not os.path.isabs(run):
        try:  # __file__ is not set when pasted into the Python Shell
            repo = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
            candidates.append(os.path.join(repo, run))
        except NameError:
            pass
    for c in candidates:
        pvd = os.path.join(c, "particles.pvd") if os.path.isdir(c) else c
        if os.path.isfile(pvd):
            return os.path.abspath(pvd)
    raise RuntimeError("arksph_state.py: no particles.pvd for '%s' (set ARKSPH_RUN to a run "
                       "directory, e.g. ARKSPH_RUN=runs/default after ./build/arksph run)" % run)


pvd = _find_pvd(RUN)

# Reader: the .pvd collection, one time step per output frame.
reader = PVDReader(registrationName="particles.pvd", FileName=pvd)
scene = GetAnimationScene()
scene.UpdateAnimationUsingDataTimeSteps()

# speed = |velocity|, as its own point array (so that its range and colour bar are its own).
speed = Calculator(registrationName="speed", Input=reader)
speed.AttributeType = "Point Data"
speed.ResultArrayName = "speed"
speed.Function = "mag(velocity)"

view = GetActiveViewOrCreate("RenderView")
if "UseColorPaletteForBackground" in view.ListProperties():
    view.UseColorPaletteForBackground = 0
view.Background = [1.0, 1.0, 1.0]
view.OrientationAxesVisibility = 0

display = Show(speed, view)
display.SetRepresentationType("Points")
if "RenderPointsAsSpheres" in display.ListProperties():
    display.RenderPointsAsSpheres = 1

# Colour by speed over the whole run (the range does not jump from frame to frame).
ColorBy(display, ("POINTS", "speed"))
display.RescaleTransferFunctionToDataRange(False, True)
lut = GetColorTransferFunction("speed")
try:
    # Range over all time steps; cheap for runs of a few hundred frames.
    lo, hi = None, None
    for t in reader.TimestepValues or [0.0]:
        speed.UpdatePipeline(t)
        a, b = speed.PointData["speed"].GetRange()
        lo = a if lo is None else min(lo, a)
        hi = b if hi is None else max(hi, b)
    if hi is not None and hi > lo:
        lut.RescaleTransferFunction(lo, hi)
        if "AutomaticRescaleRangeMode" in lut.ListProperties():
            lut.AutomaticRescaleRangeMode = "Never"
except Exception:  # keep the per-frame range
    pass
bar = GetScalarBar(lut, view)
bar.Title = "speed"
bar.ComponentTitle = ""
if "HorizontalTitle" in bar.ListProperties():
    bar.HorizontalTitle = 1
bar.TitleColor = [0.0, 0.0, 0.0]
bar.LabelColor = [0.0, 0.0, 0.0]
bar.WindowLocation = "Any Location"
bar.Orientation = "Vertical"
bar.Position = [0.86, 0.12]
bar.ScalarBarLength = 0.6
display.SetScalarBarVisibility(view, True)

# 2D view: parallel projection, camera on +z looking down, fitted to the particle bounds.
times = reader.TimestepValues
t0 = (times[0] if isinstance(times, (list, tuple)) and times else
      (times if isinstance(times, float) else 0.0))
speed.UpdatePipeline(t0)
info = speed.GetDataInformation()
x0, x1, y0, y1, _, _ = info.GetBounds()
n = max(info.GetNumberOfPoints(), 1)
view.InteractionMode = "2D"
view.CameraParallelProjection = 1
cx, cy = 0.5 * (x0 + x1), 0.5 * (y0 + y1)
view.CameraFocalPoint = [cx, cy, 0.0]
view.CameraPosition = [cx, cy, 10.0 + max(x1 - x0, y1 - y0)]
view.CameraViewUp = [0.0, 1.0, 0.0]
ResetCamera(view)
# Move the particles left of centre, clear of the colour bar on the right.
shift = 0.15 * (x1 - x0)
view.CameraFocalPoint = [cx + shift, cy, 0.0]
view.CameraPosition = [cx + shift, cy, 10.0 + max(x1 - x0, y1 - y0)]
# Point size in pixels: about one particle spacing at the fitted zoom.
spacing = math.sqrt(max(x1 - x0, 1e-12) * max(y1 - y0, 1e-12) / n)
height_px = (view.ViewSize[1] if view.ViewSize and view.ViewSize[1] > 0 else 800)
world_h = 2.0 * view.CameraParallelScale if view.CameraParallelScale > 0 else (y1 - y0) * 1.1
display.PointSize = max(2.0, min(40.0, 0.9 * spacing * height_px / max(world_h, 1e-12)))

SetActiveSource(speed)
Render(view)
