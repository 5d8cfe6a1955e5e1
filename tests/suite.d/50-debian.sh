#!/bin/sh
# Debian packages from the release tarball: atrbvh-VERSION.tar.gz (left in
# _build/ by 40-distcheck, else made here) becomes atrbvh_VERSION.orig.tar.gz,
# packaging/debian/ (shipped in the tarball) becomes debian/, and
# `dpkg-buildpackage -us -uc -b` builds the packages of debian/control
# (libatrbvhN, named after the soname, libatrbvh-dev, atrbvh, ...) in
# _build/deb/.  lintian then checks them: errors fail the stage,
# warnings and the rest are shown.
#
# DEB_BUILD_OPTIONS=nocheck by default: the same tests already ran in this
# suite (10-check on the tree, 40-distcheck on the tarball), and on the CI's
# two cores running them a third time costs minutes.  Set
# ATRBVH_DEB_CHECK=1 to run them inside the package build as well.
# Contract: print '=== stage ok' as the last line on success.
cd "$(dirname "$0")/../.." || exit 1
top=$(pwd)
sh setup.sh --packages packaging ||
    { echo "debian: 0 passed, 1 failed (installing packages failed)"; exit 1; }
for tool in dpkg-buildpackage dh lintian; do
    command -v $tool >/dev/null 2>&1 ||
        { echo "debian: $tool not installed (setup.sh installs it)"; echo "debian: 0 passed, 1 failed"; exit 1; }
done
[ -f _build/Makefile ] || { echo "debian: run setup.sh first"; exit 1; }
version=$(sed -n "s/^PACKAGE_VERSION = //p" _build/Makefile)
tarball=_build/atrbvh-$version.tar.gz
if [ ! -f "$tarball" ]; then
    echo "debian: making $tarball"
    make -C _build dist >/dev/null || { echo "debian: make dist failed"; exit 1; }
fi

work=$top/_build/deb
rm -rf "$work"
mkdir -p "$work"
cp "$tarball" "$work/atrbvh_$version.orig.tar.gz"
cd "$work" || exit 1
tar xzf "atrbvh_$version.orig.tar.gz"
src=$work/atrbvh-$version
[ -d "$src/packaging/debian" ] || { echo "debian: the tarball lacks packaging/debian"; exit 1; }
cp -R "$src/packaging/debian" "$src/debian"

opts="nocheck parallel=$(nproc 2>/dev/null || echo 2)"
[ "${ATRBVH_DEB_CHECK:-0}" = 1 ] && opts="parallel=$(nproc 2>/dev/null || echo 2)"
echo "debian: dpkg-buildpackage -us -uc -b (DEB_BUILD_OPTIONS='$opts')"
start=$(date +%s)
if ! (cd "$src" && DEB_BUILD_OPTIONS="$opts" dpkg-buildpackage -us -uc -b) >build.log 2>&1; then
    tail -n 60 build.log
    echo "debian: dpkg-buildpackage failed (log: _build/deb/build.log)"
    echo "debian: 0 passed, 1 failed"
    exit 1
fi
echo "debian: built in $(( $(date +%s) - start )) s"
grep -E '^dpkg-shlibdeps: warning|^dh_[a-z_]+: warning' build.log
passed=1
failed=0
for p in $(sed -n 's/^Package: *//p' "$src/debian/control"); do
    deb=$(ls ${p}_"$version"-*_*.deb 2>/dev/null | head -n 1)
    if [ -z "$deb" ]; then echo "debian: FAILED: no $p package"; failed=$((failed + 1)); continue; fi
    printf 'debian: %-40s %7s bytes, installed %s KiB\n' "$deb" "$(stat -c %s "$deb")" \
        "$(dpkg-deb -f "$deb" Installed-Size)"
    dpkg-deb -c "$deb" | awk '{ print "    " $6 ($7 ? " " $7 " " $8 : "") }'
    echo "    Depends: $(dpkg-deb -f "$deb" Depends)"
done

changes=$(ls atrbvh_"$version"-*_*.changes | head -n 1)
echo "debian: lintian $changes"
lintian --fail-on error --display-info --tag-display-limit 0 "$changes" >lintian.log 2>&1
lrc=$?
cat lintian.log
echo "debian: lintian: $(grep -c '^E:' lintian.log) errors, $(grep -c '^W:' lintian.log) warnings, $(grep -c '^[IP]:' lintian.log) info/pedantic"
if [ $lrc -ne 0 ] || grep -q '^E:' lintian.log; then
    echo "debian: FAILED: lintian reports errors"; failed=$((failed + 1))
else
    passed=$((passed + 1))
fi
echo "debian: $passed passed, $failed failed"
[ $failed -eq 0 ] && echo '=== stage ok'
[ $failed -eq 0 ]
