#!/bin/sh
# ab.sh LIB_A LIB_B SCENE ROUNDS [ARGS...] - two builds of the library in
# turns: ROUNDS times, docs/bench/stagetimes.c (built as /tmp/stagetimes,
# see its header) with 15 builds against the libatrbvh.so in LIB_A, then
# against the one in LIB_B, on one core (taskset -c 0); ARGS go to
# stagetimes after BUILDS (method, size, rounds, threads).  Prints each
# run's build and optimise-stage median and minimum, then the best
# minimum of each side: on a shared host whose speed drifts within
# minutes, the figure to compare (the 5 December section "The Intel host
# again" in docs/bench/log.md).  To make LIB_A and LIB_B: copy
# _build/lib/.libs/libatrbvh.so* into a directory before and after the
# change (and a rebuild).  Compare trees first (atrbvh build prints the
# SAH and node count; the test suite the hashes).
set -eu
[ $# -ge 4 ] || { echo "usage: sh ab.sh LIB_A LIB_B SCENE ROUNDS [ARGS...]" >&2; exit 2; }
A=$1 B=$2 S=$3 N=$4
shift 4
export OMP_WAIT_POLICY=passive
i=0
while [ "$i" -lt "$N" ]; do
    for side in A B; do
        if [ $side = A ]; then lib=$A; else lib=$B; fi
        LD_LIBRARY_PATH=$lib taskset -c 0 /tmp/stagetimes "$S" 15 "$@" |
            awk -v side=$side '/^build/ { t = $3; tm = $6 }
                /optimise/ { o = $5; om = $7 }
                END { printf "%s build median %.2f min %.2f  optimise median %.2f min %.2f\n",
                      side, t, tm, o, om }'
    done
    i=$((i + 1))
done | awk '{ print } { k = $1
        if (!(k in b) || $6 < b[k]) b[k] = $6
        if (!(k in o) || $11 < o[k]) o[k] = $11 }
    END { for (k in b) printf "best %s: build min %.2f ms, optimise min %.2f ms\n", k, b[k], o[k] }'
