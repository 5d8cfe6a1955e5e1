#!/bin/sh
# tests/fuzz/run.sh - build the libFuzzer harnesses with clang
# (-fsanitize=fuzzer,address,undefined) straight from the sources, outside
# automake, in _build-fuzz/, and run each for a bounded time starting from
# its seed corpus in tests/fuzz/corpus/NAME/ (new inputs go to
# _build-fuzz/work/NAME/, so the committed corpus only changes by hand).
#
#   sh tests/fuzz/run.sh [SECONDS [HARNESS...]]
#
# SECONDS per harness (default $FUZZ_SECONDS or 30).  A crash, a leak, a
# sanitizer report or a failed check is saved as
# _build-fuzz/crash-NAME-*: add it to the corpus as a regression seed once
# fixed.  Prints the executions per harness and "fuzz: N passed, M failed".
cd "$(dirname "$0")/../.." || exit 1
secs=${1:-${FUZZ_SECONDS:-30}}
[ $# -gt 0 ] && shift
harnesses=${*:-ply obj bvh build}
CC=${FUZZ_CC:-clang}
out=_build-fuzz
mkdir -p "$out" || exit 1
: >"$out/config.h"
if ! command -v "$CC" >/dev/null 2>&1; then
    echo "fuzz: $CC not found (install clang: .ci/packages.d/60-hardening.txt)"
    echo "fuzz: 0 passed, 1 failed"
    exit 1
fi
CFLAGS="-std=c99 -g -O1 -ffp-contract=off -fno-omit-frame-pointer
 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all
 -Wall -Wextra -Wno-unknown-pragmas -pthread -I$out -Ilib -Itools -Itests"
LIB=$(ls lib/*.c lib/cpu/*.c)
SCENE="tools/scene.c tools/ply.c tools/obj.c tools/builtin.c tools/camera.c"
passed=0
failed=0
for h in $harnesses; do
    src="tests/fuzz/fuzz_$h.c"
    bin="$out/fuzz_$h"
    extra=""
    case $h in build | bvh) extra="tests/testutil.c $(pkg-config --cflags --libs check 2>/dev/null || echo -lcheck)" ;; esac
    # shellcheck disable=SC2086
    if ! $CC $CFLAGS -o "$bin" "$src" $LIB $SCENE $extra -lm 2>"$out/cc-$h.log"; then
        cat "$out/cc-$h.log"
        echo "fuzz $h: does not compile"
        failed=$((failed + 1))
        continue
    fi
    mkdir -p "$out/work/$h"
    start=$(date +%s)
    ASAN_OPTIONS="detect_leaks=1:allocator_may_return_null=1" \
    UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1" \
        "$bin" -max_total_time="$secs" -timeout=10 -rss_limit_mb=2048 \
        -malloc_limit_mb=1024 -max_len=65536 -print_final_stats=1 \
        -artifact_prefix="$out/crash-$h-" \
        "$out/work/$h" "tests/fuzz/corpus/$h" >"$out/run-$h.log" 2>&1
    rc=$?
    runs=$(sed -n 's/^Done \([0-9]*\) runs.*/\1/p' "$out/run-$h.log" | tail -n 1)
    echo "fuzz $h: ${runs:-?} executions in $(( $(date +%s) - start )) s, exit $rc"
    if [ $rc -eq 0 ]; then
        passed=$((passed + 1))
    else
        grep -E 'ERROR|SUMMARY|fuzz check failed|runtime error|Test unit written' \
            "$out/run-$h.log" | head -n 20
        failed=$((failed + 1))
    fi
done
echo "fuzz: $passed passed, $failed failed"
[ $failed -eq 0 ]
