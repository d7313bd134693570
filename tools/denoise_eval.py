#!/usr/bin/env python3
"""The denoiser against references (issue 14): relMSE of the raw image, the denoised one
(blend weight 1) and the shipped blend (the weight the renderer picks from its estimated
relMSE, render/denoise.h) at 1, 4, ... spp, over the whole image, along edges and inside
textured regions, as a Markdown table (docs/denoise.md).

    python3 tools/denoise_eval.py [--bin build/native/pathtracer] [--size 128x128]
        [--ref-spp 16384] [--spp 1,4,16,64,256,1024] [--dir build/denoise-eval] [--ref-dir DIR]
        [--denoise-params P] [SCENE.xml ...]

References are rendered once into --dir (SCENE-ref.pfm and its first-hit auxiliaries,
SCENE-ref-{albedo,normal,depth}.pfm) and reused while they exist; --ref-dir takes them
from elsewhere (e.g. made on a GPU with the same --size: the command is printed). Masks
from the reference's auxiliaries: an edge pixel has a 4-neighbour across a depth step (>
5% of the nearer depth) or a normal turn (cosine < 0.9), dilated by one pixel; a textured
pixel is not an edge and has a 4-neighbour whose albedo differs by more than 0.02. The
relMSE is core/metrics.h's: the mean of (x - r)^2 / (r^2 + 0.01) over pixels and channels.
PNGs of the raw and denoised images at each spp are left in --dir to look at.
"""
import argparse
import json
import os
import re
import subprocess
import sys

from pfm import read_pfm as _read_pfm

DEFAULT_SCENES = ["scenes/cornell-box.xml", "scenes/reference/scene0.xml",
                  "scenes/seed/03-balls-solid-table-wood.xml", "scenes/gltf-instances.xml"]


def read_pfm(path):
    """(width, height, RGB values): a one-channel image repeated into three."""
    w, h, n, data = _read_pfm(path)
    if n == 1:
        data = [v for v in data for _ in range(3)]
    return w, h, data


def run(cmd):
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"{' '.join(cmd)} failed:\n{r.stdout}{r.stderr}")
    return r.stdout


def masks(w, h, albedo, normal, depth):
    def px(img, x, y):
        i = 3 * (y * w + x)
        return img[i:i + 3]
    edge0 = [False] * (w * h)
    tex = [False] * (w * h)
    for y in range(h):
        for x in range(w):
            zp = depth[3 * (y * w + x)]
            npv = px(normal, x, y)
            ap = px(albedo, x, y)
            for dx, dy in ((1, 0), (-1, 0), (0, 1), (0, -1)):
                qx, qy = x + dx, y + dy
                if not (0 <= qx < w and 0 <= qy < h):
                    continue
                zq = depth[3 * (qy * w + qx)]
                nq = px(normal, qx, qy)
                ln = (sum(v * v for v in npv) * sum(v * v for v in nq)) ** 0.5
                cos = sum(a * b for a, b in zip(npv, nq)) / ln if ln > 1e-6 else (1.0 if max(map(abs, npv + nq)) < 1e-6 else 0.0)
                if abs(zp - zq) > 0.05 * max(min(abs(zp), abs(zq)), 1e-6) or cos < 0.9:
                    edge0[y * w + x] = True
                if max(abs(a - b) for a, b in zip(ap, px(albedo, qx, qy))) > 0.02:
                    tex[y * w + x] = True
    edge = list(edge0)
    for y in range(h):
        for x in range(w):
            if edge0[y * w + x]:
                for dx in (-1, 0, 1):
                    for dy in (-1, 0, 1):
                        if 0 <= x + dx < w and 0 <= y + dy < h:
                            edge[(y + dy) * w + x + dx] = True
    tex = [t and not e for t, e in zip(tex, edge)]
    return edge, tex


def rel_mse(img, ref, mask=None):
    s, n = 0.0, 0
    for p in range(len(ref) // 3):
        if mask is not None and not mask[p]:
            continue
        for k in range(3):
            r = ref[3 * p + k]
            s += (img[3 * p + k] - r) ** 2 / (r * r + 0.01)
            n += 1
    return s / n if n else float("nan")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("scenes", nargs="*", default=DEFAULT_SCENES)
    ap.add_argument("--bin", default="build/native/pathtracer")
    ap.add_argument("--size", default="128x128")
    ap.add_argument("--ref-spp", type=int, default=16384)
    ap.add_argument("--spp", default="1,4,16,64,256,1024")
    ap.add_argument("--dir", default="build/denoise-eval")
    ap.add_argument("--ref-dir", default=None)
    ap.add_argument("--kernel", default=None, help="compute or fragment (default: the binary's)")
    ap.add_argument("--denoise-params", default=None, help="passed to the renderer (pathtracer --help), e.g. "
                    "5,1,128,4,0,0 for the a-trous passes alone (main's filter)")
    a = ap.parse_args()
    os.makedirs(a.dir, exist_ok=True)
    ref_dir = a.ref_dir or a.dir
    kernel = ["--kernel", a.kernel] if a.kernel else []
    dparams = ["--denoise-params", a.denoise_params] if a.denoise_params else []
    rows = []
    for scene in a.scenes:
        name = re.sub(r"\.xml$", "", scene.replace("scenes/", "").replace("/", "-"))
        ref = os.path.join(ref_dir, f"{name}-ref")
        cmd = [a.bin, "render", scene, "--size", a.size, "--spp", str(a.ref_spp), "--spp-per-pass", "16",
               "--out", ref + ".pfm", "--out", ref + ".png", "--out-aux", ref] + kernel
        if not os.path.exists(ref + ".pfm"):
            print("reference:", " ".join(cmd), file=sys.stderr, flush=True)
            with open(ref + ".txt", "w") as f:
                f.write(run(cmd))
        ref_est = float("nan")
        if os.path.exists(ref + ".txt"):
            m = re.search(r"estimated relMSE: ([0-9.eE+-]+)", open(ref + ".txt").read())
            ref_est = float(m.group(1)) if m else ref_est
        w, h, refimg = read_pfm(ref + ".pfm")
        _, _, albedo = read_pfm(ref + "-albedo.pfm")
        _, _, normal = read_pfm(ref + "-normal.pfm")
        _, _, depth = read_pfm(ref + "-depth.pfm")
        edge, tex = masks(w, h, albedo, normal, depth)
        for n in map(int, a.spp.split(",")):
            base = os.path.join(a.dir, f"{name}-{n}")
            out = run([a.bin, "render", scene, "--size", a.size, "--spp", str(n), "--spp-per-pass", str(min(n, 16)),
                       "--out", base + "-raw.pfm", "--out", base + "-raw.png", "--denoise-weight", "1",
                       "--out-denoised", base + "-denoised.pfm", "--out-denoised", base + "-denoised.png"] + kernel + dparams)
            m = re.search(r"from the estimated relMSE: ([0-9.]+)\), \d+ iterations in ([0-9.]+) ms", out)
            weight, ms = float(m.group(1)), float(m.group(2))
            est = re.search(r"estimated relMSE: ([0-9.eE+-]+)", out)
            _, _, raw = read_pfm(base + "-raw.pfm")
            _, _, den = read_pfm(base + "-denoised.pfm")
            blend = [r + weight * (d - r) for r, d in zip(raw, den)]
            row = {"scene": scene, "spp": n, "weight": weight, "ms": ms, "est": float(est.group(1)) if est else float("nan")}
            for key, img in (("raw", raw), ("den", den), ("blend", blend)):
                row[key] = rel_mse(img, refimg)
                row[key + "_edge"] = rel_mse(img, refimg, edge)
                row[key + "_tex"] = rel_mse(img, refimg, tex)
            rows.append(row)
            with open(base + ".json", "w") as fj:
                json.dump(row, fj)
            print(f"{scene} {n} spp: raw {row['raw']:.4g}, denoised {row['den']:.4g}, blend {row['blend']:.4g} (w {weight:.3f})",
                  file=sys.stderr, flush=True)
        row_edges, row_tex = sum(edge), sum(tex)
        rows.append({"scene": scene, "masks": (row_edges, row_tex, w * h), "ref_est": ref_est})
    print(f"| scene | spp | raw (estimated) | denoised | shipped blend (weight) | edges: raw / denoised / blend | texture: raw / denoised / blend |")
    print("|---|---|---|---|---|---|---|")
    f = lambda v: "n/a" if v != v else f"{v:.3g}"
    for r in rows:
        if "masks" in r:
            e, t, all_ = r["masks"]
            print(f"| {r['scene']} | reference {a.ref_spp} spp, its estimated relMSE {f(r['ref_est'])} | {all_} px | | | "
                  f"{e} px | {t} px |")
            continue
        print(f"| {r['scene']} | {r['spp']} | {f(r['raw'])} ({f(r['est'])}) | {f(r['den'])} | {f(r['blend'])} ({r['weight']:.2f}) | "
              f"{f(r['raw_edge'])} / {f(r['den_edge'])} / {f(r['blend_edge'])} | {f(r['raw_tex'])} / {f(r['den_tex'])} / {f(r['blend_tex'])} |")


if __name__ == "__main__":
    main()
