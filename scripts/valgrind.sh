#!/usr/bin/env bash
# valgrind memcheck on the contact box at np 1 (doc/fuzzing.md).
#   scripts/valgrind.sh [BUILD_DIR] [INPUT]   defaults: build, inputs/contact-box-close.xml
# Uses Open MPI's own suppressions (/usr/share/openmpi/openmpi-valgrind.supp) and Kiln's for
# the leaks of MPI_Init/MPI_Finalize and Open MPI's plug-ins (scripts/valgrind.supp). Passes
# (exit 0) when memcheck finds no read/write error and no definite leak in what is left; it
# takes several minutes.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
input=${2:-inputs/contact-box-close.xml}
command -v valgrind >/dev/null || { apt-get update -q && apt-get install -y -q valgrind; }
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
supp=(--suppressions="$PWD/scripts/valgrind.supp")
[ -f /usr/share/openmpi/openmpi-valgrind.supp ] &&
  supp+=(--suppressions=/usr/share/openmpi/openmpi-valgrind.supp)
kiln=$PWD/$build/src/app/kiln
input=$(realpath "$input")
cd "$work"
nice mpirun -np 1 valgrind --tool=memcheck --error-exitcode=3 --leak-check=full \
  --show-leak-kinds=definite --errors-for-leak-kinds=definite --num-callers=40 \
  "${supp[@]}" "$kiln" "$input"
