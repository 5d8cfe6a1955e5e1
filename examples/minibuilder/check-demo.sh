#!/bin/sh
# check-demo.sh - `atrbvh check` against an independent builder.
#
# Builds examples/minibuilder/minibuilder.c (plain C, no libatrbvh),
# writes a test scene with equal Morton keys and equal boxes, dumps the
# minibuilder's stages (LBVH, TRBVH and ATRBVH with collapsing) and checks them
# with `atrbvh check`: the same at every stage.  Then builds it with each
# planted bug and shows `atrbvh check` naming the stage and the first
# wrong item:
#   -DPLANTED_BUG=1  an unstable sort      -> stage sort, order[0]
#   -DPLANTED_BUG=2  a wrong ATRBVH tie    -> stage optimise_round1
#   -DPLANTED_BUG=3  a wrong TRBVH tie     -> stage optimise_round1
# Exits 0 when everything goes as described.
#
#   sh check-demo.sh [ATRBVH]    (default: $ATRBVH, atrbvh in the build
#                                 tree $ATRBVH_BUILDDIR, or on PATH)
set -u
HERE=$(cd "$(dirname "$0")" && pwd)
TOOL=${1:-${ATRBVH:-}}
if [ -z "$TOOL" ] && [ -n "${ATRBVH_BUILDDIR:-}" ]; then
    TOOL=$ATRBVH_BUILDDIR/tools/atrbvh
fi
TOOL=${TOOL:-atrbvh}
CC=${CC:-cc}
CFLAGS="-std=c99 -ffp-contract=off -O2 -Wall -Wextra"

W=$(mktemp -d "${TMPDIR:-/tmp}/minibuilder.XXXXXX") || exit 99
trap 'rm -rf "$W"' EXIT INT TERM

$CC $CFLAGS -o "$W/mb" "$HERE/minibuilder.c" || exit 99
$CC $CFLAGS -DPLANTED_BUG=1 -o "$W/mb-bug1" "$HERE/minibuilder.c" || exit 99
$CC $CFLAGS -DPLANTED_BUG=2 -o "$W/mb-bug2" "$HERE/minibuilder.c" || exit 99
$CC $CFLAGS -DPLANTED_BUG=3 -o "$W/mb-bug3" "$HERE/minibuilder.c" || exit 99
"$W/mb" --scene "$W/grid.obj" 24 || exit 99

# dump NAME BUILDER OPTIONS...: the builder's dumps in $W/NAME, then
# `atrbvh check` on them (its report in $W/NAME.out); returns its status
dump() {
    name=$1
    builder=$2
    shift 2
    mkdir "$W/$name" || exit 99
    "$W/$builder" "$@" "$W/grid.obj" "$W/$name" || exit 99
    "$TOOL" check "$W/$name" >"$W/$name.out"
    rc=$?
    cat "$W/$name.out"
    return $rc
}
bad() {
    echo "check-demo: $*" >&2
    exit 1
}

echo "== the minibuilder, LBVH"
dump lbvh mb || bad "expected the LBVH stages to match"
echo
echo "== the minibuilder, TRBVH with collapsing"
dump trbvh mb --trbvh --collapse || bad "expected the TRBVH stages to match"
grep -q '^optimise_round3 .*same' "$W/trbvh.out" || bad "no third round compared"
echo
echo "== the minibuilder, ATRBVH with collapsing"
dump atrbvh mb --atrbvh --collapse || bad "expected the ATRBVH stages to match"
grep -q '^optimise_round2 .*same' "$W/atrbvh.out" || bad "no second round compared"
grep -q '^layout .*same' "$W/atrbvh.out" || bad "layout not compared"

echo
echo "== planted bug 1: equal keys sorted by descending index"
dump bug1 mb-bug1
[ $? -eq 1 ] || bad "expected exit 1 for planted bug 1"
# bounds and morton the same; sort different, first at order[0]: the two
# copies of triangle 0 have equal keys, and the bug puts the copy
# (primitive 1152 = 24 * 24 * 2) first.
grep -q '^morton .*same' "$W/bug1.out" &&
    grep -q '^sort .*DIFFERENT' "$W/bug1.out" &&
    grep -q 'first: order\[0\] in sort-order.npy: 1152, reference 0' "$W/bug1.out" ||
    bad "the report does not name stage sort and order[0]"

echo
echo "== planted bug 2: ATRBVH clustering takes the last of equal distances"
dump bug2 mb-bug2 --atrbvh --collapse
[ $? -eq 1 ] || bad "expected exit 1 for planted bug 2"
grep -q '^refit .*same' "$W/bug2.out" &&
    grep -q '^optimise_round1 .*DIFFERENT' "$W/bug2.out" &&
    grep -q 'first: left\[[0-9]*\] in optimise_round1-left.npy' "$W/bug2.out" ||
    bad "the report does not name stage optimise_round1 and an item of left"

echo
echo "== planted bug 3: the TRBVH subset DP takes the last of equal splits"
dump bug3 mb-bug3 --trbvh
[ $? -eq 1 ] || bad "expected exit 1 for planted bug 3"
grep -q '^refit .*same' "$W/bug3.out" &&
    grep -q '^optimise_round1 .*DIFFERENT' "$W/bug3.out" ||
    bad "the report does not name stage optimise_round1"

echo
echo "check-demo: atrbvh check matched the minibuilder and found every planted bug"
