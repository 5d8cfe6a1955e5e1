#!/bin/sh
# animate.sh - `atrbvh animate`: the animated built-in scenes, the
# policies, --json, --plot, usage errors.  Run by `make check` with
# ATRBVH_BUILDDIR and ATRBVH_SRCDIR set.

# shellcheck source-path=SCRIPTDIR source=common.sh
. "$(dirname "$0")/common.sh"
setup animate python3

# py SCRIPT: python3 over $T/out's JSON as `d`; a failing assert fails.
py() {
    checks=$((checks + 1))
    python3 - "$T/out" "$1" <<'PYEOF' || fail "$1"
import json, sys
d = json.load(open(sys.argv[1]))
exec(sys.argv[2])
PYEOF
}

run 0 animate --help && grep -q 'builtin:wave, builtin:shatter, builtin:traffic' "$T/out" ||
    fail "animate --help does not name the animated scenes"
run 0 help animate

# Every scene, every policy: JSON with one entry per (policy, frame); frame 0
# is the same build for all; a rebuild's SAH relative to itself is 1.
for s in wave shatter traffic; do
    run 0 animate builtin:$s:3000 --frames 6 --threads 2 --json || continue
    py '
f = d["frames"]
pol = ["refit", "reoptimise:1", "rebuild", "auto"]
assert len(f) == 24, len(f)
assert [e["policy"] for e in f] == [p for p in pol for _ in range(6)]
assert [e["frame"] for e in f] == list(range(6)) * 4
s0 = [e["sah"] for e in f if e["frame"] == 0]
assert len(set(s0)) == 1, s0
for e in f:
    assert e["sah"] > 0 and e["ms"] >= 0, e
    if e["policy"] == "rebuild":
        assert e["sah_vs_rebuild"] == 1, e
assert [e["action"] for e in f if e["policy"] == "refit"] == ["build"] + ["refit"] * 5
assert [e["action"] for e in f if e["policy"] == "reoptimise:1"] == ["build"] + ["reoptimise"] * 5
assert [x["policy"] for x in d["summary"]] == pol
assert d["summary"][2]["rebuilds"] == 5
'
    cp "$T/out" "$T/$s.json"
    # Deterministic: the same SAH at every frame, whatever the thread count.
    run 0 animate builtin:$s:3000 --frames 6 --threads 1 --json &&
        python3 - "$T/$s.json" "$T/out" <<'PYEOF' || fail "$s: SAH differs between 2 and 1 threads"
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:3])
assert [e["sah"] for e in a["frames"]] == [e["sah"] for e in b["frames"]]
PYEOF
done

# The scene moves: refit's SAH changes, and on shatter it degrades against
# a rebuild while re-optimising stays near it.
run 0 animate builtin:shatter:3000 --frames 30 --policy refit,reoptimise:1,rebuild --json &&
    py '
r = [e for e in d["frames"] if e["policy"] == "refit"]
o = [e for e in d["frames"] if e["policy"] == "reoptimise:1"]
assert r[-1]["sah_vs_rebuild"] > 1.5, r[-1]
assert max(e["sah_vs_rebuild"] for e in o) < 1.2, o
'

# auto: with an unreachable threshold it is refit; with a tiny one it
# rebuilds whenever the tree drifted.
run 0 animate builtin:wave:2000 --frames 5 --policy refit,auto --drift 1000 --json &&
    py '
r = [e["sah"] for e in d["frames"] if e["policy"] == "refit"]
a = [e["sah"] for e in d["frames"] if e["policy"] == "auto"]
assert r == a, (r, a)
assert d["summary"][1]["rebuilds"] == 0
'
run 0 animate builtin:wave:2000 --frames 5 --policy auto --drift 1.0000001 --json &&
    py 'assert d["summary"][0]["rebuilds"] >= 2, d["summary"]'

# --alloc: the bytes the library allocates in each update.  On the open
# device, from the third frame on (the first refit and re-optimisation
# take their scratch), a refit allocates nothing, a re-optimisation no
# array (a call state of a few hundred bytes; an array of the 2000
# triangles is 8 KB or more), and a rebuild into the last tree less
# than the index array alone (its arrays are reused).  A library built
# with --enable-debug-checks also allocates, after every build, the tree
# check's scratch (lib/check.c: 12 bytes a node, at most 2n - 1 nodes,
# and 4 a primitive).  Without --alloc no frame says.
grep -q "define ATRBVH_DEBUG_CHECKS 1" "$BUILDDIR/config.h" 2>/dev/null &&
    debug_checks=1 || debug_checks=0
run 0 animate builtin:wave:2000 --frames 5 --policy refit,reoptimise:1,rebuild --alloc --json &&
    py "debug_checks = $debug_checks"'
n = d["triangles"]
f = lambda p: [e["alloc_bytes"] for e in d["frames"] if e["policy"] == p]
r, o, b = f("refit"), f("reoptimise:1"), f("rebuild")
check = (12 * (2 * n - 1) + 4 * n) if debug_checks else 0
assert b[0] > 4 * n + check, (b, check)
assert r[2:] == [0] * 3, r
assert max(o[2:]) < 1024, o
assert max(b[2:]) < 4 * n + check, (b, check)
assert [s["max_alloc_bytes"] for s in d["summary"]] == [max(r[1:]), max(o[1:]), max(b[1:])], d["summary"]
'
run 0 animate builtin:wave:2000 --frames 2 --policy refit --json &&
    py 'assert all("alloc_bytes" not in e for e in d["frames"]), d["frames"]'
run 0 animate builtin:wave:2000 --frames 3 --policy refit,rebuild --alloc &&
    grep -q 'max bytes' "$T/out" ||
    fail "animate --alloc: no bytes in the text output: $(cat "$T/out")"

# Text output: a row per frame and the summary.
run 0 animate builtin:traffic:2000 --frames 3 --policy refit,rebuild &&
    grep -q '^    2 ' "$T/out" && grep -q '^rebuild ' "$T/out" ||
    fail "text output lacks frame 2 or the summary: $(cat "$T/out")"

# --plot: data, script and (with gnuplot) the pictures.
mkdir "$T/plot"
if run 0 animate builtin:wave:1000 --frames 4 --plot "$T/plot"; then
    for f in animate.dat animate.gp; do
        [ -s "$T/plot/$f" ] || fail "--plot wrote no $f"
    done
    if command -v gnuplot >/dev/null 2>&1; then
        for f in sah.png sah.svg ms.png ms.svg; do
            [ -s "$T/plot/$f" ] || fail "--plot wrote no $f"
        done
    fi
    ls -A "$T/plot" | grep -q '^\.atrbvh-gnuplot-' && fail "--plot left gnuplot's folder"
fi
run 1 animate builtin:wave:1000 --frames 2 --plot "$T/missing"

# Usage errors (2) and bad scenes (1).
run 2 animate
run 2 animate builtin:wave --frames 0
run 2 animate builtin:wave --policy bogus
run 2 animate builtin:wave --policy refit,
run 2 animate builtin:wave --policy reoptimise:0
run 2 animate builtin:wave --drift 0.5
run 1 animate builtin:sphere:100 --frames 2
run 1 animate builtin:wave:abc --frames 2
run 1 animate scene.ply --frames 2

finish
