#!/usr/bin/env python3
"""Writes the glTF test and showcase assets under assets/gltf/ (docs/gltf.md): .gltf JSON
with one .bin buffer and PNG images, with nothing but the Python 3 standard library.

    python3 tools/gen_gltf_assets.py            # (re)writes assets/gltf/

Showcase (scenes/gltf/ shows them): mr-grid (5 x 5 spheres, metallic across, roughness
down), dielectric-grid (5 spheres, roughness 0..1, ior 1.5 through KHR_materials_ior),
maps-quad (base colour and normal maps), emissive (emissive strength 1, 4, 16),
clearcoat (KHR_materials_clearcoat over a red base: factor 0..1, then coat roughness 0..1),
sheen (KHR_materials_sheen on a draped cloth and spheres of sheen roughness 0.2..1),
specular (KHR_materials_specular: specularFactor 0..1, specularColor), transmission
(thin-walled KHR_materials_transmission: clear, frosted, amber spheres).
Tests (tests/gltf_materials_test.cpp, tests/gltf_lobes_test.cpp): test-*.gltf, quads z = 0
over [-1, 1]^2 facing +z.
"""
import json
import math
import os
import struct
import zlib

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "assets", "gltf")


def png(path, rows, channels):
    """rows: list of rows (top row first) of channel tuples of 0..255 codes."""
    h, w = len(rows), len(rows[0])
    raw = b"".join(b"\0" + bytes(c for px in row for c in px) for row in rows)
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)
    colour = {3: 2, 4: 6}[channels]
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, colour, 0, 0, 0)) +
                chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


class Gltf:
    def __init__(self, name):
        self.name = name
        self.bin = bytearray()
        self.doc = {"asset": {"version": "2.0", "generator": "tools/gen_gltf_assets.py"}, "scene": 0,
                    "scenes": [{"nodes": []}], "nodes": [], "meshes": [], "materials": [], "accessors": [],
                    "bufferViews": [], "buffers": [], "textures": [], "images": [], "samplers": []}
        self.used = set()
        self.cache = {}

    def accessor(self, fmt, kind, values, target=None):
        # The same list twice (a sphere per material): one accessor. The cache holds the list
        # too, so that its id is not reused by a later list while the cache keys it.
        key = (id(values), fmt, kind)
        if key in self.cache:
            assert self.cache[key][1] is values, "an accessor cached for another list"
            return self.cache[key][0]
        self.cache[key] = (len(self.doc["accessors"]), values)
        while len(self.bin) % 4:
            self.bin.append(0)
        offset = len(self.bin)
        comps = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4}[kind]
        flat = [c for v in values for c in (v if comps > 1 else (v,))]
        self.bin += struct.pack("<%d%s" % (len(flat), fmt), *flat)
        view = {"buffer": 0, "byteOffset": offset, "byteLength": len(self.bin) - offset}
        if target:
            view["target"] = target
        self.doc["bufferViews"].append(view)
        acc = {"bufferView": len(self.doc["bufferViews"]) - 1, "componentType": 5126 if fmt == "f" else 5125,
               "count": len(values), "type": kind}
        if kind == "VEC3" and fmt == "f":
            acc["min"] = [min(v[i] for v in values) for i in range(3)]
            acc["max"] = [max(v[i] for v in values) for i in range(3)]
        self.doc["accessors"].append(acc)
        return len(self.doc["accessors"]) - 1

    def mesh(self, positions, normals, uvs, indices, material, uvs1=None, colors=None):
        attrs = {"POSITION": self.accessor("f", "VEC3", positions, 34962),
                 "NORMAL": self.accessor("f", "VEC3", normals, 34962)}
        if uvs is not None:
            attrs["TEXCOORD_0"] = self.accessor("f", "VEC2", uvs, 34962)
        if uvs1 is not None:
            attrs["TEXCOORD_1"] = self.accessor("f", "VEC2", uvs1, 34962)
        if colors is not None:
            attrs["COLOR_0"] = self.accessor("f", "VEC4", colors, 34962)
        prim = {"attributes": attrs, "indices": self.accessor("I", "SCALAR", indices, 34963), "material": material}
        self.doc["meshes"].append({"primitives": [prim]})
        return len(self.doc["meshes"]) - 1

    def node(self, mesh, translation=(0, 0, 0)):
        self.doc["nodes"].append({"mesh": mesh, "translation": list(translation)})
        self.doc["scenes"][0]["nodes"].append(len(self.doc["nodes"]) - 1)

    def material(self, m):
        self.doc["materials"].append(m)
        for e in m.get("extensions", {}):
            self.used.add(e)
        return len(self.doc["materials"]) - 1

    def texture(self, image_name, rows, channels=3, wrap=(10497, 10497), nearest=True, tex_coord=0, transform=None):
        png(os.path.join(OUT, image_name), rows, channels)
        self.doc["images"].append({"uri": image_name})
        sampler = {"wrapS": wrap[0], "wrapT": wrap[1], "magFilter": 9728 if nearest else 9729}
        self.doc["samplers"].append(sampler)
        self.doc["textures"].append({"source": len(self.doc["images"]) - 1, "sampler": len(self.doc["samplers"]) - 1})
        info = {"index": len(self.doc["textures"]) - 1, "texCoord": tex_coord}
        if transform:
            info["extensions"] = {"KHR_texture_transform": transform}
            self.used.add("KHR_texture_transform")
        return info

    def write(self):
        self.doc["buffers"] = [{"uri": self.name + ".bin", "byteLength": len(self.bin)}]
        for k in ("textures", "images", "samplers"):
            if not self.doc[k]:
                del self.doc[k]
        if self.used:
            self.doc["extensionsUsed"] = sorted(self.used)
        with open(os.path.join(OUT, self.name + ".bin"), "wb") as f:
            f.write(self.bin)
        with open(os.path.join(OUT, self.name + ".gltf"), "w") as f:
            json.dump(self.doc, f, indent=1)
            f.write("\n")


def quad(size=1.0, uv_range=((0.0, 0.0), (1.0, 1.0))):
    """The quad z = 0 over [-size, size]^2 facing +z; glTF uv (v down the image)."""
    (u0, v0), (u1, v1) = uv_range
    p = [(-size, -size, 0), (size, -size, 0), (size, size, 0), (-size, size, 0)]
    uv = [(u0, v1), (u1, v1), (u1, v0), (u0, v0)]
    return p, [(0, 0, 1)] * 4, uv, [0, 1, 2, 0, 2, 3]


def sphere(radius, rings=24, segments=48):
    p, n, uv, idx = [], [], [], []
    for i in range(rings + 1):
        th = math.pi * i / rings
        for j in range(segments + 1):
            ph = 2 * math.pi * j / segments
            d = (math.sin(th) * math.cos(ph), math.cos(th), -math.sin(th) * math.sin(ph))
            p.append(tuple(radius * c for c in d))
            n.append(d)
            uv.append((j / segments, i / rings))
    for i in range(rings):
        for j in range(segments):
            a, b = i * (segments + 1) + j, (i + 1) * (segments + 1) + j
            idx += [a, b, a + 1, a + 1, b, b + 1]
    return p, n, uv, idx


def showcase():
    g = Gltf("mr-grid")  # metallic 0..1 left to right, roughness 0..1 bottom to top
    s = sphere(0.4)
    for i in range(5):
        for j in range(5):
            m = g.material({"name": "m%d-r%d" % (i, j), "pbrMetallicRoughness": {
                "baseColorFactor": [0.95, 0.64, 0.54, 1], "metallicFactor": i / 4, "roughnessFactor": j / 4}})
            g.node(g.mesh(*s, m), (1.0 * (i - 2), 1.0 * j + 0.4, 0))
    g.write()
    g = Gltf("dielectric-grid")  # a red plastic of ior 1.5, roughness 0..1
    for i in range(5):
        m = g.material({"name": "r%d" % i, "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.1, 0.08, 1],
                        "metallicFactor": 0, "roughnessFactor": i / 4}, "extensions": {"KHR_materials_ior": {"ior": 1.5}}})
        g.node(g.mesh(*s, m), (1.0 * (i - 2), 0.4, 0))
    g.write()
    g = Gltf("maps-quad")  # an 8 x 8 checker of two colours and a normal map of round bumps
    n = 64
    base = [[(200, 60, 40) if ((x // 8) + (y // 8)) % 2 else (230, 220, 200) for x in range(n)] for y in range(n)]
    normal = []
    for y in range(n):
        row = []
        for x in range(n):
            cx, cy = (x % 16) - 7.5, (y % 16) - 7.5
            r2 = (cx * cx + cy * cy) / 49.0
            if r2 < 1:  # a hemispherical bump: tangent-space normal (cx, -cy (image y runs down), sqrt(1 - r2))
                nx, ny = cx / 7.0, -cy / 7.0
                nz = math.sqrt(max(0.0, 1 - nx * nx - ny * ny))
            else:
                nx, ny, nz = 0.0, 0.0, 1.0
            row.append(tuple(int(round((c * 0.5 + 0.5) * 255)) for c in (nx, ny, nz)))
        normal.append(row)
    m = g.material({"name": "maps", "pbrMetallicRoughness": {"baseColorTexture": g.texture("maps-quad-base.png", base, nearest=False),
                    "metallicFactor": 0, "roughnessFactor": 0.45},
                    "normalTexture": dict(g.texture("maps-quad-normal.png", normal, nearest=False), scale=1.0)})
    g.node(g.mesh(*quad(1.5), m))
    g.write()
    g = Gltf("emissive")  # emissive strength 1, 4, 16 over a grey base
    for i, k in enumerate((1, 4, 16)):
        m = g.material({"name": "e%d" % k, "pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.5, 0.5, 1], "metallicFactor": 0,
                        "roughnessFactor": 0.5}, "emissiveFactor": [1.0, 0.55, 0.2],
                        "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": k}}})
        g.node(g.mesh(*s, m), (1.1 * (i - 1), 0.4, 0))
    g.write()


def cloth(size=1.6, n=48, folds=3, depth=0.12):
    """A draped sheet: the quad y = h(x, z) over [-size, size]^2 with folds along x, facing +y."""
    p, nn, uv, idx = [], [], [], []
    for i in range(n + 1):
        for j in range(n + 1):
            x, z = size * (2 * j / n - 1), size * (2 * i / n - 1)
            k = folds * math.pi / size
            h = depth * math.sin(k * x) * (0.6 + 0.4 * math.cos(0.5 * k * z))
            dx = depth * k * math.cos(k * x) * (0.6 + 0.4 * math.cos(0.5 * k * z))
            dz = -depth * math.sin(k * x) * 0.4 * 0.5 * k * math.sin(0.5 * k * z)
            l = math.sqrt(dx * dx + 1 + dz * dz)
            p.append((x, h, z))
            nn.append((-dx / l, 1 / l, -dz / l))
            uv.append((j / n, i / n))
    for i in range(n):
        for j in range(n):
            a, b = i * (n + 1) + j, (i + 1) * (n + 1) + j
            idx += [a, b, a + 1, a + 1, b, b + 1]
    return p, nn, uv, idx


def lobes():
    s = sphere(0.4)
    g = Gltf("clearcoat")  # a red base; front row clearcoat 0..1 (smooth), back row clearcoat 1 of roughness 0..1
    for row, (label, values) in enumerate((("factor", [(i / 4, 0.0) for i in range(5)]), ("roughness", [(1.0, i / 4) for i in range(5)]))):
        for i, (cc, ccr) in enumerate(values):
            m = g.material({"name": "cc-%s-%d" % (label, i), "pbrMetallicRoughness": {"baseColorFactor": [0.7, 0.04, 0.03, 1],
                            "metallicFactor": 0, "roughnessFactor": 0.6},
                            "extensions": {"KHR_materials_clearcoat": {"clearcoatFactor": cc, "clearcoatRoughnessFactor": ccr}}})
            g.node(g.mesh(*s, m), (1.0 * (i - 2), 0.4, -1.1 * row))
    g.write()
    g = Gltf("sheen")  # a dark blue cloth with a pink sheen, and spheres of sheen roughness 0.2 .. 1
    m = g.material({"name": "velvet", "doubleSided": True, "pbrMetallicRoughness": {"baseColorFactor": [0.03, 0.03, 0.12, 1],
                    "metallicFactor": 0, "roughnessFactor": 0.9},
                    "extensions": {"KHR_materials_sheen": {"sheenColorFactor": [0.95, 0.55, 0.75], "sheenRoughnessFactor": 0.45}}})
    g.node(g.mesh(*cloth(), m), (0, 0.2, 0))
    for i in range(5):
        m = g.material({"name": "sheen-r%d" % i, "pbrMetallicRoughness": {"baseColorFactor": [0.03, 0.03, 0.12, 1],
                        "metallicFactor": 0, "roughnessFactor": 0.9},
                        "extensions": {"KHR_materials_sheen": {"sheenColorFactor": [0.95, 0.55, 0.75], "sheenRoughnessFactor": 0.2 + 0.2 * i}}})
        g.node(g.mesh(*sphere(0.3), m), (0.75 * (i - 2), 0.75, 1.2))
    g.write()
    g = Gltf("transmission")  # thin-walled KHR_materials_transmission: clear, frosted (roughness 0.3), tinted amber
    for i, (rough, color) in enumerate(((0.0, [1, 1, 1, 1]), (0.3, [1, 1, 1, 1]), (0.0, [1.0, 0.6, 0.2, 1]))):
        m = g.material({"name": "thin-%d" % i, "doubleSided": True, "pbrMetallicRoughness": {"baseColorFactor": color, "metallicFactor": 0,
                        "roughnessFactor": rough}, "extensions": {"KHR_materials_transmission": {"transmissionFactor": 1.0}}})
        g.node(g.mesh(*sphere(0.5), m), (1.2 * (i - 1), 0.5, 0))
    g.write()
    # KHR_materials_volume (scenes/gltf/volume.xml): closed spheres whose transmission
    # refracts into an absorbing volume: clear glass, amber, frosted green, a gold half
    # metal, and half transmission under a clearcoat over a blue base.
    g = Gltf("volume")
    spheres = (
        ({"baseColorFactor": [1, 1, 1, 1], "metallicFactor": 0, "roughnessFactor": 0}, 1.0, None, {}),
        ({"baseColorFactor": [1, 1, 1, 1], "metallicFactor": 0, "roughnessFactor": 0}, 1.0, ([1.0, 0.55, 0.15], 0.5), {}),
        ({"baseColorFactor": [1, 1, 1, 1], "metallicFactor": 0, "roughnessFactor": 0.3}, 1.0, ([0.4, 0.9, 0.5], 0.6), {}),
        ({"baseColorFactor": [1.0, 0.8, 0.45, 1], "metallicFactor": 0.5, "roughnessFactor": 0.15}, 1.0, ([0.9, 0.7, 0.4], 1.0), {}),
        ({"baseColorFactor": [0.2, 0.35, 0.9, 1], "metallicFactor": 0, "roughnessFactor": 0.4}, 0.5, ([0.3, 0.5, 1.0], 0.8),
         {"KHR_materials_clearcoat": {"clearcoatFactor": 1.0, "clearcoatRoughnessFactor": 0.05}}),
    )
    for i, (pbr, transmission, attenuation, more) in enumerate(spheres):
        volume = {"thicknessFactor": 0.9}
        if attenuation:
            volume.update({"attenuationColor": attenuation[0], "attenuationDistance": attenuation[1]})
        ext = {"KHR_materials_transmission": {"transmissionFactor": transmission}, "KHR_materials_volume": volume}
        ext.update(more)
        m = g.material({"name": "volume-%d" % i, "pbrMetallicRoughness": pbr, "extensions": ext})
        g.node(g.mesh(*sphere(0.45, 32, 64), m), (1.05 * (i - 2), 0.45, 0))
    g.write()
    g = Gltf("specular")  # a grey dielectric of roughness 0.3: specularFactor 0..1; last: specularColor orange
    for i in range(6):
        ext = {"specularFactor": min(1.0, i / 4)} if i < 5 else {"specularColorFactor": [2.0, 1.0, 0.3]}
        m = g.material({"name": "spec-%d" % i, "pbrMetallicRoughness": {"baseColorFactor": [0.25, 0.25, 0.25, 1],
                        "metallicFactor": 0, "roughnessFactor": 0.3}, "extensions": {"KHR_materials_specular": ext}})
        g.node(g.mesh(*s, m), (1.0 * (i - 2.5), 0.4, 0))
    g.write()


def tests():
    W, K = (255, 255, 255), (0, 0, 0)
    # Checker: white metal (mr (0, 0, 255): roughness 0, metallic 1) beside black dielectric;
    # image rows top first: top-left and bottom-right are the metal.
    for name, tc in (("test-checker", 0), ("test-uv1", 1)):
        g = Gltf(name)
        p, n, uv, idx = quad()
        uv1 = None
        if tc == 1:
            uv1, uv = uv, [(0.7, 0.3)] * 4  # TEXCOORD_0 constant: only TEXCOORD_1 shows the checker
        m = g.material({"doubleSided": True, "pbrMetallicRoughness": {
            "baseColorTexture": g.texture(name + "-base.png", [[W, K], [K, W]], tex_coord=tc),
            "metallicRoughnessTexture": g.texture(name + "-mr.png", [[(0, 0, 255), (0, 0, 0)], [(0, 0, 0), (0, 0, 255)]], tex_coord=tc),
            "metallicFactor": 1, "roughnessFactor": 1}})
        g.node(g.mesh(p, n, uv, idx, m, uvs1=uv1))
        g.write()
    # Wrap modes and the texture transform, read in emission (black base, emissive map
    # of two texels, black | white): u runs over [-1, 2] across the quad.
    for name, wrap, transform, span in (("test-wrap-repeat", 10497, None, (-1, 2)), ("test-wrap-clamp", 33071, None, (-1, 2)),
                                        ("test-wrap-mirror", 33648, None, (-1, 2)),
                                        ("test-transform", 10497, {"offset": [0.5, 0], "scale": [2, 1]}, (0, 1))):
        g = Gltf(name)
        p, n, uv, idx = quad(uv_range=((span[0], 0.0), (span[1], 1.0)))
        m = g.material({"doubleSided": True, "pbrMetallicRoughness": {"baseColorFactor": [0, 0, 0, 1], "metallicFactor": 1, "roughnessFactor": 1},
                        "emissiveFactor": [1, 1, 1], "emissiveTexture": g.texture(name + ".png", [[K, W]], wrap=(wrap, wrap), transform=transform)})
        g.node(g.mesh(p, n, uv, idx, m))
        g.write()
    # Alpha: a black smooth metal quad (a mirror of Schlick reflectance ~0 seen head-on) whose alpha is 0.4 on its left
    # half and 0.6 on its right (base colour map alpha x COLOR_0 alpha of 1), MASK at 0.5;
    # BLEND at alpha 0.5 (the factor); a single-sided one (culled from behind).
    g = Gltf("test-mask")
    m = g.material({"doubleSided": True, "alphaMode": "MASK", "alphaCutoff": 0.5, "pbrMetallicRoughness": {
        "baseColorTexture": g.texture("test-mask.png", [[(0, 0, 0, 102), (0, 0, 0, 153)]], channels=4), "metallicFactor": 1, "roughnessFactor": 0}})
    p, n, uv, idx = quad()
    g.node(g.mesh(p, n, uv, idx, m, colors=[(1, 1, 1, 1)] * 4))
    g.write()
    for name, extra in (("test-blend", {"doubleSided": True, "alphaMode": "BLEND"}), ("test-single-sided", {})):
        g = Gltf(name)
        m = g.material(dict(extra, pbrMetallicRoughness={"baseColorFactor": [0, 0, 0, 0.5 if "blend" in name else 1],
                                                         "metallicFactor": 1, "roughnessFactor": 0}))
        g.node(g.mesh(*quad(), m))
        g.write()
    # The extensions' maps on a black base with no dielectric specular (specularFactor 0):
    # a smooth clearcoat whose clearcoatTexture (R) is 1 | 0, left | right; a specular
    # layer whose specularTexture (A) is 1 | 0 (and specularColorTexture white); a sheen
    # whose sheenColorTexture is white | black.
    for name, ext in (("test-clearcoat-map", lambda g: {"KHR_materials_specular": {"specularFactor": 0},
                                                        "KHR_materials_clearcoat": {"clearcoatFactor": 1, "clearcoatRoughnessFactor": 0,
                                                            "clearcoatTexture": g.texture("test-clearcoat-map.png", [[W, K]])}}),
                      ("test-specular-map", lambda g: {"KHR_materials_specular": {
                          "specularTexture": g.texture("test-specular-map.png", [[(0, 0, 0, 255), (0, 0, 0, 0)]], channels=4),
                          "specularColorTexture": g.texture("test-specular-color.png", [[W, W]])}}),
                      ("test-sheen-map", lambda g: {"KHR_materials_specular": {"specularFactor": 0},
                                                    "KHR_materials_sheen": {"sheenColorFactor": [1, 1, 1], "sheenRoughnessFactor": 0.5,
                                                        "sheenColorTexture": g.texture("test-sheen-map.png", [[W, K]])}})):
        g = Gltf(name)
        m = g.material({"doubleSided": True, "pbrMetallicRoughness": {"baseColorFactor": [0, 0, 0, 1], "metallicFactor": 0,
                        "roughnessFactor": 0}, "extensions": ext(g)})
        g.node(g.mesh(*quad(), m))
        g.write()


def box(lo, hi):
    """The closed box [lo, hi] (outward normals, counter-clockwise seen from outside)."""
    p, n, uv, idx = [], [], [], []
    for axis in range(3):
        for side in (0, 1):
            d = [0, 0, 0]
            d[axis] = 1 if side else -1
            u_axis, v_axis = (axis + 1) % 3, (axis + 2) % 3
            if not side:
                u_axis, v_axis = v_axis, u_axis
            base = len(p)
            for (a, b) in ((0, 0), (1, 0), (1, 1), (0, 1)):
                q = [0.0, 0.0, 0.0]
                q[axis] = hi[axis] if side else lo[axis]
                q[u_axis] = hi[u_axis] if a else lo[u_axis]
                q[v_axis] = hi[v_axis] if b else lo[v_axis]
                p.append(tuple(q))
                n.append(tuple(d))
                uv.append((a, b))
            idx += [base, base + 1, base + 2, base, base + 2, base + 3]
    return p, n, uv, idx


def volume_test():
    """test-volume: KHR_materials_volume's absorption (tests/gltf_materials_test.cpp): a
    closed slab [-1, 1]^2 x [-0.5, 0.5] of transmissive glass (ior 1.5, white, smooth) that
    keeps (0.5, 0.8, 0.2) of the light over each unit length inside."""
    g = Gltf("test-volume")
    m = g.material({"pbrMetallicRoughness": {"baseColorFactor": [1, 1, 1, 1], "metallicFactor": 0, "roughnessFactor": 0},
                    "extensions": {"KHR_materials_transmission": {"transmissionFactor": 1.0},
                                   "KHR_materials_volume": {"thicknessFactor": 1.0, "attenuationColor": [0.5, 0.8, 0.2],
                                                            "attenuationDistance": 1.0}}})
    g.node(g.mesh(*box((-1, -1, -0.5), (1, 1, 0.5)), m))
    g.write()


def punctual_lights():
    """KHR_lights_punctual: a grey floor and three spheres under a warm point light (with a
    range), a blue-white spot aimed down at the middle sphere and a dim directional light,
    seen by a camera node (docs/gltf.md: candela and lux taken 1:1 as our units)."""
    g = Gltf("punctual-lights")
    floor = g.material({"name": "floor", "pbrMetallicRoughness": {"baseColorFactor": [0.6, 0.6, 0.6, 1], "metallicFactor": 0,
                        "roughnessFactor": 0.9}})
    q = quad(3.0)  # kept alive: the accessor cache is keyed by id()
    mesh = g.mesh(*q, floor)
    g.doc["nodes"].append({"mesh": mesh, "rotation": [-0.70710678, 0, 0, 0.70710678]})  # z = 0 facing +z -> y = 0 facing +y
    g.doc["scenes"][0]["nodes"].append(len(g.doc["nodes"]) - 1)
    s = sphere(0.4)
    for i, colour in enumerate(([0.8, 0.2, 0.15, 1], [0.85, 0.85, 0.85, 1], [0.15, 0.3, 0.8, 1])):
        m = g.material({"name": "ball%d" % i, "pbrMetallicRoughness": {"baseColorFactor": colour, "metallicFactor": 0,
                        "roughnessFactor": 0.4}})
        g.node(g.mesh(*s, m), (1.2 * (i - 1), 0.4, 0))
    g.doc["extensions"] = {"KHR_lights_punctual": {"lights": [
        {"name": "warm point", "type": "point", "color": [1.0, 0.6, 0.3], "intensity": 40.0, "range": 8.0},
        {"name": "spot", "type": "spot", "color": [0.6, 0.8, 1.0], "intensity": 250.0,
         "spot": {"innerConeAngle": 0.15, "outerConeAngle": 0.3}},
        {"name": "sun", "type": "directional", "intensity": 2.0}]}}
    g.used.add("KHR_lights_punctual")
    light_nodes = [{"translation": [-1.6, 1.8, 1.0], "extensions": {"KHR_lights_punctual": {"light": 0}}},
                   # pointing down: -z turned -90 degrees about +x
                   {"translation": [0, 3.0, 0], "rotation": [-0.70710678, 0, 0, 0.70710678], "extensions": {"KHR_lights_punctual": {"light": 1}}},
                   # the sun from the upper right behind the camera: -z turned -50 degrees about +x, then 30 about +y
                   {"rotation": [-0.40821789, 0.23456972, 0.10938165, 0.8754261], "extensions": {"KHR_lights_punctual": {"light": 2}}}]
    g.doc["cameras"] = [{"type": "perspective", "perspective": {"yfov": 0.75, "znear": 0.1}}]
    light_nodes.append({"camera": 0, "translation": [0, 1.6, 4.2], "rotation": [-0.17364818, 0, 0, 0.98480775]})  # pitched 20 down
    for n in light_nodes:
        g.doc["nodes"].append(n)
        g.doc["scenes"][0]["nodes"].append(len(g.doc["nodes"]) - 1)
    g.write()


if __name__ == "__main__":
    os.makedirs(OUT, exist_ok=True)
    showcase()
    lobes()
    tests()
    volume_test()
    punctual_lights()
