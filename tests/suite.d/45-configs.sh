#!/bin/sh
# Every optional part switched off, and the developer switches on:
# out-of-tree builds in _build/configs/, one per switch, each checked to
# have really dropped the part (or, for a switch that turns something on,
# to have it).
#   all-off   --disable-openmp --disable-opencl --without-embree --without-png
#             full `make check` (every Check suite, cli.sh, symbols, man
#             pages, consumer): the serial, OpenCL-less, tool-without-extras
#             build;
#   no-openmp, no-opencl  (library switches, one each)
#             build + the quick library tests: symbols, consumer (install,
#             pkg-config, shared and static link), man pages;
#   no-embree, no-png     (tool switches, one each)
#             the same + cli.sh (the tool's tests);
#             the full suites for these already ran in 10-check (everything
#             on) and in all-off (everything off), and on the CI's two cores
#             a full check per configuration would cost minutes each;
#   clang     CC=clang, the other compiler a distribution may build with:
#             the exported symbols (clang's OpenMP makes globals of its
#             own), the consumer's link, the recorded tree hashes (the
#             same trees, bit for bit) and the vector state the library
#             hands back (test_vecstate);
#   debug-checks  --enable-debug-checks (the tree check of lib/check.c after
#             every build, in the library alone): the suites that build
#             trees on both backends, so that every tree they build is
#             checked, and the tests whose memory bounds it moves.
# Set ATRBVH_CONFIGS_FULL=1 to run the full check in every configuration.
# Contract: print '=== stage ok' as the last line on success.
cd "$(dirname "$0")/../.." || exit 1
top=$(pwd)
sh setup.sh --packages check opencl bench hardening ||
    { echo "configs: 0 passed, 1 failed (installing packages failed)"; exit 1; }
[ -x configure ] || { echo "configs: run setup.sh first (no ./configure)"; exit 1; }
jobs=$(nproc 2>/dev/null || echo 2)
quick_lib="tests/symbols.sh tests/consumer.sh tests/manpages.sh"
quick_tool="$quick_lib tests/cli.sh"
passed=0
failed=0

# name, what must hold afterwards (a shell test run in the build dir),
# full|lib|tool|"tests=LIST" (which tests), configure flags
config() {
    name=$1 verify=$2 full=$3
    shift 3
    dir=$top/_build/configs/$name
    start=$(date +%s)
    rm -rf "$dir"
    mkdir -p "$dir"
    cd "$dir" || return 1
    log=$dir/config.out
    if ! "$top/configure" "$@" >"$log" 2>&1; then
        tail -n 30 "$log"; echo "configs: FAILED: $name: configure $*"; failed=$((failed + 1)); cd "$top"; return
    fi
    if ! make -j"$jobs" >>"$log" 2>&1; then
        tail -n 30 "$log"; echo "configs: FAILED: $name: make"; failed=$((failed + 1)); cd "$top"; return
    fi
    if ! sh -c "$verify" >>"$log" 2>&1; then
        echo "configs: FAILED: $name: the build is not what the switch asks for ($verify)"; failed=$((failed + 1)); cd "$top"; return
    fi
    if [ "$full" = full ] || [ "${ATRBVH_CONFIGS_FULL:-0}" = 1 ]; then
        what="full make check"
        make -j"$jobs" check >>"$log" 2>&1
    elif [ "${full#tests=}" != "$full" ]; then
        what="${full#tests=}"
        make -j"$jobs" check TESTS="$what" >>"$log" 2>&1
        what=$(echo $what | sed 's,tests/,,g')
    else
        [ "$full" = tool ] && quick=$quick_tool || quick=$quick_lib
        what="build + $(echo $quick | sed 's,tests/,,g')"
        make -j"$jobs" check TESTS="$quick" check_PROGRAMS= check_LTLIBRARIES= >>"$log" 2>&1
    fi
    rc=$?
    res=$(grep -E '^# (PASS|SKIP|FAIL|ERROR): ' "$log" | tail -n 4 | tr -s ' ' | tr '\n' ' ')
    if [ $rc -eq 0 ]; then
        echo "configs: ok: $name ($*): $what: $res($(( $(date +%s) - start )) s)"
        passed=$((passed + 1))
    else
        grep -E '^(FAIL|ERROR):' "$log"
        for f in $(grep -lE '^(FAIL|ERROR)' tests/*.log 2>/dev/null); do echo "--- $f"; tail -n 30 "$f"; done
        echo "configs: FAILED: $name ($*): $what"
        failed=$((failed + 1))
    fi
    cd "$top" || exit 1
}

no_gomp='! readelf -d lib/.libs/libatrbvh.so | grep -q libgomp && ! grep -q "^OPENMP_CFLAGS = ." Makefile && ! grep -q -e -lgomp -e -fopenmp atrbvh.pc'
no_cl='! grep -q "define ATRBVH_HAVE_OPENCL" config.h && ! grep -q OpenCL atrbvh.pc'
no_embree='! grep -q "define HAVE_EMBREE" config.h && ! readelf -d tools/.libs/atrbvh tools/atrbvh 2>/dev/null | grep -q libembree'
no_png='! grep -q "define HAVE_PNG" config.h && ! readelf -d tools/.libs/atrbvh tools/atrbvh 2>/dev/null | grep -q libpng'

config all-off "$no_gomp && $no_cl && $no_embree && $no_png" full \
    --disable-openmp --disable-opencl --without-embree --without-png
config no-openmp "$no_gomp" lib --disable-openmp
config no-opencl "$no_cl" lib --disable-opencl
config no-embree "$no_embree" tool --without-embree
config no-png "$no_png" tool --without-png
if command -v clang >/dev/null 2>&1; then
    config clang 'grep -q "^CC = clang" Makefile' \
        "tests=tests/symbols.sh tests/consumer.sh tests/test_hashes tests/test_vecstate" \
        CC=clang
else
    echo "configs: FAILED: clang: not installed (.ci/packages.d/60-hardening.txt)"
    failed=$((failed + 1))
fi
config debug-checks 'grep -q "define ATRBVH_DEBUG_CHECKS 1" config.h' \
    "tests=tests/test_build tests/test_device tests/test_split tests/test_stages tests/test_hashes tests/test_optimise tests/test_threads tests/test_errors tests/test_animate tests/test_opencl tests/animate.sh" \
    --enable-debug-checks
config kernel-source-override 'grep -q "define ATRBVH_KERNEL_SOURCE_OVERRIDE" config.h && make check TESTS=tests/test_opencl check_PROGRAMS=tests/test_opencl' lib --enable-kernel-source-override

# The configure summary of the all-off build, for the log.
sed -n '/^  atrbvh /,/^    make check:/p' "$top/_build/configs/all-off/config.out"

echo "configs: $passed passed, $failed failed"
[ $failed -eq 0 ] && echo '=== stage ok'
[ $failed -eq 0 ]
