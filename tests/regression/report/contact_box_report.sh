#!/usr/bin/env bash
# Runs kiln on an input, then kiln_contact_box_report on its results (the comparison that
# ./setup.sh run prints), and checks that the report fails with a message on a missing file.
# usage: contact_box_report.sh INPUT.xml NP KILN REPORT MPIEXEC
#   The run happens in ./report-<input>-np<NP> (kiln's log is log.txt there).
set -euo pipefail
input=$(realpath "$1") np=$2 kiln=$3 report=$4 mpiexec=$5
name=$(basename "$input" .xml)
dir=$PWD/report-$name-np$np
rm -rf "$dir"
mkdir -p "$dir"
cd "$dir"
if ! "$mpiexec" -np "$np" --oversubscribe --allow-run-as-root "$kiln" "$input" > log.txt 2>&1; then
  cat log.txt
  echo "contact_box_report.sh: kiln failed on $input (np $np)"
  exit 1
fi
"$report" "$input" "results/$name.h5"
if "$report" "$input" "results/no-such-file.h5" > missing.txt 2>&1; then
  echo "contact_box_report.sh: the report exits with 0 on a missing file"
  exit 1
fi
grep -q "no such file" missing.txt || {
  cat missing.txt
  echo "contact_box_report.sh: no \"no such file\" message for a missing file"
  exit 1
}
