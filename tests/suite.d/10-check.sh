#!/bin/sh
# make check in _build/, then each Check suite's counts.
# Contract for every stage: print '=== stage ok' as the last line on success.
make -C _build check
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
