#!/usr/bin/env python3
"""speed_runs.py RUNS DOC - every recorded speed run against the goals.

RUNS holds the copies of recorded runs of `sh docs/run_benchmarks.sh
speed` (docs/bench/speed-runs: NAME-speed.csv beside NAME-machine.txt).
For each run, in the order of their dates, this counts the scenes where
each goal of issue 11 was met (the ratios of medians, as the generated
speed section computes them, speed_tables.py) and the worst ratio, and
rewrites the part of DOC between <!-- BEGIN RUNS --> and <!-- END RUNS -->
with that table (with the host's steal time over the run, POCL_AFFINITY
and how atrbvh's builds were made - into the last tree, `rebuild`, or
after freeing it, `fresh`, as every run before 7 December - where the
machine file has them) and a line per host.  Nothing is typed in by hand.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from speed_tables import fnum, label, load, replace_section, sname  # noqa: E402

# (header, numerator configuration, denominator configuration, goal)
GOALS = [
    ("LBVH / low (<= 0.8)", "LBVH", "embree_low", 0.8),
    ("ATRBVH(9,2) / medium (<= 0.8)", "ATRBVH(9,2)", "embree_medium", 0.8),
    ("TRBVH(7,3) / medium (<= 1.5)", "TRBVH(7,3)", "embree_medium", 1.5),
    ("OpenCL LBVH / CPU (<= 1.5)", "LBVH@opencl", "LBVH", 1.5),
    ("OpenCL ATRBVH(9,2) / CPU (<= 1.5)", "ATRBVH(9,2)@opencl",
     "ATRBVH(9,2)", 1.5),
]


def machine(path):
    out = {}
    for line in open(path):
        k, _, v = line.rstrip("\n").partition(": ")
        out[k] = v
    return out


def run_cells(rows):
    """Per goal: (scenes met, scenes measured, worst ratio)."""
    by, scenes = {}, []
    for r in rows:
        s = sname(r["scene"])
        if s not in scenes:
            scenes.append(s)
        by[(s, label(r))] = fnum(r, "build_ms")
    cells = []
    for _, num, den, goal in GOALS:
        met = total = 0
        worst = None
        for s in scenes:
            a, b = by.get((s, num)), by.get((s, den))
            if not (a and b and a > 0 and b > 0):
                continue
            v = a / b
            total += 1
            met += v <= goal
            worst = v if worst is None or v > worst else worst
        cells.append((met, total, worst))
    return cells


def main():
    runs_dir, doc = sys.argv[1], sys.argv[2]
    runs = []
    for f in os.listdir(runs_dir):
        if not f.endswith("-speed.csv"):
            continue
        name = f[: -len("-speed.csv")]
        mpath = os.path.join(runs_dir, name + "-machine.txt")
        if not os.path.exists(mpath):
            continue
        m = machine(mpath)
        runs.append((m.get("date", ""), name, m,
                     run_cells(load(os.path.join(runs_dir, f)))))
    runs.sort()
    L = ["| run | date | host | load before | steal | POCL_AFFINITY | "
         "builds | " +
         " | ".join(g[0] for g in GOALS) + " | every cell |",
         "|---|---|---|---|---:|---|---|" + "---:|" * len(GOALS) + "---|"]
    hosts = {}
    for date, name, m, cells in runs:
        host = m.get("cpu", "?").split(",")[0]
        row = ["%d/%d (%.2f)" % (met, tot, worst) if tot else "-"
               for met, tot, worst in cells]
        every = all(met == tot for met, tot, _ in cells if tot)
        # "steal during the run: 0.9% of the CPU time (...)" -> 0.9%
        steal = m.get("steal during the run", "-").split(" ")[0]
        # runs before 7 December built every tree after freeing the last
        builds = m.get("atrbvh builds", "fresh").split(" ")[0]
        L.append("| %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
            name, date, host, m.get("load before", "?"), steal,
            m.get("POCL_AFFINITY", "-"), builds, " | ".join(row),
            "yes" if every else "no"))
        h = hosts.setdefault(host, [0, 0, [[0, 0] for _ in GOALS]])
        h[0] += 1
        h[1] += every
        for k, (met, tot, _) in enumerate(cells):
            h[2][k][0] += met
            h[2][k][1] += tot
    L.append("")
    for host in sorted(hosts):
        n, every, per = hosts[host]
        L.append("* **%s**: %d runs, %d with every cell met; cells met per "
                 "goal: %s." % (host, n, every, ", ".join(
                     "%s %d of %d" % (GOALS[k][0].split(" (")[0], met, tot)
                     for k, (met, tot) in enumerate(per))))
    replace_section(doc, "RUNS", L)


if __name__ == "__main__":
    main()
