"""ROC AUC of classifier scores (numpy only), shared by train_classifier.py,
quantise_classifier.py and dataset_auc.py so all report the same statistic on
the same rows."""
import numpy as np


def roc_auc(scores, labels):
    """Mann-Whitney AUC with midranks for ties: P(score of a target > score
    of a clutter plot), ties counted one half; labels 1 = target."""
    order = np.argsort(scores, kind="mergesort")
    s = scores[order]
    ranks = np.empty(len(s))
    i = 0
    while i < len(s):
        j = i
        while j + 1 < len(s) and s[j + 1] == s[i]:
            j += 1
        ranks[i:j + 1] = 0.5 * (i + j) + 1.0
        i = j + 1
    r = np.empty(len(s))
    r[order] = ranks
    pos = labels == 1
    n_pos, n_neg = pos.sum(), (~pos).sum()
    return float((r[pos].sum() - n_pos * (n_pos + 1) / 2.0) / (n_pos * n_neg))


def scored_rows(labels, rng, max_clutter):
    """Indices (sorted) of the rows an AUC is taken over: every target row and
    at most max_clutter clutter rows drawn without replacement by rng (a
    numpy Generator; the draw is skipped when there are no more than that)."""
    pos = np.flatnonzero(labels == 1)
    neg = np.flatnonzero(labels == 0)
    if len(neg) > max_clutter:
        neg = rng.choice(neg, max_clutter, replace=False)
    return np.sort(np.concatenate([pos, neg]))


def auc_by_scr(scores, labels, scr_db):
    """{"SCR": AUC} for every SCR value holding both classes."""
    out = {}
    for v in np.unique(scr_db):
        m = scr_db == v
        if labels[m].min() != labels[m].max():
            out[f"{v:g}"] = roc_auc(scores[m], labels[m])
    return out
