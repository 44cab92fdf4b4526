"""ROC AUC of classifier scores (numpy only), shared by train_classifier.py
and quantise_classifier.py so both report the same statistic."""
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
