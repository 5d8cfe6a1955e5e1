#!/bin/sh
# The exported symbols of the built shared library must be exactly those in
# tests/symbols.txt: an accidental export or a removal fails `make check`.
# When the API changes on purpose, update the list (and -version-info).
lib="$ATRBVH_BUILDDIR/lib/.libs/libatrbvh.so"
if [ ! -f "$lib" ]; then
    echo "symbols: $lib not built (static-only build?); skipped"
    exit 77
fi
if ! command -v nm >/dev/null 2>&1; then
    echo "symbols: nm not found; skipped"
    exit 77
fi
actual=$(nm -D --defined-only "$lib" | awk '{print $3}' | grep -v '^_init$\|^_fini$' | sort)
expected=$(grep -v '^#' "$ATRBVH_SRCDIR/tests/symbols.txt" | sort)
if [ "$actual" != "$expected" ]; then
    echo "symbols: exported symbols differ from tests/symbols.txt:"
    printf '%s\n' "$expected" >expected.$$
    printf '%s\n' "$actual" >actual.$$
    diff -u expected.$$ actual.$$
    rm -f expected.$$ actual.$$
    exit 1
fi
n=$(printf '%s\n' "$actual" | wc -l)
echo "symbols: $n exported, as listed"
# The Debian symbols file must list the same symbols (a new export needs
# its line there, with the upstream version that introduced it).
# (named after the soname: libatrbvh1.symbols for libatrbvh.so.1)
deb=$(ls "$ATRBVH_SRCDIR"/packaging/debian/libatrbvh[0-9]*.symbols 2>/dev/null | head -n 1)
if [ -n "$deb" ] && [ -f "$deb" ]; then
    debsyms=$(sed -n 's/^ \([A-Za-z_0-9]*\)@Base .*/\1/p' "$deb" | sort)
    if [ "$debsyms" != "$expected" ]; then
        echo "symbols: packaging/debian/$(basename "$deb") differs from tests/symbols.txt:"
        printf '%s\n' "$expected" >expected.$$
        printf '%s\n' "$debsyms" >deb.$$
        diff -u expected.$$ deb.$$
        rm -f expected.$$ deb.$$
        echo "symbols: 1 passed, 1 failed"
        exit 1
    fi
    echo "symbols: the Debian symbols file agrees"
fi
# tests/test_clfault fails each OpenCL call the library makes, through the
# linker's --wrap of each function Makefile.am names: a function the
# library calls that is not wrapped would never fail there.
used=$(nm -D --undefined-only "$lib" | awk '{print $2}' | sed 's/@.*//' |
    grep '^cl[A-Z]' | sort -u)
wrapped=$(grep -o -- '--wrap=cl[A-Za-z]*' "$ATRBVH_SRCDIR/Makefile.am" |
    sed 's/--wrap=//' | sort -u)
missing=$(printf '%s\n' "$used" | grep -v '^$' | grep -vxF "$wrapped")
if [ -n "$missing" ]; then
    echo "symbols: OpenCL functions the library calls that tests/test_clfault"
    echo "does not wrap (Makefile.am, tests_test_clfault_LDFLAGS):"
    printf '  %s\n' $missing
    echo "symbols: 2 passed, 1 failed"
    exit 1
fi
echo "symbols: the library's $(printf '%s\n' "$used" | grep -c '^cl') OpenCL functions are all wrapped for test_clfault"
echo "symbols: 3 passed, 0 failed"
