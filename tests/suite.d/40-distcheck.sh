#!/bin/sh
# make distcheck in _build/: the release tarball builds out of tree (VPATH)
# from a read-only source, passes `make check` (Check suites, cli.sh,
# symbols, man pages, consumer), installs, uninstalls cleanly and cleans up.
# The tarball is left in _build/ (the Debian stage builds from it).
# Contract: print '=== stage ok' as the last line on success.
cd "$(dirname "$0")/../.." || exit 1
sh setup.sh --packages check opencl bench ||
    { echo "distcheck: 0 passed, 1 failed (installing packages failed)"; exit 1; }
[ -f _build/Makefile ] || { echo "distcheck: run setup.sh first (no _build/Makefile)"; exit 1; }
jobs=$(nproc 2>/dev/null || echo 2)
start=$(date +%s)
if make -C _build -j"$jobs" distcheck >_build/distcheck.log 2>&1; then
    tail -n 6 _build/distcheck.log
    grep -E '^# (TOTAL|PASS|FAIL|ERROR):' _build/distcheck.log | tr '\n' ' '; echo
    echo "distcheck: 1 passed, 0 failed ($(( $(date +%s) - start )) s)"
    echo '=== stage ok'
else
    tail -n 80 _build/distcheck.log
    for f in $(find _build -path '*/_build/sub/*' -name '*.log' 2>/dev/null); do
        grep -q '^FAIL\|^ERROR' "$f" 2>/dev/null && { echo "--- $f"; tail -n 40 "$f"; }
    done
    echo "distcheck: 0 passed, 1 failed"
    exit 1
fi
