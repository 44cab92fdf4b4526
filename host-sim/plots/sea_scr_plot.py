#!/usr/bin/env python3
"""AMOTA and MOSPA over SCR of MP, MP-NN and NEMP on one or more sea states.

Reads the compare.json that `mptrack-sim compare --scenario seed003-sea-X
--out DIR` writes (host-sim/src/sea_report.cpp) for each DIR given, and draws
one column per sea state: AMOTA (top), MOSPA with the Mahalanobis base
distance (middle) and NEMP - MP-NN paired over runs with two standard errors
(bottom; AMOTA, and the mean over all SCRs in the legend). The same runs and
seeds as the tables, so the figure and docs/results/seed003.md agree.

Needs python3-matplotlib (Debian). Usage:
  /usr/bin/python3 host-sim/plots/sea_scr_plot.py DIR [DIR ...] --out FILE.png
"""
import argparse
import json
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

NAMES = {"mfbp": "MP", "mfbp-nn": "MP-NN", "nemp": "NEMP"}
STYLE = {"mfbp": ("tab:gray", "s"), "mfbp-nn": ("tab:blue", "o"), "nemp": ("tab:red", "^")}


def load(directory):
    with open(os.path.join(directory, "compare.json")) as f:
        return json.load(f)


def series(c, tracker, key):
    xs, ys = [], []
    for level in c["levels"]:
        for row in level["rows"]:
            if row["tracker"] == tracker and isinstance(row.get(key), (int, float)):
                xs.append(level["scr_db"])
                ys.append(row[key])
    return xs, ys


def draw_state(axes, c):
    top, mid, low = axes
    trackers = [r["tracker"] for r in c["levels"][0]["rows"]]
    for t in trackers:
        colour, marker = STYLE.get(t, ("black", "x"))
        for ax, key in ((top, "amota"), (mid, "mospa_mahalanobis")):
            xs, ys = series(c, t, key)
            ax.plot(xs, ys, marker=marker, color=colour, label=NAMES.get(t, t))
    xs, means, errs = [], [], []
    for level in c["levels"]:
        d = level.get("nemp_minus_mfbp_nn", {}).get("amota")
        if d:
            xs.append(level["scr_db"])
            means.append(d["mean"])
            errs.append(2.0 * d["standard_error"])
    if xs:
        over = c.get("nemp_minus_mfbp_nn_over_scr", {}).get("amota")
        label = "NEMP - MP-NN, ± 2 SE"
        if over:
            label += f"\n(all SCRs {over['mean']:+.3f} ± {2 * over['standard_error']:.3f})"
        low.errorbar(xs, means, yerr=errs, marker="^", color="tab:red", capsize=3, label=label)
        low.axhline(0.0, color="black", linewidth=0.8)
    top.set_title(f"{c['scenario']} ({c['runs']} runs per SCR)")
    top.set_ylabel("AMOTA (higher is better)")
    mid.set_ylabel("MOSPA (lower is better)")
    low.set_ylabel("AMOTA gain of NEMP")
    low.set_xlabel("SCR [dB]")
    for ax in axes:
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=8)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("dirs", nargs="+", help="compare output directories (compare.json)")
    ap.add_argument("--out", required=True, help="PNG to write")
    a = ap.parse_args()
    states = [load(d) for d in a.dirs]
    fig, axes = plt.subplots(3, len(states), figsize=(5.2 * len(states), 10), squeeze=False, sharex=True)
    for i, c in enumerate(states):
        draw_state([axes[0][i], axes[1][i], axes[2][i]], c)
    for row in range(3):  # one y scale per row, so the sea states compare at a glance
        lo = min(axes[row][i].get_ylim()[0] for i in range(len(states)))
        hi = max(axes[row][i].get_ylim()[1] for i in range(len(states)))
        for i in range(len(states)):
            axes[row][i].set_ylim(lo, hi)
    fig.tight_layout()
    fig.savefig(a.out, dpi=110)
    print(f"wrote {a.out}")


if __name__ == "__main__":
    main()
