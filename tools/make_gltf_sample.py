#!/usr/bin/env python3
"""Writes the project's sample glTF models (our own work, CC0), run once; output committed:
  assets/models/torus-instances.gltf  JSON with an embedded base64 buffer
  assets/models/torus-instances.glb   the same model as binary glTF
  scenes/gltf/torus-instances.glb     the same .glb again, as a scene of its own in the page's
                                      gallery (every .xml, .gltf and .glb under scenes/)
A torus mesh (normals, uv) used by three nodes, two of them children of a rotated parent
(instancing and a node hierarchy), with a metallic and a diffuse material."""
import base64, json, math, os, struct

R, r, NU, NV = 1.0, 0.35, 48, 24
pos, nor, uv, idx = [], [], [], []
for j in range(NV + 1):
    v = 2 * math.pi * j / NV
    for i in range(NU + 1):
        u = 2 * math.pi * i / NU
        c = (math.cos(u), 0.0, math.sin(u))
        n = (math.cos(v) * c[0], math.sin(v), math.cos(v) * c[2])
        pos.append((R * c[0] + r * n[0], r * n[1], R * c[2] + r * n[2]))
        nor.append(n)
        uv.append((i / NU, j / NV))
for j in range(NV):
    for i in range(NU):
        a = j * (NU + 1) + i
        b, c, d = a + 1, a + NU + 1, a + NU + 2
        idx += [a, c, b, b, c, d]

def pack(fmt, rows):
    return b"".join(struct.pack(fmt, *row) for row in rows)
blobs = [pack("<3f", pos), pack("<3f", nor), pack("<2f", uv), struct.pack("<%dI" % len(idx), *idx)]
views, offset = [], 0
for k, b in enumerate(blobs):
    views.append({"buffer": 0, "byteOffset": offset, "byteLength": len(b), "target": 34963 if k == 3 else 34962})
    offset += len(b)
    while offset % 4: offset += 1
buf = bytearray()
for b in blobs:
    buf += b
    while len(buf) % 4: buf += b"\0"
lo = [min(p[k] for p in pos) for k in range(3)]
hi = [max(p[k] for p in pos) for k in range(3)]
gltf = {
    "asset": {"version": "2.0", "generator": "pathtracer tools/make_gltf_sample.py"},
    "scene": 0,
    "scenes": [{"nodes": [0, 1]}],
    "nodes": [
        {"mesh": 0, "translation": [0, 0.35, 0]},
        {"rotation": [0, 0, 0.3826834, 0.9238795], "translation": [0, 1.6, 0], "children": [2, 3]},
        {"mesh": 1, "translation": [-1.2, 0, 0], "scale": [0.6, 0.6, 0.6]},
        {"mesh": 1, "translation": [1.2, 0, 0], "scale": [0.6, 0.6, 0.6]},
    ],
    "meshes": [
        {"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}, "indices": 3, "material": 0}]},
        {"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}, "indices": 3, "material": 1}]},
    ],
    "materials": [
        {"pbrMetallicRoughness": {"baseColorFactor": [0.95, 0.75, 0.4, 1], "metallicFactor": 1.0, "roughnessFactor": 0.25}},
        {"pbrMetallicRoughness": {"baseColorFactor": [0.2, 0.45, 0.8, 1], "metallicFactor": 0.0, "roughnessFactor": 0.8}},
    ],
    "accessors": [
        {"bufferView": 0, "componentType": 5126, "count": len(pos), "type": "VEC3", "min": lo, "max": hi},
        {"bufferView": 1, "componentType": 5126, "count": len(nor), "type": "VEC3"},
        {"bufferView": 2, "componentType": 5126, "count": len(uv), "type": "VEC2"},
        {"bufferView": 3, "componentType": 5125, "count": len(idx), "type": "SCALAR"},
    ],
    "bufferViews": views,
}
out = os.path.join(os.path.dirname(__file__), "..", "assets", "models")
text = dict(gltf, buffers=[{"byteLength": len(buf), "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(buf)).decode()}])
with open(os.path.join(out, "torus-instances.gltf"), "w") as f:
    json.dump(text, f, separators=(",", ":"))
js = json.dumps(dict(gltf, buffers=[{"byteLength": len(buf)}]), separators=(",", ":")).encode()
while len(js) % 4: js += b" "
glb = struct.pack("<III", 0x46546C67, 2, 12 + 8 + len(js) + 8 + len(buf))
glb += struct.pack("<II", len(js), 0x4E4F534A) + js + struct.pack("<II", len(buf), 0x004E4942) + bytes(buf)
for where in (out, os.path.join(os.path.dirname(__file__), "..", "scenes", "gltf")):
    with open(os.path.join(where, "torus-instances.glb"), "wb") as f:
        f.write(glb)
print("wrote", len(idx) // 3, "triangles per torus")
