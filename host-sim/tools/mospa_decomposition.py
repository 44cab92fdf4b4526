#!/usr/bin/env python3
"""Where a tracker's Mahalanobis MOSPA comes from, scan by scan (docs/algorithms/metrics.md §MOSPA
with a Mahalanobis base distance): missed targets, extra tracks and localisation, from the
truth.csv and tracks.csv of `mptrack-sim` runs (one run directory per tracker, same scenario and
seed, so the scans pair up). Extra confirmed tracks are sorted by their whitened distance d to the
nearest target: a second track on a target that another track covers (d < c), a track near a
target but off by c..3c (in practice a range-rate offset), or far from every target (> 3c, on
clutter); and, over each track's life, by whether it ever covered a target.

    host-sim/tools/mospa_decomposition.py DIR [DIR ...] [--sigma-range-m 15] [--sigma-rate-mps S]

The defaults are the seed 003 sea scenes' (range bin 15 m; one Doppler bin, 1 kHz / 512 at
9.4 GHz). The script's MOSPA equals `mospa_mahalanobis` in the directory's summary.json, which it
prints next to it as a check. Pure Python; brute-force assignment (a few tracks per scan)."""
import argparse, collections, csv, itertools, json, math, os

CUTOFF = 9.4  # seed 003 Sec. IV-A; p = 2


def load(directory, sr, sv):
    truths, tracks = collections.defaultdict(list), collections.defaultdict(list)
    with open(os.path.join(directory, 'truth.csv')) as f:
        for r in csv.DictReader(f):
            if r['eval'] == '1':
                truths[(int(r['run']), int(r['scan']))].append((float(r['x']) / sr, float(r['vx']) / sv))
    with open(os.path.join(directory, 'tracks.csv')) as f:
        for r in csv.DictReader(f):
            if r['eval'] == '1' and r['confirmed'] == '1':
                key = (int(r['run']), int(r['scan']))
                tracks[key].append((float(r['x']) / sr, float(r['vx']) / sv, int(r['track_id'])))
    return truths, tracks


def dist(a, b):
    return math.hypot(a[0] - b[0], a[1] - b[1])


def best_assignment(xs, ys):
    """Pairs (i, j) of the OSPA assignment (min sum of min(d, c)^2) with d < c."""
    small, large, swap = (xs, ys, False) if len(xs) <= len(ys) else (ys, xs, True)
    best, best_cost = (), None
    for perm in itertools.permutations(range(len(large)), len(small)):
        cost = sum(min(CUTOFF, dist(small[i], large[j])) ** 2 for i, j in enumerate(perm))
        if best_cost is None or cost < best_cost:
            best, best_cost = perm, cost
    pairs = [((j, i) if swap else (i, j)) for i, j in enumerate(best)]
    return [(i, j) for i, j in pairs if dist(xs[i], ys[j]) < CUTOFF]


def scan_ospa(xs, ys, pairs):
    n = max(len(xs), len(ys))
    if n == 0:
        return 0.0
    loc = sum(dist(xs[i], ys[j]) ** 2 for i, j in pairs)
    return math.sqrt((loc + CUTOFF ** 2 * (n - len(pairs))) / n)


def decompose(directory, sr, sv):
    truths, tracks = load(directory, sr, sv)
    total = collections.Counter()
    covered_ids, extra_by_id = set(), collections.Counter()
    for key in sorted(truths):
        xs, ys = truths[key], tracks.get(key, [])
        pairs = best_assignment(xs, ys) if ys else []
        total['scans'] += 1
        total['mospa'] += scan_ospa(xs, ys, pairs)
        total['missed'] += len(xs) - len(pairs)
        matched_tracks = {j for _, j in pairs}
        covered_ids.update((key[0], ys[j][2]) for j in matched_tracks)
        for j, y in enumerate(ys):
            if j in matched_tracks:
                continue
            d = min(dist(x, y) for x in xs) if xs else math.inf
            kind = 'second track (d < c)' if d < CUTOFF else 'near a target (c..3c)' if d < 3 * CUTOFF else 'far (> 3c)'
            total[kind] += 1
            extra_by_id[(key[0], y[2])] += 1
    never = sum(v for k, v in extra_by_id.items() if k not in covered_ids)
    return total, never, len({k for k in extra_by_id if k not in covered_ids})


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('dirs', nargs='+')
    ap.add_argument('--sigma-range-m', type=float, default=15.0)
    ap.add_argument('--sigma-rate-mps', type=float, default=1000.0 / 512 * 299792458.0 / 9.4e9 / 2)
    a = ap.parse_args()
    print('| run dir | MOSPA (summary.json) | missed targets | extra tracks | second track | near (c..3c) '
          '| far (> 3c) | extra on never-covering tracks | never-covering tracks per run |')
    print('|---|---|---|---|---|---|---|---|---|')
    for d in a.dirs:
        t, never, never_tracks = decompose(d, a.sigma_range_m, a.sigma_rate_mps)
        n = t['scans']
        with open(os.path.join(d, 'summary.json')) as f:
            s = json.load(f)
        extra = t['second track (d < c)'] + t['near a target (c..3c)'] + t['far (> 3c)']
        print('| %s | %.3f (%.3f) | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.2f |' % (
            os.path.basename(os.path.normpath(d)), t['mospa'] / n, s['mospa_mahalanobis'], t['missed'] / n,
            extra / n, t['second track (d < c)'] / n, t['near a target (c..3c)'] / n, t['far (> 3c)'] / n,
            never / n, never_tracks / s['runs']))
    print('\nper scan, except the last column; d is the whitened distance to the nearest target, c = 9.4')


if __name__ == '__main__':
    main()
