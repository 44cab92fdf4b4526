#!/usr/bin/python3
"""Seed 003 range-Doppler patch classifier: training and export.

Trains the CNN feature extractor g_M and the classifier MLP g_c of
docs/algorithms/sea_clutter.md §Classifier (architecture table there) on
`mptrack-sim dataset` output, in two stages (seed 003 Sec. III-D, eq. (23)):
  1. CNN + a temporary head 8 -> 8 (ReLU) -> 1 (Sigmoid) that takes the
     8 CNN features directly (no first MLP layer, no tracker belief);
  2. the MLP 9 -> 16 -> 8 -> 1 on [8 CNN features, tracker belief], with the
     CNN fine-tuned at a tenth of the learning rate.
Balanced classes: each epoch draws every target patch and as many clutter
patches (without replacement, fresh each epoch). Binary cross-entropy.
Reproducible: one seed drives numpy and torch, deterministic algorithms,
fixed thread count.

Exports (BN folded into the convolutions, float32 written as C99 hex floats):
  core/include/mptrack/classify/generated/sea_classifier_weights.h
  tests/data/classifier_reference.h  (16 held-out patches, their 8 features
                                      and the MLP output at beliefs 0.2/0.5/0.8)
  host-sim/train/results.json        (ROC AUC in/out of domain, sizes)
"""
import argparse
import json
import os
import sys
import time

import numpy as np
import torch
from torch import nn

from roc import auc_by_scr, roc_auc, scored_rows  # same directory

REF_BELIEFS = (0.2, 0.5, 0.8)


class FeatureCnn(nn.Module):
    """g_M: 1x5x512 -> 8 features in [0, 1]."""

    def __init__(self):
        super().__init__()
        self.conv1 = nn.Conv2d(1, 8, (3, 7), padding=(1, 3))
        self.bn1 = nn.BatchNorm2d(8)
        self.pool1 = nn.MaxPool2d((1, 4))
        self.conv2 = nn.Conv2d(8, 16, (3, 5), padding=(1, 2))
        self.bn2 = nn.BatchNorm2d(16)
        self.pool2 = nn.MaxPool2d((1, 4))
        self.conv3 = nn.Conv2d(16, 16, (3, 3), padding=(1, 1))
        self.bn3 = nn.BatchNorm2d(16)
        self.pool3 = nn.MaxPool2d((5, 4))
        self.fc1 = nn.Linear(128, 32)
        self.fc2 = nn.Linear(32, 16)
        self.fc3 = nn.Linear(16, 8)

    def forward(self, x):
        x = self.pool1(torch.relu(self.bn1(self.conv1(x))))
        x = self.pool2(torch.relu(self.bn2(self.conv2(x))))
        x = self.pool3(torch.relu(self.bn3(self.conv3(x))))
        x = torch.flatten(x, 1)  # [c][h][w] order: 16 x 1 x 8
        x = torch.relu(self.fc1(x))
        x = torch.relu(self.fc2(x))
        return torch.sigmoid(self.fc3(x))


class ClassifierMlp(nn.Module):
    """g_c: [8 features, belief] -> P(target-generated)."""

    def __init__(self):
        super().__init__()
        self.mlp1 = nn.Linear(9, 16)
        self.mlp2 = nn.Linear(16, 8)
        self.mlp3 = nn.Linear(8, 1)

    def forward(self, f, belief):
        x = torch.cat([f, belief.unsqueeze(1)], 1)
        x = torch.relu(self.mlp1(x))
        x = torch.relu(self.mlp2(x))
        return torch.sigmoid(self.mlp3(x)).squeeze(1)


class Stage1Head(nn.Module):
    """Temporary head of stage 1: the 8 features straight into 8 -> 8 -> 1."""

    def __init__(self):
        super().__init__()
        self.a = nn.Linear(8, 8)
        self.b = nn.Linear(8, 1)

    def forward(self, f):
        return torch.sigmoid(self.b(torch.relu(self.a(f)))).squeeze(1)


def load(dirname):
    d = {k: np.load(os.path.join(dirname, k + ".npy")) for k in
         ("patches", "labels", "scr_db", "scene", "run", "belief")}
    d["meta"] = json.load(open(os.path.join(dirname, "meta.json")))
    return d


def to_input(patches_u8, offset, scale):
    x = (torch.from_numpy(patches_u8.astype(np.float32)) - offset) * scale
    return x.unsqueeze(1)


def balanced_epoch(labels, rng):
    pos = np.flatnonzero(labels == 1)
    neg = np.flatnonzero(labels == 0)
    k = min(len(pos), len(neg))
    idx = np.concatenate([rng.choice(pos, k, replace=False), rng.choice(neg, k, replace=False)])
    rng.shuffle(idx)
    return idx


def run_epochs(stage, params, forward, data, norm, epochs, lr, batch, rng, mask_fn=None, belief_dropout=0.0):
    opt = torch.optim.Adam(params, lr=lr)
    loss_fn = nn.BCELoss()
    for ep in range(epochs):
        idx = balanced_epoch(data["labels"], rng)
        total = 0.0
        for s in range(0, len(idx), batch):
            b = idx[s:s + batch]
            x = to_input(data["patches"][b], *norm)
            y = torch.from_numpy(data["labels"][b].astype(np.float32))
            w = data["belief"][b].astype(np.float32)
            # Belief dropout: a share of the patches is seen with the
            # uninformative belief 0.5, the input MP-NN's removal and NEMP's
            # birth veto give the network, so that it stays a patch-only
            # classifier there (docs/algorithms/sea_clutter.md §Training).
            if belief_dropout > 0.0:
                w = np.where(rng.random(len(b)) < belief_dropout, np.float32(0.5), w)
            w = torch.from_numpy(w)
            opt.zero_grad()
            loss = loss_fn(forward(x, w), y)
            loss.backward()
            if mask_fn is not None:
                mask_fn()
            opt.step()
            total += float(loss) * len(b)
        print(f"stage {stage} epoch {ep + 1}/{epochs}: loss {total / len(idx):.4f} ({len(idx)} patches,"
              f" {time.process_time():.0f} s CPU)", flush=True)


def evaluate(cnn, mlp, data, norm, rng, max_clutter, fixed_belief=None):
    idx = scored_rows(data["labels"], rng, max_clutter)
    out = []
    with torch.no_grad():
        for s in range(0, len(idx), 1024):
            b = idx[s:s + 1024]
            w = torch.from_numpy(data["belief"][b].astype(np.float32))
            if fixed_belief is not None:
                w = torch.full((len(b),), fixed_belief, dtype=torch.float32)
            out.append(mlp(cnn(to_input(data["patches"][b], *norm)), w).numpy())
    scores = np.concatenate(out)
    labels = data["labels"][idx]
    res = {"auc": roc_auc(scores, labels), "targets": int(labels.sum()),
           "clutter_scored": int(len(labels) - labels.sum()), "rows": int(len(data["labels"]))}
    res["auc_per_scr_db"] = auc_by_scr(scores, labels, data["scr_db"][idx])
    return res


def fold_bn(conv, bn):
    """Conv weight/bias with eval-mode BN folded in (float64 maths, float32 result)."""
    w = conv.weight.detach().double()
    b = conv.bias.detach().double()
    g = bn.weight.detach().double() / torch.sqrt(bn.running_var.double() + bn.eps)
    wf = (w * g.view(-1, 1, 1, 1)).float()
    bf = ((b - bn.running_mean.double()) * g + bn.bias.detach().double()).float()
    return wf, bf


class FoldedCnn(nn.Module):
    """The exported network: the folded convolutions, as the board runs it."""

    def __init__(self, cnn):
        super().__init__()
        self.convs = nn.ModuleList()
        for conv, bn in ((cnn.conv1, cnn.bn1), (cnn.conv2, cnn.bn2), (cnn.conv3, cnn.bn3)):
            c = nn.Conv2d(conv.in_channels, conv.out_channels, conv.kernel_size, padding=conv.padding)
            wf, bf = fold_bn(conv, bn)
            c.weight.data.copy_(wf)
            c.bias.data.copy_(bf)
            self.convs.append(c)
        self.pools = [cnn.pool1, cnn.pool2, cnn.pool3]
        self.fc = [cnn.fc1, cnn.fc2, cnn.fc3]

    def forward(self, x):
        for c, p in zip(self.convs, self.pools):
            x = p(torch.relu(c(x)))
        x = torch.flatten(x, 1)
        x = torch.relu(self.fc[0](x))
        x = torch.relu(self.fc[1](x))
        return torch.sigmoid(self.fc[2](x))


def hexf(v):
    v = float(np.float32(v))
    h = float.hex(v)  # exact: a float32 value is a double
    mant, exp = h.split("p")
    if "." in mant:
        mant = mant.rstrip("0").rstrip(".")
    return mant + "p" + exp + "f"


def c_array(name, values, per_line=6, ctype="float"):
    vals = np.asarray(values).ravel()
    if ctype == "float":
        items = [hexf(v) for v in vals]
    else:
        items = [str(int(v)) for v in vals]
        per_line = 24
    lines = [", ".join(items[i:i + per_line]) for i in range(0, len(items), per_line)]
    body = ",\n    ".join(lines)
    return f"inline constexpr {ctype} {name}[{len(vals)}] = {{\n    {body}}};\n"


def write_header(path, folded, mlp, norm, target_fraction, info):
    offset, scale = norm
    arrays = [("kConv1Weight", folded.convs[0].weight), ("kConv1Bias", folded.convs[0].bias),
              ("kConv2Weight", folded.convs[1].weight), ("kConv2Bias", folded.convs[1].bias),
              ("kConv3Weight", folded.convs[2].weight), ("kConv3Bias", folded.convs[2].bias),
              ("kFc1Weight", folded.fc[0].weight), ("kFc1Bias", folded.fc[0].bias),
              ("kFc2Weight", folded.fc[1].weight), ("kFc2Bias", folded.fc[1].bias),
              ("kFc3Weight", folded.fc[2].weight), ("kFc3Bias", folded.fc[2].bias),
              ("kMlp1Weight", mlp.mlp1.weight), ("kMlp1Bias", mlp.mlp1.bias),
              ("kMlp2Weight", mlp.mlp2.weight), ("kMlp2Bias", mlp.mlp2.bias),
              ("kMlp3Weight", mlp.mlp3.weight), ("kMlp3Bias", mlp.mlp3.bias)]
    out = ["// GENERATED by host-sim/train/train_classifier.py (./run train-classifier); do not edit.",
           "// Seed 003 range-Doppler patch classifier (docs/algorithms/sea_clutter.md §Classifier):",
           "// CNN g_M with BatchNorm folded into the convolutions, then the MLP g_c.",
           "// Layouts as PyTorch: conv [out][in][kh][kw], linear [out][in]; MLP input =",
           "// 8 CNN features then the tracker belief. Network input = (patch code - kInputOffset)",
           "// * kInputScale, patch codes 0..255 from seaclutter::PatchExtractor.",
           f"// Training: {info}",
           "#pragma once", "", "namespace mptrack::classify::generated {", "",
           f"inline constexpr float kInputOffset = {hexf(offset)};  // {offset:.9g}",
           f"inline constexpr float kInputScale = {hexf(scale)};  // {scale:.9g}",
           f"inline constexpr float kTrainTargetFraction = {hexf(target_fraction)};  // {target_fraction:.9g}",
           ""]
    for name, t in arrays:
        out.append(c_array(name, t.detach().float().numpy()))
    out.append("}  // namespace mptrack::classify::generated\n")
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write("\n".join(out))


def write_reference(path, patches, labels, feats, outs):
    n = len(labels)
    out = ["// GENERATED by host-sim/train/train_classifier.py (./run train-classifier); do not edit.",
           "// Reference data for the core classifier inference: held-out seed003-sea-a patches",
           "// (codes 0..255, [patch][range 5][doppler 512]), their 8 CNN features and the MLP",
           "// output at kBeliefs, as PyTorch (float32, CPU) computes them with the weights of",
           "// core/include/mptrack/classify/generated/sea_classifier_weights.h.",
           "#pragma once", "", "#include <cstdint>", "",
           "namespace mptrack::test::classifier_reference {", "",
           f"inline constexpr int kNumPatches = {n};",
           f"inline constexpr int kNumBeliefs = {len(REF_BELIEFS)};",
           c_array("kBeliefs", np.array(REF_BELIEFS, dtype=np.float32)),
           c_array("kLabels", labels, ctype="std::uint8_t"),
           c_array("kPatches", patches, ctype="std::uint8_t"),
           c_array("kFeatures", feats),
           "// kOutputs[patch * kNumBeliefs + belief index]",
           c_array("kOutputs", outs),
           "}  // namespace mptrack::test::classifier_reference\n"]
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write("\n".join(out))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--train", required=True, help="dataset dir, seed003-sea-a training runs")
    ap.add_argument("--test-in", required=True, help="dataset dir, seed003-sea-a held-out runs")
    ap.add_argument("--test-out", required=True, help="dataset dir, seed003-sea-b")
    ap.add_argument("--root", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
    ap.add_argument("--seed", type=int, default=3)
    ap.add_argument("--epochs1", type=int, default=8)
    ap.add_argument("--epochs2", type=int, default=4)
    ap.add_argument("--lr", type=float, default=2e-3)
    ap.add_argument("--batch", type=int, default=64)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--belief-dropout", type=float, default=0.5,
                    help="stage 2: share of patches trained with the belief 0.5 instead of the recorded one")
    ap.add_argument("--eval-clutter", type=int, default=4000, help="clutter patches scored per test set")
    a = ap.parse_args()
    t0 = time.time()
    torch.manual_seed(a.seed)
    torch.set_num_threads(a.threads)
    torch.use_deterministic_algorithms(True)
    rng = np.random.default_rng(a.seed)
    train, test_in, test_out = load(a.train), load(a.test_in), load(a.test_out)
    pixels = train["patches"].astype(np.float64)
    offset = float(np.float32(pixels.mean()))
    scale = float(np.float32(1.0 / pixels.std()))
    del pixels
    norm = (offset, scale)
    # Balanced sampling: the network's output is a posterior under a 0.5
    # prior, which is what the likelihood-ratio conversion w/(1-w) / (pi/(1-pi))
    # needs (docs/algorithms/sea_clutter.md §Training); the raw fraction is reported.
    raw_fraction = float(train["labels"].mean())
    target_fraction = 0.5
    print(f"train {len(train['labels'])} patches ({int(train['labels'].sum())} target), "
          f"offset {offset:.3f} scale {scale:.5f}", flush=True)

    cnn, mlp, head = FeatureCnn(), ClassifierMlp(), Stage1Head()
    # Stage 1: CNN + temporary head, no belief.
    cnn.train()
    run_epochs(1, list(cnn.parameters()) + list(head.parameters()), lambda x, w: head(cnn(x)),
               train, norm, a.epochs1, a.lr, a.batch, rng)
    # Stage 2: MLP on [features, belief], CNN fine-tuned at lr / 10. While the
    # belief column is the 0.5 placeholder it carries no information: its
    # weights are held at zero so the classifier stays belief-neutral.
    belief_constant = bool(np.all(train["belief"] == train["belief"][0]))
    mask_fn = None
    if belief_constant:
        with torch.no_grad():
            mlp.mlp1.weight[:, 8].zero_()

        def mask_fn():
            mlp.mlp1.weight.grad[:, 8].zero_()
    opt_params = [{"params": mlp.parameters()}, {"params": cnn.parameters(), "lr": a.lr / 10}]
    run_epochs(2, opt_params, lambda x, w: mlp(cnn(x), w), train, norm, a.epochs2, a.lr, a.batch, rng, mask_fn,
               0.0 if belief_constant else a.belief_dropout)
    cnn.eval()
    mlp.eval()
    folded = FoldedCnn(cnn).eval()

    results = {"seed": a.seed, "epochs": [a.epochs1, a.epochs2], "lr": a.lr, "batch": a.batch,
               "belief_placeholder": belief_constant, "belief_source": train["meta"].get("beliefs", "?"),
               "belief_dropout": 0.0 if belief_constant else a.belief_dropout,
               "belief_mean": {"target": float(train["belief"][train["labels"] == 1].mean()),
                               "clutter": float(train["belief"][train["labels"] == 0].mean())},
               "raw_target_fraction": raw_fraction,
               "train": {"rows": int(len(train["labels"])), "targets": int(train["labels"].sum()),
                         "runs": train["meta"]["runs"], "scenario": train["meta"]["scenario"]}}
    results["in_domain"] = evaluate(folded, mlp, test_in, norm, rng, a.eval_clutter)
    results["out_of_domain"] = evaluate(folded, mlp, test_out, norm, rng, a.eval_clutter)
    # The same patches with an uninformative belief 0.5: what the patch alone
    # is worth (MP-NN's hard decision uses it).
    results["in_domain_belief_0_5"] = evaluate(folded, mlp, test_in, norm, np.random.default_rng(a.seed),
                                               a.eval_clutter, 0.5)
    results["out_of_domain_belief_0_5"] = evaluate(folded, mlp, test_out, norm, np.random.default_rng(a.seed),
                                                   a.eval_clutter, 0.5)
    results["in_domain"]["scenario"] = test_in["meta"]["scenario"]
    results["out_of_domain"]["scenario"] = test_out["meta"]["scenario"]

    # Reference data: 8 target + 8 clutter held-out sea-a patches.
    pos = np.flatnonzero(test_in["labels"] == 1)
    neg = np.flatnonzero(test_in["labels"] == 0)
    ref = np.sort(np.concatenate([rng.choice(pos, 8, replace=False), rng.choice(neg, 8, replace=False)]))
    with torch.no_grad():
        x = to_input(test_in["patches"][ref], *norm)
        feats = folded(x)
        outs = torch.stack([mlp(feats, torch.full((len(ref),), b, dtype=torch.float32)) for b in REF_BELIEFS], 1)
        unfolded_diff = float((cnn(x) - feats).abs().max())
    results["reference"] = {"patches": int(len(ref)), "folded_vs_unfolded_max_feature_diff": unfolded_diff}
    info = (f"seed {a.seed}, {results['train']['rows']} sea-a patches ({results['train']['targets']} target), "
            f"AUC in domain {results['in_domain']['auc']:.4f}, out of domain {results['out_of_domain']['auc']:.4f}")
    write_header(os.path.join(a.root, "core/include/mptrack/classify/generated/sea_classifier_weights.h"),
                 folded, mlp, norm, target_fraction, info)
    write_reference(os.path.join(a.root, "tests/data/classifier_reference.h"), test_in["patches"][ref],
                    test_in["labels"][ref], feats.numpy(), outs.numpy())
    results["seconds"] = round(time.time() - t0, 1)
    with open(os.path.join(a.root, "host-sim/train/results.json"), "w") as f:
        json.dump(results, f, indent=2)
        f.write("\n")
    print(json.dumps(results, indent=2))


if __name__ == "__main__":
    sys.exit(main())
