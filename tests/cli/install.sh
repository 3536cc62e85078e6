#!/usr/bin/env bash
# The installed Kiln runs on its own (packages/cmake/KilnInstall.cmake).
# usage: install.sh CMAKE BUILD_DIR
# Installs the build into a temporary prefix (cmake --install --prefix), then, from another
# temporary folder (nothing of the source or build tree at hand), checks the installed example
# deck with the installed kiln, runs it (the closing contact box, 32 steps), has the installed
# report tool compare its result with the analytic state, and kiln-diff compare it with itself.
set -u
cmake=$1 build=$(realpath "$2")
prefix=$(mktemp -d) work=$(mktemp -d)
trap 'rm -rf "$prefix" "$work"' EXIT
fail() { echo "install.sh: $*"; exit 1; }
"$cmake" --install "$build" --prefix "$prefix" > "$work/install.log" ||
  { cat "$work/install.log"; fail "cmake --install failed"; }
for f in bin/kiln bin/kiln-diff bin/kiln_contact_box_report share/kiln/inputs/contact-box-close.xml \
         share/doc/kiln/README.md share/doc/kiln/user-guide.md; do
  [ -e "$prefix/$f" ] || fail "$f is not installed"
done
cd "$work" || exit 1
deck=$prefix/share/kiln/inputs/contact-box-close.xml
"$prefix/bin/kiln" --version | grep -q "^kiln " || fail "the installed kiln does not start"
"$prefix/bin/kiln" --check "$deck" > check.log 2>&1 || { cat check.log; fail "--check failed"; }
grep -q "input and mesh are valid" check.log || { cat check.log; fail "no verdict from --check"; }
"$prefix/bin/kiln" "$deck" > run.log 2>&1 || { cat run.log; fail "the installed kiln's run failed"; }
grep -q "^status: complete" run.log || { cat run.log; fail "the run did not complete"; }
[ -f results/contact-box-close.h5 ] || fail "no results/contact-box-close.h5 in the working folder"
"$prefix/bin/kiln_contact_box_report" "$deck" results/contact-box-close.h5 > report.log 2>&1 ||
  { cat report.log; fail "the installed report tool failed"; }
cat report.log
if python3 -c "import h5py, numpy" 2> /dev/null; then
  "$prefix/bin/kiln-diff" results/contact-box-close.h5 results/contact-box-close.h5 > diff.log 2>&1 ||
    { cat diff.log; fail "the installed kiln-diff failed"; }
fi
echo "install.sh: installed into a temporary prefix; kiln, the report tool and kiln-diff ran from $work"
