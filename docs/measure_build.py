#!/usr/bin/env python3
"""Measure `atrbvh build --json` on every scene: per-stage times (best of K
runs) and SAH with and without collapse, for 1 and 2 threads.

Usage: python3 docs/measure_build.py [--repeat K] [--methods lbvh,atrbvh]
                                     [SCENE...]   (default ../shared/scenes/*.ply)
Prints a markdown table.  Times are the minimum over K runs (the least
disturbed); SAH is exact and the same on every run."""
import argparse, glob, json, os, subprocess, sys

here = os.path.dirname(os.path.abspath(__file__))
tool = os.path.join(here, "..", "_build", "tools", "atrbvh")
ap = argparse.ArgumentParser()
ap.add_argument("--repeat", type=int, default=3)
ap.add_argument("--methods", default="lbvh,trbvh,atrbvh")
ap.add_argument("--threads", default="1,2")
ap.add_argument("scenes", nargs="*")
a = ap.parse_args()
scenes = a.scenes or sorted(glob.glob(os.path.join(here, "..", "..", "shared", "scenes", "*.ply")))
stages = ["bounds", "morton", "sort", "hierarchy", "refit", "optimise", "collapse", "layout"]

def run(scene, method, threads, collapse):
    best = None
    for _ in range(a.repeat):
        cmd = [tool, "build", scene, "--json", "--method", method, "--threads", str(threads)]
        if not collapse:
            cmd.append("--no-collapse")
        r = json.loads(subprocess.run(cmd, check=True, capture_output=True, text=True).stdout)
        if best is None or r["build_ms"] < best["build_ms"]:
            best = r
    return best

print("| scene | triangles | method | threads | SAH | SAH no collapse | build ms | " + " | ".join(stages) + " |")
print("|---|---:|---|---:|---:|---:|---:|" + "---:|" * len(stages))
for s in scenes:
    for m in a.methods.split(","):
        for t in [int(x) for x in a.threads.split(",")]:
            c = run(s, m, t, True)
            b = run(s, m, t, False)
            print("| %s | %d | %s | %d | %.3f | %.3f | %.1f | %s |" % (
                os.path.basename(s), c["triangles"], m, t, c["sah"], b["sah"], c["build_ms"],
                " | ".join("%.1f" % c["stages_ms"][k] for k in stages)))
            sys.stdout.flush()
