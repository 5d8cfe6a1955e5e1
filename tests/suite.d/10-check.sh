#!/bin/sh
# make check in _build/, then each Check suite's counts.
# Contract for every stage: print '=== stage ok' as the last line on success.
# Each stage installs the packages it needs itself (setup.sh installs only
# the build's): here Check, python3, groff/mandoc, PoCL, Embree, gnuplot,
# libpng.  Then _build/ is configured again with its own arguments, so that
# it finds what was just installed (config.h is left alone, and nothing is
# rebuilt, when nothing changed).
cd "$(dirname "$0")/../.." || exit 1
sh setup.sh --packages check opencl bench ||
    { echo "checks: 0 passed, 1 failed (installing packages failed)"; exit 1; }
[ -f _build/config.status ] || { echo "checks: run setup.sh first (no _build/config.status)"; exit 1; }
(cd _build && ./config.status --recheck >recheck.out 2>&1 && ./config.status >/dev/null) ||
    { tail -n 30 _build/recheck.out; echo "checks: 0 passed, 1 failed (configure failed)"; exit 1; }
sed -n '/^  Found:/,/^    Check/p' _build/recheck.out
# PoCL was installed above: a test that needs the OpenCL backend fails,
# not skips, without a device (testutil.h's tu_opencl_may_skip, common.sh).
ATRBVH_TEST_REQUIRE_OPENCL=1 make -C _build check
rc=$?
for f in _build/tests/*.log; do
    case "$f" in */test-suite.log) continue ;; esac
    line=$(grep -E '^[0-9]+%: Checks: ' "$f" | tail -n 1)
    res=$(sed -n 's/^:test-result: //p' "${f%.log}.trs" 2>/dev/null | head -n 1)
    echo "$(basename "${f%.log}"): ${line:-$res}"
done
cat _build/tests/*.log | awk '
    /^[0-9]+%: Checks: / { gsub(",", ""); c += $3; f += $5 + $7 }
    END { printf "checks: %d passed, %d failed\n", c - f, f }'
[ $rc -eq 0 ] && echo '=== stage ok'
exit $rc
