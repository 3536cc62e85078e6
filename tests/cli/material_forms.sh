#!/usr/bin/env bash
# The forms of a material (issue 31) give the same run: the closing contact box
# (tests/cli/reuse_summary.xml, 4^3 cells to 30 s) with
#   material   its Kiln/Material list, each property a number (the decks before issue 31);
#   materials  the same material as Kiln/Materials/aluminium with "Blocks" {2, 1}: the same
#              results to the bit;
#   table      Kiln/Material with k(T) = 240 + 5 (T - 288) W/(m K) as a table through 250
#              and 400 K (the run stays between 288 and 308 K);
#   expression the same k(T) as the formula "240 + 5*(T - 288)": the same results as the
#              table to 1e-7 K and 1e-12 m (the values agree to round-off, the derivatives to
#              1e-12; Newton may stop at another iterate within its tolerance).
# usage: material_forms.sh KILN DECK KILN_DIFF NAME [LAUNCHER...]  (NAME: the work folder)
set -uo pipefail
kiln=$1 deck=$2 diff=$3 name=$4
shift 4
fail() { echo "material_forms.sh: $*"; exit 1; }
mkdir -p "$name"
sed -e "s#reuse-summary/on#$name/material#" "$deck" > "$name/material.xml"
# Material -> Materials/aluminium (one more level: its closing tag is the first "  </..." after it).
awk -v base="$name/materials" '
  /<ParameterList name="Material">/ { print "  <ParameterList name=\"Materials\">"
    print "    <ParameterList name=\"aluminium\">"
    print "      <Parameter name=\"Blocks\" type=\"Array(int)\" value=\"{2, 1}\"/>"; inside = 1; next }
  inside && /^  <\/ParameterList>/ { print "    </ParameterList>"; print; inside = 0; next }
  { gsub("reuse-summary/on", base); print }' "$deck" > "$name/materials.xml"
grep -q '"Materials"' "$name/materials.xml" || fail "could not make the deck materials"
# The conductivity sublist replaced by `inner` (a Type and what it needs).
with_conductivity() {
  awk -v base="$name/$1" -v inner="$2" '
    /<ParameterList name="Conductivity">/ { print; print inner; skip = 1; next }
    skip && /<\/ParameterList>/ { skip = 0 }
    skip { next }
    { gsub("reuse-summary/on", base); print }' "$deck" > "$name/$1.xml"
  grep -q "$3" "$name/$1.xml" || fail "could not make the deck $1"
}
with_conductivity table '<Parameter name="Type" type="string" value="Table"/>
<Parameter name="Temperatures" type="Array(double)" value="{250, 400}"/>
<Parameter name="Values" type="Array(double)" value="{50, 800}"/>' '{50, 800}'
with_conductivity expression '<Parameter name="Type" type="string" value="Expression"/>
<Parameter name="Expression" type="string" value="240 + 5*(T - 288)"/>
<Parameter name="Temperatures" type="Array(double)" value="{250, 400}"/>' '240 + 5\*(T - 288)'
for v in material materials table expression; do
  rm -f "$name/$v.lock"
  "$@" "$kiln" "$name/$v.xml" > "$name/$v.log" 2>&1 || { cat "$name/$v.log"; fail "the run $v failed"; }
done
"$diff" --fields temperature,displacement --field temperature:0:0 --field displacement:0:0 \
  "$name/materials.h5" "$name/material.h5" || fail "Materials and Material differ"
"$diff" --fields temperature,displacement --field temperature:1e-7:0 \
  --field displacement:1e-12:0 "$name/expression.h5" "$name/table.h5" ||
  fail "the conductivity as a formula and as a table differ"
"$diff" --fields temperature --field temperature:1e-4:0 "$name/table.h5" "$name/material.h5" >/dev/null &&
  fail "k(T) made no difference to the temperature: the test would not see a formula ignored"
echo "material_forms.sh: the forms agree"
