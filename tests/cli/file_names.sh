#!/usr/bin/env bash
# File and deck names (issue 33): a deck named steel&al.xml gives an XDMF index that an XML
# parser reads (the name escaped); a Latin-1 name is refused at --check (the index is UTF-8);
# a 226-byte name runs on 2 ranks (Open MPI's lockedfile component overflowed a 256-byte
# buffer with it); a name too long for the file system with Kiln's suffixes is refused.
# usage: file_names.sh KILN MPIEXEC DECK.xml
set -u
kiln=$(realpath "$1") mpiexec=$2 deck=$(realpath "$3")
python=${PYTHON:-/usr/bin/python3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
fail() { echo "file_names.sh: $*"; exit 1; }
run() { timeout 120 "$mpiexec" -np "$1" "$kiln" "${@:2}" > log.txt 2>&1; status=$?; cat log.txt; }

cp "$deck" 'steel&al.xml'
run 1 'steel&al.xml'
[ "$status" = 0 ] || fail "steel&al.xml: exit $status"
"$python" - <<'PY' || fail "the XDMF index of steel&al.xml does not parse or names the wrong file"
import xml.etree.ElementTree as ET
items = [e.text for e in ET.parse("results/steel&al.xmf").iter("DataItem")]
assert items and all(t.startswith("steel&al.h5:") for t in items), items[:2]
PY

latin1=$(printf 'acier-\xe9t\xe9.xml')
cp "$deck" "$latin1"
run 1 --check "$latin1"
[ "$status" = 1 ] || fail "a Latin-1 name: exit $status, expected 1"
grep -q 'the file name holds the byte 0xe9 at position 7, which is not UTF-8' log.txt ||
  fail "no message for a Latin-1 name"

long=$(printf 'a%.0s' $(seq 226))
cp "$deck" "$long.xml"
run 2 "$long.xml"
[ "$status" = 0 ] || fail "a 226-byte name on 2 ranks: exit $status"
[ -s "results/$long.h5" ] || fail "no results for the 226-byte name"

longer=$(printf 'b%.0s' $(seq 240))
cp "$deck" "$longer.xml"
run 2 --check "$longer.xml"
[ "$status" = 1 ] || fail "a 240-byte name: exit $status, expected 1"
grep -q 'the file name is 240 bytes; Kiln writes names up to 25 bytes longer (.checkpoint-000000.h5.tmp), and this file system allows 255 bytes per name' log.txt ||
  fail "no message for a name too long"
echo "file_names.sh: passed"
