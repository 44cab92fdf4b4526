#!/usr/bin/env python3
"""The picture of one `mptrack-sim` run directory: DIR/plot.png.

Reads what the harness writes (host-sim/README.md, "Output files"):
DIR/truth.csv, DIR/tracks.csv, DIR/metrics.csv (run 0) and DIR/summary.json
(the OSPA of every run and the metric's real c and p), and draws

  left        x/y of run 0: each truth trajectory (line, start marked), the
              confirmed track positions (dots, one colour per track),
              zoomed to the data, axes in km
  right top   OSPA over scans: run 0 and, for several runs, the mean; the
              title carries the run's c and p
  right bottom number of confirmed tracks over scans against the truth

Needs python3-matplotlib (Debian); `./run demo` installs it. Usage:
  /usr/bin/python3 host-sim/plots/run_plot.py DIR [--out FILE]
"""
import argparse
import csv
import json
import os
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_csv(path, run=0):
    if not os.path.exists(path):
        return []
    with open(path, newline="") as f:
        return [r for r in csv.DictReader(f) if int(r["run"]) == run]


def metric_params(summary):
    o = summary.get("ospa", {})
    return o.get("cutoff_m"), o.get("order_p")


def xy_unit(truth, tracks):
    """km for wide scenes, m for small ones (seed 004's drones span tens of metres)."""
    v = [abs(float(r[k])) for r in truth + tracks for k in ("x", "y")]
    return (1e3, "km") if v and max(v) > 2000.0 else (1.0, "m")


def draw_xy(ax, truth, tracks):
    scale, unit = xy_unit(truth, tracks)
    by_target = defaultdict(list)
    for r in truth:
        by_target[r["target_id"]].append((int(r["scan"]), float(r["x"]) / scale, float(r["y"]) / scale))
    xs, ys = [], []
    for i, (tid, pts) in enumerate(sorted(by_target.items(), key=lambda kv: int(kv[0]))):
        pts.sort()
        x = [p[1] for p in pts]
        y = [p[2] for p in pts]
        ax.plot(x, y, "-", color="0.15", lw=1.4, label="truth" if i == 0 else None, zorder=3)
        ax.plot(x[0], y[0], "o", mfc="white", mec="0.15", ms=5, zorder=4,
                label="truth start" if i == 0 else None)
        xs += x
        ys += y
    by_track = defaultdict(list)
    for r in tracks:
        if r["confirmed"] == "1":
            by_track[r["track_id"]].append((float(r["x"]) / scale, float(r["y"]) / scale))
    cmap = plt.get_cmap("tab10")
    for i, (tid, pts) in enumerate(sorted(by_track.items(), key=lambda kv: int(kv[0]))):
        ax.plot([p[0] for p in pts], [p[1] for p in pts], ".", ms=3.5, color=cmap(i % 10),
                label="confirmed tracks" if i == 0 else None, zorder=2)
        xs += [p[0] for p in pts]
        ys += [p[1] for p in pts]
    if xs:
        # Zoom to the data (truth and tracks), a margin of 8 %, equal aspect.
        x0, x1, y0, y1 = min(xs), max(xs), min(ys), max(ys)
        span = max(x1 - x0, y1 - y0, 0.05 if unit == "km" else 5.0)
        cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
        half = 0.54 * span
        ax.set_xlim(cx - half, cx + half)
        ax.set_ylim(cy - half, cy + half)
    ax.set_aspect("equal", adjustable="box")
    ax.set_xlabel("x [%s]" % unit)
    ax.set_ylabel("y [%s]" % unit)
    ax.grid(True, color="0.9")
    ax.set_title("run 0: truth and confirmed tracks (%d tracks)" % len(by_track), fontsize=10)
    ax.legend(loc="best", fontsize=8, framealpha=0.9)


def draw_ospa(ax, metrics, summary):
    c, p = metric_params(summary)
    scans = [int(r["scan"]) for r in metrics]
    ax.plot(scans, [float(r["ospa"]) for r in metrics], color="tab:blue", lw=1.2, label="run 0")
    mean = summary.get("ospa_per_scan", [])
    runs = summary.get("runs", 1)
    if runs > 1 and mean:
        ax.plot(range(1, len(mean) + 1), mean, color="tab:orange", lw=1.2, label="mean of %d runs" % runs)
    if c is not None:
        ax.axhline(c, color="0.5", ls="--", lw=0.8, label="cutoff c = %g m" % c)
        top = max([float(r["ospa"]) for r in metrics] + mean + [0.0])
        # Zoom to the data; an all-zero curve (the oracle) is drawn against c.
        ax.set_ylim(0, c * 1.08 if (top <= 0.0 or top >= c) else top * 1.15)
    ax.set_xlabel("scan")
    ax.xaxis.get_major_locator().set_params(integer=True)
    ax.set_ylabel("OSPA [m]")
    title = "OSPA of confirmed tracks"
    if c is not None:
        title += " (p = %g, c = %g m)" % (p, c)
    ax.set_title(title, fontsize=10)
    ax.grid(True, color="0.9")
    ax.legend(loc="upper right", fontsize=8, framealpha=0.9)


def draw_cardinality(ax, metrics):
    scans = [int(r["scan"]) for r in metrics]
    ax.step(scans, [int(r["truths"]) for r in metrics], where="mid", color="0.15", lw=1.4, label="truth")
    ax.step(scans, [int(r["confirmed"]) for r in metrics], where="mid", color="tab:green", lw=1.2,
            label="confirmed tracks (run 0)")
    ax.set_xlabel("scan")
    ax.set_ylabel("number of objects")
    ax.yaxis.get_major_locator().set_params(integer=True)
    n = max([int(r["truths"]) for r in metrics] + [int(r["confirmed"]) for r in metrics] + [1])
    ax.set_ylim(-0.3, n + 0.7)
    ax.set_title("cardinality over time", fontsize=10)
    ax.grid(True, color="0.9")
    ax.legend(loc="best", fontsize=8, framealpha=0.9)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("dir")
    ap.add_argument("--out", help="output file (default DIR/plot.png)")
    a = ap.parse_args()
    with open(os.path.join(a.dir, "summary.json")) as f:
        summary = json.load(f)
    truth = read_csv(os.path.join(a.dir, "truth.csv"))
    tracks = read_csv(os.path.join(a.dir, "tracks.csv"))
    metrics = read_csv(os.path.join(a.dir, "metrics.csv"))
    if not metrics:
        sys.exit("%s/metrics.csv: no rows of run 0 (was the run written with --csv-runs 0?)" % a.dir)
    fig = plt.figure(figsize=(13, 6.2), dpi=110)
    gs = fig.add_gridspec(2, 2, width_ratios=[1.05, 1.0], hspace=0.42, wspace=0.22)
    draw_xy(fig.add_subplot(gs[:, 0]), truth, tracks)
    draw_ospa(fig.add_subplot(gs[0, 1]), metrics, summary)
    draw_cardinality(fig.add_subplot(gs[1, 1]), metrics)
    fig.suptitle("%s / %s: %d run(s), %d scans, mean OSPA %.2f m" % (
        summary.get("scenario", "?"), summary.get("tracker", "?"), summary.get("runs", 1),
        summary.get("scans", len(metrics)), summary.get("mean_ospa", float("nan"))), fontsize=11)
    out = a.out or os.path.join(a.dir, "plot.png")
    fig.savefig(out, bbox_inches="tight")
    print("wrote %s" % out)


if __name__ == "__main__":
    main()
