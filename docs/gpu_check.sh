#!/bin/sh
# docs/gpu_check.sh - the OpenCL backend on a lent GPU machine, in one
# short call of the device tool (docs/opencl.md, "On an NVIDIA GPU").
#
#   sh docs/gpu_check.sh pack    here, once: configures and builds the
#                                library, the tool (without Embree) and
#                                the OpenCL test programs in a build
#                                folder of its own, and copies the
#                                programs and the libraries they need
#                                into .gpu/ (ignored by git, about 4 MB)
#   sh docs/gpu_check.sh run     there: the device tool's run with
#                                carry [".gpu"] and a timeout_s of about
#                                400; writes $OUT/gpu-check.txt
#
# The machine there has a GPU driver and nothing of ours, and the copy of
# the tree lies at another path: the programs are run from .gpu/ with
# LD_LIBRARY_PATH, never through libtool's wrappers.  OpenCL goes through
# the ICD loader carried in .gpu/lib, with OCL_ICD_VENDORS naming only the
# driver's library (libnvidia-opencl.so.1), so "opencl" is the GPU.  Where
# no such library is found (a trial run here) the system's ICDs are used,
# and the report says so.  Tests need ATRBVH_TEST_REQUIRE_OPENCL: a device
# that cannot be opened fails them instead of skipping them.
#
# What runs there, each with a time limit, all output in the report:
#   test_opencl, test_clreuse, test_clrays    (the device's trees and ray
#                                              hits equal to the CPU's)
#   atrbvh validate builtin:city:100000       (every stage's output)
#   atrbvh trace builtin:sphere:1000000 --backend opencl --json
#                                             (the device's name, the ray
#                                              kernels' rates)
#   atrbvh bench builtin:sphere:N --backend cpu,opencl for N = 10^5 and
#   10^6, LBVH and ATRBVH(9,2), all the machine's threads on the CPU
#   (the same SAH and nodes on both backends, and the build times)
# The generated scenes only: ../shared/scenes does not travel.
set -eu

here=$(cd "$(dirname "$0")/.." && pwd)
cd "$here"

libs_of() {
    # the shared libraries a program needs, but the C library's own
    ldd "$1" | awk '$3 ~ /^\// {print $3}' |
        grep -v -E '/(libc|libm|libpthread|libdl|librt|ld-linux[^/]*)\.so' ||
        true
}

pack() {
    B=${GPU_CHECK_BUILD:-/tmp/atrbvh-gpu-build}
    [ -x configure ] || autoreconf -fi
    mkdir -p "$B"
    (cd "$B" && "$here/configure" --without-embree --enable-opencl \
        CFLAGS="-O2 -g" >/dev/null)
    make -C "$B" -j"$(nproc)" >/dev/null
    # the test programs, built but not run
    make -C "$B" -j"$(nproc)" check TESTS= >/dev/null
    rm -rf .gpu.tmp
    mkdir -p .gpu.tmp/bin .gpu.tmp/lib
    for p in tools/atrbvh tests/test_opencl tests/test_clrays \
        tests/test_clreuse; do
        d=$(dirname "$p")
        f=$(basename "$p")
        if [ -x "$B/$d/.libs/$f" ]; then
            cp "$B/$d/.libs/$f" .gpu.tmp/bin/
        else
            cp "$B/$p" .gpu.tmp/bin/
        fi
    done
    cp -P "$B"/lib/.libs/libatrbvh.so* .gpu.tmp/lib/
    for p in .gpu.tmp/bin/*; do
        LD_LIBRARY_PATH=.gpu.tmp/lib libs_of "$p"
    done | sort -u | while read -r l; do
        case $l in */.gpu.tmp/*) continue ;; esac
        cp -L "$l" .gpu.tmp/lib/
    done
    git describe --always --dirty >.gpu.tmp/commit
    rm -rf .gpu
    mv .gpu.tmp .gpu
    echo "gpu_check: .gpu/ holds $(find .gpu/bin -type f | wc -l) programs" \
        "and $(find .gpu/lib -name '*.so*' | wc -l) libraries" \
        "($(du -sh .gpu | cut -f1)),"  \
        "built from $(cat .gpu/commit)"
}

run() {
    O=${OUT:-/tmp/gpu-check-out}
    mkdir -p "$O"
    R=$O/gpu-check.txt
    T=$(mktemp -d)
    G=$here/.gpu
    [ -d "$G/bin" ] || {
        echo "gpu_check: no .gpu/ (run 'sh docs/gpu_check.sh pack' here" \
            "first, and carry .gpu)" >&2
        exit 2
    }
    export LD_LIBRARY_PATH="$G/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
    nv=
    for d in /usr/local/nvidia/lib64 /usr/local/nvidia/lib \
        /usr/lib/x86_64-linux-gnu /usr/lib64; do
        if [ -e "$d/libnvidia-opencl.so.1" ]; then
            nv=$d/libnvidia-opencl.so.1
            break
        fi
    done
    [ -n "$nv" ] || nv=$(ldconfig -p 2>/dev/null |
        awk '/libnvidia-opencl\.so\.1/ {print $NF; exit}')
    {
        echo "# gpu_check run $(date -u '+%Y-%m-%d %H:%M UTC'), built from" \
            "$(cat "$G/commit")"
        uname -a
        command -v nvidia-smi >/dev/null 2>&1 &&
            nvidia-smi --query-gpu=name,driver_version,memory.total \
                --format=csv,noheader
        echo "cpu threads: $(nproc)"
        if [ -n "$nv" ]; then
            mkdir -p "$T/icd"
            echo "$nv" >"$T/icd/nvidia.icd"
            export OCL_ICD_VENDORS="$T/icd"
            echo "OpenCL: the driver's ICD only ($nv)"
        else
            echo "OpenCL: no libnvidia-opencl.so.1 found; the system's" \
                "ICDs (${OCL_ICD_VENDORS:-/etc/OpenCL/vendors})"
        fi
    } >"$R" 2>&1
    export ATRBVH_TEST_REQUIRE_OPENCL=1 ATRBVH_SRCDIR="$here"
    status=0
    for t in test_opencl test_clreuse test_clrays; do
        echo "## $t" >>"$R"
        if timeout 240 "$G/bin/$t" >>"$R" 2>&1; then
            echo "$t: passed" >>"$R"
        else
            echo "$t: FAILED (exit $?)" >>"$R"
            status=1
        fi
    done
    echo "## validate builtin:city:100000 (every stage, CPU against OpenCL)" \
        >>"$R"
    timeout 120 "$G/bin/atrbvh" validate builtin:city:100000 >>"$R" 2>&1 ||
        { echo "validate: FAILED (exit $?)" >>"$R"; status=1; }
    echo "## trace builtin:sphere:1000000 --backend opencl" >>"$R"
    timeout 120 "$G/bin/atrbvh" trace builtin:sphere:1000000 \
        --backend opencl --json >>"$R" 2>&1 ||
        { echo "trace: FAILED (exit $?)" >>"$R"; status=1; }
    for n in 100000 1000000; do
        echo "## bench builtin:sphere:$n" >>"$R"
        timeout 120 "$G/bin/atrbvh" bench "builtin:sphere:$n" --no-rays \
            --repeat 5 --threads "$(nproc)" --configs lbvh,atrbvh:9:2 \
            --backend cpu,opencl >>"$R" 2>&1 ||
            { echo "bench: FAILED (exit $?)" >>"$R"; status=1; }
    done
    rm -rf "$T"
    echo "gpu_check: $R ($(wc -l <"$R") lines), status $status"
    return $status
}

case ${1:-} in
pack) pack ;;
run) run ;;
*)
    echo "usage: sh docs/gpu_check.sh pack|run" >&2
    exit 2
    ;;
esac
