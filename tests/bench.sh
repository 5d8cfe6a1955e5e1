#!/bin/sh
# bench.sh - `atrbvh bench` (CSV well formed, every column there, each
# row's SAH equal to a direct `atrbvh build --json` with the same options,
# the scaling study's CSV) and `atrbvh render` (a PNG of the requested
# size: IHDR bytes, and libpng reads it back).  Tiny scenes, --repeat 1.
# Run by `make check` with ATRBVH_BUILDDIR set.

# shellcheck source-path=SCRIPTDIR source=common.sh
. "$(dirname "$0")/common.sh"
PNGCHECK=$BUILDDIR/tests/pngcheck
setup bench python3

SCENE=builtin:sphere:3000
TINY="--repeat 1 --width 24 --height 16 --viewpoints 2 --spp 1"

# ---------------------------------------------------------------- bench
run 0 bench "$SCENE" builtin:city:2000 $TINY --csv "$T/b.csv" \
    --configs lbvh,trbvh:5:2,atrbvh:9:2,atrbvh:6:3,fast,balanced,high,embree &&
    grep -q '^# atrbvh bench' "$T/out" || fail "bench: no header line"
grep -Eq '^# Embree' "$T/out" || fail "bench: the header does not say whether Embree is there"

checks=$((checks + 1))
python3 - "$T/b.csv" "$TOOL" "$SCENE" builtin:city:2000 <<'PY' || fail "bench CSV check failed"
import csv, json, math, subprocess, sys
path, tool, scenes = sys.argv[1], sys.argv[2], sys.argv[3:]
need = ("scene method treelet_size rounds backend threads build_ms sah "
        "sah_binary nodes leaves peak_bytes primary_mrays ao_mrays "
        "diffuse_mrays relative_pct box_tests_per_ray tri_tests_per_ray "
        "ray_cost_pct").split()
with open(path, newline="") as f:
    rows = list(csv.reader(f))
head, body = rows[0], rows[1:]
for c in need:
    assert c in head, "missing column " + c
assert len(set(head)) == len(head), "duplicate columns"
for r in body:
    assert len(r) == len(head), "row with %d fields, header %d" % (len(r), len(head))
recs = [dict(zip(head, r)) for r in body]
# 2 scenes x (lbvh, trbvh 5 2, atrbvh 9 2, atrbvh 6 3, high, trbvh 7 3 [ref]
# [+ 3 embree]); fast and balanced repeat lbvh and atrbvh 9 2.
lib = [r for r in recs if not r["method"].startswith("embree")]
emb = [r for r in recs if r["method"].startswith("embree")]
assert len(lib) == 12, "expected 12 library rows, got %d" % len(lib)
assert len(emb) in (0, 6), "expected 0 or 6 Embree rows, got %d" % len(emb)
for r in recs:
    assert r["scene"] in scenes, r["scene"]
    for c in ("build_ms", "sah", "sah_binary", "primary_mrays", "relative_pct"):
        v = float(r[c])
        assert math.isfinite(v) and v > 0, (c, r[c])
    for c in ("nodes", "leaves", "peak_bytes", "threads"):
        assert int(r[c]) > 0, (c, r[c])
    assert int(r["nodes"]) == 2 * int(r["leaves"]) - 1, "nodes != 2 leaves - 1"
    # cpu_use: the share of the build's threads' time kept busy; a
    # library row has one (above 0; not far above 1 unless more threads
    # ran than the threads column says), Embree's none
    if r["method"].startswith("embree"):
        assert r["cpu_use"] == "", ("cpu_use", r["cpu_use"])
    else:
        assert 0 < float(r["cpu_use"]) <= 1.5, ("cpu_use", r["cpu_use"])
for s in scenes:
    ref = [r for r in lib if r["scene"] == s and r["method"] == "trbvh"
           and r["treelet_size"] == "7" and r["rounds"] == "3"]
    assert len(ref) == 1 and float(ref[0]["relative_pct"]) == 100.0, "reference row"
for r in lib:
    cmd = [tool, "build", r["scene"], "--json", "--method", r["method"],
           "--max-leaf", "8"]
    if r["method"] != "lbvh":
        cmd += ["--treelet", r["treelet_size"], "--rounds", r["rounds"]]
    js = json.loads(subprocess.check_output(cmd))
    assert repr(js["sah"]) == repr(float(r["sah"])), \
        "SAH %s in the CSV, %r from %s" % (r["sah"], js["sah"], " ".join(cmd))
    assert str(js["nodes"]) == r["nodes"], "nodes differ"
    bcmd = cmd[:cmd.index("--max-leaf")] + cmd[cmd.index("--max-leaf") + 2:] + ["--no-collapse"]
    jb = json.loads(subprocess.check_output(bcmd))
    assert repr(jb["sah"]) == repr(float(r["sah_binary"])), \
        "binary SAH %s in the CSV, %r from %s" % (r["sah_binary"], jb["sah"], " ".join(bcmd))
for r in emb:
    assert int(r["treelet_size"]) == 0 and r["backend"] == "embree"
    assert float(r["embree_primary_mrays"]) > 0
PY

# Exact ray cost: the CSV's per-ray counts are those `atrbvh trace --json`
# reports for the same tree and rays (viewpoint 0, same size and spp), and
# ray_cost_pct is 100 for the reference TRBVH(7,3).
checks=$((checks + 1))
run 0 bench builtin:sphere:3000 --configs lbvh --repeat 1 --width 24 \
    --height 16 --viewpoints 1 --spp 1 --csv "$T/cost.csv" &&
    run 0 trace builtin:sphere:3000 --method lbvh --max-leaf 8 --width 24 \
    --height 16 --spp 1 --json &&
    python3 - "$T/cost.csv" "$T/out" <<'PY' || fail "bench ray cost check failed"
import csv, json, sys
rows = list(csv.DictReader(open(sys.argv[1], newline="")))
js = json.load(open(sys.argv[2]))
lb = [r for r in rows if r["method"] == "lbvh"][0]
ref = [r for r in rows if r["method"] == "trbvh"][0]
assert float(ref["ray_cost_pct"]) == 100.0, ref["ray_cost_pct"]
for kind, col in (("primary", "primary_"), ("ao", "ao_"),
                  ("diffuse", "diffuse_"), ("all", "")):
    for what in ("box", "tri"):
        a = float(lb[col + what + "_tests_per_ray"])
        b = js["rays"][kind][what + "_tests_per_ray"]
        assert a > 0 and repr(a) == repr(b), (kind, what, a, b)
assert repr(float(lb["ray_cost"])) == repr(js["ray_cost"]), \
    (lb["ray_cost"], js["ray_cost"])
assert abs(float(lb["ray_cost_pct"]) -
           100 * float(lb["ray_cost"]) / float(ref["ray_cost"])) < 1e-9
PY

# The timed builds take turns (atrbvh(1) BENCH), seen in --builds: per
# scene every configuration's warm-up in the list's order, then round k
# builds each once, in that order, each timed build right after an
# untimed one of the same configuration, then the binary trees; seq counts
# 1, 2, ...; each configuration's build_ms in --csv is the median of its
# timed rows (repeat 3: the middle one).
checks=$((checks + 1))
run 0 bench "$SCENE" builtin:city:2000 --repeat 3 --no-rays \
    --configs lbvh,atrbvh:9:2,embree_low,atrbvh:5:1 --csv "$T/t.csv" \
    --builds "$T/builds.csv" &&
    python3 - "$T/t.csv" "$T/builds.csv" <<'PY' || fail "bench --builds: turn order"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1], newline="")))
log = list(csv.DictReader(open(sys.argv[2], newline="")))
assert [int(b["seq"]) for b in log] == list(range(1, len(log) + 1)), "seq"
def label(r):
    m = r["method"]
    if m.startswith("embree"):
        return m
    cl = "/cl" if r["backend"] == "opencl" else ""
    if m == "lbvh":
        return "LBVH" + cl
    return "%s(%s,%s)%s" % (m.upper(), r["treelet_size"], r["rounds"], cl)
scenes = []
for r in rows:
    if r["scene"] not in scenes:
        scenes.append(r["scene"])
at = 0
for s in scenes:
    cfgs = [label(r) for r in rows if r["scene"] == s]
    assert len(cfgs) >= 4 and cfgs[:2] == ["LBVH", "ATRBVH(9,2)"], cfgs
    want = [(c, "warmup", "") for c in cfgs]
    for k in range(3):
        for c in cfgs:
            want += [(c, "untimed", ""), (c, "timed", str(k))]
    want += [(c, "binary", "") for c in cfgs]
    got = [(b["configuration"], b["kind"], b["turn"])
           for b in log[at:at + len(want)]]
    assert got == want, (s, got, want)
    assert all(b["scene"] == s for b in log[at:at + len(want)]), s
    for r in rows:
        if r["scene"] != s:
            continue
        t = sorted(float(b["build_ms"]) for b in log[at:at + len(want)]
                   if b["configuration"] == label(r) and b["kind"] == "timed")
        assert len(t) == 3 and repr(t[1]) == repr(float(r["build_ms"])), \
            (s, label(r), t, r["build_ms"])
        assert repr(t[0]) == repr(float(r["build_min_ms"])), (t, r["build_min_ms"])
    at += len(want)
assert at == len(log), "%d rows past the scenes" % (len(log) - at)
PY
# --builds and --csv on the same file: a usage error, nothing written
run 2 bench "$SCENE" --repeat 1 --no-rays --configs lbvh --csv "$T/same.csv" \
    --builds "$T/same.csv" && { [ ! -e "$T/same.csv" ] || fail "--builds = --csv wrote $T/same.csv"; }
checks=$((checks + 1))

# The header records POCL_AFFINITY, and warns of OMP_PROC_BIND when the
# bench has Embree rows (the bound main thread's mask is Embree's too);
# neither line without its variable.
hdr() { grep -c "^# $1" "$T/out"; }
if env -u POCL_AFFINITY -u OMP_PROC_BIND "$TOOL" bench builtin:sphere:500 --repeat 1 --no-rays \
    --configs lbvh >"$T/out" 2>"$T/err"; then
    [ "$(hdr POCL_AFFINITY=)" -eq 0 ] || fail "bench header names POCL_AFFINITY, which is unset"
    [ "$(hdr OMP_PROC_BIND=)" -eq 0 ] || fail "bench header warns of OMP_PROC_BIND, which is unset"
else
    fail "bench without POCL_AFFINITY failed: $(cat "$T/err")"
fi
if POCL_AFFINITY=1 OMP_PROC_BIND=spread "$TOOL" bench builtin:sphere:500 --repeat 1 \
    --no-rays --threads 1 --configs lbvh >"$T/out" 2>"$T/err"; then
    [ "$(hdr 'POCL_AFFINITY=1$')" -eq 1 ] || fail "bench header does not record POCL_AFFINITY=1"
    if grep -q '^# Embree [0-9]' "$T/out"; then
        [ "$(hdr 'OMP_PROC_BIND=spread: ')" -eq 1 ] || fail "bench header does not warn of OMP_PROC_BIND"
    fi
else
    fail "bench with POCL_AFFINITY=1 failed: $(cat "$T/err")"
fi
checks=$((checks + 1))

# Rebuilding (the default) and --fresh: the header says which, and the
# rows' trees are the same (SAH, nodes, leaves, peak: the first build's)
run 0 bench "$SCENE" --repeat 3 --no-rays --configs lbvh,atrbvh:9:2 \
    --csv "$T/re.csv" && { [ "$(hdr 'atrbvh: each build into the last')" -eq 1 ] ||
    fail "bench header does not say it rebuilds"; }
run 0 bench "$SCENE" --repeat 3 --no-rays --configs lbvh,atrbvh:9:2 --fresh \
    --csv "$T/fr.csv" && { [ "$(hdr 'atrbvh: each build after the last tree is freed')" -eq 1 ] ||
    fail "bench --fresh header does not say so"; }
python3 - "$T/re.csv" "$T/fr.csv" <<'PY' || fail "bench: --fresh and rebuilding differ"
import csv, sys
keys = ("sah", "nodes", "leaves", "peak_bytes")
a, b = ([{k: r[k] for k in ("method", "treelet_size") + keys}
         for r in csv.DictReader(open(f)) if r["method"] in ("lbvh", "atrbvh")]
        for f in sys.argv[1:])
assert len(a) == 2 and a == b, (a, b)
PY
checks=$((checks + 1))

# --methods x --treelet x --rounds, no rays
run 0 bench "$SCENE" --repeat 1 --no-rays --methods atrbvh,lbvh --treelet 5,7 \
    --rounds 1,2 --csv "$T/m.csv" &&
    { [ "$(wc -l <"$T/m.csv")" -eq 7 ] || fail "--methods: $(wc -l <"$T/m.csv") lines, expected 1 + 4 + lbvh + trbvh ref"; }
checks=$((checks + 1))

# the adaptive treelet size: atrbvh:auto:R, the CSV saying auto, and the
# same SAH as atrbvh build --treelet auto (scene of 3000: sizes 9 and 16)
run 0 bench "$SCENE" --repeat 1 --no-rays --configs atrbvh:auto:2,atrbvh:48:1 \
    --csv "$T/a.csv" && python3 - "$T/a.csv" <<'PY' || fail "atrbvh:auto:2: $(cat "$T/a.csv")"
import csv, sys
rows = [r for r in csv.DictReader(open(sys.argv[1])) if r["method"] == "atrbvh"]
assert sorted((r["treelet_size"], r["rounds"]) for r in rows) == \
    [("48", "1"), ("auto", "2")], rows
PY
checks=$((checks + 1))
# triangle splitting: +split=B builds what `build --split B` builds and
# +split=B/tree what `--split-rule tree` adds (same SAH, same references,
# more than the triangles on this sphere, the rule named in the CSV);
# rows without it list each triangle once; Embree's spatial splits stay
# within their 20% room.
run 0 build "$SCENE" --treelet 9 --rounds 2 --max-leaf 8 --split 0.5 \
    --split-rule tree --json && cp "$T/out" "$T/tree.json" &&
    run 0 bench "$SCENE" --repeat 1 --no-rays --csv "$T/sp.csv" \
    --configs atrbvh:9:2,atrbvh:9:2+split=0.5,atrbvh:9:2+split=0.5/tree,embree_split &&
    run 0 build "$SCENE" --treelet 9 --rounds 2 --max-leaf 8 --split 0.5 \
    --json && python3 - "$T/sp.csv" "$T/out" "$T/tree.json" <<'PY' || fail "bench +split=0.5: $(cat "$T/sp.csv")"
import csv, json, sys
rows = list(csv.DictReader(open(sys.argv[1])))
js = {"sah": json.load(open(sys.argv[2])), "tree": json.load(open(sys.argv[3]))}
sp = [r for r in rows if r["method"] == "atrbvh" and r["split_budget"] == "0.5"]
assert sorted(r["split_rule"] for r in sp) == ["sah", "tree"], rows
n = int(sp[0]["triangles"])
for r in sp:
    j = js[r["split_rule"]]
    assert j["split_rule"] == r["split_rule"], j["split_rule"]
    assert repr(float(r["sah"])) == repr(j["sah"]), (r["sah"], j["sah"])
    assert int(r["references"]) == j["references"], j["references"]
    assert n < int(r["references"]) <= n + n // 2, r["references"]
for r in rows:
    if r["method"] == "embree_split":
        assert float(r["split_budget"]) == 0.2 and r["split_rule"] == "sbvh"
        assert n <= int(r["references"]) <= n + n // 5, r["references"]
    elif r not in sp:
        assert float(r["split_budget"]) == 0 and int(r["references"]) == n, r
        assert r["split_rule"] == "", r
PY
checks=$((checks + 1))
run 2 bench "$SCENE" --repeat 1 --no-rays --configs atrbvh:9:2+split=0.1/bogus &&
    { grep -q "split rule 'bogus'" "$T/err" || fail "+split=0.1/bogus: $(cat "$T/err")"; }
run 2 bench "$SCENE" --repeat 1 --no-rays --configs atrbvh:9:2+split=0
run 2 bench "$SCENE" --repeat 1 --no-rays --configs lbvh+split=4.5
run 2 bench "$SCENE" --repeat 1 --no-rays --configs embree_high+split=0.2
run 2 bench "$SCENE" --repeat 1 --no-rays --configs trbvh:auto:2 &&
    { grep -q "treelet size 'auto'" "$T/err" || fail "trbvh:auto: $(cat "$T/err")"; }
checks=$((checks + 1))

# plots, when gnuplot is there
if command -v gnuplot >/dev/null 2>&1; then
    run 0 bench "$SCENE" --repeat 1 --width 8 --height 8 --viewpoints 1 \
        --configs lbvh,atrbvh:5:1 --plot "$T/plots" &&
        for p in pareto-builtin_sphere_3000.png pareto-builtin_sphere_3000.svg rays-builtin_sphere_3000.png; do
            [ -s "$T/plots/$p" ] || fail "--plot: no $p ($(ls "$T/plots"))"
        done
    checks=$((checks + 1))
fi

# scaling study: each size's median of --repeat timed builds (builds of
# milliseconds: never the one-build rule of the slow sizes), which the
# --builds log lists after every size's warm-up, in turns across the
# sizes (turn k of every size before turn k+1 of any), each right after
# an untimed build of its size
run 0 bench --scaling builtin:sphere --sizes 1000,3000,9000 --configs lbvh \
    --repeat 2 --csv "$T/s.csv" --builds "$T/sb.csv" && grep -q 'N^' "$T/out" ||
    fail "scaling: no fitted exponent: $(cat "$T/out")"
checks=$((checks + 1))
python3 - "$T/s.csv" "$T/sb.csv" <<'PY' || fail "scaling CSV check failed"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1], newline="")))
log = list(csv.DictReader(open(sys.argv[2], newline="")))
assert len(rows) == 3, len(rows)
for r in rows:
    assert int(r["peak_bytes"]) > 0 and float(r["build_ms"]) > 0
    assert float(r["peak_bytes_per_triangle"]) > 0
    assert r["repeat"] == "2", r["repeat"]
    mine = [(b["kind"], b["turn"]) for b in log if b["triangles"] == r["triangles"]]
    assert mine == [("warmup", ""), ("untimed", ""), ("timed", "0"),
                    ("untimed", ""), ("timed", "1")], mine
    t = sorted(float(b["build_ms"]) for b in log
               if b["triangles"] == r["triangles"] and b["kind"] == "timed")
    assert abs((t[0] + t[1]) / 2 - float(r["build_ms"])) <= 1e-9 * t[1], (t, r["build_ms"])
seq = [(int(b["seq"]), b["kind"], b["turn"], b["triangles"]) for b in log]
assert [s for s, _, _, _ in seq] == sorted(s for s, _, _, _ in seq), seq
last_warmup = max(s for s, k, _, _ in seq if k == "warmup")
timed = [(s, int(t), n) for s, k, t, n in seq if k == "timed"]
assert all(s > last_warmup for s, _, _ in timed), seq
assert [t for _, t, _ in timed] == sorted(t for _, t, _ in timed), timed
assert [n for _, t, n in timed if t == 0] == [r["triangles"] for r in rows], timed
PY

# the scaling table has a header naming its columns
grep -Eq '^base scene +config +triangles +copies +build ms +peak B/tri +peak/tree' "$T/out" ||
    fail "scaling: no table header: $(head -c 600 "$T/out")"

# OpenCL asked for without any OpenCL platform (an empty ICD folder): the
# run fails, rather than report the CPU rows alone.
checks=$((checks + 1))
OCL_ICD_VENDORS="$T/no-icds" "$TOOL" bench "$SCENE" --repeat 1 --no-rays \
    --configs lbvh --backend opencl >"$T/out" 2>"$T/err"
rc=$?
[ $rc = 1 ] || fail "bench --backend opencl without OpenCL exited $rc, expected 1"
grep -q '^atrbvh: .*OpenCL' "$T/err" || fail "bench --backend opencl without OpenCL: $(cat "$T/err")"

# A run that fails leaves an existing CSV as it was (written beside it
# and renamed only when complete), and leaves no temporary file.
mkdir "$T/keep" && echo 'keep me' >"$T/keep/k.csv"
run 1 bench /nonexistent/scene.ply --repeat 1 --no-rays --csv "$T/keep/k.csv"
[ "$(cat "$T/keep/k.csv")" = 'keep me' ] || fail "a failed bench changed the CSV: $(head -c 200 "$T/keep/k.csv")"
[ "$(ls "$T/keep")" = k.csv ] || fail "a failed bench left files: $(ls "$T/keep")"
# An unwritable CSV is reported before any measurement.
run 1 bench "$SCENE" --repeat 1 --no-rays --csv "$T/no/such/dir/x.csv" &&
    { grep -q '^#' "$T/out" && fail "bench measured before finding the CSV unwritable"; }

# usage and errors: out-of-range values name the option
for bad in "--threads -1" "--threads 100000" "--threads 2147483647" \
    "--repeat -1" "--ci 0" "--max-leaf 5000" "--spp -2"; do
    run 2 bench $bad &&
        { grep -q "^atrbvh: bench: ${bad%% *}: " "$T/err" || fail "bench $bad: $(cat "$T/err")"; }
done
run 2 bench --repeat 0
run 2 bench --repeat 1x
run 2 bench --configs lbvh,quick
run 2 bench --configs atrbvh:0
run 2 bench --width -3
run 2 bench --bogus
run 2 bench --treelet 9
run 2 bench --quality best
run 2 bench --scaling --configs embree_low
run 1 bench /nonexistent/scene.ply --repeat 1 --no-rays
run 2 build builtin:sphere:100 --quality slow
run 0 build builtin:sphere:1000 --quality high --json &&
    grep -q '"treelet_size": *"auto"' "$T/out" &&
    grep -q '"rounds": *4' "$T/out" || fail "--quality high: $(cat "$T/out")"

# --------------------------------------------------------------- render
if [ -x "$PNGCHECK" ]; then
    for mode in "" --heatmap; do
        run 0 render builtin:city:2000 $mode --width 37 --height 23 -o "$T/r.png" \
            --quality fast || continue
        checks=$((checks + 1))
        # IHDR: bytes 16-19 width, 20-23 height, big-endian
        sig=$(od -An -tx1 -N8 "$T/r.png" | tr -d ' \n')
        dims=$(od -An -tu1 -j16 -N8 "$T/r.png" |
               awk '{ print $1*16777216 + $2*65536 + $3*256 + $4, $5*16777216 + $6*65536 + $7*256 + $8 }')
        [ "$sig" = 89504e470d0a1a0a ] || fail "render $mode: not a PNG signature ($sig)"
        [ "$dims" = "37 23" ] || fail "render $mode: IHDR says $dims, expected 37 23"
        got=$("$PNGCHECK" "$T/r.png") || fail "render $mode: libpng cannot read it"
        [ "$got" = "37 23" ] || fail "render $mode: libpng reads $got"
    done
    run 2 render builtin:city:2000 --width 10
    run 2 render builtin:city:2000 -o "$T/x.png" --width 0
    run 1 render /nonexistent.ply -o "$T/x.png"
    run 1 render builtin:city:2000 -o "$T/no/such/dir/x.png"
else
    run 1 render builtin:city:2000 -o "$T/r.png" && err_line=$(cat "$T/err") &&
        case "$err_line" in *libpng*) ;; *) fail "render without libpng: $err_line" ;; esac
fi

# ---------------------------------------------------------------- cameras
# A closed cube is a room (every face of its box covered): viewpoint 0 is
# inside it, so every primary ray hits; from --eye outside, looking at it,
# some rays miss.  The camera options' usage errors.
{
    echo "v 0 0 0"; echo "v 1 0 0"; echo "v 1 1 0"; echo "v 0 1 0"
    echo "v 0 0 1"; echo "v 1 0 1"; echo "v 1 1 1"; echo "v 0 1 1"
    for f in "1 2 3" "1 3 4" "5 7 6" "5 8 7" "1 5 6" "1 6 2" \
             "4 3 7" "4 7 8" "1 4 8" "1 8 5" "2 6 7" "2 7 3"; do
        echo "f $f"
    done
} >"$T/cube.obj"
checks=$((checks + 1))
run 0 trace "$T/cube.obj" --width 16 --height 12 --spp 0 --json &&
    python3 - "$T/out" <<'PY' || fail "trace in a room: the camera is not inside"
import json, sys
p = json.load(open(sys.argv[1]))["rays"]["primary"]
assert p["count"] == 192 and p["hits"] == 192, p
PY
checks=$((checks + 1))
run 0 trace "$T/cube.obj" --width 16 --height 12 --spp 0 --json \
    --eye 3,2,4 --look-at 0.5,0.5,0.5 --fov 60 &&
    python3 - "$T/out" <<'PY' || fail "trace --eye outside the cube"
import json, sys
p = json.load(open(sys.argv[1]))["rays"]["primary"]
assert 0 < p["hits"] < p["count"] == 192, p
PY
# bench with --eye traces that camera's rays: the same counts as trace
checks=$((checks + 1))
run 0 bench builtin:city:2000 --configs lbvh --repeat 1 --width 20 \
    --height 10 --spp 1 --eye 0,50,300 --look-at 10,0,0 --csv "$T/eye.csv" &&
    run 0 trace builtin:city:2000 --method lbvh --max-leaf 8 --width 20 \
    --height 10 --spp 1 --eye 0,50,300 --look-at 10,0,0 --json &&
    python3 - "$T/eye.csv" "$T/out" <<'PY' || fail "bench --eye and trace --eye differ"
import csv, json, sys
lb = [r for r in csv.DictReader(open(sys.argv[1], newline=""))
      if r["method"] == "lbvh"][0]
js = json.load(open(sys.argv[2]))
assert repr(float(lb["box_tests_per_ray"])) == \
    repr(js["rays"]["all"]["box_tests_per_ray"]), (lb, js["rays"])
assert js["rays"]["primary"]["count"] == 200
PY
run 2 trace builtin:city:2000 --look-at 1,2,3
run 2 trace builtin:city:2000 --eye 1,2
run 2 trace builtin:city:2000 --eye 1,2,x
# a stray comma is not skipped: each of these is no point
for e in 0,0,5, ,0,0,5 0,,0,5 1,,2,3 1,2,3,4; do
    run 2 trace builtin:city:2000 --eye "$e" && err_has -- "--eye: '$e' is not X,Y,Z"
done
run 2 trace builtin:city:2000 --look-at 1,,2,3 && err_has -- "--look-at: "
run 2 render builtin:city:2000 -o "$T/x.png" --eye 1,2,3 --look-at 1,2,3
run 2 bench builtin:city:2000 --fov 0

finish
