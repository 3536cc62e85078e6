#!/usr/bin/env bash
# Runs an input on 1, 2 and 3 ranks, each in its own folder, compares the HDF5
# files with h5diff (every dataset and attribute but /mesh/cell_rank; values to
# 1e-9 relative, as the solver tolerances allow), and checks each XDMF file.
# usage: compare_np.sh KILN CHECK_XDMF INPUT.xml MESH.exo MPIEXEC
set -euo pipefail
kiln=$1 check_xdmf=$2 input=$3 mesh=$4 mpiexec=$5
name=$(basename "$input" .xml)
args=()
[ "$name" = contact-box-exodus ] && args=(--mesh "$mesh")
top=$PWD/out-$name
rm -rf "$top"
for np in 1 2 3; do
  mkdir -p "$top/np$np"
  (cd "$top/np$np" && "$mpiexec" -np $np --oversubscribe --allow-run-as-root "$kiln" "${args[@]}" "$input" > log.txt)
  "$check_xdmf" "$top/np$np/results/$name.xmf"
done
for np in 2 3; do
  if ! h5diff -r -p 1e-9 --exclude-path /mesh/cell_rank "$top/np1/results/$name.h5" \
       "$top/np$np/results/$name.h5" > "$top/diff$np.txt"; then
    cat "$top/diff$np.txt"
    echo "compare_np.sh: np 1 and np $np differ"
    exit 1
  fi
done
# cell_rank is the partition: at np 3 it must hold rank 2.
h5dump -d /mesh/cell_rank "$top/np3/results/$name.h5" | grep -q '\b2\b' || {
  echo "compare_np.sh: /mesh/cell_rank at np 3 has no rank 2"; exit 1; }
echo "compare_np.sh: $name identical on 1, 2 and 3 ranks"
