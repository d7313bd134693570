#!/usr/bin/env python3
"""Light selection, before vs after (issue 17, "Samples that add nothing"): for each scene,
the fraction of exactly black pixels at 2, 3 and 5 spp, and the relMSE at equal spp
(--spp, default 16 and 64) against a reference, for one or more pathtracer binaries.

    python3 tools/light_selection_stats.py --bin before=/tmp/pt-main --bin after=build/native/pathtracer \\
        [--size 160x120] [--ref-spp 4096] [--out /tmp/lightsel] [scene.xml ...]

The reference is rendered by the last binary named (the estimators are unbiased, so any
of them converges to the same image) and cached in --out. A pixel is black when all
three channels are exactly 0; relMSE as core/metrics.h: the mean over pixels and channels
of (x - r)^2 / (r^2 + 0.01). One render per figure (the sampler is deterministic: the same
binary renders the same image); the figures average over every pixel, and the reference's
own error (at --ref-spp) is included in the relMSE, equally for every binary.
"""
import argparse
import os
import subprocess
import sys

from pfm import read_pfm as _read_pfm

DEFAULT_SCENES = ["scenes/reference/scene2.xml", "scenes/cornell-box.xml", "scenes/reference/scene0.xml",
                  "scenes/lights/many-lights.xml"]


def read_pfm(path):
    w, h, _, data = _read_pfm(path)
    return w, h, data


def render(binary, scene, spp, size, out):
    cmd = [binary, "render", scene, "--spp", str(spp), "--spp-per-pass", str(min(spp, 64)), "--size", size, "--out", out]
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    return read_pfm(out)[2]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--bin", action="append", required=True, help="NAME=PATH")
    ap.add_argument("--size", default="160x120")
    ap.add_argument("--spp", default="16,64", help="the sample counts of the relMSE columns")
    ap.add_argument("--ref-spp", type=int, default=4096)
    ap.add_argument("--out", default="/tmp/lightsel")
    ap.add_argument("scenes", nargs="*")
    a = ap.parse_args()
    bins = [b.split("=", 1) for b in a.bin]
    os.makedirs(a.out, exist_ok=True)
    rel = [int(v) for v in a.spp.split(",")]
    print("| scene | binary | black 2 spp | black 3 spp | black 5 spp | " + " | ".join("relMSE %d spp" % v for v in rel) + " |")
    print("|---|---|---|---|---|" + "---|" * len(rel))
    for scene in a.scenes or DEFAULT_SCENES:
        stem = scene.replace("/", "-").replace(".xml", "")
        ref_path = os.path.join(a.out, "%s-ref-%s-%d.pfm" % (stem, a.size, a.ref_spp))
        if not os.path.exists(ref_path):
            render(bins[-1][1], scene, a.ref_spp, a.size, ref_path)
        ref = read_pfm(ref_path)[2]
        for name, binary in bins:
            cells = []
            tmp = os.path.join(a.out, "tmp.pfm")
            for spp in (2, 3, 5):
                x = render(binary, scene, spp, a.size, tmp)
                px = len(x) // 3
                black = sum(1 for i in range(px) if x[3 * i] == 0 and x[3 * i + 1] == 0 and x[3 * i + 2] == 0) / px
                cells.append("%.2f%%" % (100 * black))
            for spp in [int(v) for v in a.spp.split(",")]:
                x = render(binary, scene, spp, a.size, tmp)
                cells.append("%.4g" % (sum((xi - ri) ** 2 / (ri * ri + 0.01) for xi, ri in zip(x, ref)) / len(x)))
            print("| %s | %s | %s |" % (scene, name, " | ".join(cells)), flush=True)


if __name__ == "__main__":
    sys.exit(main())
