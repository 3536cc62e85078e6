#!/usr/bin/env bash
# Benchmark (issue 31): one time step of a viscoplastic box against the same step elastic.
# A unit cube of N^3 Q1 cells (Physics Elasticity), rollers on x = 0, y = 0, z = 0, a traction
# 4e6 t Pa along x on x = 1 (von Mises 4e6 t Pa, uniaxial), lambda = 2e9, G = 1e9 Pa; one
# backward Euler step 0 -> 1 s after the equilibrium at t = 0 (no load). Elastic: no Model
# (the Hooke fast path, constant Jacobian). Viscoplastic: Power Law A = 1e-7, n = 0.5 (a
# plastic strain increment 2.8e-4 in the step, every point flowing; "Maximum Plastic Strain
# Increment" 1 so that the step is not cut).
# KILN_STEPS=S (default 1): S steps of 1 s (0 -> S s, the traction growing all the way) instead
# of one; the step time is then the timers' sum over the run, and, with S > 1, the line
# "later" gives the mean of steps 2..S: (the run of S steps - the run of 1 step) / (S - 1),
# each from its own run. The user CPU time of each run ("cpu_s", set-up and output included)
# is measured too (of kiln itself with NP = 1, else of mpirun): on a shared machine it is less
# disturbed than the timers' wall times.
# usage: benchmarks/viscoplastic_box.sh [NP] [N...]     (default: 1  16 32)
# KILN=path/to/kiln (default build/src/app/kiln); KILN_SOLVER_XML=file.xml adds the
# <ParameterList name="Solver"> block in that file to both decks (a variant to compare, e.g.
# "Keep Preconditioner Within Solve" false); KILN_STEPPING='<Parameter .../>' adds parameters
# to both decks' Time Stepping (e.g. "Extrapolated Newton Start"); KILN_MODELS="powerlaw" runs only the
# viscoplastic deck (no ratio).
# Prints per mesh and material: Newton and Krylov iterations of the step, the step's time
# (the sum of kiln --timers' assembly (residual, Jacobian), preconditioner set-up and NOX's
# linear solves: the equilibrium at t = 0, unloaded, takes no iteration, so they are the
# step's; set-up and output are left out), each part, and the ratio viscoplastic / elastic.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
kiln=${KILN:-$here/build/src/app/kiln}
np=${1:-1}
shift || true
sizes=("${@:-16 32}")
steps=${KILN_STEPS:-1}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
deck() { # N MODEL(elastic|powerlaw) FILE; $end_time: the end time [s]
  local model=""
  if [ "$2" = powerlaw ]; then
    model='<ParameterList name="Model"><Parameter name="Type" type="string" value="Power Law"/><Parameter name="Power Law A" type="double" value="1e-7"/><Parameter name="Power Law n" type="double" value="0.5"/></ParameterList>'
  fi
  local solver=""
  if [ -n "${KILN_SOLVER_XML:-}" ]; then solver=$(tr -d '\n' < "$KILN_SOLVER_XML"); fi
  cat > "$3" <<XML
<ParameterList name="Kiln">
  <Parameter name="Physics" type="string" value="Elasticity"/>
  <ParameterList name="Mesh">
    <Parameter name="Type" type="string" value="Box"/>
    <Parameter name="Gap Side Set" type="int" value="0"/>
    <ParameterList name="Box">
      <Parameter name="Size" type="Array(double)" value="{1, 1, 1}"/>
      <Parameter name="Cells" type="Array(int)" value="{$1, $1, $1}"/>
      <Parameter name="Translation" type="Array(double)" value="{0.5, 0.5, 0.5}"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Material">
    <Parameter name="Lame Lambda" type="double" value="2e9"/>
    <Parameter name="Shear Modulus" type="double" value="1e9"/>
    <Parameter name="Thermal Expansion" type="double" value="0"/>
    <Parameter name="Reference Temperature" type="double" value="300"/>
    <Parameter name="Density" type="double" value="1e3"/>
    $model
  </ParameterList>
  <ParameterList name="Mechanics">
    <ParameterList name="Boundary Conditions">
      <ParameterList name="x0"><Parameter name="Type" type="string" value="Displacement"/>
        <Parameter name="Side Sets" type="Array(int)" value="{1}"/>
        <Parameter name="Components" type="Array(string)" value="{x}"/></ParameterList>
      <ParameterList name="y0"><Parameter name="Type" type="string" value="Displacement"/>
        <Parameter name="Side Sets" type="Array(int)" value="{3}"/>
        <Parameter name="Components" type="Array(string)" value="{y}"/></ParameterList>
      <ParameterList name="z0"><Parameter name="Type" type="string" value="Displacement"/>
        <Parameter name="Side Sets" type="Array(int)" value="{5}"/>
        <Parameter name="Components" type="Array(string)" value="{z}"/></ParameterList>
      <ParameterList name="pull"><Parameter name="Type" type="string" value="Traction"/>
        <Parameter name="Side Sets" type="Array(int)" value="{2}"/>
        <Parameter name="Traction Expressions" type="Array(string)" value="{4e6*t, 0, 0}"/></ParameterList>
    </ParameterList>
  </ParameterList>
  $solver
  <ParameterList name="Time Stepping">
    <Parameter name="Method" type="string" value="Backward Euler"/>
    <Parameter name="Initial Step" type="double" value="1"/>
    <Parameter name="Maximum Step" type="double" value="1"/>
    <Parameter name="Maximum Plastic Strain Increment" type="double" value="1"/>
    ${KILN_STEPPING:-}
  </ParameterList>
  <ParameterList name="Output">
    <Parameter name="File Base" type="string" value="$work/out-$1-$2"/>
    <Parameter name="Times" type="Array(double)" value="{0, $end_time}"/>
  </ParameterList>
  <ParameterList name="Checkpoint"><Parameter name="At End" type="bool" value="false"/></ParameterList>
</ParameterList>
XML
}
timer() { # LOG NAME: the timer's time [s] (the table's first number after the name)
  grep -F "$2" "$1" | head -1 | sed -e "s/.*$2//" | awk '{print $1}' | tr -d '()'
}
run() { # N MODEL STEPS: runs the deck; sets newton, linear (per step, comma separated), the
  # timers res jac prec krylov, their sum step, and cpu (user CPU time of the run)
  end_time=$3 deck "$1" "$2" "$work/box-$1-$2-$3.xml"
  local log=$work/box-$1-$2-$3.log
  local launch=(mpirun -np "$np") # one rank: kiln alone, so that time(1) sees its CPU time
  if [ "$np" = 1 ]; then launch=(); fi
  /usr/bin/time -f "%U" -o "$work/cpu" "${launch[@]}" "$kiln" --timers \
    "$work/box-$1-$2-$3.xml" > "$log" 2>&1 || { cat "$log"; exit 1; }
  cpu=$(tail -1 "$work/cpu")
  newton=$(sed -n 's/^step [0-9]*:.*Newton \([0-9]*\) (\([0-9]*\) linear.*/\1/p' "$log" | paste -sd,)
  linear=$(sed -n 's/^step [0-9]*:.*Newton \([0-9]*\) (\([0-9]*\) linear.*/\2/p' "$log" | paste -sd,)
  res=$(timer "$log" "Kiln: 5 assembly (residual)")
  jac=$(timer "$log" "Kiln: 5 assembly (Jacobian)")
  prec=$(timer "$log" "Kiln: 7 preconditioner set-up")
  krylov=$(timer "$log" "NOX Total Linear Solve")
  # The equilibrium at t = 0 has no load (no Newton iteration): every pass counted is a step's.
  step=$(echo "${res:-0} + ${jac:-0} + ${prec:-0} + ${krylov:-0}" | bc -l)
}
row() { # N LABEL NEWTON LINEAR STEP RES JAC PREC KRYLOV CPU RATIO
  printf "%4s %-17s %9s %14s %9.3f %9.3f %9.3f %9.3f %9.3f %7.2f %7s\n" "$@"
}
printf "%4s %-17s %9s %14s %9s %9s %9s %9s %9s %7s %7s\n" N material Newton linear step_s \
  asm_res_s asm_jac_s prec_s krylov_s cpu_s ratio
for n in ${sizes[@]}; do
  elastic_step="" elastic_later=""
  for model in ${KILN_MODELS:-elastic powerlaw}; do
    run "$n" "$model" "$steps"
    all=($step ${res:-0} ${jac:-0} ${prec:-0} ${krylov:-0} $cpu)
    ratio=""
    if [ "$model" = elastic ]; then
      elastic_step=$step
    elif [ -n "$elastic_step" ]; then
      ratio=$(printf %.2f "$(echo "$step / $elastic_step" | bc -l)")
    fi
    row "$n" "$model" "$newton" "$linear" "${all[@]}" "$ratio"
    if [ "$steps" -gt 1 ]; then # the mean of steps 2..S: this run less a run of one step
      run "$n" "$model" 1
      one=($step ${res:-0} ${jac:-0} ${prec:-0} ${krylov:-0} $cpu)
      later=()
      for i in 0 1 2 3 4 5; do
        later+=("$(echo "(${all[$i]} - ${one[$i]}) / ($steps - 1)" | bc -l)")
      done
      ratio=""
      if [ "$model" = elastic ]; then
        elastic_later=${later[0]}
      elif [ -n "$elastic_later" ]; then
        ratio=$(printf %.2f "$(echo "${later[0]} / $elastic_later" | bc -l)")
      fi
      row "$n" "$model later" "" "" "${later[@]}" "$ratio"
    fi
  done
done
