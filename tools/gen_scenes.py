#!/usr/bin/env python3
"""Random scenes with extreme but legal parameters, for the NaN hunt (issue 15).

    python3 tools/gen_scenes.py OUTDIR [--seeds 1-200 | --seeds 3,7,11] [--repo ROOT]
    python3 tools/gen_scenes.py --check-kinds [--repo ROOT]

Writes OUTDIR/gen-<seed>.xml for each seed, and beside them the meshes they use
(gen-<seed>-<k>.obj / .json) and, in OUTDIR/assets/, the images they name (copied from
the repository's assets/). Python 3 standard library only; seeded and deterministic:
the same seed writes the same bytes on any machine. Every material and shape kind of the
lists in src/materials/kinds.h and src/shapes/kinds.h has a generator below (MATERIALS,
SHAPES); the kinds are read from those headers, and a kind without a generator stops the
script (--check-kinds is run by the test suite), so a new kind cannot be forgotten.

The parameters reach the limits the loader allows (docs/scene-format.md, "Limits"):
PhongSpecular n from 0 to 1e5; glossiness and roughness 0, at the mirror threshold and 1;
IOR 1.0001 to 200 (and below 1); radii from 1e-9 to 1e4; meshes with degenerate and sliver
triangles, shading normals opposite the geometric normal, zero and unnormalised normals;
emitters inside dielectrics; every procedural texture and the image maps of Textured;
composites nested to the limit; moving spheres and lights.
"""
import math
import os
import random
import re
import shutil
import sys


def kinds(repo, header, macro):
    """The XML names of the kinds in a kind list: X(Type, glsl, "Xml", ...)."""
    text = open(os.path.join(repo, header)).read()
    body = text[text.index("#define " + macro):]
    body = body[: body.index("\n\n")]
    return re.findall(r'X\(\s*\w+\s*,\s*\w+\s*,\s*"(\w+)"', body)


from gen_scene_meshes import fmt, vec, write_mesh  # noqa: E402 (beside this file)


class Ctx:
    def __init__(self, rng, outdir, repo, seed):
        self.rng = rng
        self.outdir = outdir
        self.repo = repo
        self.seed = seed
        self.meshes = 0
        self.depth = 0  # FresnelComposite nesting

    def rel(self, repo_path):
        # The images are copied into OUTDIR/assets/ (main), so scenes name them the same
        # way wherever the repository and the folder are.
        return repo_path

    def logu(self, lo, hi):
        return math.exp(self.rng.uniform(math.log(lo), math.log(hi)))

    def colour(self, lo=0.0, hi=1.0):
        return [self.rng.uniform(lo, hi) for _ in range(3)]

    def pick(self, *xs):
        return self.rng.choice(xs)

    def ior(self):
        r = self.rng.random()
        if r < 0.25:
            return self.pick(1.0001, 200.0, 120.5, 1.5, 1.0)
        if r < 0.35:
            return self.logu(0.2, 1.0)  # below 1: a ratio, as for a bubble
        return self.logu(1.0001, 200.0)


# --- materials: each returns the XML of one material element -------------------------

def m_diffuse(c):
    if c.rng.random() < 0.5:
        return '<Attenuate color="%s"><Diffuse/></Attenuate>' % vec(c.colour())
    return "<Diffuse/>"


def m_metal(c):
    g = c.pick(0.0, 1.0, 0.03, 0.0301, 0.029, c.rng.random(), c.rng.random() ** 3)
    ior = ('iorComplex="%s %s"' % (fmt(c.logu(0.05, 50)), fmt(c.pick(0.0, c.logu(1e-3, 10))))
           if c.rng.random() < 0.7 else 'ior="%s"' % fmt(c.ior()))
    return '<Metal %s glossiness="%s" montecarlo="%s" color="%s"/>' % (ior, fmt(g), c.pick("0", "1", "0.5"), vec(c.colour()))


def m_transmit(c):
    return '<Transmit outerIor="%s" innerIor="%s"/>' % (fmt(c.pick(1.0, c.ior())), fmt(c.ior()))


def medium(c):
    """An absorbing medium inside (half the time): a colour with zeros and ones, a distance
    from 1e-6 to 1e6."""
    if c.rng.random() < 0.5:
        return ""
    colour = [c.pick(0.0, 1.0, c.rng.random(), c.rng.random() ** 4) for _ in range(3)]
    return ' attenuationColor="%s" attenuationDistance="%s"' % (vec(colour), fmt(c.logu(1e-6, 1e6)))


def m_smooth_dielectric(c):
    return '<SmoothDielectric ior="%s" color="%s"%s/>' % (fmt(c.ior()), vec(c.colour(0.5, 1.0)), medium(c))


def m_rough_dielectric(c):
    r = c.pick(0.0, 1.0, 0.0316, 0.03, c.rng.random(), c.rng.random() ** 3)
    return '<RoughDielectric ior="%s" roughness="%s" color="%s"%s/>' % (fmt(c.ior()), fmt(r), vec(c.colour(0.5, 1.0)), medium(c))


def m_emit(c):
    i = c.pick(c.logu(1e-3, 1e3), 1e4, 0.0)
    if c.rng.random() < 0.6:
        return '<Emit><Absorb intensity="%s" color="%s"/></Emit>' % (fmt(i), vec(c.colour()))
    return '<Emit intensity="%s" color="%s">%s</Emit>' % (fmt(i), vec(c.colour()), material(c, no_emit=True))


def m_reflect(c):
    return '<Reflect color="%s"/>' % vec(c.colour())


def m_phong_specular(c):
    n = c.pick(0.0, 1.0, 300.0, 1e4, 1e5, c.logu(1.0, 1e4), c.logu(1e3, 1e5))
    return '<PhongSpecular n="%s" color="%s"/>' % (fmt(n), vec(c.colour()))


def m_fresnel_composite(c):
    if c.depth >= 4:
        return m_reflect(c)
    c.depth += 1
    a, b = material(c), material(c)
    c.depth -= 1
    return '<FresnelComposite na="%s" nb="%s">%s%s</FresnelComposite>' % (fmt(c.pick(1.0, c.ior())), fmt(c.ior()), a, b)


def solid(name):
    def gen(c):
        scale = c.pick(c.logu(1e-3, 1e3), 1e-3, 1e3, 25.0)
        return '<%s color1="%s" color2="%s" scale="%s"/>' % (name, vec(c.colour()), vec(c.colour()), fmt(scale))
    return gen


def m_textured(c):
    attrs = []
    for attr, f in (("diffuse", "wood_diffuse.png"), ("specular", "wood_specular.png"), ("normal", "wood_normal.png")):
        if c.rng.random() < 0.7:
            attrs.append('%s="%s"' % (attr, c.rel("assets/textures/" + f)))
    attrs.append('n="%s"' % fmt(c.pick(0.0, 1.0, 50.0, 1e4, 1e5)))
    attrs.append('uvScale="%s %s"' % (fmt(c.pick(1.0, 0.0, -2.0, c.logu(1e-3, 1e3))), fmt(c.pick(1.0, 0.0, -1.0, c.logu(1e-3, 1e3)))))
    attrs.append('uvOffset="%s %s"' % (fmt(c.rng.uniform(-5, 5)), fmt(c.rng.uniform(-5, 5))))
    return "<Textured %s/>" % " ".join(attrs)


def m_metallic_roughness(c):
    return '<MetallicRoughness baseColor="%s" metallic="%s" roughness="%s" ior="%s"/>' % (
        vec(c.colour()), fmt(c.pick(0.0, 1.0, c.rng.random())), fmt(c.pick(0.0, 0.03, 0.0301, 1.0, c.rng.random())), fmt(c.ior()))


def m_gltf_pbr(c):
    attrs = ['baseColor="%s"' % vec(c.colour()), 'metallic="%s"' % fmt(c.pick(0.0, 1.0, c.rng.random())),
             'roughness="%s"' % fmt(c.pick(0.0, 0.03, 1.0, c.rng.random())), 'ior="%s"' % fmt(c.pick(0.0, 1.0, 1.0001, 1.5, 100.0)),
             'alpha="%s"' % fmt(c.pick(1.0, 0.0, c.rng.random())), 'alphaMode="%s"' % c.pick("OPAQUE", "MASK", "BLEND"),
             'doubleSided="%s"' % c.pick("true", "false")]
    for attr, f in (("baseColorMap", "wood_diffuse.png"), ("metallicRoughnessMap", "wood_specular.png"),
                    ("normalMap", "wood_normal.png"), ("emissiveMap", "wood_diffuse.png")):
        if c.rng.random() < 0.4:
            attrs.append('%s="%s"' % (attr, c.rel("assets/textures/" + f)))
    if c.rng.random() < 0.3:
        attrs.append('normalScale="%s"' % fmt(c.pick(-100.0, 0.0, 100.0, 1.0)))
    return "<GltfPbr %s/>" % " ".join(attrs)


MATERIALS = {
    "Diffuse": m_diffuse,
    "Metal": m_metal,
    "Transmit": m_transmit,
    "SmoothDielectric": m_smooth_dielectric,
    "Emit": m_emit,
    "Reflect": m_reflect,
    "PhongSpecular": m_phong_specular,
    "FresnelComposite": m_fresnel_composite,
    "ChessTexture": solid("ChessTexture"),
    "WorleyTexture": solid("WorleyTexture"),
    "PerlinTexture": solid("PerlinTexture"),
    "FormulaTexture": solid("FormulaTexture"),
    "FormulaPowTexture": solid("FormulaPowTexture"),
    "Textured": m_textured,
    "MetallicRoughness": m_metallic_roughness,
    "GltfPbr": m_gltf_pbr,
    "RoughDielectric": m_rough_dielectric,
}


def material(c, no_emit=False):
    names = [n for n in sorted(MATERIALS) if not (no_emit and n == "Emit")]
    return MATERIALS[c.rng.choice(names)](c)


# --- shapes: each returns the XML of one shape holding material m ---------------------

def point(c, r=4.0):
    return [c.rng.uniform(-r, r) for _ in range(3)]


def radius(c):
    return c.pick(c.logu(0.05, 2.0), c.logu(0.05, 2.0), 1e-9, 1e-6, 1e-4, 1e4, c.logu(1e-4, 1e4))


def s_sphere(c, m):
    extra = ""
    if c.rng.random() < 0.2:
        extra = ' velocity="%s"' % vec(point(c, 2.0))
    r = radius(c)
    centre = point(c)
    if r >= 1e4:  # a huge sphere: its surface passes near the scene (or holds the camera)
        centre[1] = -r + c.rng.uniform(-3.0, 0.0)
    return '<Sphere center="%s" radius="%s"%s>%s</Sphere>' % (vec(centre), fmt(r), extra, m)


def s_box(c, m):
    a = point(c)
    size = [c.pick(c.logu(0.05, 3.0), c.logu(0.05, 3.0), 0.0, 1e-6) for _ in range(3)]
    if all(s == 0.0 for s in size):
        size[0] = 1.0
    b = [a[i] + size[i] * c.pick(1, -1) for i in range(3)]  # min > max on an axis: normalised
    return '<Box min="%s" max="%s">%s</Box>' % (vec(a), vec(b), m)


def s_plane(c, m):
    n = c.pick([0.0, 1.0, 0.0], [c.rng.uniform(-1, 1) for _ in range(3)], [1e-6, 1.0, 0.0], [0.0, 1e-3, 1.0])
    if max(abs(x) for x in n) < 1e-3:
        n = [0.0, 1.0, 0.0]
    return '<Plane normal="%s" d="%s">%s</Plane>' % (vec(n), fmt(c.rng.uniform(-4.0, 0.0)), m)


def s_triangle(c, m):
    while True:
        v0, v1 = point(c), point(c)
        if c.rng.random() < 0.4:  # a sliver: v2 almost on the edge v0 v1
            t = c.rng.random()
            eps = c.pick(1e-3, 1e-5)
            v2 = [v0[i] + t * (v1[i] - v0[i]) + (eps if i == 1 else 0.0) for i in range(3)]
        else:
            v2 = point(c)
        e1 = [v1[i] - v0[i] for i in range(3)]
        e2 = [v2[i] - v0[i] for i in range(3)]
        cr = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]]
        if math.sqrt(sum(x * x for x in cr)) > 1e-5:  # the loader refuses zero area (in float)
            break
    uv = " ".join('uv%d="%s %s"' % (k, fmt(c.rng.uniform(-2, 2)), fmt(c.rng.uniform(-2, 2))) for k in range(3))
    return '<Triangle v0="%s" v1="%s" v2="%s" %s>%s</Triangle>' % (vec(v0), vec(v1), vec(v2), uv, m)


def s_mesh(c, m):
    place = 'position="%s" rotation="%s" scale="%s"' % (
        vec(point(c, 3.0)), vec([c.rng.uniform(-180, 180) for _ in range(3)]), fmt(c.pick(c.logu(0.5, 4.0), 1e-3, 1e3)))
    if c.rng.random() < 0.25:
        return '<Mesh generate="icosphere" level="%d" displace="%s" %s>%s</Mesh>' % (
            c.rng.randint(0, 3), fmt(c.pick(0.0, 0.49, c.rng.uniform(0, 0.3))), place, m)
    return '<Mesh src="%s" %s>%s</Mesh>' % (write_mesh(c), place, m)


def s_disk(c, m):
    n = c.pick([0.0, -1.0, 0.0], [c.rng.uniform(-1, 1) for _ in range(3)], [1e-6, 1.0, 0.0])
    if max(abs(x) for x in n) < 1e-3:
        n = [0.0, 1.0, 0.0]
    return '<Disk center="%s" normal="%s" radius="%s">%s</Disk>' % (vec(point(c)), vec(n), fmt(radius(c)), m)


SHAPES = {
    "Sphere": s_sphere,
    "Box": s_box,
    "Plane": s_plane,
    "Triangle": s_triangle,
    "Mesh": s_mesh,
    "Disk": s_disk,
}


def check_kinds(repo):
    problems = []
    for header, macro, table in (("src/materials/kinds.h", "PT_MATERIAL_KINDS", MATERIALS),
                                 ("src/shapes/kinds.h", "PT_SHAPE_KINDS", SHAPES)):
        listed = kinds(repo, header, macro)
        if not listed:
            problems.append("%s: no kinds found in %s" % (header, macro))
        for k in listed:
            if k not in table:
                problems.append("%s lists %s, which tools/gen_scenes.py has no generator for" % (header, k))
        for k in table:
            if k not in listed:
                problems.append("tools/gen_scenes.py generates %s, which %s does not list" % (k, header))
    return problems


def scene(c):
    rng = c.rng
    dist = c.logu(6.0, 20.0)
    yaw, pitch = rng.uniform(0, 360), rng.uniform(-60, 60)
    y, p = math.radians(yaw), math.radians(pitch)
    fwd = [-math.cos(y) * math.cos(p), math.sin(p), -math.sin(y) * math.cos(p)]
    cam = [-dist * f for f in fwd]
    out = ['<?xml version="1.0" encoding="UTF-8"?>',
           "<!-- tools/gen_scenes.py, seed %d -->" % c.seed,
           '<SceneLevel dotWeight="%s">' % c.pick("true", "false")]
    lens = ""
    if rng.random() < 0.2:
        lens = ' aperture="%s" focalDistance="%s" shutter="%s"' % (fmt(c.pick(0.0, 0.3)), fmt(dist), fmt(c.pick(0.0, 1.0)))
    out.append('  <Camera position="%s" yaw="%s" pitch="%s"%s/>' % (vec(cam), fmt(yaw), fmt(pitch), lens))
    r = rng.random()
    if r < 0.4:
        out.append('  <Environment color="%s"/>' % vec(c.colour(0.0, 2.0)))
    elif r < 0.7:
        out.append('  <Environment map="%s" rotation="%s" intensity="%s"/>' % (
            c.rel("assets/env/" + c.pick("morning.hdr", "afternoon.hdr", "night.hdr")), fmt(rng.uniform(0, 720)),
            fmt(c.pick(1.0, c.logu(1e-3, 1e3)))))
    objects = []
    for _ in range(rng.randint(0, 3)):
        lr = c.pick(c.logu(0.05, 1.0), 1e-9, 1e-6, 1e-3, c.logu(1e-4, 2.0))
        pos = point(c)
        motion = ' velocity="%s"' % vec(point(c, 1.0)) if rng.random() < 0.2 else ""
        out.append('  <Light position="%s" radius="%s" color="%s" intensity="%s"%s/>' % (
            vec(pos), fmt(lr), vec(c.colour()), fmt(c.pick(c.logu(1.0, 1e3), min(1e9, 10.0 * lr ** -2) if lr < 1e-3 else 50.0)), motion))
        if rng.random() < 0.4:  # an emitter inside a dielectric
            glass = c.pick(m_smooth_dielectric, m_transmit)(c)
            objects.append('<Sphere center="%s" radius="%s">%s</Sphere>' % (vec(pos), fmt(lr * c.pick(2.0, 1.001, 50.0)), glass))
    if rng.random() < 0.3:  # an emissive shape inside a dielectric box
        q = point(c, 2.0)
        objects.append('<Sphere center="%s" radius="0.2"><Emit><Absorb intensity="%s" color="1 1 1"/></Emit></Sphere>' % (
            vec(q), fmt(c.logu(1.0, 100.0))))
        objects.append('<Box min="%s" max="%s">%s</Box>' % (vec([x - 0.5 for x in q]), vec([x + 0.5 for x in q]),
                                                           m_smooth_dielectric(c)))
    for _ in range(rng.randint(2, 7)):
        shape = SHAPES[rng.choice(sorted(SHAPES))]
        objects.append(shape(c, material(c)))
    out.append("  <Objects>")
    out += ["    " + o for o in objects]
    out.append("  </Objects>")
    out.append("</SceneLevel>")
    return "\n".join(out) + "\n"


def parse_seeds(text):
    seeds = []
    for part in text.split(","):
        if "-" in part:
            a, b = part.split("-")
            seeds += list(range(int(a), int(b) + 1))
        elif part:
            seeds.append(int(part))
    return seeds


def main(argv):
    repo = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    seeds = list(range(1, 11))
    outdir = None
    check = False
    i = 0
    while i < len(argv):
        a = argv[i]
        if a == "--repo":
            repo = os.path.abspath(argv[i + 1]); i += 1
        elif a == "--seeds":
            seeds = parse_seeds(argv[i + 1]); i += 1
        elif a == "--check-kinds":
            check = True
        elif a.startswith("-"):
            sys.exit("gen_scenes.py: unknown option %s\n%s" % (a, __doc__))
        else:
            outdir = a
        i += 1
    problems = check_kinds(repo)
    for p in problems:
        print("gen_scenes.py: " + p, file=sys.stderr)
    if problems:
        return 1
    if check:
        print("gen_scenes.py: generators for every kind listed (%d materials, %d shapes)" % (len(MATERIALS), len(SHAPES)))
        return 0
    if not outdir:
        sys.exit(__doc__)
    os.makedirs(outdir, exist_ok=True)
    outdir = os.path.abspath(outdir)
    for sub, names in (("assets/textures", ("wood_diffuse.png", "wood_specular.png", "wood_normal.png")),
                       ("assets/env", ("morning.hdr", "afternoon.hdr", "night.hdr"))):
        os.makedirs(os.path.join(outdir, sub), exist_ok=True)
        for n in names:
            shutil.copyfile(os.path.join(repo, sub, n), os.path.join(outdir, sub, n))
    for s in seeds:
        c = Ctx(random.Random(s), outdir, repo, s)
        path = os.path.join(outdir, "gen-%d.xml" % s)
        with open(path, "w") as f:
            f.write(scene(c))
        print(path)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
