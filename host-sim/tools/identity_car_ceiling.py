#!/usr/bin/env python3
"""Bayes ceiling of identity CAR on seed 000 S1 (Table V): the pair assignment decided per scan
with the true states and SNRs known (amplitude and, optionally, the 7-10 m range offset), no clutter.
No tracker can beat it on average; see docs/results/seed000-s1.md §Identity ceiling.  Pure Python."""
import random, math
def sim(sw, snr_w, snr_s, dr, sr=20.0, n=400000, use_range=True, seed=1):
    rnd = random.Random(seed)
    d2 = 0.715**2
    ks = 1 if sw == 1 else 2
    cw, cs = 1+snr_w, 1+snr_s
    def pd(c):  # P(u > d2), u ~ Gamma(k, c/k)
        x = ks*d2/c
        return math.exp(-x) if ks == 1 else math.exp(-x)*(1+x)
    def draw(c):
        while True:
            u = rnd.gammavariate(ks, c/ks)
            if u > d2: return u
    def logf(u, c):  # log Gamma(k, c/k) density (truncation constant separately)
        return (ks-1)*math.log(u) - ks*u/c - ks*math.log(c/ks) - math.log(pd(c))
    pw, ps = pd(cw), pd(cs)
    correct = total = 0
    for _ in range(n):
        dw, ds = rnd.random() < pw, rnd.random() < ps
        rw_true, rs_true = 0.0, dr
        if dw and ds:
            total += 2
            ua, ub = draw(cw), draw(cs)  # a from weak, b from strong
            ra, rb = rnd.gauss(rw_true, sr), rnd.gauss(rs_true, sr)
            # H1 (correct): a->w, b->s ; H2: a->s, b->w
            l1 = logf(ua, cw) + logf(ub, cs)
            l2 = logf(ua, cs) + logf(ub, cw)
            if use_range:
                l1 += -((ra-rw_true)**2 + (rb-rs_true)**2)/(2*sr*sr)
                l2 += -((ra-rs_true)**2 + (rb-rw_true)**2)/(2*sr*sr)
            if l1 > l2: correct += 2
        elif dw or ds:
            total += 1
            c, rt = (cw, rw_true) if dw else (cs, rs_true)
            u, r = draw(c), rnd.gauss(rt, sr)
            lw = math.log(pw*(1-ps)) + logf(u, cw)
            ls = math.log(ps*(1-pw)) + logf(u, cs)
            if use_range:
                lw += -((r-rw_true)**2)/(2*sr*sr); ls += -((r-rs_true)**2)/(2*sr*sr)
            if (lw > ls) == dw: correct += 1
    return correct/total


if __name__ == "__main__":
    for sw in (1, 3):
        for s2 in (10, 20, 30):
            print(sw, s2, "amp only %.3f" % sim(sw, 10/3, s2, 8.5, use_range=False, n=200000),
                  "amp+range(8.5m) %.3f" % sim(sw, 10/3, s2, 8.5, n=200000),
                  "amp+range(10m) %.3f" % sim(sw, 10/3, s2, 10.0, n=200000))
