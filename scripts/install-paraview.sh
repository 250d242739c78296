#!/bin/sh
# Installs what rendering arksph runs with ParaView needs on Debian 12, idempotently:
#   1. the Debian packages paraview, xvfb and xauth (only those missing; apt-get update only then);
#   2. ParaView's Python modules, unpacked (not installed) into a cache directory.
# Why unpacked: Debian's python3-paraview Conflicts with python3-vtk9 and would remove libvtk9-dev,
# which arksph builds against. `apt-get download` + `dpkg-deb -x` puts the modules beside it instead.
#
#   ARKSPH_PV_DIR   where the modules are unpacked (default: $HOME/.cache/arksph/python3-paraview)
#   -q              quiet: print nothing but the final line
#   --check         install nothing: exit 0 (printing the PYTHONPATH) when everything is in place,
#                   1 otherwise
#
# The last line printed is the PYTHONPATH to use with pvbatch, e.g.
#   PYTHONPATH=$(scripts/install-paraview.sh -q | tail -n 1) xvfb-run -a pvbatch script.py
# scripts/pvbatch.sh does exactly that.
set -eu

QUIET=0
if [ "${1:-}" = "-q" ] || [ "${1:-}" = "--quiet" ]; then QUIET=1; fi
if [ "${1:-}" = "--check" ]; then
  PV_DIR="${ARKSPH_PV_DIR:-${HOME:-/root}/.cache/arksph/python3-paraview}"
  for p in paraview xvfb xauth; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || exit 1
  done
  [ -f "$PV_DIR/.arksph-python3-paraview-version" ] &&
    [ "$(cat "$PV_DIR/.arksph-python3-paraview-version")" = "$(dpkg-query -W -f='${Version}' paraview)" ] || exit 1
  echo "$PV_DIR/usr/lib/python3/dist-packages"
  exit 0
fi
say() { if [ "$QUIET" -eq 0 ]; then echo "install-paraview: $*" >&2; fi; }

PV_DIR="${ARKSPH_PV_DIR:-${HOME:-/root}/.cache/arksph/python3-paraview}"
SITE="$PV_DIR/usr/lib/python3/dist-packages"

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
UPDATED=0
apt_update_once() {
  if [ "$UPDATED" -eq 0 ]; then
    say "apt-get update"
    if [ "$QUIET" -eq 1 ]; then $SUDO apt-get update -qq >/dev/null; else $SUDO apt-get update -qq; fi
    UPDATED=1
  fi
}

# 1. Debian packages.
missing=""
for p in paraview xvfb xauth; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing="$missing $p"
  fi
done
if [ -n "$missing" ]; then
  say "installing$missing"
  apt_update_once
  # shellcheck disable=SC2086
  if [ "$QUIET" -eq 1 ]; then
    $SUDO apt-get install -y -qq --no-install-recommends $missing >/dev/null
  else
    $SUDO apt-get install -y -qq --no-install-recommends $missing
  fi
else
  say "paraview, xvfb, xauth present"
fi

# 2. ParaView's Python modules, unpacked. The stamp names the package version, so that an
#    upgraded paraview gets matching modules.
PV_VERSION="$(dpkg-query -W -f='${Version}' paraview)"
STAMP="$PV_DIR/.arksph-python3-paraview-version"
if [ -f "$SITE/paraview/__init__.py" ] && [ -f "$STAMP" ] && [ "$(cat "$STAMP")" = "$PV_VERSION" ]; then
  say "python3-paraview $PV_VERSION already unpacked in $PV_DIR"
else
  say "unpacking python3-paraview into $PV_DIR"
  TMP="$(mktemp -d)"
  trap 'rm -rf "$TMP"' EXIT
  # apt-get download runs as the calling user and writes to the current directory. It needs
  # package lists; try without an update first.
  if ! (cd "$TMP" && apt-get download -qq "python3-paraview=$PV_VERSION" >/dev/null 2>&1); then
    apt_update_once
    (cd "$TMP" && apt-get download -qq "python3-paraview=$PV_VERSION" >/dev/null 2>&1) ||
      (cd "$TMP" && apt-get download -qq python3-paraview)
  fi
  deb="$(ls "$TMP"/python3-paraview_*.deb)"
  rm -rf "$PV_DIR"
  mkdir -p "$PV_DIR"
  dpkg-deb -x "$deb" "$PV_DIR"
  if [ ! -f "$SITE/paraview/__init__.py" ]; then
    echo "install-paraview: $deb has no paraview module under usr/lib/python3/dist-packages" >&2
    exit 1
  fi
  echo "$PV_VERSION" >"$STAMP"
  say "unpacked $(basename "$deb")"
fi

echo "$SITE"
