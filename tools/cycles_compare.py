#!/usr/bin/env python3
"""Our render of the glTF test assets against Blender's Cycles (issue 13, docs/gltf.md
"Against Cycles"). For each asset of assets/gltf/ that scenes/gltf/ shows, with that
scene's camera: a comparison scene (build/cycles/NAME.xml: the glTF alone, a constant
sky of radiance SKY and a sun, no floor, no HDR map, so that both renderers see exactly
the same light), rendered by `build/native/pathtracer` and by Cycles
(tools/cycles_render.py in `blender -b`), then compared in linear RGB: relMSE (core/
metrics.h's: mean over pixels and channels of (x - r)^2 / (r^2 + 0.01), Cycles as r), the
mean of each channel, and a PNG with ours left and Cycles' right (tone-mapped alike).

    python3 tools/cycles_compare.py [--size 160x120] [--spp 256] [--cycles-spp 256]
        [--only mr-grid,sheen] [--out build/cycles] [--ms] [--spec-absorption] [--compare-only]

Needs Debian's blender (apt-get install blender) and a native build. Stdlib only."""
import argparse
import math
import os
import re
import struct
import subprocess
import sys
import zlib

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from pfm import read_pfm  # noqa: E402

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CASES = ["mr-grid", "dielectric-grid", "maps-quad", "emissive", "transmission", "clearcoat", "sheen", "specular", "volume"]
SKY = 0.5
SUN = (-0.4, -1.0, -0.5, 2.0)  # direction the light travels, irradiance


def camera_of(name):
    text = open(os.path.join(REPO, "scenes/gltf", name + ".xml")).read()
    m = re.search(r'<Camera position="([^"]+)"[^>]*yaw="([^"]+)" pitch="([^"]+)"', text)
    return [float(v) for v in m.group(1).replace(",", " ").split()], float(m.group(2)), float(m.group(3))


def write_png(path, w, h, rgb8):
    rows = b"".join(b"\0" + bytes(rgb8[(h - 1 - y) * w * 3:(h - y) * w * 3]) for y in range(h))
    chunk = lambda t, d: struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d) & 0xFFFFFFFF)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0)) +
                chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b""))


def tonemap(v):
    v = max(0.0, v)
    v = v / (1.0 + v)  # Reinhard, then sRGB
    v = 12.92 * v if v <= 0.0031308 else 1.055 * v ** (1 / 2.4) - 0.055
    return int(max(0, min(255, round(v * 255))))


def blender_env():
    # Blender embeds the system's Python (Debian's, with its numpy): a python3 of another
    # installation first on PATH (pyenv's, here) makes it look for its modules there.
    env = {k: v for k, v in os.environ.items() if not k.startswith("PYENV")}
    env["PATH"] = "/usr/bin:/bin"
    return env


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--size", default="160x120")
    ap.add_argument("--spp", type=int, default=256)
    ap.add_argument("--cycles-spp", type=int, default=256)
    ap.add_argument("--only", default="")
    ap.add_argument("--out", default=os.path.join(REPO, "build/cycles"))
    ap.add_argument("--bin", default=os.path.join(REPO, "build/native/pathtracer"))
    ap.add_argument("--ms", action="store_true", help="multiple scattering on both sides: our Kulla-Conty compensation (--gltf-ms on) "
                    "against Cycles' MULTI_GGX; else the specification's single-scattering model on both (--gltf-ms off, GGX)")
    ap.add_argument("--compare-only", action="store_true", help="compare the images already in --out")
    ap.add_argument("--spec-absorption", action="store_true", help="Cycles' Volume Absorption set to KHR_materials_volume's "
                    "coefficient -ln(c) / d (Blender 3.4's importer gives (1 - c) / d: docs/gltf-cycles.md)")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    cases = a.only.split(",") if a.only else CASES
    rows = []
    for name in cases:
        gltf = os.path.join(REPO, "assets/gltf", name + ".gltf")
        pos, yaw, pitch = camera_of(name)
        xml = os.path.join(a.out, name + ".xml")
        with open(xml, "w") as f:
            f.write('<SceneLevel>\n  <Camera position="%g %g %g" up="0 1 0" yaw="%g" pitch="%g"/>\n' % (*pos, yaw, pitch))
            f.write('  <Environment color="%g %g %g"/>\n' % (SKY, SKY, SKY))
            f.write('  <DirectionalLight direction="%g %g %g" color="1 1 1" intensity="%g"/>\n' % SUN)
            f.write('  <Render bounces="8"/>\n  <Objects>\n    <Mesh src="%s"/>\n  </Objects>\n</SceneLevel>\n' % gltf)
        ours, theirs = os.path.join(a.out, name + "-ours.pfm"), os.path.join(a.out, name + "-cycles.pfm")
        if not a.compare_only:
            subprocess.run([a.bin, "render", xml, "--size", a.size, "--spp", str(a.spp), "--bounces", "8", "--gltf-ms", "on" if a.ms else "off",
                            "--out", ours], check=True, stdout=subprocess.DEVNULL)
        log = "" if a.compare_only else subprocess.run(["blender", "-b", "--factory-startup", "-P", os.path.join(REPO, "tools/cycles_render.py"), "--",
                              "--gltf", gltf, "--out", theirs, "--camera", "%g %g %g %g %g" % (*pos, yaw, pitch), "--sky", str(SKY),
                              "--sun", "%g %g %g %g" % SUN, "--size", a.size, "--spp", str(a.cycles_spp), "--bounces", "8",
                              "--distribution", "MULTI_GGX" if a.ms else "GGX", "--spec-absorption", "1" if a.spec_absorption else "0"],
                             check=True, capture_output=True, text=True, env=blender_env()).stdout
        if a.compare_only and os.path.exists(theirs + ".log"):
            log = open(theirs + ".log").read()
        elif not a.compare_only:
            open(theirs + ".log", "w").write(log)
        if not os.path.exists(theirs):
            sys.exit("cycles_compare: Blender wrote no image for %s:\n%s" % (name, log[-3000:]))
        notes = [l.split("cycles_render: ")[1] for l in log.splitlines() if l.startswith("cycles_render: ")]
        w, h, _, x = read_pfm(ours)
        w2, h2, _, r = read_pfm(theirs)
        assert (w, h) == (w2, h2)
        n = w * h
        rel = sum((x[i] - r[i]) ** 2 / (r[i] ** 2 + 0.01) for i in range(3 * n)) / (3 * n)
        mo = [sum(x[i * 3 + k] for i in range(n)) / n for k in range(3)]
        mc = [sum(r[i * 3 + k] for i in range(n)) / n for k in range(3)]
        # The object's pixels: those where either image is not the sky (a camera ray that
        # leaves sees exactly SKY in both renderers), so the background does not dilute it.
        obj = [i for i in range(n) if any(abs(x[i * 3 + k] - SKY) > 1e-4 or abs(r[i * 3 + k] - SKY) > 1e-4 for k in range(3))]
        no = max(1, len(obj))
        oo = [sum(x[i * 3 + k] for i in obj) / no for k in range(3)]
        oc = [sum(r[i * 3 + k] for i in obj) / no for k in range(3)]
        orel = sum((x[i * 3 + k] - r[i * 3 + k]) ** 2 / (r[i * 3 + k] ** 2 + 0.01) for i in obj for k in range(3)) / (3 * no)
        side = []
        for y in range(h):
            for img in (x, r):
                side += [tonemap(img[(y * w + i) * 3 + k]) for i in range(w) for k in range(3)]
        write_png(os.path.join(a.out, name + "-side.png"), 2 * w, h, side)
        rows.append((name, rel, mo, mc, notes, len(obj), orel, oo, oc))
        print("%-16s relMSE %.4g  mean ours %s  cycles %s  ratio %s" % (name, rel, " ".join("%.4f" % v for v in mo),
              " ".join("%.4f" % v for v in mc), " ".join("%.3f" % (mo[k] / mc[k] if mc[k] else math.nan) for k in range(3))), flush=True)
        print("%-16s object pixels %d: relMSE %.4g  mean ours %s  cycles %s  ratio %s" % ("", len(obj), orel, " ".join("%.4f" % v for v in oo),
              " ".join("%.4f" % v for v in oc), " ".join("%.3f" % (oo[k] / oc[k] if oc[k] else math.nan) for k in range(3))), flush=True)
        for t in notes:
            print("    " + t)
    with open(os.path.join(a.out, "table.md"), "w") as f:
        f.write("| asset | relMSE, whole image | object pixels | relMSE, object | mean RGB of the object, ours | Cycles | ours / Cycles |\n|---|---|---|---|---|---|---|\n")
        for name, rel, mo, mc, _, nobj, orel, oo, oc in rows:
            f.write("| %s | %.3g | %d | %.3g | %s | %s | %s |\n" % (name, rel, nobj, orel, " ".join("%.4f" % v for v in oo), " ".join("%.4f" % v for v in oc),
                                                     " ".join("%.3f" % (oo[k] / oc[k] if oc[k] else math.nan) for k in range(3))))
    print("wrote %s/table.md and NAME-side.png (ours left, Cycles right)" % a.out)


if __name__ == "__main__":
    main()
