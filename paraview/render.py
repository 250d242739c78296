"""Render an arksph run to PNG files with ParaView (pvbatch).

    scripts/pvbatch.sh paraview/render.py RUN_DIR [--field speed] [--times 0 1 5] [--out DIR]
                                          [--size W H] [--point-size PX] [--palette]

RUN_DIR is a run's output directory (or its particles.pvd). For each requested simulated time the
nearest stored timestep is shown: the particles as points (spheres), coloured by the field, with a
colour bar titled with the field and the time, in a 2D view (parallel projection from +z) on white.
Each picture is saved as <field>_t<time>.png, <time> being the stored timestep's time (%g).

For every picture one line goes to stdout (tests parse it):
    frame time=<t> requested=<t> points=<n> arrays=<a,b,...> field=<name> range=<min>,<max> png=<path>

Exit codes: 0 done; 2 bad input (no .pvd, unknown or absent field, bad argument).
"""

import argparse
import math
import os
import sys

FIELDS = {
    # name: (array, component for ColorBy, component for GetRange)
    "speed": ("velocity", "Magnitude", -1),
    "pressure": ("pressure", None, 0),
    "density": ("density", None, 0),
    "summation_density": ("summation_density", None, 0),
    "phase": ("phase", None, 0),
    "velocity_x": ("velocity", "X", 0),
    "velocity_y": ("velocity", "Y", 1),
}


def fail(msg, code=2):
    # os._exit, not sys.exit: a SystemExit raised once a render view exists makes pvbatch finalize
    # Python before VTK lets go of its GLX context ("X Error ... GLXBadContext", exit status 1).
    sys.stdout.flush()
    sys.stderr.write("render.py: %s\n" % msg)
    sys.stderr.flush()
    os._exit(code)


def parse_args(argv):
    p = argparse.ArgumentParser(prog="render.py", description=__doc__.split("\n\n")[0])
    p.add_argument("run", help="run directory or its particles.pvd")
    p.add_argument("--field", default="speed", help="one of " + ", ".join(FIELDS))
    p.add_argument("--times", type=float, nargs="+", default=None,
                   help="simulated times; the nearest stored timestep is used (default: first and last)")
    p.add_argument("--out", default=None, help="output directory (default: the run directory)")
    p.add_argument("--size", type=int, nargs=2, default=[800, 800], metavar=("W", "H"))
    p.add_argument("--point-size", type=float, default=None,
                   help="point diameter in pixels (default: from the particle spacing)")
    p.add_argument("--palette", action="store_true",
                   help="save 256-colour palette PNGs (about 4x smaller; needs python3-pil)")
    a = p.parse_args(argv)
    if a.field not in FIELDS:
        fail("unknown field '%s' (one of: %s)" % (a.field, ", ".join(FIELDS)))
    if a.size[0] < 16 or a.size[1] < 16:
        fail("--size must be at least 16 16")
    if a.point_size is not None and a.point_size <= 0:
        fail("--point-size must be positive")
    return a


def find_pvd(run):
    if not os.path.exists(run):
        fail("no such run directory or .pvd file: %s" % run)
    if os.path.isdir(run):
        pvd = os.path.join(run, "particles.pvd")
    else:
        pvd = run
    if not pvd.endswith(".pvd"):
        fail("'%s' is neither a run directory nor a .pvd file" % run)
    if not os.path.isfile(pvd):
        fail("no such file: %s" % pvd)
    return os.path.abspath(pvd)


def fmt_time(t):
    return "%g" % t


def to_palette(png):
    """Rewrites png as a 256-colour palette image (octree quantization: smooth colour bar)."""
    try:
        from PIL import Image
    except ImportError:
        fail("--palette needs PIL (Debian: apt-get install python3-pil)")
    im = Image.open(png).convert("RGB")
    im.quantize(colors=256, method=Image.Quantize.FASTOCTREE).save(png, optimize=True)


def main(argv):
    args = parse_args(argv)
    pvd = find_pvd(args.run)
    out_dir = os.path.abspath(args.out) if args.out else os.path.dirname(pvd)
    os.makedirs(out_dir, exist_ok=True)

    from paraview import simple as pv  # imported late: argument errors come out fast and clean

    reader = pv.PVDReader(FileName=pvd)
    steps = list(reader.TimestepValues) if reader.TimestepValues else []
    if isinstance(reader.TimestepValues, (int, float)):
        steps = [float(reader.TimestepValues)]
    if not steps:
        steps = [0.0]
    reader.UpdatePipeline(steps[0])
    if reader.GetDataInformation().GetNumberOfPoints() == 0 and len(steps) == 1:
        fail("%s has no particles (is every .vtp it names present?)" % pvd)

    array, color_comp, range_comp = FIELDS[args.field]
    requested = args.times if args.times else sorted({steps[0], steps[-1]})

    view = pv.CreateView("RenderView")
    view.ViewSize = list(args.size)
    if "UseColorPaletteForBackground" in view.ListProperties():
        view.UseColorPaletteForBackground = 0
    view.Background = [1.0, 1.0, 1.0]
    view.OrientationAxesVisibility = 0
    view.CameraParallelProjection = 1

    display = pv.Show(reader, view)
    display.SetRepresentationType("Points")
    if "RenderPointsAsSpheres" in display.ListProperties():
        display.RenderPointsAsSpheres = 1

    # paraview.simple resets the camera on a view's first Render(); have that happen now, so that
    # it does not undo the camera set below for the first picture.
    pv.Render(view)

    done = set()
    for t_req in requested:
        t = min(steps, key=lambda s: abs(s - t_req))
        if t in done:  # two requested times with the same nearest step: one picture
            continue
        done.add(t)
        reader.UpdatePipeline(t)
        view.ViewTime = t
        info = reader.GetDataInformation()
        npts = info.GetNumberOfPoints()
        names = list(reader.PointData.keys())
        if array not in names:
            fail("field '%s' needs point array '%s', which %s at t=%s lacks (arrays: %s)"
                 % (args.field, array, pvd, fmt_time(t), ",".join(names) or "none"))
        lo, hi = reader.PointData[array].GetRange(range_comp)

        # Colours: a fixed range per picture, the field's range at this time.
        if color_comp is None:
            pv.ColorBy(display, ("POINTS", array))
        else:
            pv.ColorBy(display, ("POINTS", array, color_comp))
        lut = pv.GetColorTransferFunction(array)
        if hi > lo:
            lut.RescaleTransferFunction(lo, hi)
        elif lo == 0.0 and args.field in ("speed", "phase"):  # constant, never negative
            lut.RescaleTransferFunction(0.0, 1.0)
        else:  # constant field: a range around it, so that the map and the labels stay sane
            d = 0.01 * abs(lo) if lo != 0.0 else 1.0
            lut.RescaleTransferFunction(lo - d, hi + d)
        if "AutomaticRescaleRangeMode" in lut.ListProperties():
            lut.AutomaticRescaleRangeMode = "Never"

        bar = pv.GetScalarBar(lut, view)
        bar.Title = "%s\nt = %s" % (args.field, fmt_time(t))
        bar.ComponentTitle = ""
        bar.TitleColor = [0.0, 0.0, 0.0]
        bar.LabelColor = [0.0, 0.0, 0.0]
        scale = min(args.size) / 800.0
        bar.TitleFontSize = max(9, int(round(18 * scale)))
        bar.LabelFontSize = max(8, int(round(15 * scale)))
        if "HorizontalTitle" in bar.ListProperties():
            bar.HorizontalTitle = 1
        bar.WindowLocation = "Any Location"
        bar.Orientation = "Vertical"
        bar.Position = [0.82, 0.08]
        bar.ScalarBarLength = 0.78
        bar.RangeLabelFormat = "%-#6.3g"
        bar.Visibility = 1
        display.SetScalarBarVisibility(view, True)

        # 2D camera: from +z, parallel projection, the data bounds fitted into the left 76% of the
        # picture (the colour bar takes the right) and 90% of its height.
        x0, x1, y0, y1, z0, z1 = info.GetBounds()
        w, h = args.size
        data_w = max(x1 - x0, 1e-12)
        data_h = max(y1 - y0, 1e-12)
        # Particle spacing from the bounds and the count (square lattice in 2D, a line in 1D); the
        # outer particles sit half a spacing inside the box, so add one spacing to the extent.
        if npts < 2:
            spacing = 0.0
        elif min(y1 - y0, x1 - x0) <= 1e-9 * max(x1 - x0, y1 - y0):  # 1D
            spacing = max(x1 - x0, y1 - y0) / (npts - 1)
        else:
            spacing = math.sqrt(data_w * data_h / npts)
        ext_w = data_w + spacing
        ext_h = data_h + spacing
        region_w, region_h = 0.76 * w, 0.90 * h
        world_per_px = max(ext_w / region_w, ext_h / region_h)
        cx, cy = 0.5 * (x0 + x1), 0.5 * (y0 + y1)
        fx = cx + 0.10 * w * world_per_px  # data centre 10% of the width left of the picture's
        view.CameraPosition = [fx, cy, 10.0 + max(data_w, data_h)]
        view.CameraFocalPoint = [fx, cy, 0.0]
        view.CameraViewUp = [0.0, 1.0, 0.0]
        view.CameraParallelScale = 0.5 * h * world_per_px

        if args.point_size is not None:
            display.PointSize = args.point_size
        elif spacing > 0:
            display.PointSize = max(2.0, 0.9 * spacing / world_per_px)
        else:
            display.PointSize = 5.0

        png = os.path.join(out_dir, "%s_t%s.png" % (args.field, fmt_time(t)))
        pv.Render(view)
        pv.SaveScreenshot(png, view, ImageResolution=list(args.size), TransparentBackground=0)
        if args.palette:
            to_palette(png)
        print("frame time=%s requested=%s points=%d arrays=%s field=%s range=%.9g,%.9g png=%s"
              % (fmt_time(t), fmt_time(t_req), npts, ",".join(names), args.field, lo, hi, png))
        sys.stdout.flush()
    return 0


if __name__ == "__main__":
    # No sys.exit on success, for the reason given in fail(): the script just ends.
    main(sys.argv[1:])
