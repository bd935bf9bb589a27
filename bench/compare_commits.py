#!/usr/bin/env python3
"""Side by side: the solvers of an older commit against those of a newer one (or of the working
tree), on one machine, in one run, alternating the two builds.

Each revision is exported (`git archive`) into a work folder and its `bench_geodesics` built
there (Release, ccache when installed); the working tree (NEW = `.`) is built from the checkout
itself, uncommitted changes included. Then, for every round, every (mesh, method) is run once
with each build, the order of the two swapped every other round, so that a machine that drifts
during the run hurts both alike. Solve times (`seconds_solve`) are compared by their medians and
by the pairs of one round (which build was faster in how many rounds).

--check compares the distances of the two builds (one run each, `--dump`): identical bytes, or
the largest difference over the bounding box diagonal. --callgrind counts the instructions of
the solve of each build (valgrind, the solver's `run()` only), which unlike time repeats; only
for sequential runs (one thread), since the work of other threads is not under `run()`.

Methods are written NAME[:T[:LAMBDA]] (`vtp`, `pvtp:2`, `pavtp:2:8`, `pmmp:2`); meshes as in
run_benchmarks.py (`armadillo@1`: armadillo after one Loop subdivision) or as a path.

Examples:
  python3 bench/compare_commits.py 3311f1a HEAD --mesh armadillo@1 --method vtp,pvtp:2,fwp_mmp,pmmp:2
  python3 bench/compare_commits.py HEAD . --mesh armadillo@1 --method vtp --runs 7 --check --callgrind
  python3 bench/compare_commits.py OLD NEW --drivers old-build/bench/bench_geodesics build/bench/bench_geodesics
"""

import argparse
import math
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

import run_benchmarks as rb

# The solver's run() of each family: what --callgrind counts (an exact name: callgrind toggles
# collection at each function that matches, so a pattern matching nested functions would undo
# itself).
RUN_FUNCTION = {"mmp": "CGAL_ext::Geodesics_3::internal::MMP_solver::run()",
                "vtp": "CGAL_ext::Geodesics_3::internal::VTP_solver::run()"}


def parse_method(spec):
    parts = spec.split(":")
    if not parts[0] or len(parts) > 3:
        raise SystemExit("error: method '%s': write NAME[:THREADS[:LAMBDA]]" % spec)
    extra = []
    if len(parts) > 1:
        extra += ["--threads", parts[1]]
    if len(parts) > 2:
        extra += ["--lambda", parts[2]]
    if parts[0] in ("mmp", "fwp_mmp", "pmmp"):
        extra += ["--paths", "0"]
    sequential = len(parts) == 1 or parts[1] == "1"
    return {"label": spec, "name": parts[0], "extra": extra, "sequential": sequential}


def revision_id(repo, rev):
    if rev == ".":
        return "worktree"
    out = subprocess.run(["git", "-C", str(repo), "rev-parse", "--short", rev + "^{commit}"],
                         capture_output=True, text=True)
    if out.returncode != 0:
        raise SystemExit("error: '%s' is not a commit of %s" % (rev, repo))
    return out.stdout.strip()


def build(repo, rev, short, work, jobs):
    """Builds bench_geodesics of `rev` (or of the working tree) under `work`; returns its path."""
    if rev == ".":
        source = repo
    else:
        source = work / ("src-" + short)
        if not (source / "CMakeLists.txt").exists():
            source.mkdir(parents=True, exist_ok=True)
            archive = subprocess.Popen(["git", "-C", str(repo), "archive", short], stdout=subprocess.PIPE)
            subprocess.run(["tar", "-x", "-C", str(source)], stdin=archive.stdout, check=True)
            if archive.wait() != 0:
                raise SystemExit("error: git archive %s failed" % short)
    build_dir = work / ("build-" + short)
    configure = ["cmake", "-S", str(source), "-B", str(build_dir), "-DCMAKE_BUILD_TYPE=Release",
                 "-DCGAL_EXT_BUILD_BENCHMARKS=ON", "-DCGAL_EXT_BUILD_TESTS=OFF",
                 "-DCGAL_EXT_BUILD_EXAMPLES=OFF", "-DCGAL_EXT_BUILD_TOOLS=OFF"]
    if shutil.which("ccache"):
        configure += ["-DCMAKE_CXX_COMPILER_LAUNCHER=ccache"]
    rb.log("building bench_geodesics of %s in %s" % (short, build_dir))
    for cmd in (configure, ["cmake", "--build", str(build_dir), "--target", "bench_geodesics", "-j", str(jobs)]):
        done = subprocess.run(cmd, capture_output=True, text=True)
        if done.returncode != 0:
            sys.stderr.write(done.stdout[-3000:] + done.stderr[-3000:])
            raise SystemExit("error: building %s failed: %s" % (short, " ".join(cmd)))
    return build_dir / "bench" / "bench_geodesics"


def solve(driver, mesh, method, args, dump=None):
    cmd = [str(driver), "--mesh", str(mesh), "--method", method["name"], "--source", str(args.source)]
    cmd += method["extra"] + (["--dump", str(dump)] if dump else [])
    status, stdout, stderr, _ = rb.run_process(cmd, args.timeout, None)
    if status != "ok":
        raise SystemExit("error: %s %s: %s %s" % (driver, method["label"], status, stderr.strip()[-500:]))
    return rb.parse_result_line(stdout)


def instructions(driver, mesh, method, args, work):
    family = "mmp" if "mmp" in method["name"] else "vtp"
    out = work / "callgrind.out"
    cmd = ["valgrind", "--tool=callgrind", "--callgrind-out-file=" + str(out),
           "--toggle-collect=" + RUN_FUNCTION[family], str(driver), "--mesh", str(mesh),
           "--method", method["name"], "--source", str(args.source)] + method["extra"]
    done = subprocess.run(cmd, capture_output=True, text=True)
    if done.returncode != 0:
        raise SystemExit("error: callgrind failed: %s" % done.stderr[-500:])
    for line in open(out):
        if line.startswith("summary:") or line.startswith("totals:"):
            return int(line.split()[1])
    raise SystemExit("error: no total in %s" % out)


def compare_dumps(a, b, n, diagonal):
    if a.read_bytes() == b.read_bytes():
        return "identical"
    c = rb.compare_exact(rb.read_dump(a, n), rb.read_dump(b, n), diagonal)
    return "max diff / diagonal %.3g (vertex %d)" % (c["max_error_over_diagonal"], c["worst_vertex"])


def mesh_path(spec, args):
    if os.path.exists(spec):
        return Path(spec)
    name, level = rb.parse_mesh_spec(spec)
    return rb.prepare_mesh(name, level, args)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("base", help="the older revision (any git revision)")
    p.add_argument("new", nargs="?", default=".", help="the newer revision, or '.' for the working tree (default)")
    p.add_argument("--mesh", default="armadillo@1", help="comma-separated meshes (default: %(default)s)")
    p.add_argument("--method", default="vtp,pvtp:2,fwp_mmp,pmmp:2", help="comma-separated methods (default: %(default)s)")
    p.add_argument("--runs", type=int, default=5, help="rounds; each runs both builds once (default: %(default)s)")
    p.add_argument("--source", type=int, default=0)
    p.add_argument("--check", action="store_true", help="compare the distances of the two builds")
    p.add_argument("--callgrind", action="store_true", help="count the instructions of each solve (valgrind)")
    p.add_argument("--work", help="folder of the exports and builds (default: a temporary folder, removed)")
    p.add_argument("--drivers", nargs=2, metavar=("BASE_BENCH", "NEW_BENCH"),
                   help="bench_geodesics binaries already built from the two revisions (no export, no build)")
    p.add_argument("--jobs", type=int, default=os.cpu_count() or 2)
    p.add_argument("--timeout", type=float, default=3600)
    p.add_argument("--cache", default=str(rb.DEFAULT_CACHE), help="folder of unpacked and subdivided meshes")
    p.add_argument("--archive", default=str(rb.DEFAULT_ARCHIVE))
    p.add_argument("--raw", help="also write every run, one per line, to this file")
    args = p.parse_args()
    if args.runs < 1:
        raise SystemExit("error: --runs must be at least 1")
    methods = [parse_method(s) for s in args.method.split(",")]
    repo = rb.REPO
    revs = [(args.base, revision_id(repo, args.base)), (args.new, revision_id(repo, args.new))]

    work_folder = args.work or tempfile.mkdtemp(prefix="compare_commits_")
    work = Path(work_folder)
    work.mkdir(parents=True, exist_ok=True)
    try:
        if args.drivers:
            drivers = [Path(d).resolve() for d in args.drivers]
        else:
            drivers = [build(repo, rev, short, work, args.jobs) for rev, short in revs]
        args.driver = drivers[-1]  # subdivides the meshes that need it
        args.mem_limit_mb = None
        meshes = [(spec, mesh_path(spec, args)) for spec in args.mesh.split(",")]
        times = {}
        raw = []
        for r in range(args.runs):
            order = [0, 1] if r % 2 == 0 else [1, 0]
            for spec, path in meshes:
                for m in methods:
                    for k in order:
                        res = solve(drivers[k], path, m, args)
                        times.setdefault((spec, m["label"]), ([], []))[k].append(res["seconds_solve"])
                        raw.append("%d %s %s %s %.6f %s" % (r + 1, revs[k][1], spec, m["label"],
                                                            res["seconds_solve"], res.get("windows_created", "")))
            rb.log("round %d of %d done" % (r + 1, args.runs))

        print("# %s (base) against %s (new), %d rounds, source %d, `seconds_solve`" %
              (revs[0][1], revs[1][1], args.runs, args.source))
        header = ["mesh", "method", "base median (s)", "new median (s)", "new / base", "rounds new faster"]
        extra_rows = {}
        if args.check or args.callgrind:
            for spec, path in meshes:
                for m in methods:
                    cells = []
                    if args.check:
                        dumps = [work / ("dump%d.bin" % k) for k in (0, 1)]
                        res = [solve(drivers[k], path, m, args, dumps[k]) for k in (0, 1)]
                        cells.append(compare_dumps(dumps[0], dumps[1], res[0]["vertices"], res[0]["bbox_diagonal"]))
                    if args.callgrind and not m["sequential"]:
                        cells += ["-", "-", "-"]
                    elif args.callgrind:
                        ir = [instructions(drivers[k], path, m, args, work) for k in (0, 1)]
                        cells += ["%.4g" % ir[0], "%.4g" % ir[1], "%+.1f %%" % (100.0 * (ir[1] / ir[0] - 1))]
                    extra_rows[(spec, m["label"])] = cells
            header += (["distances"] if args.check else []) + \
                      (["base instructions", "new instructions", "change"] if args.callgrind else [])
        rows = []
        for spec, _ in meshes:
            for m in methods:
                base, new = times[(spec, m["label"])]
                faster = sum(1 for a, b in zip(base, new) if b < a)
                mb, mn = statistics.median(base), statistics.median(new)
                rows.append([spec, m["label"], "%.3f" % mb, "%.3f" % mn,
                             "%.3f" % (mn / mb) if mb > 0 else "-", "%d/%d" % (faster, len(base))]
                            + extra_rows.get((spec, m["label"]), []))
        print(rb.markdown_table(header, rows))
        if args.raw:
            with open(args.raw, "w") as f:
                f.write("# round revision mesh method seconds_solve windows_created\n" + "\n".join(raw) + "\n")
    finally:
        if not args.work:
            shutil.rmtree(work_folder, ignore_errors=True)


if __name__ == "__main__":
    main()
