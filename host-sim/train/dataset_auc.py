#!/usr/bin/python3
"""ROC AUC of the committed float classifier on one dataset, per SCR.

Scores every target patch and a seeded subsample of the clutter patches of a
dataset directory written by `mptrack-sim dataset` (roc.scored_rows, the
rows train_classifier.py and quantise_classifier.py score), with the belief
input at 0.5 (the patch alone, as MP-NN's removal and the birth veto use it)
and with the belief NEMP recorded for the patch. Use it to ask how well the classifier carries over to
a sea state it was not trained on (docs/algorithms/sea_clutter.md §Results):

  mptrack-sim dataset --scenario seed003-sea-c --runs 3 --run-offset 1000 --out DIR
  host-sim/train/dataset_auc.py DIR

Needs only numpy: the network is read from the generated float header.
"""
import argparse
import json

import numpy as np

from quantise_classifier import FLOAT_HEADER, batched, float_layers, load, mlp, parse_float_header, sigmoid
from roc import auc_by_scr, roc_auc, scored_rows  # same directory


def auc_table(labels, scr_db, prob_half, prob_nemp):
    rows = {}
    half, nemp = auc_by_scr(prob_half, labels, scr_db), auc_by_scr(prob_nemp, labels, scr_db)
    for v in np.unique(scr_db):
        key = f"{v:g}"
        if key in half:
            rows[key] = {"belief_0.5": half[key], "nemp_belief": nemp[key], "targets": int(labels[scr_db == v].sum())}
    rows["all"] = {"belief_0.5": roc_auc(prob_half, labels), "nemp_belief": roc_auc(prob_nemp, labels),
                   "targets": int(labels.sum()), "clutter_scored": int(len(labels) - labels.sum())}
    return rows


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("dataset", help="dataset dir (mptrack-sim dataset)")
    ap.add_argument("--seed", type=int, default=3, help="seed of the clutter subsample")
    ap.add_argument("--max-clutter", type=int, default=4000, help="clutter patches scored")
    a = ap.parse_args()
    fw = parse_float_header(FLOAT_HEADER)
    data = load(a.dataset)
    idx = scored_rows(data["labels"], np.random.default_rng(a.seed), a.max_clutter)
    feats = sigmoid(batched(lambda c: float_layers(fw, c)[-1], data["patches"][idx]))
    prob_half = mlp(fw, feats, np.full(len(idx), 0.5))
    prob_nemp = mlp(fw, feats, data["belief"][idx].astype(np.float64))
    print(json.dumps(auc_table(data["labels"][idx], data["scr_db"][idx], prob_half, prob_nemp), indent=2))


if __name__ == "__main__":
    main()
