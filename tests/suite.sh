#!/bin/sh
# tests/suite.sh - the whole test suite: every stage in tests/suite.d/, in
# order (10-check: `make check`; later stages: sanitizers, fuzzing,
# distcheck, packaging).  Run after setup.sh, which installs only what the
# build needs: each stage installs the packages it uses itself (`sh
# setup.sh --packages ...`, the lists in .ci/packages.d/).  About 35 minutes
# on two cores.  Runs every stage, exits non-zero if any failed.  A stage may print lines "WORD: N passed, M
# failed"; the closing line adds them up (a stage that prints none counts as
# one check).
cd "$(dirname "$0")/.." || exit 1
out=$(mktemp)
trap 'rm -f "$out"' EXIT
passed=0
failed=0
failures=""
for stage in tests/suite.d/*.sh; do
    name=$(basename "$stage" .sh)
    echo "=== suite stage $name"
    start=$(date +%s)
    sh "$stage" 2>&1 | tee "$out"
    set -- $(awk '/^[A-Za-z_-]+: [0-9]+ passed, [0-9]+ failed/ { p += $2; f += $4; n++ }
                  END { print p + 0, f + 0, n + 0 }' "$out")
    if [ "$(tail -n 1 "$out")" = "=== stage ok" ]; then
        echo "=== $name: ok ($(( $(date +%s) - start )) s)"
        [ "$3" -gt 0 ] && { passed=$((passed + $1)); failed=$((failed + $2)); } ||
            passed=$((passed + 1))
    else
        echo "=== $name: FAILED ($(( $(date +%s) - start )) s)"
        failures="$failures $name"
        [ "$3" -gt 0 ] && { passed=$((passed + $1)); failed=$((failed + $2)); }
        [ "$2" -gt 0 ] || failed=$((failed + 1))
    fi
done
[ -z "$failures" ] || echo "failed stages:$failures"
echo "total: $passed passed, $failed failed"
[ -z "$failures" ]
