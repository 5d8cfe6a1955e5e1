#!/bin/sh
# Debian packages from the release tarball: atrbvh-VERSION.tar.gz (left in
# _build/ by 40-distcheck, else made here) becomes atrbvh_VERSION.orig.tar.gz,
# packaging/debian/ (shipped in the tarball) becomes debian/, and
# `dpkg-buildpackage -us -uc` builds the source package and the packages of
# debian/control (libatrbvhN, named after the soname, libatrbvh-dev, atrbvh,
# atrbvh-doc) in _build/deb/.  lintian --pedantic then checks them all,
# source included (watch file, upstream metadata, tests/control): errors
# fail the stage, the rest is shown (the tags left are explained in
# packaging/debian/README.source).  Last, the autopkgtests
# (debian/tests/) run against the packages unpacked into a folder (PATH,
# LD_LIBRARY_PATH and pkg-config pointed there: nothing is installed on
# this machine): a smoke test of the scripts, not an autopkgtest testbed.
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
echo "debian: dpkg-buildpackage -us -uc (DEB_BUILD_OPTIONS='$opts')"
start=$(date +%s)
if ! (cd "$src" && DEB_BUILD_OPTIONS="$opts" dpkg-buildpackage -us -uc) >build.log 2>&1; then
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
lintian --fail-on error --display-info --pedantic --show-overrides --tag-display-limit 0 "$changes" >lintian.log 2>&1
lrc=$?
cat lintian.log
echo "debian: lintian: $(grep -c '^E:' lintian.log) errors, $(grep -c '^W:' lintian.log) warnings, $(grep -c '^[IP]:' lintian.log) info/pedantic, $(grep -c '^O:' lintian.log) overridden"
if [ $lrc -ne 0 ] || grep -q '^E:' lintian.log; then
    echo "debian: FAILED: lintian reports errors"; failed=$((failed + 1))
else
    passed=$((passed + 1))
fi

# ------------------------------------------- the autopkgtests, unpacked
root=$work/root
rm -rf "$root"
mkdir -p "$root"
for p in $(sed -n 's/^Package: *//p' "$src/debian/control"); do
    deb=$(ls ${p}_"$version"-*_*.deb 2>/dev/null | head -n 1)
    [ -n "$deb" ] && dpkg-deb -x "$deb" "$root"
done
multiarch=$(dpkg-architecture -qDEB_HOST_MULTIARCH)
sys_pc=$(pkg-config --variable pc_path pkg-config 2>/dev/null)
for t in $(sed -n 's/^Tests: *//p' "$src/debian/tests/control"); do
    tmp=$(mktemp -d)
    if env PATH="$root/usr/bin:$PATH" LD_LIBRARY_PATH="$root/usr/lib/$multiarch" \
           PKG_CONFIG_LIBDIR="$root/usr/lib/$multiarch/pkgconfig:$sys_pc" PKG_CONFIG_PATH= \
           PKG_CONFIG_SYSROOT_DIR="$root" AUTOPKGTEST_TMP="$tmp" \
           sh "$src/debian/tests/$t" >"autopkgtest-$t.log" 2>&1; then
        echo "debian: autopkgtest $t (unpacked): ok"
        passed=$((passed + 1))
    else
        tail -n 20 "autopkgtest-$t.log"
        echo "debian: FAILED: autopkgtest $t (unpacked; log: _build/deb/autopkgtest-$t.log)"
        failed=$((failed + 1))
    fi
    rm -rf "$tmp"
done

echo "debian: $passed passed, $failed failed"
[ $failed -eq 0 ] && echo '=== stage ok'
[ $failed -eq 0 ]
