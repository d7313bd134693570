#!/usr/bin/env python3
"""The most adaptive sampling can gain on a scene (issue 14): from a uniform render's mean
and per-pixel variance (`pathtracer render --spp N --out M.pfm --out-variance V.pfm`),
the ratio of uniform's relMSE to that of the best allocation of the same samples.

relMSE sums, over pixels i and channels, v_i / (n_i (r_i^2 + 0.01)), v_i a sample's
variance, r_i the true value (here the mean M, or --reference). With q_i = v_i / (r_i^2 +
0.01) summed over channels and sum n_i = N fixed, the minimum is at n_i proportional to
sqrt(q_i) (Lagrange), and the ratio is mean(q) / mean(sqrt(q))^2 (Cauchy-Schwarz: >= 1).
render/adaptive.h allocates per tile (counts per tile of --tile pixels, q the tile's mean)
with a floor (no tile below --floor x the mean count): both ceilings are printed, per
pixel, per tile, per tile with the floor. The renderer's measured gain also pays for its
slower sweeps; this is the gain at equal samples, an upper bound for independent samples
(Sobol's faster convergence where the variance is smooth is not in it).

  python3 tools/adaptive_bound.py --mean M.pfm --variance V.pfm --spp N [--reference R.pfm]
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from pfm import read_pfm  # noqa: E402


def ceiling(weights, q):
    """Uniform's relMSE over the best allocation's, for cells of `weights` pixels with mean
    per-pixel q."""
    p = sum(weights)
    mean_q = sum(w * x for w, x in zip(weights, q)) / p
    mean_s = sum(w * math.sqrt(max(x, 0.0)) for w, x in zip(weights, q)) / p
    return mean_q / (mean_s * mean_s) if mean_s > 0 else 1.0


def with_floor(weights, q, floor):
    """The same with render/adaptive.h's floor: counts proportional to max(sqrt(q), floor x
    their pixel-weighted mean)."""
    p = sum(weights)
    s = [math.sqrt(max(x, 0.0)) for x in q]
    least = floor * sum(w * x for w, x in zip(weights, s)) / p
    n = [max(x, least) for x in s]
    scale = p / sum(w * x for w, x in zip(weights, n))  # mean count 1
    adaptive = sum(w * x / (c * scale) for w, x, c in zip(weights, q, n) if c > 0) / p
    uniform = sum(w * x for w, x in zip(weights, q)) / p
    return uniform / adaptive if adaptive > 0 else 1.0


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--mean", required=True)
    ap.add_argument("--variance", required=True)
    ap.add_argument("--spp", type=int, required=True)
    ap.add_argument("--reference")
    ap.add_argument("--tile", type=int, default=16)
    ap.add_argument("--floor", type=float, default=0.25)
    a = ap.parse_args()
    w, h, ch, mean = read_pfm(a.mean)
    w2, h2, ch2, var = read_pfm(a.variance)
    ref = read_pfm(a.reference)[3] if a.reference else mean
    if (w, h, ch) != (w2, h2, ch2) or ch != 3 or len(ref) != len(mean):
        sys.exit("adaptive_bound: the images differ in size or are not RGB")
    q = []
    for i in range(w * h):
        s = 0.0
        for c in range(3):
            r = ref[3 * i + c]
            s += max(var[3 * i + c], 0.0) * a.spp / (r * r + 0.01)  # a sample's variance
        q.append(s)
    tx, ty = (w + a.tile - 1) // a.tile, (h + a.tile - 1) // a.tile
    tq, tp = [0.0] * (tx * ty), [0] * (tx * ty)
    for y in range(h):
        for x in range(w):
            t = (y // a.tile) * tx + x // a.tile
            tq[t] += q[y * w + x]
            tp[t] += 1
    tq = [s / n for s, n in zip(tq, tp)]
    print("%s: %dx%d, %d spp" % (os.path.basename(a.mean), w, h, a.spp))
    print("  ceiling per pixel: %.3f" % ceiling([1] * len(q), q))
    print("  ceiling per %dx%d tile: %.3f" % (a.tile, a.tile, ceiling(tp, tq)))
    print("  per tile with the floor %.2f: %.3f" % (a.floor, with_floor(tp, tq, a.floor)))


if __name__ == "__main__":
    main()
