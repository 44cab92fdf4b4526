#!/usr/bin/python3
"""int8 post-training quantisation of the patch classifier's CNN g_M.

Reads the float network (core/include/mptrack/classify/generated/
sea_classifier_weights.h, written by train_classifier.py), calibrates one
activation scale per layer on seed003-sea-a patches, and writes

  core/include/mptrack/classify/generated/sea_features_q8_weights.h
      int8 weights, int32 biases and fixed-point requantisation of every layer
  tests/data/classifier_q8_reference.h
      the int8 features of the 16 reference patches of tests/data/
      classifier_reference.h as this script's exact integer emulation gives them
  host-sim/train/quantise_results.json
      the scales, the feature error against the float network, and the AUC of
      the classifier fed float or int8 features, in and out of domain

The scheme (docs/algorithms/nemp.md §int8 inference): weights symmetric per
output channel, s_w = max|w| / 127; activations after ReLU unsigned 8-bit,
zero point 0, s_y = calibrated max / 255; the input patch code c enters as
c - z, z = round(input_offset), with scale input_scale; accumulators int32 with
the bias in accumulator units; requantisation y = min(255, (acc * m + 2^(s-1))
>> s) on the non-negative pooled accumulator, m / 2^s = s_x s_w / s_y. The last
layer's accumulator becomes a float logit acc * (s_x s_w) before the sigmoid.
Needs only numpy. Run by `./run quantise-classifier` (also at the end of
`./run train-classifier`).
"""
import argparse
import json
import pathlib
import re

import numpy as np

from roc import roc_auc, scored_rows  # same directory

ROOT = pathlib.Path(__file__).resolve().parents[2]
FLOAT_HEADER = ROOT / "core/include/mptrack/classify/generated/sea_classifier_weights.h"
Q8_HEADER = ROOT / "core/include/mptrack/classify/generated/sea_features_q8_weights.h"
REF_HEADER = ROOT / "tests/data/classifier_reference.h"
Q8_REF_HEADER = ROOT / "tests/data/classifier_q8_reference.h"
RESULTS = ROOT / "host-sim/train/quantise_results.json"

H, W = 5, 512
# name, float arrays, pool (Ph, Pw) or None for dense
LAYERS = [("conv1", "kConv1", (1, 4)), ("conv2", "kConv2", (1, 4)), ("conv3", "kConv3", (5, 4)),
          ("fc1", "kFc1", None), ("fc2", "kFc2", None), ("fc3", "kFc3", None)]
SHAPES = {"kConv1Weight": (8, 1, 3, 7), "kConv2Weight": (16, 8, 3, 5), "kConv3Weight": (16, 16, 3, 3),
          "kFc1Weight": (32, 128), "kFc2Weight": (16, 32), "kFc3Weight": (8, 16),
          "kMlp1Weight": (16, 9), "kMlp2Weight": (8, 16), "kMlp3Weight": (1, 8)}


# ------------------------------------------------------------------ reading
def parse_float_header(path):
    text = path.read_text()
    arrays = {}
    for m in re.finditer(r"inline constexpr float (k\w+)\[(\d+)\] = \{(.*?)\};", text, re.S):
        vals = [float.fromhex(v.strip().rstrip("f")) for v in m.group(2 + 1).split(",") if v.strip()]
        assert len(vals) == int(m.group(2)), m.group(1)
        a = np.array(vals, dtype=np.float32)
        arrays[m.group(1)] = a.reshape(SHAPES[m.group(1)]) if m.group(1) in SHAPES else a
    for name in ("kInputOffset", "kInputScale", "kTrainTargetFraction"):
        m = re.search(r"inline constexpr float %s = ([^;]+);" % name, text)
        arrays[name] = float.fromhex(m.group(1).strip().rstrip("f"))
    return arrays


def parse_reference_patches(path):
    text = path.read_text()
    m = re.search(r"kPatches\[(\d+)\] = \{(.*?)\};", text, re.S)
    codes = np.array([int(v) for v in m.group(2).split(",") if v.strip()], dtype=np.uint8)
    return codes.reshape(-1, H, W)


# ------------------------------------------------------- float64 reference
def conv_relu_pool(x, wgt, b, pool):
    """x: (N, Cin, H, W) float64 or int64; same padding, ReLU, max-pool."""
    n, cin, h, w = x.shape
    cout, _, kh, kw = wgt.shape
    xp = np.zeros((n, cin, h + kh - 1, w + kw - 1), dtype=x.dtype)
    xp[:, :, kh // 2:kh // 2 + h, kw // 2:kw // 2 + w] = x
    y = np.zeros((n, cout, h, w), dtype=x.dtype)
    for a in range(kh):
        for c in range(kw):
            y += np.einsum("oi,nihw->nohw", wgt[:, :, a, c], xp[:, :, a:a + h, c:c + w])
    y += b[None, :, None, None]
    y = np.maximum(y, 0)
    ph, pw = pool
    return y.reshape(n, cout, h // ph, ph, w // pw, pw).max(axis=(3, 5))


def float_layers(fw, codes):
    """Pooled / dense outputs of every layer (float64), the last one as logits."""
    x = ((codes.astype(np.float64) - fw["kInputOffset"]) * fw["kInputScale"])[:, None]
    outs = []
    for name, key, pool in LAYERS:
        wgt, b = fw[key + "Weight"].astype(np.float64), fw[key + "Bias"].astype(np.float64)
        if pool is not None:
            x = conv_relu_pool(x, wgt, b, pool)
        else:
            x = x.reshape(len(x), -1) @ wgt.T + b
            if name != "fc3":
                x = np.maximum(x, 0.0)
        outs.append(x)
    return outs


def sigmoid(x):
    return 1.0 / (1.0 + np.exp(-x))


def mlp(fw, feats, belief):
    x = np.concatenate([feats, belief[:, None]], axis=1)
    x = np.maximum(x @ fw["kMlp1Weight"].astype(np.float64).T + fw["kMlp1Bias"], 0.0)
    x = np.maximum(x @ fw["kMlp2Weight"].astype(np.float64).T + fw["kMlp2Bias"], 0.0)
    return sigmoid(x @ fw["kMlp3Weight"].astype(np.float64).T + fw["kMlp3Bias"])[:, 0]


def batched(fn, codes, batch=500):
    parts = [fn(codes[s:s + batch]) for s in range(0, len(codes), batch)]
    if isinstance(parts[0], list):
        return [np.concatenate([p[i] for p in parts]) for i in range(len(parts[0]))]
    return np.concatenate(parts)


# ------------------------------------------------------------ quantisation
def fixed_point(m):
    """m (> 0) as mult * 2^-shift, mult in [2^30, 2^31)."""
    frac, exp = np.frexp(m)
    mult = np.round(frac * (1 << 31)).astype(np.int64)
    over = mult == (1 << 31)
    mult[over] //= 2
    exp = exp + over
    shift = 31 - exp
    assert np.all((shift >= 1) & (shift <= 62)), shift
    return mult, shift.astype(np.int64)


def quantise(fw, act_max):
    """Integer parameters of every layer; act_max: calibrated max per layer
    (fc3 excluded: its output stays an accumulator)."""
    q = {"input_zero_point": int(round(fw["kInputOffset"]))}
    s_x = fw["kInputScale"]
    for i, (name, key, pool) in enumerate(LAYERS):
        wgt = fw[key + "Weight"].astype(np.float64)
        flat = wgt.reshape(len(wgt), -1)
        s_w = np.abs(flat).max(axis=1) / 127.0
        s_w[s_w == 0] = 1.0
        wq = np.clip(np.round(flat / s_w[:, None]), -127, 127).astype(np.int64).reshape(wgt.shape)
        bq = np.round(fw[key + "Bias"].astype(np.float64) / (s_x * s_w)).astype(np.int64)
        layer = {"weight": wq, "bias": bq, "s_w": s_w, "s_x": s_x}
        if name == "fc3":
            layer["out_scale"] = (s_x * s_w).astype(np.float32)
        else:
            s_y = act_max[i] / 255.0
            layer["mult"], layer["shift"] = fixed_point(s_x * s_w / s_y)
            layer["s_y"] = s_y
            s_x = s_y
        q[name] = layer
    return q


def check_accumulator_bounds(q):
    """The core sums in int32 (layers_q8.h): assert that no layer's accumulator
    can leave it for any input, |b| + sum |w| * max|x| < 2^31 per output (every
    tap counted, so padding only lowers it), the first layer's input being the
    centred code c - z of a uint8 c and the others uint8 activations."""
    z = q["input_zero_point"]
    x_max = max(z, 255 - z)
    for name, _, _ in LAYERS:
        layer = q[name]
        w_abs = np.abs(layer["weight"].reshape(len(layer["weight"]), -1)).sum(axis=1)
        worst = int((np.abs(layer["bias"]) + w_abs * x_max).max())
        assert worst < (1 << 31), f"{name}: worst-case accumulator {worst} does not fit int32"
        x_max = 255


def requantise(acc, layer, axis_shape):
    m = layer["mult"].reshape(axis_shape)
    s = layer["shift"].reshape(axis_shape)
    y = (acc * m + (np.int64(1) << (s - 1))) >> s
    return np.minimum(y, 255)


def q8_logits(q, codes):
    """Exact integer emulation of the core's int8 g_M: fc3 accumulators (int64)."""
    x = (codes.astype(np.int64) - q["input_zero_point"])[:, None]
    for name, _, pool in LAYERS:
        layer = q[name]
        if pool is not None:
            acc = conv_relu_pool(x, layer["weight"], layer["bias"], pool)
            x = requantise(acc, layer, (1, -1, 1, 1))
        else:
            acc = x.reshape(len(x), -1) @ layer["weight"].T + layer["bias"]
            if name == "fc3":
                return acc
            x = requantise(np.maximum(acc, 0), layer, (1, -1))
    raise AssertionError


def q8_features(q, codes):
    acc = batched(lambda c: q8_logits(q, c), codes)
    assert np.abs(acc).max() < (1 << 24), "fc3 accumulator must convert to float exactly"
    logit = acc.astype(np.float32) * q["fc3"]["out_scale"][None, :]  # float32, as the core
    return sigmoid(logit.astype(np.float64)), acc


# ------------------------------------------------------------------ output
def c_array(ctype, name, values, per_line):
    vals = [str(int(v)) for v in np.asarray(values).reshape(-1)]
    lines = [", ".join(vals[i:i + per_line]) for i in range(0, len(vals), per_line)]
    return f"inline constexpr {ctype} {name}[{len(vals)}] = {{\n    " + ",\n    ".join(lines) + "};\n"


def c_floats(name, values, per_line=4):
    vals = [float(v).hex() + "f" for v in np.asarray(values, dtype=np.float32).reshape(-1)]
    lines = [", ".join(vals[i:i + per_line]) for i in range(0, len(vals), per_line)]
    return f"inline constexpr float {name}[{len(vals)}] = {{\n    " + ",\n    ".join(lines) + "};\n"


def write_q8_header(q, info):
    out = ["// GENERATED by host-sim/train/quantise_classifier.py (./run quantise-classifier); do not edit.",
           "// int8 CNN g_M of the seed 003 patch classifier (docs/algorithms/nemp.md §int8 inference),",
           "// quantised from generated/sea_classifier_weights.h. Weights int8 per output channel,",
           "// layouts as the float set; biases int32 in accumulator units; requantisation",
           "// y = min(255, (acc * kXMult + 2^(kXShift - 1)) >> kXShift). fc3: logit = acc * kFc3OutScale.",
           f"// Calibration: {info}",
           "#pragma once", "", "#include <cstdint>", "",
           "namespace mptrack::classify::generated {", "",
           f"inline constexpr std::int32_t kQ8InputZeroPoint = {q['input_zero_point']};", ""]
    for name, key, _ in LAYERS:
        layer = q[name]
        cap = name[0].upper() + name[1:]
        out.append(c_array("std::int8_t", f"kQ8{cap}Weight", layer["weight"], 24))
        out.append(c_array("std::int32_t", f"kQ8{cap}Bias", layer["bias"], 8))
        if name == "fc3":
            out.append(c_floats("kQ8Fc3OutScale", layer["out_scale"]))
        else:
            out.append(c_array("std::int32_t", f"kQ8{cap}Mult", layer["mult"], 6))
            out.append(c_array("std::uint8_t", f"kQ8{cap}Shift", layer["shift"], 16))
    out.append("}  // namespace mptrack::classify::generated")
    Q8_HEADER.write_text("\n".join(out) + "\n")


def write_q8_reference(feats, acc):
    out = ["// GENERATED by host-sim/train/quantise_classifier.py (./run quantise-classifier); do not edit.",
           "// The int8 g_M on the 16 patches of classifier_reference.h, from the script's exact",
           "// integer emulation: fc3 accumulators and features sigmoid(float32(acc) * scale) in float64.",
           "#pragma once", "", "#include <cstdint>", "",
           "namespace mptrack::test::classifier_q8_reference {", "",
           c_array("std::int32_t", "kFc3Accumulators", acc, 8),
           "inline constexpr double kFeatures[%d] = {\n    %s};\n" % (
               feats.size, ",\n    ".join(", ".join(repr(float(v)) for v in feats.reshape(-1)[i:i + 4])
                                          for i in range(0, feats.size, 4))),
           "}  // namespace mptrack::test::classifier_q8_reference"]
    Q8_REF_HEADER.write_text("\n".join(out) + "\n")


# ---------------------------------------------------------------- evaluate
def load(dirname):
    d = {k: np.load(pathlib.Path(dirname) / (k + ".npy")) for k in ("patches", "labels", "scr_db", "belief")}
    return d


def evaluate(fw, q, data, seed, max_clutter):
    """AUC of g_c fed float and int8 features (recorded beliefs, the clutter
    subsample of roc.scored_rows), and the feature error."""
    idx = scored_rows(data["labels"], np.random.default_rng(seed), max_clutter)
    codes, labels, belief = data["patches"][idx], data["labels"][idx], data["belief"][idx].astype(np.float64)
    f_float = sigmoid(batched(lambda c: float_layers(fw, c)[-1], codes))
    f_q8, _ = q8_features(q, codes)
    err = np.abs(f_q8 - f_float)
    p_float, p_q8 = mlp(fw, f_float, belief), mlp(fw, f_q8, belief)
    return {"auc_float": roc_auc(p_float, labels), "auc_int8": roc_auc(p_q8, labels),
            "feature_abs_error": {"max": float(err.max()), "p99": float(np.percentile(err, 99)),
                                  "mean": float(err.mean())},
            "probability_abs_error": {"max": float(np.abs(p_q8 - p_float).max()),
                                      "p99": float(np.percentile(np.abs(p_q8 - p_float), 99))},
            "targets": int(labels.sum()), "clutter_scored": int(len(labels) - labels.sum())}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--calibration", required=True, help="dataset dir (mptrack-sim dataset), seed003-sea-a")
    ap.add_argument("--calibration-patches", type=int, default=4000,
                    help="patches drawn for calibration, half targets where there are enough")
    ap.add_argument("--test-in", help="dataset dir, seed003-sea-a held-out runs (AUC float vs int8)")
    ap.add_argument("--test-out", help="dataset dir, seed003-sea-b (AUC float vs int8)")
    ap.add_argument("--seed", type=int, default=3)
    a = ap.parse_args()

    fw = parse_float_header(FLOAT_HEADER)
    cal = load(a.calibration)
    rng = np.random.default_rng(a.seed)
    pos = np.flatnonzero(cal["labels"] == 1)
    neg = np.flatnonzero(cal["labels"] == 0)
    n_pos = min(len(pos), a.calibration_patches // 2)
    pick = np.sort(np.concatenate([rng.choice(pos, n_pos, replace=False),
                                   rng.choice(neg, a.calibration_patches - n_pos, replace=False)]))
    outs = batched(lambda c: float_layers(fw, c), cal["patches"][pick])
    act_max = [float(o.max()) for o in outs]
    q = quantise(fw, act_max)
    check_accumulator_bounds(q)
    info = (f"{len(pick)} seed003-sea-a patches ({n_pos} target), per-layer max "
            + " / ".join(f"{v:.3g}" for v in act_max[:-1]))
    write_q8_header(q, info)

    ref = parse_reference_patches(REF_HEADER)
    f_ref, acc_ref = q8_features(q, ref)
    write_q8_reference(f_ref, acc_ref)
    f_ref_float = sigmoid(float_layers(fw, ref)[-1])

    results = {"seed": a.seed, "calibration": {"patches": int(len(pick)), "targets": int(n_pos),
                                               "layer_max": dict(zip([l[0] for l in LAYERS[:-1]], act_max[:-1]))},
               "reference_patches_feature_abs_error_max": float(np.abs(f_ref - f_ref_float).max())}
    for key, path in (("in_domain", a.test_in), ("out_of_domain", a.test_out)):
        if path:
            results[key] = evaluate(fw, q, load(path), a.seed, 4000)
    RESULTS.write_text(json.dumps(results, indent=2) + "\n")
    print(json.dumps(results, indent=2))
    print(f"-> {Q8_HEADER.relative_to(ROOT)}, {Q8_REF_HEADER.relative_to(ROOT)}, {RESULTS.relative_to(ROOT)}")


if __name__ == "__main__":
    main()
