#!/bin/sh
# docs/run_benchmarks.sh [PART...] - regenerates the measurements, plots and
# tables of docs/benchmarks.md.  PART: machine, main, sweep, scaling,
# render, tables (default: all, in that order), and speed (not in the
# default: the build-speed section beside Embree, 1-2 minutes on 2 cores; run it
# alone on a quiet machine).  Run from anywhere after the build
# in _build/ (BUILDDIR=... to use another); scenes from ../shared/scenes,
# or ../../shared/scenes from a worktree (ATRBVH_SCENES=... to use others).  Needs gnuplot and python3.
set -eu
cd "$(dirname "$0")/.."
TOOL=${BUILDDIR:-_build}/tools/atrbvh
S=${ATRBVH_SCENES:-../shared/scenes}
# a worktree of the repository sits one level deeper
[ -d "$S" ] || [ -n "${ATRBVH_SCENES:-}" ] || S=../../shared/scenes
OUT=docs/bench
SCENES="$S/bunny.ply $S/sibenik.ply $S/dabrovic_sponza.ply $S/conference.ply $S/dragon.ply"
# The machine these ran on is shared (load average above its core count):
# OpenMP threads that spin at barriers then lose whole time slices, and
# builds take 5-10 times longer.  Passive waiting is what such a machine
# needs (docs/benchmarks.md shows both).
OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-passive}
export OMP_WAIT_POLICY
# PoCL's CPU device pins its worker threads to cores (its own knob): on the
# virtual machines these ran on, unpinned workers that had been idle for a
# while were often stacked on one vCPU by the guest's scheduler, and an
# OpenCL LBVH of bunny took 6.6-7.8 ms instead of 3.5-4.3 (docs/opencl.md,
# "PoCL's workers after an idle spell").  The OpenMP threads stay unbound:
# OMP_PROC_BIND binds the main thread to one core, and Embree's threads,
# which inherit its mask, then build on that core alone.
POCL_AFFINITY=${POCL_AFFINITY:-1}
export POCL_AFFINITY
[ $# -gt 0 ] || set -- machine main sweep scaling render tables
mkdir -p "$OUT"
for part in "$@"; do
    case $part in
    machine)
        {
            echo "date: $(date -u '+%Y-%m-%d %H:%M UTC')"
            echo "cpu: $(sed -n 's/^model name[^:]*: //p' /proc/cpuinfo | head -n 1)"
            echo "nproc: $(nproc)"
            echo "memory: $(awk '/MemTotal/ { printf "%.1f GiB", $2 / 1048576 }' /proc/meminfo)"
            echo "compiler: $(${CC:-cc} --version | head -n 1)"
            echo "embree: $("$TOOL" bench --repeat 1 --no-rays --configs lbvh builtin:sphere:100 | sed -n 's/^# Embree\([^:]*\):.*/Embree\1/p')"
            echo "OMP_WAIT_POLICY: $OMP_WAIT_POLICY"
            echo "POCL_AFFINITY: $POCL_AFFINITY"
            echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)"
            echo "command: sh docs/run_benchmarks.sh"
        } >"$OUT/machine.txt"
        ;;
    main)
        # shellcheck disable=SC2086
        "$TOOL" bench $SCENES --repeat 3 --width 320 --height 240 --spp 4 \
            --configs lbvh,trbvh:7:3,atrbvh:9:2,atrbvh:16:2,atrbvh:16:3,atrbvh:24:3,atrbvh:32:6,fast,balanced,high,embree \
            --csv "$OUT/bench.csv" --plot "$OUT" >"$OUT/bench.txt"
        ;;
    sweep)
        # shellcheck disable=SC2086
        "$TOOL" bench $SCENES --no-rays --repeat 1 --methods lbvh,atrbvh,embree \
            --treelet 9,12,16,20,24,32 --rounds 2,3,4,6 \
            --csv "$OUT/sweep.csv" --plot "$OUT/sweep" >"$OUT/sweep.txt"
        ;;
    scaling)
        "$TOOL" bench --scaling builtin:sphere "$S/bunny.ply" --repeat 3 \
            --sizes 10000,100000,1000000,3000000,10000000 \
            --csv "$OUT/scaling.csv" --plot "$OUT" >"$OUT/scaling.txt"
        ;;
    render)
        for q in fast balanced high; do
            "$TOOL" render "$S/conference.ply" --heatmap --heat-top 120 \
                --quality $q --width 400 --height 300 --viewpoint 2 \
                -o "$OUT/heat-conference-$q.png" >"$OUT/render-$q.txt"
        done
        "$TOOL" render "$S/conference.ply" --width 400 --height 300 \
            --viewpoint 2 -o "$OUT/shaded-conference.png" >/dev/null
        ;;
    speed)
        # Builds only, 2 threads, median of 5, beside Embree in one run;
        # then the standalone Embree timing and the 10^7 scaling.  The
        # host's steal time over the run is recorded beside the load: on a
        # virtual machine the load average shows only this guest's
        # threads, steal the time its vCPUs were ready and the host ran
        # something else (/proc/stat, all CPUs, clock ticks).
        steal() { awk '/^cpu / { print $2 + $3 + $4 + $7 + $8, $9 }' /proc/stat; }
        STEAL0=$(steal)
        {
            echo "date: $(date -u '+%Y-%m-%d %H:%M UTC')"
            echo "cpu: $(sed -n 's/^model name[^:]*: //p' /proc/cpuinfo | head -n 1), $(nproc) cores"
            echo "OMP_WAIT_POLICY: $OMP_WAIT_POLICY"
            echo "POCL_AFFINITY: $POCL_AFFINITY"
            echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)"
            echo "command: ${ATRBVH_BENCH_FRESH:+ATRBVH_BENCH_FRESH=1 }sh docs/run_benchmarks.sh speed"
            if [ -n "${ATRBVH_BENCH_FRESH:-}" ]; then
                echo "atrbvh builds: fresh (each after the last tree is freed, --fresh)"
            else
                echo "atrbvh builds: rebuild (each into the last tree, atrbvh_rebuild)"
            fi
        } >"$OUT/speed-machine.txt"
        mkdir -p "$OUT/speed"
        # ATRBVH_BENCH_FRESH=1: every atrbvh build after freeing the last
        # tree (the bench's --fresh, as all runs before 7 December did)
        FRESH=${ATRBVH_BENCH_FRESH:+--fresh}
        # shellcheck disable=SC2086
        "$TOOL" bench $SCENES --no-rays --repeat 5 --threads 2 $FRESH \
            --configs lbvh,atrbvh:7:1,atrbvh:9:1,atrbvh:6:2,atrbvh:9:2,atrbvh:16:3,trbvh:7:3,fast,balanced,high,embree,lbvh@opencl,atrbvh:9:2@opencl \
            --csv "$OUT/speed.csv" --builds "$OUT/speed-builds.csv" \
            --plot "$OUT/speed" >"$OUT/speed.txt"
        ALONE=$(dirname "$TOOL")/embree-alone
        if [ -x "$ALONE" ]; then
            for s in $SCENES; do "$ALONE" "$s" 2 5; done >"$OUT/embree-alone.txt"
        fi
        # shellcheck disable=SC2086
        "$TOOL" bench --scaling builtin:sphere --configs lbvh --threads 2 \
            $FRESH --repeat 3 --sizes 100000,1000000,3000000,10000000 \
            --csv "$OUT/speed-scaling.csv" >"$OUT/speed-scaling.txt"
        {
            echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
            echo "$STEAL0 $(steal)" | awk '{ b = $3 - $1; s = $4 - $2;
                printf "steal during the run: %.1f%% of the CPU time (%d of %d ticks)\n",
                       (b + s > 0 ? 100 * s / (b + s) : 0), s, b + s }'
        } >>"$OUT/speed-machine.txt"
        python3 docs/speed_tables.py "$OUT" docs/benchmarks.md
        ;;
    tables)
        echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)" >>"$OUT/machine.txt"
        rm -f "$OUT"/*.gp.log "$OUT"/gnuplot.log "$OUT"/sweep/gnuplot.log
        python3 docs/bench_tables.py "$OUT" docs/benchmarks.md
        ;;
    *)
        echo "run_benchmarks.sh: unknown part '$part'" >&2
        exit 2
        ;;
    esac
done
