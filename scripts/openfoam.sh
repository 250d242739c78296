# Helpers shared by the OpenFOAM reference scripts (cases/*/openfoam/run.sh); sourced, not run.

# foam_header CLASS OBJECT [LOCATION]: the FoamFile header of an OpenFOAM dictionary or field file.
foam_header() {
  printf 'FoamFile\n{\n    version 2.0;\n    format ascii;\n    class %s;\n' "$1"
  if [[ -n "${3:-}" ]]; then printf '    location "%s";\n' "$3"; fi
  printf '    object %s;\n}\n' "$2"
}

# foam_run DIR TOOL...: runs each OpenFOAM tool in the case folder DIR, one thread at nice 10, its
# output in DIR/log.TOOL; stops the script with a one-line message naming the log when a tool
# fails. FOAM_SECONDS is the wall time of the last tool.
foam_run() {
  local dir=$1 tool start
  shift
  export OMP_NUM_THREADS=1
  if [[ -z "${WM_PROJECT_DIR:-}" ]]; then  # Debian's OpenFOAM environment (etc/controlDict and libraries)
    set +eu
    source /usr/share/openfoam/etc/bashrc 2>/dev/null  # (its path clean-up helper is not packaged)
    set -eu
  fi
  for tool in "$@"; do
    start=$(date +%s)
    if ! (cd "$dir" && nice -n 10 $tool > "log.${tool%% *}" 2>&1); then
      echo "run.sh: $tool failed; its log is $dir/log.${tool%% *}" >&2
      exit 1
    fi
    FOAM_SECONDS=$(( $(date +%s) - start ))
  done
}
