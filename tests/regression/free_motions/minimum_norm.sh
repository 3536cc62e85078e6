#!/usr/bin/env bash
# "Free Motions" = "Minimum Norm" (doc/mechanics.md, "Free motions") on Truchas' compress-x,
# whose z translation is free (compress-x.xml): with the Direct preconditioner (the default
# at this size) and with MueLu under GMRES, on 1 and 2 ranks, the run completes, the mean
# z displacement is zero (the solution has no component in the free motion), u_x is
# -1e-4 (x + 0.5) m (what Truchas' test-stretch-contact.py compares), and the runs agree
# with each other (kiln-diff; Direct np 1 and np 2: displacement to 1e-15 m, stress to
# 1e-3 Pa of the 2.7e6 Pa; MueLu to its Krylov tolerance, 1e-11 m and 1 Pa). The same deck
# with a traction on z = +0.5
# (a net force along the free translation) has no solution: exit 2 and a message naming
# the force and the motion.
# usage: minimum_norm.sh KILN MPIEXEC COMPRESS-X.xml KILN-DIFF
set -u
kiln=$(realpath "$1") mpiexec=$2 input=$(realpath "$3") kiln_diff=$(realpath "$4")
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
fail() { echo "minimum_norm.sh: $*"; exit 1; }

# A MueLu variant (a Krylov solve of the pinned system with multigrid) and an unbalanced one.
sed -e 's|<Parameter name="Method" type="string" value="Steady"/>|&</ParameterList><ParameterList name="Solver"><ParameterList name="Linear Solver"><Parameter name="Preconditioner Type" type="string" value="MueLu"/></ParameterList>|' \
  "$input" > muelu.xml
grep -q '"MueLu"' muelu.xml || fail "could not make the MueLu variant"
sed -e 's|<ParameterList name="displ-r">|<ParameterList name="pulled top"><Parameter name="Type" type="string" value="Traction"/><Parameter name="Side Sets" type="Array(int)" value="{6}"/><Parameter name="Traction" type="Array(double)" value="{0, 0, 1e5}"/></ParameterList>&|' \
  "$input" > unbalanced.xml
grep -q 'pulled top' unbalanced.xml || fail "could not make the unbalanced variant"

for deck in compress-x muelu; do
  src=$input
  [ "$deck" = muelu ] && src=$work/muelu.xml
  for np in 1 2; do
    mkdir -p "$deck-np$np"
    (cd "$deck-np$np" && "$mpiexec" -np "$np" "$kiln" "$src" > log.txt 2>&1) ||
      { cat "$deck-np$np/log.txt"; fail "kiln failed on $deck, np $np"; }
  done
done

/usr/bin/python3 - "$work" <<'PY' || fail "the solutions are not the minimum-norm ones"
import glob, sys
import h5py, numpy as np
ok = True
for path in sorted(p for p in glob.glob(sys.argv[1] + "/*-np*/results/*.h5") if "checkpoint" not in p):
    with h5py.File(path, "r") as f:
        x = f["mesh/coordinates"][:]
        u = f["steps/000000/displacement"][:]
    mean_z = u[:, 2].mean()
    error_x = np.abs(u[:, 0] + 1e-4 * (x[:, 0] + 0.5)).max()
    print(f"{path}: mean u_z {mean_z:.3e} m, max |u_z| {np.abs(u[:, 2]).max():.3e} m, "
          f"u_x error {error_x:.3e} m")
    ok = ok and abs(mean_z) < 1e-15 and np.abs(u[:, 2]).max() > 1e-5 and error_x < 1e-12
sys.exit(0 if ok else 1)
PY

"$kiln_diff" --field displacement:1e-15:- --field strain:1e-15:- --field stress:1e-3:- \
  --field principal_stress:1e-3:- --field von_mises_stress:1e-3:- --field pressure:1e-3:- \
  compress-x-np1/results/compress-x.h5 compress-x-np2/results/compress-x.h5 > diff.txt ||
  { cat diff.txt; fail "Direct: np 1 and np 2 differ"; }
# The Krylov solves stop at their tolerance (the Newton test's 1e-8 relative): 1e-11 m and
# 1e-11 are 1e-7 of the 1e-4 m displacement and strain (1.7e-12 and 1.2e-12 measured).
"$kiln_diff" --field displacement:1e-11:- --field strain:1e-11:- --field stress:1:- \
  --field principal_stress:1:- --field von_mises_stress:1:- --field pressure:1:- \
  muelu-np1/results/muelu.h5 muelu-np2/results/muelu.h5 > diff.txt ||
  { cat diff.txt; fail "MueLu: np 1 and np 2 differ"; }
"$kiln_diff" --field displacement:1e-12:- --field strain:1e-12:- --field stress:1:- \
  --field principal_stress:1:- --field von_mises_stress:1:- --field pressure:1:- \
  compress-x-np1/results/compress-x.h5 muelu-np1/results/muelu.h5 > diff.txt ||
  { cat diff.txt; fail "Direct and MueLu differ"; }

mkdir -p unbalanced && cd unbalanced || exit 1
"$mpiexec" -np 2 "$kiln" ../unbalanced.xml > log.txt 2>&1
status=$?
[ "$status" -eq 2 ] || { cat log.txt; fail "the unbalanced deck exited with $status, not 2"; }
grep -q 'the load has a net force or moment along a free rigid motion .*: 1e+05 N along the translation along z; no displacement balances it' log.txt ||
  { cat log.txt; fail "the unbalanced deck's message"; }
echo "minimum_norm.sh: minimum-norm solutions, np 1 = np 2, Direct = MueLu; the unbalanced load refused"
