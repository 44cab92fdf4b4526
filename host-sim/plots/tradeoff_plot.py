#!/usr/bin/env python3
"""Confirmation delay against false tracks in clutter, from a sweep directory.

Reads DIR/<tracker>@<param>=<value>/compare.json, each written by
`mptrack-sim compare --scenario S --trackers <tracker> ... --<kind>-param <param>=<value>`
(`./run tradeoff` makes them), and draws for each tracker one line through
its sweep points: x = false tracks per run first confirmed inside a Gaussian
clutter component (track_scores.false_tracks_in_clutter_per_run), y = the
chosen target's confirmation delay, each point labelled with its parameter
value; left panel the TTL (scans from birth to the first scan a confirmed
track covers, in the final estimates: a smoother's confirmation covers scans
back to the track's birth), right panel the real-time delay (scans from birth
to the first scan whose own step() handed out a confirmed track on it,
realtime_delay_scans: a smoother's provisional output). Lower-left is better.
Writes DIR/tradeoff.png and DIR/tradeoff.md (the same numbers).

Needs python3-matplotlib (Debian) for the PNG (`./run tradeoff` installs it).
"""
import argparse
import json
import os
import sys
from collections import defaultdict


def read_points(root, target):
    points = defaultdict(list)  # tracker -> [(value, param, ttl, ft_in_clutter, ft, never, realtime)]
    for name in sorted(os.listdir(root)):
        path = os.path.join(root, name, "compare.json")
        if "@" not in name or "=" not in name or not os.path.isfile(path):
            continue
        tracker, setting = name.split("@", 1)
        param, value = setting.split("=", 1)
        with open(path) as f:
            row = json.load(f)["rows"][0]
        ts = row["track_scores"]
        by_target = ts["by_target"].get(str(target))
        if by_target is None:
            sys.exit(f"{path}: no target {target} in track_scores.by_target")
        points[tracker].append((float(value), param, by_target["ttl_scans"],
                                ts["false_tracks_in_clutter_per_run"], ts["false_tracks_per_run"],
                                by_target["never_tracked"], by_target.get("realtime_delay_scans", float("nan"))))
    for p in points.values():
        p.sort()
    return points


def write_table(points, target, path):
    with open(path, "w") as f:
        f.write(f"| tracker | setting | target {target} TTL [scans] (runs never tracked) | real-time delay [scans] "
                "| false tracks in clutter / run | false tracks / run |\n|---|---|---:|---:|---:|---:|\n")
        for tracker, pts in points.items():
            for value, param, ttl, ftc, ft, never, rt in pts:
                f.write(f"| {tracker} | {param} = {value:g} | {ttl:.2f} ({never}) | {rt:.2f} | {ftc:.2f} | {ft:.2f} |\n")


def draw(points, target, title, path):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import matplotlib.ticker  # noqa: F401 (matplotlib.ticker below)

    fig, axes = plt.subplots(1, 2, figsize=(12, 4.8), sharex=True, sharey=True)
    panels = ((axes[0], 2, "in the final estimates (TTL)"), (axes[1], 6, "in real time (first report of its own scan)"))
    xs_all = [p[3] for pts in points.values() for p in pts if p[3] > 0]
    for ax, col, what in panels:
        for tracker, pts in points.items():
            xs = [p[3] for p in pts]
            ys = [p[col] for p in pts]
            ax.plot(xs, ys, marker="o", label=f"{tracker} ({pts[0][1]})")
            for p in pts:
                ax.annotate(f"{p[0]:g}", (p[3], p[col]), textcoords="offset points", xytext=(4, 4), fontsize=7)
        ax.set_xscale("log")
        if xs_all:
            ticks = [t for t in (0.1, 0.2, 0.5, 1, 2, 5, 10, 20, 50, 100, 200)
                     if min(xs_all) / 1.5 <= t <= max(xs_all) * 1.5]
            ax.set_xticks(ticks)
            ax.xaxis.set_major_formatter(matplotlib.ticker.FormatStrFormatter("%g"))
            ax.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
        ax.set_xlabel("false tracks per run first confirmed inside a clutter component")
        ax.set_title(what, fontsize=10)
        ax.grid(True, which="both", alpha=0.3)
    axes[0].set_ylabel(f"target {target}: scans from birth to a confirmed track")
    axes[1].legend(fontsize=8)
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("dir", help="sweep directory (./run tradeoff writes out/tradeoff)")
    ap.add_argument("--target", type=int, default=1, help="target id whose confirmation delay is plotted (default 1)")
    ap.add_argument("--title", default="confirmation delay against false tracks in clutter")
    a = ap.parse_args()
    points = read_points(a.dir, a.target)
    if not points:
        sys.exit(f"{a.dir}: no <tracker>@<param>=<value>/compare.json directories")
    write_table(points, a.target, os.path.join(a.dir, "tradeoff.md"))
    draw(points, a.target, a.title, os.path.join(a.dir, "tradeoff.png"))
    print(f"wrote {a.dir}/tradeoff.md, {a.dir}/tradeoff.png")


if __name__ == "__main__":
    main()
