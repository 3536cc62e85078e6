#!/usr/bin/env bash
# ./setup.sh run builds only what the run needs (kiln and the report tool), not the test
# suite; ./setup.sh test builds everything before ctest (issue 35, item 7: a new user
# waited 11m48 for the tests to build before the first run).
# setup.sh is run from a copy of the checkout's top level with stand-ins for
# packages/install.sh, cmake, ctest, mpirun and the two executables, which log their
# arguments.
# Usage: setup_targets.sh SOURCE_DIR
set -euo pipefail
src=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/top/packages" "$work/bin"
cp "$src/setup.sh" "$work/top/"
log="$work/calls.log"
printf '#!/bin/sh\necho "install.sh" >> %s\n' "$log" > "$work/top/packages/install.sh"
for tool in cmake ctest mpirun; do
  printf '#!/bin/sh\necho "%s $*" >> %s\n' "$tool" "$log" > "$work/bin/$tool"
done
mkdir -p "$work/top/build/tools"
printf '#!/bin/sh\necho "report $*" >> %s\n' "$log" > "$work/top/build/tools/kiln_contact_box_report"
chmod +x "$work/top/packages/install.sh" "$work/bin/"* "$work/top/build/tools/kiln_contact_box_report"

fail=0
check() { # mode, expected pattern, forbidden pattern
  : > "$log"
  PATH="$work/bin:$PATH" CI= "$work/top/setup.sh" "$1" > /dev/null
  echo "setup.sh $1:"; sed 's/^/  /' "$log"
  if ! grep -Eq -- "$2" "$log"; then echo "FAIL: setup.sh $1 did not run: $2"; fail=1; fi
  if [ -n "$3" ] && grep -Eq -- "$3" "$log"; then echo "FAIL: setup.sh $1 ran: $3"; fail=1; fi
}
# run: the two targets only, then the run; no whole build, no ctest.
check run '^cmake --build build -j [0-9]+ --target kiln kiln_contact_box_report$' \
  '^cmake --build build -j [0-9]+$|^ctest'
grep -q '^mpirun -np 2 build/src/app/kiln inputs/contact-box-close.xml$' "$log" ||
  { echo "FAIL: setup.sh run did not run the contact box"; fail=1; }
# test: everything, then ctest.
check test '^cmake --build build -j [0-9]+$' '--target'
grep -q '^ctest ' "$log" || { echo "FAIL: setup.sh test did not run ctest"; fail=1; }
exit $fail
