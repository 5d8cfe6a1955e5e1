#!/usr/bin/env python3
"""speed_tables.py OUT DOC - the build-speed section of docs/benchmarks.md.

Reads what `sh docs/run_benchmarks.sh speed` wrote into OUT (speed.csv,
speed-scaling.csv, embree-alone.txt, speed-machine.txt, and
speed-builds.csv when there) and rewrites the
part of DOC between <!-- BEGIN SPEED --> and <!-- END SPEED -->: the
ratios of build times to Embree's per scene against the goals of issue 11,
the standalone Embree cross-check, the per-stage nanoseconds per triangle,
which configurations dominate Embree (faster and lower SAH), and the
scaling to 10^7 triangles with peak memory.  Every number is from the one
run; nothing is typed in by hand.
"""
import csv
import math
import os
import re
import sys

STAGES = ["bounds", "morton", "sort", "hierarchy", "refit", "optimise",
          "collapse", "layout"]


def load(path):
    with open(path, newline="") as fh:
        return list(csv.DictReader(fh))


def fnum(r, k):
    try:
        v = float(r.get(k, ""))
    except ValueError:
        return float("nan")
    return v


def label(r):
    m = r["method"]
    if m.startswith("embree"):
        return m
    suffix = "@opencl" if r.get("backend") == "opencl" else ""
    if m == "lbvh":
        return "LBVH" + suffix
    ts = r["treelet_size"]
    return "%s(%s,%s)%s" % (m.upper(), ts, r["rounds"], suffix)


def sname(path):
    return os.path.splitext(os.path.basename(path))[0]


def replace_section(doc, name, lines):
    """DOC's text between <!-- BEGIN name --> and <!-- END name --> becomes
    `lines`, written to a file beside DOC and renamed over it."""
    text = open(doc).read()
    a, b = "<!-- BEGIN %s -->" % name, "<!-- END %s -->" % name
    i, j = text.index(a), text.index(b)
    text = text[:i + len(a)] + "\n" + "\n".join(lines) + "\n" + text[j:]
    tmp = doc + ".tmp"
    with open(tmp, "w") as fh:
        fh.write(text)
    os.replace(tmp, doc)


def ratio_cell(num, den, goal):
    if not (num > 0 and den > 0):
        return "-"
    v = num / den
    ok = v <= goal
    return ("%.2f" % v) if ok else ("**%.2f**" % v)


def main():
    out, doc = sys.argv[1], sys.argv[2]
    rows = load(os.path.join(out, "speed.csv"))
    machine = open(os.path.join(out, "speed-machine.txt")).read().splitlines()
    alone = {}
    cur = None
    apath = os.path.join(out, "embree-alone.txt")
    if os.path.exists(apath):
        for line in open(apath):
            m = re.match(r"# embree-alone (\S+):", line)
            if m:
                cur = sname(m.group(1))
                continue
            m = re.match(r"(embree_\w+) ([0-9.]+) ms", line)
            if m and cur:
                alone[(cur, m.group(1))] = float(m.group(2))
    scenes = []
    by = {}
    for r in rows:
        s = sname(r["scene"])
        if s not in scenes:
            scenes.append(s)
        by[(s, label(r))] = r
    L = []
    L.append("### Machine and run")
    L.append("")
    for m in machine:
        k, _, v = m.partition(": ")
        L.append("* **%s**: %s" % (k, v))
    L.append("")
    L.append("### Ratios to Embree (build time, same run; goal in the header, "
             "**bold** where missed)")
    L.append("")
    L.append("| scene | triangles | LBVH / low (<= 0.8) | ATRBVH(9,2) / medium "
             "(<= 0.8) | TRBVH(7,3) / medium (<= 1.5) | ATRBVH(16,3) / medium "
             "| Embree low, medium ms |")
    L.append("|---|---:|---:|---:|---:|---:|---:|")
    for s in scenes:
        g = lambda lab: fnum(by.get((s, lab), {}), "build_ms")
        lo, me = g("embree_low"), g("embree_medium")
        tri = by.get((s, "LBVH"), {}).get("triangles", "")
        L.append("| %s | %s | %s | %s | %s | %s | %.1f, %.1f |" % (
            s, tri, ratio_cell(g("LBVH"), lo, 0.8),
            ratio_cell(g("ATRBVH(9,2)"), me, 0.8),
            ratio_cell(g("TRBVH(7,3)"), me, 1.5),
            ratio_cell(g("ATRBVH(16,3)"), me, 99), lo, me))
    L.append("")
    bpath = os.path.join(out, "speed-builds.csv")
    if os.path.exists(bpath):
        # Turn k's timed build of ours over turn k's of Embree's: the two
        # ran seconds apart, so the range over the turns is the ratio's
        # spread within this run (the table above takes medians).
        turn = {}
        for b in load(bpath):
            if b["kind"] != "timed":
                continue
            lab = b["configuration"]
            if lab.endswith("/cl"):
                lab = lab[:-3] + "@opencl"
            turn.setdefault((sname(b["scene"]), lab), {})[b["turn"]] = \
                float(b["build_ms"])

        def spread(s, num, den):
            a, d = turn.get((s, num), {}), turn.get((s, den), {})
            v = sorted(a[k] / d[k] for k in a if k in d and d[k] > 0)
            if not v:
                return "-"
            return "%.2f-%.2f" % (v[0], v[-1])
        L.append("Each goal ratio turn by turn (timed build k over the other "
                 "side's timed build k, seconds apart), lowest to highest "
                 "over the turns of this run (`speed-builds.csv`, "
                 "`atrbvh bench --builds`):")
        L.append("")
        L.append("| scene | LBVH / low | ATRBVH(9,2) / medium | TRBVH(7,3) / "
                 "medium | LBVH OpenCL / CPU | ATRBVH(9,2) OpenCL / CPU |")
        L.append("|---|---:|---:|---:|---:|---:|")
        for s in scenes:
            L.append("| %s | %s | %s | %s | %s | %s |" % (
                s, spread(s, "LBVH", "embree_low"),
                spread(s, "ATRBVH(9,2)", "embree_medium"),
                spread(s, "TRBVH(7,3)", "embree_medium"),
                spread(s, "LBVH@opencl", "LBVH"),
                spread(s, "ATRBVH(9,2)@opencl", "ATRBVH(9,2)")))
        L.append("")
    if any(lab.endswith("@opencl") for (_, lab) in by):
        L.append("### OpenCL on PoCL against the CPU backend (same tree, same "
                 "run; device opened once, outside the timing; goal <= 1.5)")
        L.append("")
        L.append("| scene | LBVH OpenCL / CPU | ATRBVH(9,2) OpenCL / CPU |")
        L.append("|---|---:|---:|")
        for s in scenes:
            g = lambda lab: fnum(by.get((s, lab), {}), "build_ms")
            L.append("| %s | %s | %s |" % (
                s, ratio_cell(g("LBVH@opencl"), g("LBVH"), 1.5),
                ratio_cell(g("ATRBVH(9,2)@opencl"), g("ATRBVH(9,2)"), 1.5)))
        L.append("")
    if alone:
        L.append("### Cross-check: the bench's Embree rows against a standalone "
                 "`rtcBuildBVH` (`tools/embree-alone`)")
        L.append("")
        L.append("Median ms; *bench / alone* near 1 means the bench times "
                 "Embree as its own users would (the bench's also cover its "
                 "OpenMP primitive fill and slightly larger callbacks).")
        L.append("")
        L.append("| scene | quality | bench ms | alone ms | bench / alone |")
        L.append("|---|---|---:|---:|---:|")
        for s in scenes:
            for q in ("embree_low", "embree_medium", "embree_high"):
                b = fnum(by.get((s, q), {}), "build_ms")
                a = alone.get((s, q), float("nan"))
                if math.isnan(b) or math.isnan(a):
                    continue
                L.append("| %s | %s | %.1f | %.1f | %.2f |" % (
                    s, q[7:], b, a, b / a))
        L.append("")
    L.append("### Nanoseconds per triangle, per stage (2 threads, median)")
    L.append("")
    L.append("CPU use: the build's CPU time over 2 x its wall time (median; "
             "the CSV's cpu_use), the share of the two threads' time kept "
             "busy; it does not move with the host's speed.")
    L.append("")
    L.append("| scene | config | total | " + " | ".join(STAGES) +
             " | CPU use |")
    L.append("|---|---|---:|" + "---:|" * len(STAGES) + "---:|")
    for s in scenes:
        for lab in ("LBVH", "ATRBVH(9,2)", "ATRBVH(16,3)", "TRBVH(7,3)"):
            r = by.get((s, lab))
            if not r:
                continue
            n = fnum(r, "triangles")
            cells = ["%.0f" % (fnum(r, st + "_ms") * 1e6 / n) for st in STAGES]
            use = r.get("cpu_use", "")
            L.append("| %s | %s | %.0f | %s | %s |" % (
                s, lab, fnum(r, "build_ms") * 1e6 / n, " | ".join(cells),
                "%.2f" % float(use) if use else "-"))
    L.append("")
    L.append("### Build time and SAH, and who dominates Embree medium")
    L.append("")
    L.append("| scene | " + " | ".join(
        "%s ms / SAH" % lab for lab in
        ("LBVH", "ATRBVH(9,2)", "ATRBVH(16,3)", "TRBVH(7,3)", "embree_low",
         "embree_medium", "embree_high")) + " | faster and lower SAH than "
        "Embree medium |")
    L.append("|---|" + "---:|" * 7 + "---|")
    for s in scenes:
        cells = []
        for lab in ("LBVH", "ATRBVH(9,2)", "ATRBVH(16,3)", "TRBVH(7,3)",
                    "embree_low", "embree_medium", "embree_high"):
            r = by.get((s, lab))
            cells.append("%.1f / %.2f" % (fnum(r, "build_ms"), fnum(r, "sah"))
                         if r else "-")
        em = by.get((s, "embree_medium"))
        dom = []
        if em:
            for (ss, lab), r in by.items():
                if ss != s or lab.startswith("embree") or "@" in lab:
                    continue
                if (fnum(r, "build_ms") < fnum(em, "build_ms")
                        and fnum(r, "sah") < fnum(em, "sah")):
                    dom.append(lab)
        if not dom and em:
            best = min((fnum(r, "sah"), lab) for (ss, lab), r in by.items()
                       if ss == s and not lab.startswith("embree")
                       and "@" not in lab)
            dom = ["none: the lowest atrbvh SAH run, %s %.2f, is %+.1f%% "
                   "from Embree medium's" % (best[1], best[0],
                                             100 * (best[0] / fnum(em, "sah")
                                                    - 1))]
        L.append("| %s | %s | %s |" % (s, " | ".join(cells), ", ".join(dom)))
    L.append("")
    spath = os.path.join(out, "speed-scaling.csv")
    if os.path.exists(spath):
        sc = load(spath)
        L.append("### Scaling to 10^7 triangles (LBVH, 2 threads)")
        L.append("")
        L.append("| base | triangles | build ms | ns / triangle | peak B / "
                 "triangle | peak / BVH |")
        L.append("|---|---:|---:|---:|---:|---:|")
        pts = {}
        for r in sc:
            n = fnum(r, "triangles")
            ms = fnum(r, "build_ms")
            L.append("| %s | %d | %.1f | %.1f | %.1f | %.2f |" % (
                r["base"], n, ms, ms * 1e6 / n,
                fnum(r, "peak_bytes_per_triangle"), fnum(r, "peak_over_bvh")))
            if n >= 5e4 and r["method"] == "lbvh":
                pts.setdefault(r["base"], []).append((math.log(n),
                                                      math.log(ms)))
        L.append("")
        for b, p in pts.items():
            if len(p) < 2:
                continue
            mx = sum(x for x, _ in p) / len(p)
            my = sum(y for _, y in p) / len(p)
            k = (sum((x - mx) * (y - my) for x, y in p)
                 / sum((x - mx) ** 2 for x, _ in p))
            L.append("* %s: LBVH time ~ N^%.3f from 10^5 (%d points, least "
                     "squares on log-log; goal <= 1.05)" % (b, k, len(p)))
        L.append("")
    L.append("Build time against SAH (lower left is better), from this run:")
    L.append("")
    L.append(" ".join("![%s](bench/speed/pareto-%s.png)" % (s, s)
                      for s in scenes))
    replace_section(doc, "SPEED", L)


if __name__ == "__main__":
    main()
