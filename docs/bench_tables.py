#!/usr/bin/env python3
"""bench_tables.py OUTDIR MARKDOWN - writes the generated part of
docs/benchmarks.md (between the BEGIN/END GENERATED markers) from the CSV
files and logs docs/run_benchmarks.sh leaves in OUTDIR."""
import csv, math, os, re, sys

out, md = sys.argv[1], sys.argv[2]
rel = os.path.relpath(out, os.path.dirname(md))


def rows(name):
    p = os.path.join(out, name)
    if not os.path.exists(p):
        return []
    with open(p, newline="") as f:
        return list(csv.DictReader(f))


def num(r, k):
    try:
        v = float(r[k])
        return v if math.isfinite(v) else None
    except (KeyError, ValueError):
        return None


def f(v, fmt="%.1f"):
    return "-" if v is None else fmt % v


def label(r):
    m = r["method"]
    if m.startswith("embree"):
        return m
    if m == "lbvh":
        return "LBVH"
    return "%s(%s,%s)" % (m.upper(), r["treelet_size"], r["rounds"])


def sname(s):
    return os.path.splitext(os.path.basename(s))[0]


def tag(s):
    b = s.rsplit("/", 1)[-1]
    if "." in b:
        b = b[: b.rfind(".")]
    return re.sub(r"[^A-Za-z0-9]", "_", b)


L = []
P = L.append

# ---------------------------------------------------------------- machine
info = {}
try:
    for line in open(os.path.join(out, "machine.txt")):
        k, _, v = line.partition(":")
        info[k.strip()] = v.strip()
except OSError:
    pass
P("### Machine and run\n")
for k in ("date", "cpu", "nproc", "memory", "compiler", "embree", "OMP_WAIT_POLICY", "POCL_AFFINITY",
          "load before", "load after", "command"):
    if k in info:
        P("* **%s**: %s" % (k, info[k] if k != "command" else "`%s`" % info[k]))
P("")

# ------------------------------------------------------------- main tables
bench = rows("bench.csv")
scenes = []
for r in bench:
    if r["scene"] not in scenes:
        scenes.append(r["scene"])
goals = []
for s in scenes:
    rs = [r for r in bench if r["scene"] == s]
    P("### %s (%s triangles)\n" % (sname(s), rs[0]["triangles"]))
    P("| configuration | build ms | optimise ms | SAH | SAH binary | nodes | "
      "peak MB | peak / BVH | primary | AO | diffuse | all Mrays/s | "
      "relative % | time % | SAH % |")
    P("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for r in rs:
        peak, bb = num(r, "peak_bytes"), num(r, "bvh_bytes")
        P("| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
            label(r), f(num(r, "build_ms")), f(num(r, "optimise_ms")),
            f(num(r, "sah"), "%.3f"), f(num(r, "sah_binary"), "%.3f"),
            r["nodes"], f(peak / 1048576.0 if peak else None),
            f(peak / bb if peak and bb else None, "%.2f"),
            f(num(r, "primary_mrays"), "%.2f"), f(num(r, "ao_mrays"), "%.2f"),
            f(num(r, "diffuse_mrays"), "%.2f"), f(num(r, "total_mrays"), "%.2f"),
            f(num(r, "relative_pct")), f(num(r, "time_pct")),
            f(num(r, "sah_pct"))))
    emb = [r for r in rs if r["method"].startswith("embree")]
    if emb:
        P("\nEmbree's own traversal of the same rays (rtcIntersect1 / "
          "rtcOccluded1 on an Embree scene of that quality), Mrays/s: " +
          "; ".join("%s: primary %s, AO %s, diffuse %s (scene commit %s ms)" % (
              r["method"], f(num(r, "embree_primary_mrays"), "%.2f"),
              f(num(r, "embree_ao_mrays"), "%.2f"),
              f(num(r, "embree_diffuse_mrays"), "%.2f"),
              f(num(r, "embree_commit_ms"))) for r in emb) + ".")
    P("\n![%s: build time against SAH](%s/pareto-%s.png) "
      "![%s: rays against build time](%s/rays-%s.png)\n" % (
          sname(s), rel, tag(s), sname(s), rel, tag(s)))

    # goals, per scene
    lib = [r for r in rs if not r["method"].startswith("embree")]
    def find(m, n=None, k=None):
        for r in lib:
            if r["method"] == m and (n is None or r["treelet_size"] == n) and (
                    k is None or r["rounds"] == k):
                return r
        return None
    g = {"scene": sname(s)}
    for e in emb:
        best = None
        for r in lib:
            if num(r, "build_ms") <= num(e, "build_ms") and num(r, "sah") < num(e, "sah"):
                if best is None or num(r, "sah") < num(best, "sah"):
                    best = r
        if best:
            g[e["method"]] = "yes: %s (%s ms, SAH %s) vs %s ms, SAH %s" % (
                label(best), f(num(best, "build_ms")), f(num(best, "sah"), "%.2f"),
                f(num(e, "build_ms")), f(num(e, "sah"), "%.2f"))
        else:
            lower = [r for r in lib if num(r, "sah") < num(e, "sah")]
            if lower:
                fastest = min(lower, key=lambda r: num(r, "build_ms"))
                g[e["method"]] = "**no**: %s ms, SAH %s; the fastest lower SAH is %s at %s ms (%.1fx)" % (
                    f(num(e, "build_ms")), f(num(e, "sah"), "%.2f"), label(fastest),
                    f(num(fastest, "build_ms")),
                    num(fastest, "build_ms") / num(e, "build_ms"))
            else:
                best_sah = min(lib, key=lambda r: num(r, "sah"))
                g[e["method"]] = "**no**: SAH %s; no atrbvh configuration run is lower (best %s, %s)" % (
                    f(num(e, "sah"), "%.2f"), label(best_sah), f(num(best_sah, "sah"), "%.2f"))
    tr, at, lb = find("trbvh", "7", "3"), find("atrbvh", "9", "2"), find("lbvh")
    if tr and at:
        t = num(at, "build_ms") / num(tr, "build_ms")
        q = num(at, "sah") / num(tr, "sah") - 1
        g["atrbvh92"] = "%s: time %.2fx, SAH %+.2f%%" % (
            "yes" if t <= 0.5 and q <= 0.01 else "**no**", t, 100 * q)
    el = [e for e in emb if e["method"] == "embree_low"]
    if lb and el:
        sp = num(el[0], "build_ms") / num(lb, "build_ms")
        g["lbvh"] = "%s: %.2fx Embree low's speed, SAH %.2f vs %.2f" % (
            "yes" if sp >= 1.5 and num(lb, "sah") < num(el[0], "sah") else "**no**",
            sp, num(lb, "sah"), num(el[0], "sah"))
    em = [e for e in emb if e["method"] == "embree_medium"]
    if at and em and num(at, "total_mrays") and num(em[0], "total_mrays"):
        best = max((r for r in lib if r["method"] == "atrbvh"),
                   key=lambda r: num(r, "total_mrays") or 0)
        ratio = num(at, "total_mrays") / num(em[0], "total_mrays")
        g["rays"] = "%s: ATRBVH(9,2) %.2f vs Embree medium %.2f Mrays/s (%.2fx); best ATRBVH %s %.2f" % (
            "yes" if ratio >= 1 else "**no**", num(at, "total_mrays"),
            num(em[0], "total_mrays"), ratio, label(best), num(best, "total_mrays"))
    peaks = [num(r, "peak_bytes") / num(r, "bvh_bytes") for r in lib]
    if peaks:
        g["memory"] = "%s: peak / BVH %.2f to %.2f" % (
            "yes" if max(peaks) <= 2 else "**no**", min(peaks), max(peaks))
    goals.append(g)

if goals:
    P("### Goals, scene by scene\n")
    P("| scene | Embree low dominated | Embree medium dominated | Embree high dominated | "
      "ATRBVH(9,2) <= 0.5x TRBVH(7,3) time, SAH within 1% | LBVH >= 1.5x Embree low, lower SAH | "
      "ATRBVH rays >= Embree medium's (our traverser) | peak <= 2x BVH |")
    P("|---|---|---|---|---|---|---|---|")
    for g in goals:
        P("| %s |" % g["scene"] + " | ".join(g.get(k, "-") for k in (
            "embree_low", "embree_medium", "embree_high", "atrbvh92", "lbvh",
            "rays", "memory")) + " |")
    P("")

# ---------------------------------------------------------------- sweep
sweep = rows("sweep.csv")
if sweep:
    P("### Treelet size and rounds (ATRBVH; builds only)\n")
    P("Median build ms / SAH; in brackets time and SAH as %% of TRBVH(7,3) on "
      "the same scene.  Embree rows for reference.\n")
    sc = []
    for r in sweep:
        if r["scene"] not in sc:
            sc.append(r["scene"])
    for s in sc:
        rs = [r for r in sweep if r["scene"] == s]
        ns = sorted({int(r["treelet_size"]) for r in rs if r["method"] == "atrbvh"})
        ks = sorted({int(r["rounds"]) for r in rs if r["method"] == "atrbvh"})
        P("**%s**\n" % sname(s))
        P("| n \\ rounds | " + " | ".join(str(k) for k in ks) + " |")
        P("|---|" + "---:|" * len(ks))
        for n in ns:
            cells = []
            for k in ks:
                r = [x for x in rs if x["method"] == "atrbvh" and int(x["treelet_size"]) == n and int(x["rounds"]) == k]
                if r:
                    r = r[0]
                    cells.append("%s / %s (%s, %s)" % (
                        f(num(r, "build_ms"), "%.0f"), f(num(r, "sah"), "%.2f"),
                        f(num(r, "time_pct"), "%.0f"), f(num(r, "sah_pct"), "%.1f")))
                else:
                    cells.append("-")
            P("| %d | %s |" % (n, " | ".join(cells)))
        others = [r for r in rs if r["method"] != "atrbvh"]
        P("\n" + "; ".join("%s %s ms / %s" % (label(r), f(num(r, "build_ms"), "%.0f"),
                                            f(num(r, "sah"), "%.2f")) for r in others) + "\n")
        P("![%s sweep](%s/sweep/pareto-%s.png)\n" % (sname(s), rel, tag(s)))

# -------------------------------------------------------------- scaling
scal = rows("scaling.csv")
if scal:
    P("### Scaling\n")
    P("| base | triangles | copies | method | build ms | bounds | morton | sort | hierarchy | refit | optimise | collapse | layout | peak B/triangle | peak / BVH |")
    P("|---|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for r in scal:
        P("| %s | %s | %s | %s | %s | %s | %s | %s |" % (
            sname(r["base"]), r["triangles"], r["copies"], label(r),
            f(num(r, "build_ms")),
            " | ".join(f(num(r, k + "_ms")) for k in (
                "bounds", "morton", "sort", "hierarchy", "refit", "optimise",
                "collapse", "layout")),
            f(num(r, "peak_bytes_per_triangle")), f(num(r, "peak_over_bvh"), "%.2f")))
    fits = [l.strip() for l in open(os.path.join(out, "scaling.txt")) if "N^" in l]
    P("\nFitted exponents (least squares on log-log):\n")
    for l in fits:
        P("* `%s`" % re.sub(r"\s+", " ", l))
    P("\n![scaling](%s/scaling.png) ![stages](%s/scaling-stages.png) "
      "![memory](%s/scaling-memory.png)\n" % (rel, rel, rel))

text = open(md).read()
a, b = "<!-- BEGIN GENERATED -->", "<!-- END GENERATED -->"
i, j = text.index(a) + len(a), text.index(b)
open(md, "w").write(text[:i] + "\n" + "\n".join(L) + "\n" + text[j:])
