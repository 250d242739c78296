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

# foam_walled_box NX NY HEIGHT DEPTH: the blockMeshDict of the box [0, 1] x [0, HEIGHT], NX x NY
# cells one cell DEPTH thick, its four sides one wall patch "walls", front and back "frontAndBack".
foam_walled_box() {
  foam_header dictionary blockMeshDict
  cat <<EOD
convertToMeters 1;
vertices ((0 0 0) (1 0 0) (1 $3 0) (0 $3 0) (0 0 $4) (1 0 $4) (1 $3 $4) (0 $3 $4));
blocks (hex (0 1 2 3 4 5 6 7) ($1 $2 1) simpleGrading (1 1 1));
edges ();
boundary
(
    walls { type wall; faces ((3 7 6 2) (0 4 7 3) (2 6 5 1) (1 5 4 0)); }
    frontAndBack { type empty; faces ((0 3 2 1) (4 5 6 7)); }
);
EOD
}

# foam_ico_schemes DDT: the fvSchemes of an icoFoam case, time scheme DDT (Euler, backward),
# central differences in space on an orthogonal mesh.
foam_ico_schemes() {
  foam_header dictionary fvSchemes
  cat <<EOD
ddtSchemes { default $1; }
gradSchemes { default Gauss linear; }
divSchemes { default none; div(phi,U) Gauss linear; }
laplacianSchemes { default Gauss linear orthogonal; }
interpolationSchemes { default linear; }
snGradSchemes { default orthogonal; }
EOD
}

# foam_piso_solution P_TOL P_RELTOL U_TOL: the fvSolution of an icoFoam case: GAMG for p (pFinal to
# P_TOL without a relative tolerance), symmetric Gauss-Seidel for U, 2 PISO correctors.
foam_piso_solution() {
  foam_header dictionary fvSolution
  cat <<EOD
solvers
{
    p { solver GAMG; smoother GaussSeidel; tolerance $1; relTol $2; }
    pFinal { \$p; relTol 0; }
    U { solver smoothSolver; smoother symGaussSeidel; tolerance $3; relTol 0; }
}
PISO { nCorrectors 2; nNonOrthogonalCorrectors 0; pRefCell 0; pRefValue 0; }
EOD
}
