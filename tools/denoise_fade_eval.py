#!/usr/bin/env python3
"""The measured blend weight recomputed from saved images (docs/denoise.md, "The fade"; the
renderer ships it since 2026-12-07, this tool evaluated it first and now cross-checks it,
or tries it on images rendered elsewhere): from a tools/denoise_eval.py folder, per scene
and sample count, the raw image's
estimated relMSE E (the renderer's own, from the run's JSON), the measured change of the
denoised image D = mean((denoised - raw)^2 / (raw^2 + 0.01)), the weight w = min(1, E / D),
and the true relMSE of raw + w (denoised - raw) against the reference, beside the raw, the
denoised and the shipped blend's. With raw = T + n and denoised = T + b (its noise left
out), E[D] = E + B, and (1 - w)^2 E + w^2 B is least at w = E / (E + B) = E / D, where it is
E B / (E + B), below both E and B.

    python3 tools/denoise_fade_eval.py DIR SCENE_STEM SPP[,SPP...] [REF_DIR]
e.g. python3 tools/denoise_fade_eval.py build/denoise-eval cornell-box 1,4,16,64,256,1024
"""
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from pfm import read_pfm  # noqa: E402


def rel(a, r):
    return sum((a[i] - r[i]) ** 2 / (r[i] ** 2 + 0.01) for i in range(len(r))) / len(r)


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    d, scene, spps = sys.argv[1], sys.argv[2], [int(s) for s in sys.argv[3].split(",")]
    ref_dir = sys.argv[4] if len(sys.argv) > 4 else d
    ref = read_pfm(f"{ref_dir}/{scene}-ref.pfm")[3]
    print("| spp | raw | denoised | shipped blend | E (estimated) | D | w = min(1, E / D) | raw + w (denoised - raw) |")
    print("|---|---|---|---|---|---|---|---|")
    for n in spps:
        raw = read_pfm(f"{d}/{scene}-{n}-raw.pfm")[3]
        den = read_pfm(f"{d}/{scene}-{n}-denoised.pfm")[3]
        e = json.load(open(f"{d}/{scene}-{n}.json"))["est"]
        change = sum((den[i] - raw[i]) ** 2 / (raw[i] ** 2 + 0.01) for i in range(len(raw))) / len(raw)
        w = min(1.0, e / change) if change > 0 else 1.0
        blend = [raw[i] + w * (den[i] - raw[i]) for i in range(len(raw))]
        shipped = json.load(open(f"{d}/{scene}-{n}.json"))["blend"]
        print(f"| {n} | {rel(raw, ref):.3g} | {rel(den, ref):.3g} | {shipped:.3g} | {e:.3g} | {change:.3g} | {w:.2f} | {rel(blend, ref):.3g} |")


if __name__ == "__main__":
    main()
