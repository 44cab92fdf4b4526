#!/usr/bin/env python3
"""Seed 004's figures from a raw-frame `mptrack-sim compare` directory.

Reads DIR/frames.csv, DIR/rmse.csv and DIR/compare.json (written by
`mptrack-sim compare --scenario seed004-drones ...`) and draws, one line per
tracker, the three plots seed 004 shows for its VMP tracker against the
detect-then-track baseline:

  DIR/ospa.png        mean OSPA over frames (Fig. 4), the scenario's phases shaded
  DIR/cardinality.png mean confirmed-track count +-3 std over runs, with the truth
  DIR/rmse_ecdf.png   empirical CDF of the per-(run, object) RMSE (Fig. 5)

Needs python3-matplotlib (Debian); `./run figures DIR` installs it.
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


def read_frames(path):
    rows = defaultdict(lambda: defaultdict(list))
    with open(path, newline="") as f:
        for r in csv.DictReader(f):
            t = rows[r["tracker"]]
            for key in ("frame", "ospa_mean_m", "confirmed_mean", "confirmed_std", "truths_mean"):
                t[key].append(float(r[key]))
    return rows


def read_rmse(path):
    rows = defaultdict(list)
    with open(path, newline="") as f:
        for r in csv.DictReader(f):
            rows[r["tracker"]].append(float(r["rmse_m"]))
    return rows


def header(summary):
    s = summary[0]
    return s["scenario"], s["runs"]


def shade_phases(ax, phases):
    for i, p in enumerate(phases):
        if p["name"].startswith("frames_"):
            continue
        a, b = p["frames"]
        ax.axvspan(a - 0.5, b + 0.5, color="0.92" if i % 2 else "0.86", zorder=0)
        ax.text((a + b) / 2, 0.98, p["name"].replace("_", " "), transform=ax.get_xaxis_transform(),
                ha="center", va="top", fontsize=7, color="0.35", rotation=90)


def plot_ospa(out, frames, scenario, runs, cutoff, phases):
    fig, ax = plt.subplots(figsize=(9, 4.5))
    shade_phases(ax, phases)
    for name, t in frames.items():
        ax.plot(t["frame"], t["ospa_mean_m"], label=name, linewidth=1.6)
    ax.set_xlabel("frame n (10 Hz)")
    ax.set_ylabel(f"mean OSPA [m]  (c = {cutoff:g} m, p = 2)")
    ax.set_ylim(0, cutoff * 1.02)
    ax.set_xlim(1, max(max(t["frame"]) for t in frames.values()))
    ax.set_title(f"{scenario}: OSPA over frames, mean of {runs} runs")
    ax.grid(True, alpha=0.3)
    ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=9)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    plt.close(fig)


def plot_cardinality(out, frames, scenario, runs):
    names = list(frames)
    fig, axes = plt.subplots(len(names), 1, figsize=(9, 1.9 * len(names) + 0.6), sharex=True, squeeze=False)
    for ax, name in zip(axes[:, 0], names):
        t = frames[name]
        lo = [m - 3 * s for m, s in zip(t["confirmed_mean"], t["confirmed_std"])]
        hi = [m + 3 * s for m, s in zip(t["confirmed_mean"], t["confirmed_std"])]
        ax.fill_between(t["frame"], lo, hi, alpha=0.25, label="mean +- 3 std")
        ax.plot(t["frame"], t["confirmed_mean"], linewidth=1.5, label="mean confirmed tracks")
        ax.step(t["frame"], t["truths_mean"], where="mid", color="k", linewidth=1.0, label="truth")
        ax.set_ylabel(name)
        ax.set_ylim(-0.5, 5.5)
        ax.grid(True, alpha=0.3)
    axes[0, 0].legend(loc="upper left", ncol=3, fontsize=8)
    axes[-1, 0].set_xlabel("frame n (10 Hz)")
    fig.suptitle(f"{scenario}: number of confirmed tracks, {runs} runs")
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    plt.close(fig)


def plot_rmse_ecdf(out, rmse, scenario, runs):
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    hi = 0.0
    for name, values in rmse.items():
        v = sorted(values)
        if not v:
            continue
        y = [(i + 1) / len(v) for i in range(len(v))]
        ax.step(v, y, where="post", label=f"{name} (n = {len(v)})", linewidth=1.6)
        hi = max(hi, v[int(0.99 * (len(v) - 1))])
    ax.axhline(0.9, color="0.5", linestyle=":", linewidth=1)
    ax.set_xlim(0, max(hi * 1.1, 0.5))
    ax.set_ylim(0, 1.0)
    ax.set_xlabel("per-object position RMSE [m] (frames matched within c)")
    ax.set_ylabel("empirical CDF")
    ax.set_title(f"{scenario}: RMSE of tracked objects, {runs} runs")
    ax.grid(True, alpha=0.3)
    ax.legend(loc="lower right", fontsize=9)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    plt.close(fig)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("dir", help="output directory of a raw-frame `mptrack-sim compare`")
    a = ap.parse_args()
    try:
        frames = read_frames(os.path.join(a.dir, "frames.csv"))
        rmse = read_rmse(os.path.join(a.dir, "rmse.csv"))
        with open(os.path.join(a.dir, "compare.json")) as f:
            summary = json.load(f)
    except (OSError, KeyError, ValueError) as e:
        sys.exit(f"compare_figures: {a.dir}: {e}")
    scenario, runs = header(summary)
    cutoff = summary[0]["ospa"]["cutoff_m"]
    phases = summary[0].get("phases", [])
    plot_ospa(os.path.join(a.dir, "ospa.png"), frames, scenario, runs, cutoff, phases)
    plot_cardinality(os.path.join(a.dir, "cardinality.png"), frames, scenario, runs)
    plot_rmse_ecdf(os.path.join(a.dir, "rmse_ecdf.png"), rmse, scenario, runs)
    print(f"wrote {a.dir}/ospa.png, cardinality.png, rmse_ecdf.png")


if __name__ == "__main__":
    main()
