#!/bin/sh
# Runs ParaView's pvbatch headless with its Python modules on the path:
#   scripts/pvbatch.sh paraview/render.py RUN_DIR --field speed --times 0 1 5 --out pics/
# under xvfb-run, since Debian's ParaView aborts without an X server. ParaView itself (about 40
# Debian packages, 1-2 minutes) is installed only with consent: run scripts/install-paraview.sh
# first, or give --install as the first argument (or ARKSPH_INSTALL_PARAVIEW=1); without it a
# missing ParaView is named and nothing is installed (exit 2).
set -eu
HERE="$(cd "$(dirname "$0")" && pwd)"
INSTALL="${ARKSPH_INSTALL_PARAVIEW:-0}"
if [ "${1:-}" = "--install" ]; then INSTALL=1; shift; fi
if ! SITE="$("$HERE/install-paraview.sh" --check)"; then
  if [ "$INSTALL" != "1" ]; then
    echo "pvbatch.sh: ParaView (paraview, xvfb, xauth and its Python modules) is not installed; install it with" \
      "scripts/install-paraview.sh (about 40 Debian packages, uses sudo when not root), or run" \
      "scripts/pvbatch.sh --install ... to install and render" >&2
    exit 2
  fi
  echo "pvbatch.sh: installing ParaView (scripts/install-paraview.sh; about 40 Debian packages, 1-2 minutes the first time)" >&2
  SITE="$("$HERE/install-paraview.sh" -q | tail -n 1)"
fi
PYTHONPATH="$SITE${PYTHONPATH:+:$PYTHONPATH}"
export PYTHONPATH
# Start the free-display search at a number of our own, not at 99 for everyone: concurrent
# xvfb-run -a calls race for the same display, and a just-closed one may still be going away.
# On a loaded machine a fresh Xvfb sometimes refuses pvbatch's OpenGL window ("bad X server
# connection", seen 2 times in 5 at load 7, while xdpyinfo on the same server works); a new server
# then works, so such a failure is retried with a new Xvfb, at most 8 attempts.
log="$(mktemp)"
trap 'rm -f "$log"' EXIT
attempt=1
while :; do
  status=0
  xvfb-run -a -n $((100 + ($$ + 37 * attempt) % 400)) -s "-screen 0 1920x1080x24" pvbatch "$@" 2>"$log" || status=$?
  if [ "$status" -ne 0 ] && [ "$attempt" -lt 8 ] && grep -q "bad X server connection" "$log"; then
    echo "pvbatch.sh: the X server refused the render window (attempt $attempt); retrying with a new one" >&2
    attempt=$((attempt + 1))
    sleep 1
    continue
  fi
  cat "$log" >&2
  exit "$status"
done
