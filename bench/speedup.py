#!/usr/bin/env python3
"""Side by side, one build: a reference method against another (VTP against PVTP on two threads,
by default), alternating, in one run.

The ratio of a parallel solver to the sequential one is what issue 12 asks of PVTP ("best of 3
alternating runs": this machine's second core comes and goes). Every round runs the reference
and then the other method, in swapped order every other round, so that a machine that drifts
hurts both alike; the summary gives the best of each and their ratio, the median of each, and
the ratio of each round's pair. With --check, the two methods' distances are compared once
(`--dump`): identical bytes, or the largest difference over the bounding box diagonal.

Methods are written as for compare_commits.py, NAME[:THREADS[:LAMBDA]]; meshes as in
run_benchmarks.py (`armadillo@2`: armadillo after two Loop subdivisions) or as a path.

Example (the build as in bench/README.md):
  python3 bench/speedup.py build-bench/bench/bench_geodesics --mesh armadillo@2,armadillo@3 --rounds 3
"""

import argparse
import statistics
import sys
import tempfile
from pathlib import Path

import compare_commits as cc
import run_benchmarks as rb

PHASES = ("selection", "propagation", "merge")


def describe(result):
    phases = [p for p in PHASES if result.get("seconds_" + p, 0) > 0]
    text = "%.3f" % result["seconds_solve"]
    if phases:
        text += " (" + " / ".join("%.3f" % result["seconds_" + p] for p in phases) + ")"
    return text


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("driver", help="path to bench_geodesics")
    p.add_argument("--mesh", required=True, help="comma-separated meshes")
    p.add_argument("--reference", default="vtp", help="the method the other is measured against (default: vtp)")
    p.add_argument("--method", default="pvtp:2", help="the other method (default: pvtp:2)")
    p.add_argument("--rounds", type=int, default=3, help="alternating rounds (default: 3)")
    p.add_argument("--source", type=int, default=0)
    p.add_argument("--check", action="store_true", help="compare the two methods' distances once")
    p.add_argument("--timeout", type=int, default=1800, help="seconds before a run is killed")
    p.add_argument("--cache", default=str(rb.DEFAULT_CACHE), help="folder of unpacked and subdivided meshes")
    p.add_argument("--archive", default=str(rb.DEFAULT_ARCHIVE), help="CGAL's data set (libcgal-demo)")
    args = p.parse_args()
    args.mem_limit_mb = None
    driver = Path(args.driver)
    if not driver.exists():
        raise SystemExit("error: no driver at %s (build the target bench_geodesics first)" % driver)
    if args.rounds < 1:
        raise SystemExit("error: --rounds must be at least 1")
    methods = [cc.parse_method(args.reference), cc.parse_method(args.method)]
    for spec in args.mesh.split(","):
        mesh = cc.mesh_path(spec, args)
        times = [[], []]
        print("## %s: %s against %s, %d alternating rounds (seconds of the solve; in brackets, of its phases: "
              "%s)" % (spec, methods[1]["label"], methods[0]["label"], args.rounds, " / ".join(PHASES)))
        print()
        print("| round | %s s | %s s | ratio |" % (methods[0]["label"], methods[1]["label"]))
        print("|---:|---:|---:|---:|")
        last = None
        for r in range(args.rounds):
            order = (0, 1) if r % 2 == 0 else (1, 0)
            results = [None, None]
            for i in order:
                results[i] = cc.solve(driver, mesh, methods[i], args)
                times[i].append(results[i]["seconds_solve"])
            last = results
            print("| %d | %s | %s | %.2fx |" % (r + 1, describe(results[0]), describe(results[1]),
                                                  times[0][-1] / times[1][-1]))
            sys.stdout.flush()
        best = [min(t) for t in times]
        median = [statistics.median(t) for t in times]
        pairs = [a / b for a, b in zip(times[0], times[1])]
        print()
        print("%s, %d vertices: best of %d %.3f s against %.3f s, **%.2fx**; medians %.3f s against %.3f s "
              "(%.2fx); the rounds' pairs %.2f-%.2fx (median %.2fx)"
              % (spec, last[0]["vertices"], args.rounds, best[0], best[1], best[0] / best[1], median[0],
                 median[1], median[0] / median[1], min(pairs), max(pairs), statistics.median(pairs)))
        if args.check:
            with tempfile.TemporaryDirectory() as work:
                dumps = [Path(work) / "a.bin", Path(work) / "b.bin"]
                for i in (0, 1):
                    cc.solve(driver, mesh, methods[i], args, dumps[i])
                print("distances: %s" % cc.compare_dumps(dumps[0], dumps[1], last[0]["vertices"],
                                                        last[0]["bbox_diagonal"]))
        print()


if __name__ == "__main__":
    main()
