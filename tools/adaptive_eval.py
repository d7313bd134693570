#!/usr/bin/env python3
"""Adaptive sampling against uniform sampling (issue 14; render/adaptive.h).

For each scene: a converged reference (rendered once with many samples, kept in --work),
then uniform (--adaptive off) and adaptive (--adaptive on) renders compared with it
  - at equal wall time: `pathtracer bench --seconds S`, --repeat times alternating off/on.
    bench's rows are at powers of two of the spp and where the time ran out at a sweep's
    end; its last row is the last one written within S (the two modes may stop at the
    same count at different times, or at different counts), so the
    comparison is of relMSE x seconds at that row (the inverse of the efficiency: at equal
    time the relMSE of an unbiased estimate falls as 1/t), the median of the repeats;
  - at equal total samples: `pathtracer render --spp N` (adaptive spends the same
    pixel-samples, N per pixel on average, within one per tile).
Prints a table (markdown) of relMSE uniform, adaptive, their ratio (uniform / adaptive:
above 1 adaptive is better) and the spp each reached; --csv writes the rows.

    python3 tools/adaptive_eval.py [--bin build/native/pathtracer] [--size 128x128]
        [--seconds 10] [--ref-seconds 240] [--spp 256] [--repeat 3] [--kernel compute|fragment]
        [--work /tmp/adaptive-eval] [--csv FILE] [SCENE ...]

The issue's rule for the default: at least 1.5x lower relMSE at equal time on at least
two scenes, and never more than 5% worse on any. The H200 command is in docs/benchmarks.md.
No numpy: the PFM files are read with struct.
"""
import argparse
import csv
import os
import re
import statistics
import subprocess
import sys

from pfm import read_pfm

SCENES = ["scenes/cornell-box.xml", "scenes/reference/scene0.xml", "scenes/seed/05-cornell-blue-yellow.xml", "scenes/mesh-cube.xml"]


def rel_mse(img, ref):
    # core/metrics.cpp image_error: mean of (x - r)^2 / (r^2 + 0.01) over pixels and channels
    s = 0.0
    for x, r in zip(img, ref):
        d = x - r
        s += d * d / (r * r + 0.01)
    return s / len(ref)


def run(cmd):
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if p.returncode not in (0, 3):
        sys.stderr.write(p.stdout)
        raise SystemExit("failed: " + " ".join(cmd))
    return p.stdout


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--bin", default="build/native/pathtracer")
    ap.add_argument("--size", default="128x128")
    ap.add_argument("--seconds", type=float, default=10.0)
    ap.add_argument("--ref-seconds", type=float, default=240.0)
    ap.add_argument("--ref-spp", type=int, default=1 << 20)
    ap.add_argument("--spp", type=int, default=256, help="equal samples: spp per pixel (0: skip)")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--kernel", default="compute")
    ap.add_argument("--work", default="/tmp/adaptive-eval")
    ap.add_argument("--csv")
    ap.add_argument("scenes", nargs="*")
    a = ap.parse_args()
    scenes = a.scenes or SCENES
    os.makedirs(a.work, exist_ok=True)
    common = ["--size", a.size, "--kernel", a.kernel]
    rows = []
    for scene in scenes:
        name = os.path.splitext(os.path.basename(scene))[0]
        ref = os.path.join(a.work, "%s-%s-ref.pfm" % (name, a.size))
        if not os.path.exists(ref):
            out = run([a.bin, "render", scene, *common, "--spp", str(a.ref_spp), "--seconds", str(a.ref_seconds), "--out", ref])
            m = re.search(r"rendered (\d+) spp", out)
            e = re.search(r"estimated relMSE: ([0-9.e+-]+)", out)
            print("# reference %s: %s spp, its estimated relMSE %s" % (ref, m and m.group(1), e and e.group(1)), flush=True)
        _, _, _, refpx = read_pfm(ref)
        timed = {"off": [], "on": []}
        for rep in range(a.repeat):
            for mode in ("off", "on") if rep % 2 == 0 else ("on", "off"):
                csvf = os.path.join(a.work, "%s-%s.csv" % (name, mode))
                run([a.bin, "bench", scene, *common, "--seconds", str(a.seconds), "--reference", ref, "--adaptive", mode, "--csv", csvf])
                with open(csvf) as f:
                    last = list(csv.DictReader(f))[-1]
                timed[mode].append((float(last["rel_mse"]) * float(last["seconds"]), int(last["spp"]), float(last["est_rel_mse"] or "nan"),
                                    float(last["rel_mse"]), float(last["seconds"])))
        row = {"scene": scene, "size": a.size, "kernel": a.kernel, "seconds": a.seconds}
        for mode in ("off", "on"):
            errs = sorted(timed[mode])
            med = errs[len(errs) // 2]
            row["time_%s" % mode] = med[0]
            row["time_spp_%s" % mode] = med[1]
            row["time_est_%s" % mode] = med[2]
            row["time_relmse_%s" % mode] = med[3]
            row["time_seconds_%s" % mode] = med[4]
            row["time_all_%s" % mode] = " ".join("%.4g" % e[0] for e in timed[mode])
        row["time_ratio"] = row["time_off"] / row["time_on"]
        if a.spp > 0:
            for mode in ("off", "on"):
                img = os.path.join(a.work, "%s-%s-%d.pfm" % (name, mode, a.spp))
                run([a.bin, "render", scene, *common, "--spp", str(a.spp), "--adaptive", mode, "--out", img])
                row["spp_%s" % mode] = rel_mse(read_pfm(img)[3], refpx)
            row["spp_ratio"] = row["spp_off"] / row["spp_on"]
        rows.append(row)
        print("# %s: equal time uniform %s, adaptive %s; ratio %.3f" % (scene, row["time_all_off"], row["time_all_on"], row["time_ratio"]),
              flush=True)
    print()
    print("| scene | uniform: relMSE at spp in s | adaptive: relMSE at spp in s | equal time: ratio of relMSE x s |"
          " estimated relMSE: uniform, adaptive | relMSE at %d spp: uniform | adaptive | ratio |" % a.spp)
    print("|---|---|---|---|---|---|---|---|")
    for r in rows:
        print("| %s | %.4g at %d in %.1f | %.4g at %d in %.1f | %.2f | %.4g, %.4g | %s | %s | %s |" % (
            r["scene"], r["time_relmse_off"], r["time_spp_off"], r["time_seconds_off"], r["time_relmse_on"], r["time_spp_on"],
            r["time_seconds_on"], r["time_ratio"], r["time_est_off"], r["time_est_on"], "%.4g" % r["spp_off"] if "spp_off" in r else "", "%.4g" % r["spp_on"] if "spp_on" in r else "",
            "%.2f" % r["spp_ratio"] if "spp_ratio" in r else ""))
    if a.csv:
        with open(a.csv, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
            w.writeheader()
            w.writerows(rows)


if __name__ == "__main__":
    main()
