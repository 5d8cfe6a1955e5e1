#!/bin/sh
# stages.sh - `atrbvh stages` and `atrbvh check` (docs/stages.md): the
# reference's own dumps check clean for every method; a one-item change
# in any stage file is reported at that stage and item, earlier stages
# equal; malformed .npy files and manifests are exit 2; the dumps are the
# same bytes for 1, 2 and 3 threads (and on OpenCL when built with it);
# dump writing never loses a file.
# Run by `make check` with ATRBVH_BUILDDIR and ATRBVH_SRCDIR set.

# shellcheck source-path=SCRIPTDIR source=common.sh
. "$(dirname "$0")/common.sh"
EDIT="python3 $SRCDIR/tests/npy_edit.py"
setup stages python3

# A status 1 or 2 with an error comes with exactly one "atrbvh: " line on
# stderr; check's "different" (1) is a report on stdout, not an error.
error_line() {
    [ "$1" -eq 2 ] || { [ "$1" -eq 1 ] && [ "$2" != check ]; }
}

SCENE=builtin:city:1500

# ------------------------------------------------ own dumps check clean
for m in lbvh trbvh atrbvh; do
    run 0 stages "$SCENE" --method "$m" --dump "$T/$m"
    run 0 check "$T/$m"
    grep -q '^result: same' "$T/out" || fail "check $m: $(cat "$T/out")"
    [ -f "$T/$m/manifest.json" ] || fail "$m: no manifest"
done
# every optimise round of trbvh is there
for r in 1 2 3; do
    [ -f "$T/trbvh/optimise_round$r-box.npy" ] || fail "trbvh: no round $r"
done
# a subset of the stages checks clean too
mkdir "$T/sub"
python3 - "$T/atrbvh/manifest.json" "$T/sub/manifest.json" <<'PY' || fail "subset manifest"
import json, sys
m = json.load(open(sys.argv[1]))
m["stages"] = [s for s in m["stages"] if s["name"] in ("sort", "collapse")]
json.dump(m, open(sys.argv[2], "w"))
PY
cp "$T/atrbvh"/sort-*.npy "$T/atrbvh"/collapse-*.npy "$T/sub/"
run 0 check "$T/sub"
# two dump folders
run 0 check "$T/atrbvh" --against "$T/atrbvh"
# options given to check replace the manifest's: a different tree
run 1 check "$T/atrbvh" --method lbvh

# one triangle: empty left/right arrays, shape (0,)
cat >"$T/one.ply" <<'PLY'
ply
format ascii 1.0
element vertex 3
property float x
property float y
property float z
element face 1
property list uchar int vertex_indices
end_header
0 0 0
1 0 0
0 1 0
3 0 1 2
PLY
run 0 stages "$T/one.ply" --dump "$T/one"
run 0 check "$T/one"
[ "$($EDIT "$T/one/hierarchy-left.npy" info)" = "<u4 0" ] || fail "one triangle: left is not empty"

# NumPy (when installed) reads every file, and numpy.save writes the same
# bytes back
if python3 -c 'import numpy' 2>/dev/null; then
    python3 - "$T/trbvh" <<'PY' || fail "numpy round trip"
import glob, json, os, sys, numpy as np
d = sys.argv[1]
m = json.load(open(os.path.join(d, "manifest.json")))
for st in m["stages"]:
    for f in st["files"]:
        path = os.path.join(d, f["file"])
        a = np.load(path)
        assert a.dtype.str == f["dtype"] and list(a.shape) == f["shape"], f
        raw = open(path, "rb").read()
        np.save(path, a)
        assert open(path, "rb").read() == raw, path
PY
else
    echo "stages.sh: no numpy, the NumPy round trip skipped" >&2
fi

# an invalid primitive: an error, or left out with --skip-invalid (the
# manifest says so, and check's reference build does the same)
run 1 stages "$SRCDIR/data/nan.obj" --dump "$T/nan"
[ -e "$T/nan/manifest.json" ] && fail "a manifest after a failed build"
run 0 stages "$SRCDIR/data/nan.obj" --skip-invalid --dump "$T/nan"
run 0 check "$T/nan"
[ "$($EDIT "$T/nan/bounds-prim_boxes.npy" info)" = "<f4 12" ] || fail "skip-invalid: not 2 boxes"

# ------------------------------------------- the same bytes everywhere
for th in 1 2 3; do
    run 0 stages "$SCENE" --threads "$th" --dump "$T/t$th"
done
cmp -s "$T/t1/manifest.json" "$T/atrbvh/manifest.json" || fail "manifest differs"
for f in "$T/t1"/*; do
    b=$(basename "$f")
    for th in 2 3; do
        cmp -s "$f" "$T/t$th/$b" || fail "$b differs between 1 and $th threads"
    done
done
if "$TOOL" --version | grep -q 'OpenCL yes'; then
    if "$TOOL" stages "$SCENE" --backend opencl --dump "$T/cl" >"$T/out" 2>"$T/err"; then
        for f in "$T/t1"/*; do
            b=$(basename "$f")
            cmp -s "$f" "$T/cl/$b" || fail "$b differs between the CPU and OpenCL"
        done
        run 0 check "$T/cl"
        run 0 check "$T/atrbvh" --backend opencl
    elif opencl_may_skip "$T/err"; then
        echo "stages.sh: no OpenCL device ($(cat "$T/err")), OpenCL part skipped" >&2
    else
        fail "stages --backend opencl: $(cat "$T/err")"
    fi
fi

# -------------------- a one-item change in any file: that stage and item
# stage order, to check that every earlier stage is reported the same
for f in "$T/atrbvh"/*.npy; do
    b=$(basename "$f" .npy)
    stage=${b%%-*}
    array=${b#*-}
    set -- $($EDIT "$f" info)
    count=$2
    idx=$((count / 2))
    rm -rf "$T/p"
    cp -r "$T/atrbvh" "$T/p"
    $EDIT "$T/p/$b.npy" flip "$idx" || { fail "cannot edit $b"; continue; }
    run 1 check "$T/p" --json || continue
    python3 - "$T/out" "$stage" "$array" "$idx" <<'PY' || fail "$b item $idx: $(head -c 2000 "$T/out")"
import json, sys
r = json.load(open(sys.argv[1]))
stage, array, idx = sys.argv[2], sys.argv[3], int(sys.argv[4])
assert r["result"] == "different", r["result"]
assert r["first_different_stage"] == stage, r["first_different_stage"]
seen = False
for s in r["stages"]:
    if s["stage"] == stage:
        seen = True
        assert s["result"] == "different"
        assert s["differing_items"] == 1, s["differing_items"]
        assert s["first"]["array"] == array, s["first"]
        assert s["first"]["index"] == idx, s["first"]
        assert s["first"]["value"] != s["first"]["reference"] or \
            s["first"]["dtype"].startswith("<f"), s["first"]
        if s["first"]["dtype"].startswith("<f"):
            assert s["first"]["ulps"] == 1, s["first"]
    elif not seen:
        assert s["result"] == "same", s
    else:
        assert s["result"] == "not compared", s
assert seen
PY
done
# the text report names the stage and the item
rm -rf "$T/p"
cp -r "$T/atrbvh" "$T/p"
$EDIT "$T/p/sort-order.npy" flip 17
run 1 check "$T/p"
grep -q '^sort .*DIFFERENT: 1 of' "$T/out" || fail "text report: $(cat "$T/out")"
grep -q 'first: order\[17\] in sort-order.npy' "$T/out" || fail "text report item: $(cat "$T/out")"
grep -q '^hierarchy' "$T/out" && fail "text report goes on past the first different stage"
run 1 check "$T/p" --against "$T/atrbvh"
# a float one ulp off: different, and the same within one ulp
rm -rf "$T/p"
cp -r "$T/atrbvh" "$T/p"
$EDIT "$T/p/refit-box.npy" flip 100
run 1 check "$T/p"
grep -q '(1 ulps)' "$T/out" || fail "ulps not reported: $(cat "$T/out")"
run 0 check "$T/p" --tolerance-ulps 1

# --------------------------------------------------- trouble: exit 2
for op in magic truncate dtype shape; do
    rm -rf "$T/p"
    cp -r "$T/atrbvh" "$T/p"
    $EDIT "$T/p/hierarchy-left.npy" $op
    run 2 check "$T/p"
done
# a shape of 2^40 rows in the header and the manifest, over the file's own
# few bytes: truncated, found as the data comes (before, the reader
# allocated the claimed 4 TiB first: "out of memory", or under ASan an
# abort)
rm -rf "$T/p"
cp -r "$T/atrbvh" "$T/p"
$EDIT "$T/p/hierarchy-left.npy" huge
python3 - "$T/p/manifest.json" <<'PY'
import json, sys
m = json.load(open(sys.argv[1]))
for s in m["stages"]:
    for f in s["files"]:
        if f["file"] == "hierarchy-left.npy":
            f["shape"][0] = 1 << 40
json.dump(m, open(sys.argv[1], "w"))
PY
run 2 check "$T/p"
grep -q 'hierarchy-left.npy: truncated data' "$T/err" ||
    fail "a shape of 2^40 rows: $(cat "$T/err")"
rm -rf "$T/p"
cp -r "$T/atrbvh" "$T/p"
rm "$T/p/morton-keys.npy"
run 2 check "$T/p"
# manifests
mani() { # NAME PYTHON-EXPRESSION-ON-m : a broken manifest in $T/m
    rm -rf "$T/m"
    cp -r "$T/atrbvh" "$T/m"
    python3 - "$T/m/manifest.json" "$2" <<'PY'
import json, sys
m = json.load(open(sys.argv[1]))
exec(sys.argv[2])
json.dump(m, open(sys.argv[1], "w"))
PY
}
mani version 'del m["version"]'
run 2 check "$T/m" && grep -q "version" "$T/err" || fail "missing version: $(cat "$T/err")"
mani stages 'del m["stages"]'
run 2 check "$T/m"
mani dtype 'del m["stages"][0]["files"][0]["dtype"]'
run 2 check "$T/m"
mani wrongdtype 'm["stages"][2]["files"][1]["dtype"] = "<f4"'
run 2 check "$T/m"
mani shape 'm["stages"][0]["files"][0]["shape"] = [5, 6]'
run 2 check "$T/m"
mani method 'del m["options"]["method"]'
run 2 check "$T/m"
mani scene 'del m["scene"]'
run 2 check "$T/m"
run 0 check "$T/m" --against "$SCENE"
mani stagename 'm["stages"][0]["name"] = "nonsense"'
run 2 check "$T/m"
mani path 'm["stages"][0]["files"][0]["file"] = "../x.npy"'
run 2 check "$T/m"
mani empty 'm["stages"] = []'
run 2 check "$T/m"
mani nothing 'pass'
printf '{"version": 1, "stages": [' >"$T/m/manifest.json"
run 2 check "$T/m"
printf 'not json' >"$T/m/manifest.json"
run 2 check "$T/m"
rm "$T/m/manifest.json"
run 2 check "$T/m"
run 2 check "$T/nowhere"
run 2 check
run 2 stages "$SCENE"
run 2 check "$T/atrbvh" --tolerance-ulps -1

# -------------------------------------------------------- output safety
D=$T/safe
mkdir "$D"
printf 'precious\n' >"$D/manifest.json"
chmod 444 "$D/manifest.json"
printf 'old dump\n' >"$D/sort-order.npy"
printf 'keep me\n' >"$D/notes.txt"
mkdir "$D/layout-prim_indices.npy" # the last file cannot be written
run 1 stages "$SCENE" --dump "$D"
[ "$(cat "$D/manifest.json")" = precious ] || fail "manifest.json touched on failure"
[ "$(cat "$D/sort-order.npy")" = "old dump" ] || fail "an earlier stage's file replaced by a failed run"
have=$(cd "$D" && ls -A | sort | tr '\n' ' ')
[ "$have" = "layout-prim_indices.npy manifest.json notes.txt sort-order.npy " ] || fail "left behind in $D: $have"
rmdir "$D/layout-prim_indices.npy"
run 0 stages "$SCENE" --dump "$D"
[ "$(cat "$D/notes.txt")" = "keep me" ] || fail "another file of DIR touched"
cmp -s "$D/manifest.json" "$T/atrbvh/manifest.json" || fail "manifest not replaced"
cmp -s "$D/sort-order.npy" "$T/atrbvh/sort-order.npy" || fail "sort-order.npy not replaced"
run 0 check "$D"

# Killed mid-way: past a file size limit, SIGXFSZ (not ignored) ends the
# run while it writes an array, with the earlier ones in temporary files;
# DIR keeps its earlier dump, with no temporary file left.  The limit,
# 50 KiB, lets bounds-prim_boxes.npy (38 KB) through and stops
# refit-box.npy (77 KB), several stages later; `ulimit -f` counts 512- or
# 1024-byte blocks, so a 600-byte write under a limit of 1 tells which.
kib=$(
    trap '' XFSZ
    ulimit -f 1 2>/dev/null || exit 0
    if printf '%0600d' 0 >"$T/probe" 2>/dev/null; then echo 50; else echo 100; fi
)
D=$T/killed
mkdir "$D"
cp "$T/atrbvh"/* "$D/"
printf 'keep me\n' >"$D/notes.txt"
want=$(cd "$D" && ls -A | sort | tr '\n' ' ')
checks=$((checks + 1))
(
    [ -n "$kib" ] && ulimit -f "$kib" 2>/dev/null || exit 77
    "$TOOL" stages builtin:city:1600 --method trbvh --dump "$D"
    exit $? # (not the last command: this subshell reports the signal)
) >"$T/out" 2>"$T/err"
rc=$?
if [ "$rc" -eq 77 ]; then
    echo "stages.sh: ulimit -f not available: a dump killed mid-way skipped"
else
    [ "$rc" -gt 128 ] || fail "stages past a file size limit exited $rc"
    have=$(cd "$D" && ls -A | sort | tr '\n' ' ')
    [ "$have" = "$want" ] || fail "a killed dump left $D holding: $have"
    for f in "$T/atrbvh"/*; do
        cmp -s "$f" "$D/${f##*/}" || fail "a killed dump changed ${f##*/}"
    done
    [ "$(cat "$D/notes.txt")" = "keep me" ] || fail "a killed dump touched notes.txt"
    run 0 check "$D"
fi
# a missing DIR is created (its parent must exist)
run 0 stages "$SCENE" --method lbvh --dump "$T/new"
run 1 stages "$SCENE" --dump "$T/no/such/dir"
run 1 stages "$SCENE" --dump "$D/notes.txt"

# ------------------------------------------------------------------ help
run 0 help stages
grep -q -- '--dump' "$T/out" || fail "help stages lacks --dump"
run 0 help check
grep -q -- '--tolerance-ulps' "$T/out" || fail "help check lacks --tolerance-ulps"

finish
