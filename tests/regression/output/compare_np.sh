#!/usr/bin/env bash
# Runs an input on 1, 2 and 3 ranks, each in its own folder, compares the HDF5
# files with h5diff (every dataset and attribute but /mesh/cell_rank; values to
# 1e-9 relative; vectors and tensors absolutely, see below), and checks each XDMF file. The input's solver tolerances are
# tightened first (Newton relative 1e-12, GMRES 1e-13; the input has no Solver
# block): with the defaults the displacement of the thermo-elastic contact box
# agrees only to ~5e-8 between rank counts, the accuracy of its linear solves.
# With a 6th argument "by-block", Mesh/"Partition" = "By Block" is injected and the runs are
# np 1 and 2 only: the two halves of the contact box on two ranks, so that every contact
# pair has its nodes on different ranks (the partition boundary on the gap). With "np12",
# METIS as by default but np 1 and 2 only (see the CMakeLists.txt for why).
# usage: compare_np.sh KILN CHECK_XDMF INPUT.xml MESH.exo MPIEXEC [by-block|np12]
set -euo pipefail
kiln=$1 check_xdmf=$2 input=$3 mesh=$4 mpiexec=$5 mode=${6:-metis}
name=$(basename "$input" .xml)
args=()
[ "$name" = contact-box-exodus ] && args=(--mesh "$mesh")
nps=(1 2 3)
[ "$mode" = by-block ] || [ "$mode" = np12 ] && nps=(1 2)
top=$PWD/out-$name-$mode
rm -rf "$top"
mkdir -p "$top"
tight='<ParameterList name="Solver"><Parameter name="Relative Tolerance" type="double" value="1e-12"/><ParameterList name="Linear Solver"><ParameterList name="Linear Solver Types"><ParameterList name="Belos"><ParameterList name="Solver Types"><ParameterList name="Block GMRES"><Parameter name="Convergence Tolerance" type="double" value="1e-13"/></ParameterList></ParameterList></ParameterList></ParameterList></ParameterList></ParameterList>'
grep -q '<ParameterList name="Solver">' "$input" && { echo "compare_np.sh: $input has a Solver block"; exit 1; }
sed "s#<ParameterList name=\"Time Stepping\">#$tight&#" "$input" > "$top/$name.xml"
if [ "$mode" = by-block ]; then
  sed -i 's#<ParameterList name="Mesh">#&<Parameter name="Partition" type="string" value="By Block"/>#' "$top/$name.xml"
fi
input=$top/$name.xml
for np in "${nps[@]}"; do
  mkdir -p "$top/np$np"
  (cd "$top/np$np" && "$mpiexec" -np $np --oversubscribe --allow-run-as-root "$kiln" "${args[@]}" "$input" > log.txt)
  "$check_xdmf" "$top/np$np/results/$name.xmf"
done
# Vector and tensor fields are compared absolutely instead: a component of a few kPa (or nm)
# next to others of 1e7 Pa (or um) differs relatively by ~2e-9 while the tensors agree to
# 1e-12 of their size. Tolerances: stress 1e-3 Pa, strain 1e-13, displacement 1e-14 m; the
# stress measures as the stress; the gap heat flux 1e-5 W/m^2 (h = 1e4 W/(m^2 K) times the
# 1e-10 K of the temperatures' solver noise, where the flux is 0).
absolute=(stress:1e-3 strain:1e-13 displacement:1e-14 principal_stress:1e-3
  von_mises_stress:1e-3 pressure:1e-3 gap_heat_flux:1e-5)
# The gap surface repeats every node field at the gap (/gap/steps/NNNNNN/FIELD): the same
# tolerances. /history is left out: its iteration counts and wall times depend on the ranks.
steps=$(h5ls "$top/np1/results/$name.h5/steps" | awk '{print $1}')
# The root's attributes hold the date the file was created: each run's status is checked below.
excludes=(--exclude-path /mesh/cell_rank --exclude-path /history --exclude-attribute /)
for step in $steps; do
  for entry in "${absolute[@]}"; do
    for group in steps gap/steps; do
      h5ls "$top/np1/results/$name.h5/$group/$step" 2>/dev/null | grep -q "^${entry%%:*} " &&
        excludes+=(--exclude-path "/$group/$step/${entry%%:*}")
    done
  done
done
for np in "${nps[@]}"; do
  h5dump -a /status "$top/np$np/results/$name.h5" | grep -q '"complete"' || {
    echo "compare_np.sh: the np $np run's results are not marked complete"; exit 1; }
done
for np in "${nps[@]:1}"; do
  if ! h5diff -r -p 1e-9 "${excludes[@]}" "$top/np1/results/$name.h5" \
       "$top/np$np/results/$name.h5" > "$top/diff$np.txt"; then
    cat "$top/diff$np.txt"
    echo "compare_np.sh: np 1 and np $np differ"
    exit 1
  fi
  for step in $steps; do
    for entry in "${absolute[@]}"; do
      field=${entry%%:*}
      for group in steps gap/steps; do
        h5ls "$top/np1/results/$name.h5/$group/$step" 2>/dev/null | grep -q "^$field " || continue
        if ! h5diff -r -d "${entry#*:}" "$top/np1/results/$name.h5" \
             "$top/np$np/results/$name.h5" "/$group/$step/$field" > "$top/diff$np-$field.txt"; then
          cat "$top/diff$np-$field.txt"
          echo "compare_np.sh: /$group/$step/$field of np 1 and np $np differs"
          exit 1
        fi
      done
    done
  done
done
if [ "$mode" = by-block ]; then
  grep -q "partition (by block)" "$top/np2/log.txt" || {
    echo "compare_np.sh: the np 2 run did not partition by block"; exit 1; }
  echo "compare_np.sh: $name identical on 1 rank and on 2 ranks split at the gap"
  exit 0
fi
if [ "$mode" = np12 ]; then
  echo "compare_np.sh: $name identical on 1 and 2 ranks"
  exit 0
fi
# cell_rank is the partition: at np 3 it must hold rank 2.
h5dump -d /mesh/cell_rank "$top/np3/results/$name.h5" | grep -q '\b2\b' || {
  echo "compare_np.sh: /mesh/cell_rank at np 3 has no rank 2"; exit 1; }
echo "compare_np.sh: $name identical on 1, 2 and 3 ranks"
