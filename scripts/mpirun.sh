#!/bin/sh
# Open MPI's mpirun as the tour and the docs use it: one OpenMP thread per rank (unless
# OMP_NUM_THREADS is set), more ranks than cores allowed (--oversubscribe), and allowed as root,
# which containers and CI run as and which mpirun refuses otherwise. Arguments go to mpirun:
#   scripts/mpirun.sh -n 2 ./build/arksph run SCENE.toml
set -eu
export OMP_NUM_THREADS="${OMP_NUM_THREADS:-1}"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
exec mpirun --oversubscribe "$@"
