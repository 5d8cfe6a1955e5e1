# common.sh - what the shell tests of the atrbvh tool share (cli.sh,
# animate.sh, bench.sh, outputs.sh, stages.sh source it):
#   setup NAME [python3]  the tool must be built (else exit 99), python3
#                         there when asked (else exit 77, skipped); makes
#                         the temporary folder $T, removed on exit by
#                         cleanup (a script may redefine cleanup);
#   fail MESSAGE          counts a failure and says it on stderr;
#   run RC ARGS...        runs the tool, output in $T/out and $T/err, and
#                         checks its exit status; a failing status comes
#                         with exactly one "atrbvh: " line on stderr (for
#                         the statuses error_line says, which a script may
#                         redefine);
#   opencl_may_skip FILE  whether a run on OpenCL that failed, its stderr
#                         in FILE, may be skipped: only when there is no
#                         OpenCL (the library's ATRBVH_ERR_UNSUPPORTED
#                         messages), never with ATRBVH_TEST_REQUIRE_OPENCL
#                         set (tests/testutil.h, tu_opencl_may_skip);
#   finish                the summary line; its status is the script's.
# Sourced: `. "$(dirname "$0")/common.sh"`, with ATRBVH_BUILDDIR and
# ATRBVH_SRCDIR set by `make check` (the current folder otherwise).
# shellcheck shell=sh

BUILDDIR=${ATRBVH_BUILDDIR:-.}
# shellcheck disable=SC2034 # (for the scripts)
SRCDIR=${ATRBVH_SRCDIR:-.}
TOOL=$BUILDDIR/tools/atrbvh

cleanup() {
    rm -rf "$T"
}

setup() {
    NAME=$1
    if [ ! -x "$TOOL" ]; then
        echo "$NAME.sh: $TOOL not built" >&2
        exit 99
    fi
    if [ "${2:-}" = python3 ] && ! command -v python3 >/dev/null 2>&1; then
        echo "$NAME.sh: no python3, skipped" >&2
        exit 77
    fi
    T=$(mktemp -d "${TMPDIR:-/tmp}/atrbvh_$NAME.XXXXXX") || exit 99
    trap cleanup EXIT INT TERM
    failures=0
    checks=0
}

fail() {
    echo "FAIL: $*" >&2
    failures=$((failures + 1))
}

opencl_may_skip() {
    case ${ATRBVH_TEST_REQUIRE_OPENCL:-} in
    '' | 0) ;;
    *) return 1 ;;
    esac
    grep -q 'OpenCL: no platform found\|OpenCL: no device found\|has no OpenCL backend' "$1"
}

# error_line RC ARGS...: whether run wants one "atrbvh: " line on stderr.
error_line() {
    [ "$1" -ne 0 ]
}

run() {
    want=$1
    shift
    checks=$((checks + 1))
    "$TOOL" "$@" >"$T/out" 2>"$T/err"
    rc=$?
    if [ "$rc" -ne "$want" ]; then
        fail "atrbvh $* exited $rc, expected $want; stderr: $(cat "$T/err"); stdout: $(tail -3 "$T/out")"
        return 1
    fi
    if error_line "$want" "$@"; then
        if [ "$(wc -l <"$T/err")" -ne 1 ] || ! grep -q '^atrbvh: ' "$T/err"; then
            fail "atrbvh $*: stderr is not one 'atrbvh: ' line: $(cat "$T/err")"
            return 1
        fi
    fi
    return 0
}

finish() {
    echo "$NAME.sh: $checks checks, $failures failed"
    [ "$failures" -eq 0 ]
}
