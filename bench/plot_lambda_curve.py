#!/usr/bin/env python3
"""Plots AVTP's mean relative error and time against lambda (thesis figure 4.11).

Reads the CSV written by the lambda section of run_benchmarks.py (one row per mesh and lambda)
and draws two log-log panels: the mean relative error (%) against lambda, and the time (s)
against lambda with VTP's time as a dashed line of the same colour. Errors of exactly 0 (lambda
so large that the wavefront is never reset) cannot be drawn on a log axis and are left out.

  python3 bench/plot_lambda_curve.py [bench/results/lambda_curve.csv] [-o bench/results/lambda_curve.png]

Needs matplotlib (`apt-get install -y python3-matplotlib`, for /usr/bin/python3); exits 1 when
it cannot be imported.
"""

import argparse
import csv
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
DEFAULT_CSV = HERE / "results" / "lambda_curve.csv"


def number(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return None


def lambda_axes(ax, ticks, xlabel):
    """Log-log axes over lambda, a tick at each lambda measured (shared with doc/make_figures.py)."""
    import matplotlib.ticker
    ax.set_xscale("log", base=2)
    ax.set_yscale("log")
    ax.set_xticks(ticks)
    ax.set_xticklabels(["%g" % t for t in ticks])
    ax.xaxis.set_minor_locator(matplotlib.ticker.NullLocator())
    ax.set_xlabel(xlabel)
    ax.grid(True, which="both", alpha=0.3)


def read_curves(path):
    """{mesh label: {'vertices', 'lambda': [...], 'error': [...], 'seconds': [...], 'vtp_seconds'}}."""
    curves = {}
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            if row.get("status", "ok") != "ok":
                continue
            c = curves.setdefault(row["mesh"], {"vertices": row.get("vertices"), "lambda": [], "error": [],
                                                "seconds": [], "vtp_seconds": number(row.get("vtp_seconds_total"))})
            c["lambda"].append(number(row["lambda"]))
            c["error"].append(number(row["mean_rel_error_percent"]))
            c["seconds"].append(number(row["seconds_total"]))
    for c in curves.values():
        order = sorted(range(len(c["lambda"])), key=lambda i: c["lambda"][i])
        for k in ("lambda", "error", "seconds"):
            c[k] = [c[k][i] for i in order]
    return curves


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("csv", nargs="?", default=str(DEFAULT_CSV), help="the CSV (default: %(default)s)")
    p.add_argument("-o", "--output", help="the image (default: the CSV's name with .png)")
    args = p.parse_args()

    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        import matplotlib.ticker
    except ImportError as e:
        print("plot_lambda_curve.py: matplotlib cannot be imported by %s (%s); install it with "
              "`apt-get install -y python3-matplotlib` and run this script with /usr/bin/python3"
              % (sys.executable, e), file=sys.stderr)
        return 1

    curves = read_curves(args.csv)
    if not curves:
        print("plot_lambda_curve.py: no successful row in %s" % args.csv, file=sys.stderr)
        return 1
    output = Path(args.output) if args.output else Path(args.csv).with_suffix(".png")

    fig, (ax_err, ax_time) = plt.subplots(1, 2, figsize=(11, 4.5))
    exact = []  # (mesh, lambda) whose error is 0: never reset, not drawn on the log axis
    for k, (mesh, c) in enumerate(curves.items()):
        color = "C%d" % k
        label = "%s (%s vertices)" % (mesh, "{:,}".format(int(c["vertices"]))) if c["vertices"] else mesh
        pts = [(l, e) for l, e in zip(c["lambda"], c["error"]) if l and e and e > 0]
        zeros = [l for l, e in zip(c["lambda"], c["error"]) if l and e == 0]
        if zeros:
            exact.append("%s: λ ≥ %g" % (mesh, min(zeros)))
        if pts:
            ax_err.plot([x for x, _ in pts], [y for _, y in pts], "o-", color=color, label=label)
        pts = [(l, s) for l, s in zip(c["lambda"], c["seconds"]) if l and s and s > 0]
        if pts:
            ax_time.plot([x for x, _ in pts], [y for _, y in pts], "o-", color=color, label="AVTP, " + label)
        if c["vtp_seconds"]:
            ax_time.axhline(c["vtp_seconds"], color=color, linestyle="--", linewidth=1, label="VTP, " + mesh)
    ticks = sorted({l for c in curves.values() for l in c["lambda"] if l})
    for ax in (ax_err, ax_time):
        lambda_axes(ax, ticks, "λ (reset step, in mean edge lengths)")
        ax.legend(fontsize=8)
    ax_err.set_ylabel("mean relative error (%)")
    ax_err.set_title("AVTP: mean relative error against VTP")
    if exact:
        ax_err.text(0.02, 0.02, "error 0 (exact, not drawn): " + "; ".join(exact), transform=ax_err.transAxes,
                    fontsize=7, va="bottom")
    ax_time.set_ylabel("time (s)")
    ax_time.set_title("AVTP: time (setup + propagation)")
    fig.tight_layout()
    output.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(str(output), dpi=120)
    print("plot_lambda_curve.py: wrote %s" % output)
    return 0


if __name__ == "__main__":
    sys.exit(main())
