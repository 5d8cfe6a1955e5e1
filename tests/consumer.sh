#!/bin/sh
# consumer.sh - install into a DESTDIR staging tree, then build and run
# tests/consumer/consumer.c against it with pkg-config only, the way a
# program outside the project would:
#   shared: pkg-config --cflags --libs atrbvh, run with LD_LIBRARY_PATH
#           pointing into the staging tree;
#   static: pkg-config --static --cflags --libs atrbvh against a copy of the
#           staging tree without libatrbvh.so, so the link must take
#           libatrbvh.a and everything it needs must come from Libs.private;
#           the program must not need libatrbvh.so.
# PKG_CONFIG_LIBDIR/PKG_CONFIG_SYSROOT_DIR point into the tree, so nothing
# installed on the system can stand in for it.  Run by `make check`.
set -u
: "${ATRBVH_BUILDDIR:?}" "${ATRBVH_SRCDIR:?}"
CC=${CC:-cc}
# A consumer of an instrumented build (the sanitizer stage configures with
# -fsanitize=...) must be compiled and linked the same way, or the static
# link misses the sanitizer runtime: use the build's own CFLAGS/LDFLAGS.
CC="$CC ${ATRBVH_BUILD_CFLAGS:-} ${ATRBVH_BUILD_LDFLAGS:-}"
MAKE=${MAKE:-make}
command -v pkg-config >/dev/null 2>&1 || { echo "consumer: no pkg-config; skipped"; exit 77; }

work=$(mktemp -d "${TMPDIR:-/tmp}/atrbvh-consumer.XXXXXX") || exit 99
trap 'rm -rf "$work"' EXIT
stage=$work/stage
passed=0
failed=0
ok() { echo "consumer: ok: $1"; passed=$((passed + 1)); }
ko() { echo "consumer: FAILED: $1"; failed=$((failed + 1)); }

# The sub-make must not join the jobserver of the `make check` that runs us.
if ! env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL $MAKE -s -C "$ATRBVH_BUILDDIR" \
        install DESTDIR="$stage" >"$work/install.log" 2>&1; then
    cat "$work/install.log"
    echo "consumer: make install DESTDIR=... failed"
    echo "consumer: 0 passed, 1 failed"
    exit 1
fi

pc=$(find "$stage" -name atrbvh.pc -path '*/pkgconfig/*' | head -n 1)
[ -n "$pc" ] || { echo "consumer: atrbvh.pc not installed"; exit 1; }
pcdir=$(dirname "$pc")
libdir=$(dirname "$pcdir")          # $stage$libdir
echo "consumer: staging tree $stage, atrbvh.pc in ${pcdir#$stage}"

# OpenCL comes through Requires.private (OpenCL.pc) when the build has the
# backend: the search path is the staging tree's pkgconfig folder plus the
# folder of the system's OpenCL.pc (and nothing else).
opencl_pcdir=
if grep -q 'define ATRBVH_HAVE_OPENCL' "$ATRBVH_BUILDDIR/config.h" 2>/dev/null; then
    build_opencl=yes
    opencl_pcdir=$(env -u PKG_CONFIG_SYSROOT_DIR pkg-config --variable=pcfiledir OpenCL 2>/dev/null)
else
    build_opencl=no
fi
pkgc() { # search dir, pkg-config arguments
    d=$1; shift
    PKG_CONFIG_LIBDIR=$d${opencl_pcdir:+:$opencl_pcdir} PKG_CONFIG_PATH= \
        PKG_CONFIG_SYSROOT_DIR=$stage pkg-config "$@"
}

# ------------------------------------------------------ atrbvh.pc's fields
# Libs and Libs.private hold libraries only (-l, -L): a compiler flag such
# as -fopenmp there breaks static links made with another compiler (GCC's
# flag given to Clang asks for libomp; the archive's objects need the
# runtime they were compiled for).  OpenCL: in Requires.private when the
# build has the backend, never as -lOpenCL of our own; absent otherwise.
field() { sed -n "s/^$1:[ \t]*//p" "$pc"; }
bad=
for f in $(field Libs) $(field Libs.private); do
    case "$f" in -l*|-L*|'${libdir}'|-L'${libdir}') ;; *) bad="$bad $f" ;; esac
done
if [ -n "$bad" ]; then ko "atrbvh.pc: Libs/Libs.private hold non-library flags:$bad"
else ok "atrbvh.pc: Libs.private '$(field Libs.private)' (libraries only)"; fi
reqp=$(field Requires.private)
if [ "$build_opencl" = yes ] && [ -z "$opencl_pcdir" ]; then
    # configure found libOpenCL without OpenCL.pc: then, and only then, the
    # .pc names -lOpenCL itself (configure.ac, atrbvh.pc)
    if printf '%s\n' "$reqp" | grep -qw OpenCL; then ko "atrbvh.pc: requires OpenCL.pc, which is not installed"
    elif ! field Libs.private | grep -q -- -lOpenCL; then ko "atrbvh.pc: no OpenCL.pc and no -lOpenCL in Libs.private"
    else ok "atrbvh.pc: -lOpenCL in Libs.private (no OpenCL.pc on this system)"; fi
elif [ "$build_opencl" = yes ]; then
    if ! printf '%s\n' "$reqp" | grep -qw OpenCL; then ko "atrbvh.pc: OpenCL not in Requires.private ('$reqp')"
    elif field Libs.private | grep -q -- -lOpenCL; then ko "atrbvh.pc: -lOpenCL in Libs.private besides Requires.private"
    else ok "atrbvh.pc: Requires.private: $reqp"; fi
else
    if printf '%s\n' "$reqp" | grep -qw OpenCL || grep -q -- -lOpenCL "$pc"; then
        ko "atrbvh.pc: names OpenCL but the build has no OpenCL backend"
    else ok "atrbvh.pc: no OpenCL (the build has none)"; fi
fi

src=$ATRBVH_SRCDIR/tests/consumer/consumer.c
has_needed() { # binary, library soname prefix
    LC_ALL=C readelf -d "$1" 2>/dev/null | grep NEEDED | grep -q "\[$2"
}

# ------------------------------------------------------------------ shared
if ls "$libdir"/libatrbvh.so >/dev/null 2>&1; then
    flags=$(pkgc "$pcdir" --cflags --libs atrbvh) || { ko "pkg-config (shared)"; flags=; }
    echo "consumer: shared: $CC ... $flags"
    if $CC -o "$work/consumer-shared" "$src" $flags 2>"$work/cc.log"; then
        out=$(LD_LIBRARY_PATH=$libdir "$work/consumer-shared" 2>&1)
        rc=$?
        echo "$out"
        if [ $rc -ne 0 ]; then
            ko "shared consumer exited $rc"
        elif ! has_needed "$work/consumer-shared" libatrbvh.so; then
            ko "shared consumer does not need libatrbvh.so"
        elif command -v ldd >/dev/null 2>&1 &&
             ! LD_LIBRARY_PATH=$libdir ldd "$work/consumer-shared" | grep libatrbvh | grep -q "$stage"; then
            ko "shared consumer did not load libatrbvh from the staging tree"
        else
            ok "shared"
        fi
    else
        cat "$work/cc.log"; ko "shared consumer does not build"
    fi
else
    echo "consumer: no libatrbvh.so (--disable-shared); shared case skipped"
fi

# ------------------------------------------------------------------ static
if [ -f "$libdir/libatrbvh.a" ]; then
    # A copy of the tree without the shared library: the linker can only
    # take the archive.
    cp -R "$stage" "$work/static-stage"
    sstage=$work/static-stage
    slibdir=$sstage${libdir#$stage}
    rm -f "$slibdir"/libatrbvh.so* "$slibdir"/libatrbvh.la
    spcdir=$sstage${pcdir#$stage}
    flags=$(PKG_CONFIG_LIBDIR=$spcdir${opencl_pcdir:+:$opencl_pcdir} PKG_CONFIG_PATH= \
            PKG_CONFIG_SYSROOT_DIR=$sstage pkg-config --static --cflags --libs atrbvh) ||
        { ko "pkg-config --static"; flags=; }
    if [ "$build_opencl" = yes ] && [ -n "$opencl_pcdir" ]; then
        case " $flags " in
            *" -lOpenCL "*) ok "pkg-config --static names -lOpenCL (through OpenCL.pc)" ;;
            *) ko "pkg-config --static --libs atrbvh lacks -lOpenCL: $flags" ;;
        esac
    fi
    echo "consumer: static: $CC ... $flags"
    if $CC -o "$work/consumer-static" "$src" $flags 2>"$work/cc.log"; then
        out=$(env -u LD_LIBRARY_PATH "$work/consumer-static" 2>&1)
        rc=$?
        echo "$out"
        if [ $rc -ne 0 ]; then
            ko "static consumer exited $rc"
        elif has_needed "$work/consumer-static" libatrbvh; then
            ko "static consumer needs libatrbvh.so"
        else
            ok "static (needs: $(LC_ALL=C readelf -d "$work/consumer-static" |
                sed -n 's/.*NEEDED.*\[\(.*\)\]/\1/p' | tr '\n' ' '))"
        fi
    else
        cat "$work/cc.log"; ko "static consumer does not link with pkg-config --static"
    fi
    # The same archive linked by another compiler with the same flags:
    # Clang when the build used GCC (and the reverse), unless the build is
    # instrumented (sanitizer runtimes differ between the two).
    case "${ATRBVH_BUILD_CFLAGS:-} ${ATRBVH_BUILD_LDFLAGS:-}" in
        *-fsanitize*) other= ;;
        *) if $CC -dM -E - </dev/null 2>/dev/null | grep -q __clang__; then other=gcc; else other=clang; fi ;;
    esac
    if [ -n "$other" ] && [ -n "$flags" ] && command -v "$other" >/dev/null 2>&1; then
        if "$other" -o "$work/consumer-static-$other" "$src" $flags 2>"$work/cc.log" &&
           env -u LD_LIBRARY_PATH "$work/consumer-static-$other" >"$work/run.log" 2>&1; then
            ok "static, linked by $other"
        else
            cat "$work/cc.log" "$work/run.log" 2>/dev/null
            ko "static consumer linked by $other with pkg-config --static"
        fi
    fi
else
    echo "consumer: no libatrbvh.a (--disable-static); static case skipped"
fi

echo "consumer: $passed passed, $failed failed"
[ $failed -eq 0 ] || exit 1
[ $passed -gt 0 ] || exit 77
exit 0
