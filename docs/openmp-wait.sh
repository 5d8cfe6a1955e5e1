#!/bin/sh
# docs/openmp-wait.sh - the measurement of docs/openmp.md: `atrbvh build`
# at 2 threads with OpenMP's default waiting (threads spin at barriers) and
# with passive waiting, on a quiet machine and with two busy loops
# (`yes > /dev/null`, one per core of a 2-core machine) competing.
#
#   sh docs/openmp-wait.sh BEFORE AFTER [RUNS]
#
# BEFORE: an atrbvh binary that leaves OMP_WAIT_POLICY alone (the tool
# before the change); AFTER: one that sets it to passive unless the user
# did.  Both run with OMP_WAIT_POLICY unset; BEFORE also with it set to
# passive by hand.  Prints, per case, the median of RUNS (7) build times
# (the tool's build_ms) and of the process's wall time, in ms, with the
# load average.
set -u
before=$1 after=$2 runs=${3:-7}
unset OMP_WAIT_POLICY
now() { date +%s%N; }
median() { sort -n | awk '{ a[NR] = $1 } END { print a[int((NR + 1) / 2)] }'; }
one() { # label, scene, command...
    label=$1 scene=$2; shift 2
    b=$(mktemp) w=$(mktemp)
    i=0
    while [ $i -lt "$runs" ]; do
        t0=$(now)
        "$@" build "$scene" --threads 2 --json >"$b.json" || exit 1
        t1=$(now)
        sed -n 's/.*"build_ms": \([0-9.]*\).*/\1/p' "$b.json" >>"$b"
        echo $(( (t1 - t0) / 1000000 )) >>"$w"
        i=$((i + 1))
    done
    printf '%-8s %-22s %-28s build %8.1f ms  process %6s ms  (load %s)\n' \
        "$load" "$scene" "$label" "$(median <"$b")" "$(median <"$w")" \
        "$(cut -d' ' -f1-3 /proc/loadavg)"
    rm -f "$b" "$b.json" "$w"
}
cases() {
    for scene in builtin:sphere builtin:city:100000; do
        one "before (spin, default)" "$scene" "$before"
        one "before, passive by hand" "$scene" env OMP_WAIT_POLICY=passive "$before"
        one "after (passive, default)" "$scene" "$after"
    done
}
load=quiet
cases
yes >/dev/null & y1=$!
yes >/dev/null & y2=$!
trap 'kill $y1 $y2 2>/dev/null' EXIT
sleep 2
load="2x yes"
cases
kill $y1 $y2
