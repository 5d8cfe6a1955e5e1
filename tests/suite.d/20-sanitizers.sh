#!/bin/sh
# The whole `make check` again, built with AddressSanitizer (and its
# LeakSanitizer) and UndefinedBehaviorSanitizer in _build-asan/: any
# report fails the stage (-fno-sanitize-recover=all, halt_on_error).
# The only suppressions (tests/lsan.supp) are for libgomp's thread pool.
# Contract: print '=== stage ok' as the last line on success.
cd "$(dirname "$0")/../.." || exit 1
sh setup.sh --packages check opencl bench || exit 1
top=$(pwd)
SAN="-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all"
mkdir -p _build-asan || exit 1
cd _build-asan || exit 1
if [ ! -f Makefile ]; then
    ../configure CFLAGS="-O1 -g $SAN" LDFLAGS="$SAN" >configure.out 2>&1 || {
        tail -n 40 configure.out
        exit 1
    }
fi
make -j"$(nproc)" >make.out 2>&1 || {
    tail -n 60 make.out
    exit 1
}
ASAN_OPTIONS="detect_leaks=1:halt_on_error=1:abort_on_error=0:detect_stack_use_after_return=1:strict_string_checks=1:check_initialization_order=1"
LSAN_OPTIONS="suppressions=$top/tests/lsan.supp:print_suppressions=0"
UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
# The largest extreme scenes are cut down under ASan (its shadow memory
# and slower code): see tests/test_extremes.c.
ATRBVH_TEST_SANITIZER=1
export ASAN_OPTIONS LSAN_OPTIONS UBSAN_OPTIONS ATRBVH_TEST_SANITIZER
make check
rc=$?
for f in tests/*.log; do
    case "$f" in */test-suite.log) continue ;; esac
    res=$(sed -n 's/^:test-result: //p' "${f%.log}.trs" 2>/dev/null | head -n 1)
    echo "asan $(basename "${f%.log}"): $res"
    # a sanitizer report fails the test already; say so plainly as well
    grep -l 'ERROR: \(Address\|Leak\)Sanitizer\|runtime error:' "$f" \
        >/dev/null 2>&1 && echo "  sanitizer report in _build-asan/$f"
done
awk '/^[0-9]+%: Checks: / { gsub(",", ""); c += $3; f += $5 + $7 }
     END { printf "asan-checks: %d passed, %d failed\n", c - f, f }' tests/*.log
[ $rc -eq 0 ] && echo '=== stage ok'
exit $rc
