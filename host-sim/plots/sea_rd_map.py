#!/usr/bin/env python3
"""Range-Doppler map of one seed 003 sea scene with its detections and tracks.

Reads what `mptrack-sim --scenario seed003-sea-a|b --tracker T --out DIR`
writes (host-sim/src/sea_runner.h): DIR/rd_map.npy (run 0's map of one scan,
float32 [range][Doppler] in dB, fftshifted), DIR/rd_map.json (its axes),
DIR/sea_detections.csv (run 0's plots with Doppler and origin), DIR/truth.csv
and DIR/tracks.csv (x = range, vx = range rate). Draws DIR/rd_map.png:

  left   the map of that scan (dB relative to its median), the scan's plots
         (circles: clutter, squares: target-generated), the true targets
         (crosses) and the confirmed tracks at that scan (triangles, labelled
         with their id)
  right  range over scans of run 0: every plot (grey), truth (lines) and
         confirmed tracks (coloured markers)

Needs python3-matplotlib and python3-numpy (Debian). Usage:
  /usr/bin/python3 host-sim/plots/sea_rd_map.py DIR [--out FILE]
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
import numpy as np  # noqa: E402


def rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("dir")
    ap.add_argument("--out", default=None)
    a = ap.parse_args()
    meta = json.load(open(os.path.join(a.dir, "rd_map.json")))
    rd = np.load(os.path.join(a.dir, "rd_map.npy"))
    lam = meta["wavelength_m"]
    scan = meta["scan"]
    nd, dhz, rbin = meta["doppler_bins"], meta["doppler_bin_hz"], meta["range_bin_m"]

    def doppler_hz(range_rate):
        return -2.0 * range_rate / lam

    dets = [r for r in rows(os.path.join(a.dir, "sea_detections.csv")) if r["run"] == "0"]
    truth = [r for r in rows(os.path.join(a.dir, "truth.csv")) if r["run"] == "0"]
    tracks = [r for r in rows(os.path.join(a.dir, "tracks.csv")) if r["run"] == "0" and r["confirmed"] == "1"]

    fig, (ax, ax2) = plt.subplots(1, 2, figsize=(14, 6), gridspec_kw={"width_ratios": [1.4, 1]})
    img = rd - np.median(rd)
    extent = [(-nd / 2 - 0.5) * dhz, (nd / 2 - 0.5) * dhz, (rd.shape[0] - 0.5) * rbin, -0.5 * rbin]
    im = ax.imshow(img, aspect="auto", extent=extent, cmap="viridis", vmin=-5, vmax=40, interpolation="nearest")
    fig.colorbar(im, ax=ax, label="power re median [dB]")
    sd = [r for r in dets if int(r["scan"]) == scan]
    clutter = [r for r in sd if r["target_id"] == "0"]
    target = [r for r in sd if r["target_id"] != "0"]
    ax.scatter([float(r["doppler_hz"]) for r in clutter], [float(r["range_m"]) for r in clutter], s=30,
               facecolors="none", edgecolors="white", linewidths=0.8, label="plot (clutter)")
    ax.scatter([float(r["doppler_hz"]) for r in target], [float(r["range_m"]) for r in target], s=50, marker="s",
               facecolors="none", edgecolors="red", linewidths=1.2, label="plot (target)")
    st = [r for r in truth if int(r["scan"]) == scan]
    ax.scatter([doppler_hz(float(r["vx"])) for r in st], [float(r["x"]) for r in st], marker="x", c="red", s=60,
               label="truth")
    sk = [r for r in tracks if int(r["scan"]) == scan]
    ax.scatter([doppler_hz(float(r["vx"])) for r in sk], [float(r["x"]) for r in sk], marker="^", c="orange", s=60,
               label="confirmed track")
    for r in sk:
        ax.annotate(r["track_id"], (doppler_hz(float(r["vx"])), float(r["x"])), color="orange", fontsize=8,
                    xytext=(4, 4), textcoords="offset points")
    ax.set_xlabel("Doppler [Hz]")
    ax.set_ylabel("range [m]")
    ax.set_title("%s, SCR %g dB, run 0 scan %d" % (meta["scenario"], meta["scr_db"], scan))
    ax.legend(loc="lower left", fontsize=8, framealpha=0.6)

    ax2.scatter([int(r["scan"]) for r in dets], [float(r["range_m"]) for r in dets], s=4, c="0.7", label="plots")
    by_target = defaultdict(list)
    for r in truth:
        by_target[r["target_id"]].append((int(r["scan"]), float(r["x"])))
    for tid, pts in sorted(by_target.items()):
        pts.sort()
        ax2.plot([p[0] for p in pts], [p[1] for p in pts], "k-", lw=1)
    by_track = defaultdict(list)
    for r in tracks:
        by_track[r["track_id"]].append((int(r["scan"]), float(r["x"])))
    for tid, pts in sorted(by_track.items()):
        ax2.plot([p[0] for p in pts], [p[1] for p in pts], "o", ms=4, label="track %s" % tid)
    ax2.set_xlabel("scan")
    ax2.set_ylabel("range [m]")
    ax2.set_title("run 0: plots, truth (lines), confirmed tracks")
    if len(by_track) <= 12:
        ax2.legend(fontsize=7, loc="upper right")
    fig.tight_layout()
    out = a.out or os.path.join(a.dir, "rd_map.png")
    fig.savefig(out, dpi=110)
    print("wrote", out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
