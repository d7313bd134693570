#!/usr/bin/env python3
"""Scenes of N primitives for measuring the flat-or-BVH rule (accel/accel_choice.h,
docs/benchmarks.md "Fragment-pass steps (issue 17)"): scene2's Cornell box (its walls,
emitter, light and two spheres) with small diffuse boxes and spheres added inside the room
until the scene has N primitives. Deterministic (seeded); written outside the repository's
scenes/ so that no test or gallery picks them up.

    python3 tools/gen_accel_scenes.py OUT_DIR N [N ...]     writes OUT_DIR/room-N.xml
"""
import os
import random
import re
import sys

REPO = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    base = open(os.path.join(REPO, "scenes/reference/scene2.xml")).read()
    # The base's primitives: every shape element, the <Light> (a sphere) included.
    have = len(re.findall(r"<(Box|Sphere|Light)\b", re.sub(r"<!--.*?-->", "", base, flags=re.S)))
    for n in map(int, sys.argv[2:]):
        rng = random.Random(n)
        extra = []
        for i in range(max(0, n - have)):
            x, y, z = rng.uniform(-180, 80), rng.uniform(15, 105), rng.uniform(-85, 85)
            c = " ".join("%.2f" % rng.uniform(0.2, 0.9) for _ in range(3))
            mat = '<Attenuate color="%s"><Diffuse/></Attenuate>' % c
            if i % 2:
                r = rng.uniform(2, 6)
                extra.append('<Sphere center="%.2f %.2f %.2f" radius="%.2f">%s</Sphere>' % (x, y, z, r, mat))
            else:
                e = [rng.uniform(2, 6) for _ in range(3)]
                extra.append('<Box min="%.2f %.2f %.2f" max="%.2f %.2f %.2f">%s</Box>' % (x - e[0], y - e[1], z - e[2], x + e[0], y + e[1], z + e[2], mat))
        text = base.replace("</Objects>", "\n".join(extra) + "\n</Objects>")
        path = os.path.join(out, "room-%d.xml" % n)
        open(path, "w").write(text)
        print(path, max(n, have), "primitives")


if __name__ == "__main__":
    main()
