#!/usr/bin/env bash
# The Debian package (CPack, packages/cmake/KilnInstall.cmake).
# usage: debian_package.sh CPACK BUILD_DIR
# Builds it into a temporary folder and checks with dpkg-deb that it holds usr/bin/kiln,
# kiln-diff, the report tool and the example decks, and that its Depends names the Debian
# packages of the libraries kiln links (Trilinos, Open MPI, HDF5, Exodus, METIS).
# CPack's preinstall step builds every target first: after a full build it only packs.
set -u
cpack=$1 build=$(realpath "$2")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "debian_package.sh: $*"; exit 1; }
command -v dpkg-deb > /dev/null && command -v dpkg-shlibdeps > /dev/null ||
  { echo "debian_package.sh: no dpkg-deb or dpkg-shlibdeps: not tested"; exit 0; }
"$cpack" -G DEB --config "$build/CPackConfig.cmake" -B "$work" > "$work/cpack.log" 2>&1 ||
  { cat "$work/cpack.log"; fail "cpack failed"; }
deb=$(ls "$work"/kiln_*.deb) || fail "no kiln_*.deb"
dpkg-deb -I "$deb" > "$work/info" && dpkg-deb -c "$deb" > "$work/contents" || fail "dpkg-deb failed"
cat "$work/info"
for f in usr/bin/kiln usr/bin/kiln-diff usr/bin/kiln_contact_box_report \
         usr/share/kiln/inputs/contact-box-close.xml usr/share/doc/kiln/README.md; do
  grep -q "\./$f\$" "$work/contents" || fail "$f is not in the package"
done
depends=$(grep '^ Depends:' "$work/info") || fail "no Depends"
for p in libtrilinos-tpetra libtrilinos-muelu libopenmpi libhdf5-openmpi libexodusii libmetis \
         python3-h5py; do
  grep -q "$p" <<< "$depends" || fail "Depends does not name $p"
done
echo "debian_package.sh: $(basename "$deb") holds kiln and names its dependencies"
