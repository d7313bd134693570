#!/usr/bin/env python3
"""Layers point down (DESIGN.md): reads every #include of a project header under src/ and
fails on an arrow against the order

    core < {scene, shapes, materials, accel, lights} < {shadergen, gpu} < render < app < platform < cli

where a folder may include itself and every layer below, never a layer above nor another
folder of its own layer (the folders of a layer do not know each other: gpu compiles plain
text, it does not know the shader generator), and cli never reaches app (the headless
binary needs no UI; it sits on the EGL platform). Tests beside the code (*_test.cpp) are outside the
order: they may include what they test and the test harness.

    python3 tools/check_layers.py [SRC_DIR]     prints each arrow per folder pair; exit 1 on a violation
"""
import collections
import os
import re
import sys

RANK = {
    "core": 0,
    "scene": 1, "shapes": 1, "materials": 1, "accel": 1, "lights": 1,
    "shadergen": 2, "gpu": 2,
    "render": 3,
    "app": 4,
    "platform": 5,
    "cli": 6,
}
FORBIDDEN = {("cli", "app")}  # cli is on top but never reaches the UI
# Sideways arrows within a layer that are part of the design: the scene model holds each
# material kind's, each shape kind's and each light kind's parameters (materials/all.h,
# shapes/all.h, lights/all.h: the
# kinds know nothing of scenes).
ALLOWED_SIDEWAYS = {("scene", "materials"), ("scene", "shapes"), ("scene", "lights")}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')


def main():
    src = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "src")
    src = os.path.normpath(src)
    arrows = collections.Counter()
    bad = []
    for root, _, files in os.walk(src):
        for name in sorted(files):
            if not name.endswith((".h", ".cpp")) or name.endswith("_test.cpp"):
                continue
            path = os.path.join(root, name)
            rel = os.path.relpath(path, src)
            layer = rel.split(os.sep)[0]
            if layer not in RANK:
                bad.append(f"{rel}: folder '{layer}' has no place in the layer order (tools/check_layers.py)")
                continue
            with open(path, encoding="utf-8") as f:
                for number, line in enumerate(f, 1):
                    m = INCLUDE.match(line)
                    if not m or "/" not in m.group(1):
                        continue  # generated or same-folder headers
                    target = m.group(1).split("/")[0]
                    if target not in RANK:
                        continue  # not a project folder (a system or generated header)
                    arrows[(layer, target)] += 1
                    sideways = RANK[target] == RANK[layer] and layer != target and (layer, target) not in ALLOWED_SIDEWAYS
                    if RANK[target] > RANK[layer] or sideways or (layer, target) in FORBIDDEN:
                        bad.append(f"{rel}:{number}: {layer} includes {m.group(1)} ({target} is not below {layer})")
    for (a, b), n in sorted(arrows.items(), key=lambda x: (RANK[x[0][0]], x[0][0], RANK[x[0][1]], x[0][1])):
        print(f"  {a:9} -> {b:9} {n:3} includes")
    if bad:
        print("layers: %d include(s) point up:" % len(bad))
        for b in bad:
            print("  " + b)
        return 1
    print("layers: every include points down (sideways only: %s)" % ", ".join(f"{a} -> {b}" for a, b in sorted(ALLOWED_SIDEWAYS)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
