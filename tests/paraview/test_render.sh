#!/bin/sh
# End-to-end ParaView check, headless: a short run of the real binary, rendered by the real
# pvbatch through scripts/pvbatch.sh --install (which installs ParaView first when it is missing).
#   tests/paraview/test_render.sh path/to/arksph
# Checks: every frame line printed by paraview/render.py lists the point arrays velocity, pressure,
# density, mass, id, phase and 900 points; every PNG exists and is not blank (more than 2 colours,
# at least 1% of the pixels differ from the background).
# Exit 0 when all pass; otherwise non-zero with a message naming what failed.
set -eu

BIN="${1:-}"
if [ -z "$BIN" ] || [ ! -x "$BIN" ]; then
  echo "test_render: usage: $0 path/to/arksph (got '${BIN}')" >&2
  exit 2
fi
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
TMP="$(mktemp -d "${TMPDIR:-/tmp}/arksph-pv-test.XXXXXX")"
trap 'rm -rf "$TMP"' EXIT
RUN="$TMP/run"
PICS="$TMP/pics"
FIELDS="speed pressure density phase"

# A Python with numpy and matplotlib: Debian's, ahead of any pyenv shim on the PATH.
PY=""
for p in /usr/bin/python3 python3; do
  if command -v "$p" >/dev/null 2>&1 && "$p" -c "import numpy, matplotlib.image" 2>/dev/null; then
    PY="$p"; break
  fi
done
if [ -z "$PY" ]; then
  echo "test_render: FAIL: no python3 with numpy and matplotlib (scripts/install-deps.sh installs them)" >&2
  exit 1
fi

echo "test_render: (a) run: $BIN run --quiet --set time.end=0.1 --set output.every=0.05"
"$BIN" run --quiet --set time.end=0.1 --set output.every=0.05 --out "$RUN" >"$TMP/run.log" 2>&1 || {
  echo "test_render: FAIL: arksph run exited $?:" >&2; cat "$TMP/run.log" >&2; exit 1; }
[ -f "$RUN/particles.pvd" ] || { echo "test_render: FAIL: no $RUN/particles.pvd" >&2; exit 1; }

echo "test_render: (b) render $FIELDS at t = 0 and 0.1"
: >"$TMP/frames.txt"
for f in $FIELDS; do
  # One retry, only when the X server aborted pvbatch while it opened its window (seen once under
  # ctest -j2 load: SIGABRT in vtkXOpenGLRenderWindow::CreateAWindow); any other failure counts.
  render() {
    "$ROOT/scripts/pvbatch.sh" --install "$ROOT/paraview/render.py" "$RUN" --field "$f" --times 0 0.1 \
      --size 400 400 --out "$PICS" >"$TMP/render_$f.out" 2>"$TMP/render_$f.err"
  }
  ok=0
  for attempt in 1 2; do
    if render; then ok=1; break; fi
    grep -q "CreateAWindow" "$TMP/render_$f.err" || break  # a real failure: no retry
    echo "test_render: X server aborted pvbatch for $f (attempt $attempt)" >&2
    sleep 1
  done
  if [ "$ok" -ne 1 ]; then
    echo "test_render: FAIL: render.py --field $f failed:" >&2
    cat "$TMP/render_$f.out" "$TMP/render_$f.err" >&2
    exit 1
  fi
  cat "$TMP/render_$f.out"
  grep '^frame ' "$TMP/render_$f.out" >>"$TMP/frames.txt" || true
done

echo "test_render: (c, d) check the frame lines and the pictures"
"$PY" - "$TMP/frames.txt" "$PICS" "$FIELDS" <<'EOF'
import os
import sys

import matplotlib.image as mpimg
import numpy as np

frames_path, pics, fields = sys.argv[1], sys.argv[2], sys.argv[3].split()
want_arrays = {"velocity", "pressure", "density", "summation_density", "mass", "id", "phase"}
want_times = ["0", "0.1"]
passed, failed = 0, 0


def check(ok, what):
    global passed, failed
    if ok:
        passed += 1
    else:
        failed += 1
        print("test_render: FAIL: " + what)


frames = []
for line in open(frames_path):
    kv = dict(tok.split("=", 1) for tok in line.split()[1:] if "=" in tok)
    frames.append(kv)

for f in fields:
    for t in want_times:
        hits = [k for k in frames if k.get("field") == f and k.get("time") == t]
        check(len(hits) == 1, "field %s t=%s: %d frame lines (want 1)" % (f, t, len(hits)))
        if not hits:
            continue
        k = hits[0]
        arrays = set(k.get("arrays", "").split(","))
        check(want_arrays <= arrays, "field %s t=%s: arrays %s lack %s"
              % (f, t, sorted(arrays), sorted(want_arrays - arrays)))
        check(k.get("points") == "900", "field %s t=%s: %s points (want 900)" % (f, t, k.get("points")))
        lo, hi = (float(x) for x in k.get("range", "nan,nan").split(","))
        check(np.isfinite(lo) and np.isfinite(hi) and lo <= hi,
              "field %s t=%s: bad range %s" % (f, t, k.get("range")))

        png = os.path.join(pics, "%s_t%s.png" % (f, t))
        check(k.get("png") == png, "field %s t=%s: png=%s, expected %s" % (f, t, k.get("png"), png))
        if not os.path.isfile(png):
            check(False, "missing picture %s" % png)
            continue
        img = mpimg.imread(png)
        rgb = np.round(img[..., :3] * 255).astype(np.uint8) if img.dtype != np.uint8 else img[..., :3]
        check(rgb.shape[0] == 400 and rgb.shape[1] == 400, "%s: size %s (want 400x400)" % (png, rgb.shape))
        colours = np.unique(rgb.reshape(-1, 3), axis=0)
        background = rgb[0, 0]
        differ = np.any(rgb != background, axis=-1).mean()
        check(len(colours) > 2, "%s: %d distinct colours (want > 2)" % (png, len(colours)))
        check(differ >= 0.01, "%s: %.2f%% of pixels differ from the background %s (want >= 1%%)"
              % (png, 100 * differ, background.tolist()))
        check(tuple(background.tolist()) == (255, 255, 255),
              "%s: background %s is not white" % (png, background.tolist()))
        print("test_render: %s: %d colours, %.1f%% non-background, range [%g, %g]"
              % (os.path.basename(png), len(colours), 100 * differ, lo, hi))

# The velocity at t = 0.1 cannot be all zero (the lid drives the cavity).
sp = [k for k in frames if k.get("field") == "speed" and k.get("time") == "0.1"]
if sp:
    check(float(sp[0]["range"].split(",")[1]) > 0.1, "speed at t=0.1 has max %s (want > 0.1)"
          % sp[0]["range"].split(",")[1])

print("test_render: %d passed, %d failed" % (passed, failed))
sys.exit(1 if failed else 0)
EOF
