#!/bin/sh
# speed.sh - the build-speed section of docs/benchmarks.md end to end on a
# tiny scene: tools/embree-alone (the standalone rtcBuildBVH timing) prints
# one positive median per Embree quality, and docs/speed_tables.py turns a
# bench CSV, its --builds log, the scaling CSV and that output into the
# section, leaving the rest of the document as it was, with every ratio,
# per-turn range and ns/triangle cell recomputed here from the CSVs.
# Skipped without Embree or python3.
# Run by `make check` with ATRBVH_BUILDDIR and ATRBVH_SRCDIR set.

# shellcheck source-path=SCRIPTDIR source=common.sh
. "$(dirname "$0")/common.sh"
ALONE=$BUILDDIR/tools/embree-alone
setup speed python3
if [ ! -x "$ALONE" ]; then
    echo "speed.sh: built without Embree (no tools/embree-alone), skipped" >&2
    exit 77
fi

SCENE=builtin:sphere:4000
OUT=$T/out.d
mkdir -p "$OUT" || exit 99

# ------------------------------------------------------- embree-alone
checks=$((checks + 1))
if "$ALONE" "$SCENE" 2 3 >"$OUT/embree-alone.txt" 2>"$T/alone.err"; then
    grep -q "^# embree-alone $SCENE:" "$OUT/embree-alone.txt" ||
        fail "embree-alone: no '# embree-alone $SCENE:' header"
    for q in low medium high; do
        grep -Eq "^embree_$q [0-9]+\.[0-9]+ ms" "$OUT/embree-alone.txt" ||
            fail "embree-alone: no median for embree_$q"
        grep -Eq "^embree_$q 0\.0+ ms" "$OUT/embree-alone.txt" &&
            fail "embree-alone: embree_$q took no time"
    done
else
    fail "embree-alone $SCENE 2 3 failed: $(cat "$T/alone.err")"
fi
checks=$((checks + 1))
"$ALONE" builtin:nothing 2 3 >/dev/null 2>"$T/alone.err" &&
    fail "embree-alone accepted an unknown scene"

# ------------------------------------------------- the CSVs and the doc
run 0 bench "$SCENE" --no-rays --repeat 2 --threads 2 \
    --configs lbvh,atrbvh:9:2,atrbvh:16:3,trbvh:7:3,embree \
    --csv "$OUT/speed.csv" --builds "$OUT/speed-builds.csv"
run 0 bench --scaling builtin:sphere --configs lbvh --threads 2 \
    --repeat 1 --sizes 60000,120000 --csv "$OUT/speed-scaling.csv"
printf 'date: test\nload before: 0 0 0\n' >"$OUT/speed-machine.txt"
printf '# before\n<!-- BEGIN SPEED -->\nold text\n<!-- END SPEED -->\n# after\n' \
    >"$T/doc.md"

checks=$((checks + 1))
if python3 "$SRCDIR/docs/speed_tables.py" "$OUT" "$T/doc.md" 2>"$T/py.err"; then
    python3 - "$OUT" "$T/doc.md" "$SCENE" <<'PY' || fail "speed_tables.py: the section does not match its inputs"
import csv, math, os, re, sys
out, doc, S = sys.argv[1], sys.argv[2], sys.argv[3]
text = open(doc).read()
assert text.startswith("# before\n<!-- BEGIN SPEED -->\n"), "text before the section changed"
assert text.endswith("<!-- END SPEED -->\n# after\n"), "text after the section changed"
assert "old text" not in text, "the old section is still there"
rows = list(csv.DictReader(open(os.path.join(out, "speed.csv"))))
def ms(method, ts=None):
    for r in rows:
        if r["method"] == method and (ts is None or r["treelet_size"] == ts):
            return float(r["build_ms"]), r
    raise AssertionError("no %s row" % method)
lb, r = ms("lbvh")
lo, _ = ms("embree_low")
me, _ = ms("embree_medium")
at, _ = ms("atrbvh", "9")
tr, _ = ms("trbvh", "7")
line = [l for l in text.splitlines() if l.startswith("| %s | " % S)][0]
cells = [c.strip().strip("*") for c in line.strip("|").split("|")]
assert cells[1] == r["triangles"], cells
for got, want in ((cells[2], lb / lo), (cells[3], at / me), (cells[4], tr / me)):
    assert got == "%.2f" % want, (got, want)
# a missed goal is bold, a met one is not
assert ("**" in line.split("|")[3]) == (lb / lo > 0.8), line
# the cross-check row of each quality: bench / alone
alone = dict(re.findall(r"^(embree_\w+) ([0-9.]+) ms", open(os.path.join(out, "embree-alone.txt")).read(), re.M))
for q in ("low", "medium", "high"):
    b, _ = ms("embree_" + q)
    want = "| %s | %s | %.1f | %.1f | %.2f |" % (S, q, b, float(alone["embree_" + q]), b / float(alone["embree_" + q]))
    assert want in text, want
# ns per triangle of the LBVH: total and every stage from the CSV
n = float(r["triangles"])
stages = ["bounds", "morton", "sort", "hierarchy", "refit", "optimise", "collapse", "layout"]
want = "| %s | LBVH | %.0f | %s |" % (S, lb * 1e6 / n, " | ".join("%.0f" % (float(r[s + "_ms"]) * 1e6 / n) for s in stages))
assert want in text, want
# the per-turn ratios: turn k's timed builds, lowest to highest
turns = {}
for b in csv.DictReader(open(os.path.join(out, "speed-builds.csv"))):
    if b["kind"] == "timed":
        turns.setdefault(b["configuration"], {})[b["turn"]] = float(b["build_ms"])
def span(a, d):
    v = sorted(turns[a][k] / turns[d][k] for k in turns[a])
    assert len(v) == 2, v
    return "%.2f-%.2f" % (v[0], v[-1])
rows_t = [l for l in text.splitlines() if l.startswith("| %s | " % S) and "-" in l.split("|")[2]]
assert rows_t, "no per-turn row"
cells = [c.strip() for c in rows_t[0].strip("|").split("|")]
assert cells[1:4] == [span("LBVH", "embree_low"), span("ATRBVH(9,2)", "embree_medium"),
                      span("TRBVH(7,3)", "embree_medium")], (cells, turns)
# the growth exponent from the two scaling points
sc = [x for x in csv.DictReader(open(os.path.join(out, "speed-scaling.csv"))) if x["method"] == "lbvh"]
assert len(sc) == 2, sc
(n0, t0), (n1, t1) = [(float(x["triangles"]), float(x["build_ms"])) for x in sc]
k = math.log(t1 / t0) / math.log(n1 / n0)
m = re.search(r"LBVH time ~ N\^(-?[0-9.]+) from 10\^5 \(2 points", text)
assert m and abs(float(m.group(1)) - k) < 0.0015, (m and m.group(1), k)
PY
else
    fail "speed_tables.py failed: $(cat "$T/py.err")"
fi

# ---------------------------------- every recorded run (speed_runs.py)
# Two copies of this run under run names, dated out of name order, and a
# CSV without its machine file (not a run: left out).
RUNS=$T/runs
mkdir -p "$RUNS" || exit 99
for r in b a; do cp "$OUT/speed.csv" "$RUNS/$r-speed.csv" || exit 99; done
cp "$OUT/speed.csv" "$RUNS/lone-speed.csv" || exit 99
printf 'date: 2026-01-02 00:00 UTC\ncpu: Test CPU, 2 cores\nload before: 1 2 3\nPOCL_AFFINITY: 1\nsteal during the run: 2.5%% of the CPU time (5 of 200 ticks)\natrbvh builds: rebuild (each into the last tree, atrbvh_rebuild)\n' >"$RUNS/a-machine.txt"
printf 'date: 2026-01-01 00:00 UTC\ncpu: Test CPU, 2 cores\nload before: 0 0 0\n' >"$RUNS/b-machine.txt"
printf '# before\n<!-- BEGIN RUNS -->\nold text\n<!-- END RUNS -->\n# after\n' >"$T/runs.md"
checks=$((checks + 1))
if python3 "$SRCDIR/docs/speed_runs.py" "$RUNS" "$T/runs.md" 2>"$T/py.err"; then
    python3 - "$OUT" "$T/runs.md" <<'PY' || fail "speed_runs.py: the table does not match its runs"
import csv, os, sys
out, doc = sys.argv[1], sys.argv[2]
text = open(doc).read()
assert text.startswith("# before\n<!-- BEGIN RUNS -->\n"), "text before the table changed"
assert text.endswith("<!-- END RUNS -->\n# after\n"), "text after the table changed"
assert "old text" not in text, "the old table is still there"
rows = list(csv.DictReader(open(os.path.join(out, "speed.csv"))))
def ms(method, ts=None):
    return [float(r["build_ms"]) for r in rows
            if r["method"] == method and (ts is None or r["treelet_size"] == ts)][0]
want = [(ms("lbvh"), ms("embree_low"), 0.8), (ms("atrbvh", "9"), ms("embree_medium"), 0.8),
        (ms("trbvh", "7"), ms("embree_medium"), 1.5)]
cells = ["%d/1 (%.2f)" % (a / b <= g, a / b) for a, b, g in want] + ["-", "-"]
every = "yes" if all(a / b <= g for a, b, g in want) else "no"
lines = [l for l in text.splitlines() if l.startswith("| a |") or l.startswith("| b |")]
assert [l.split("|")[1].strip() for l in lines] == ["b", "a"], lines  # by date
assert "lone" not in text, "a CSV without its machine file was counted"
# (a run without the builds line freed its last tree first: "fresh")
for l, load, steal, pin, builds in zip(lines, ["0 0 0", "1 2 3"], ["-", "2.5%"],
                                       ["-", "1"], ["fresh", "rebuild"]):
    got = [c.strip() for c in l.strip("|").split("|")]
    assert got[2:] == ["Test CPU", load, steal, pin, builds] + cells + [every], (got, cells)
host = [l for l in text.splitlines() if l.startswith("* **Test CPU**")]
assert host and ("2 runs, %d with every cell met" % (2 if every == "yes" else 0)) in host[0], host
assert "LBVH / low %d of 2" % (2 * (want[0][0] / want[0][1] <= 0.8)) in host[0], host
assert "OpenCL LBVH / CPU 0 of 0" in host[0], host
PY
else
    fail "speed_runs.py failed: $(cat "$T/py.err")"
fi
finish
