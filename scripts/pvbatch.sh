#!/bin/sh
# Runs ParaView's pvbatch headless with its Python modules on the path:
#   scripts/pvbatch.sh paraview/render.py RUN_DIR --field speed --times 0 1 5 --out pics/
# Installs what is missing first (scripts/install-paraview.sh, quietly; a no-op once done) and
# runs pvbatch under xvfb-run, since Debian's ParaView aborts without an X server.
set -eu
HERE="$(cd "$(dirname "$0")" && pwd)"
SITE="$("$HERE/install-paraview.sh" -q | tail -n 1)"
PYTHONPATH="$SITE${PYTHONPATH:+:$PYTHONPATH}"
export PYTHONPATH
# Start the free-display search at a number of our own, not at 99 for everyone: concurrent
# xvfb-run -a calls race for the same display, and a just-closed one may still be going away.
exec xvfb-run -a -n $((100 + $$ % 400)) -s "-screen 0 1920x1080x24" pvbatch "$@"
