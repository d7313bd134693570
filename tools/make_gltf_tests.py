#!/usr/bin/env python3
"""Writes the small glTF files the tests use (our own work, CC0), run once; output committed:
  tests/fuzz/corpus/mesh_gltf/   seeds of the glTF fuzzer: a textured quad as .gltf (data URIs)
                                 and .glb (one BIN chunk holding the geometry and the PNG)
  tests/malformed/gltf/          the same quad broken in one way each (tests/malformed/expected.tsv)
  assets/models/textured-quad.*  the quad with its texture as a separate PNG (.gltf, by file URI)
                                 and embedded (.glb); tests/mesh_shading_test.cpp renders them
The quad: 4 vertices in the z = 0 plane (-1..1) with normals +z and uv, 2 triangles (uint16
indices), a material whose baseColorTexture is a 4x4 PNG of four 2x2 quadrants: red, green
(top row) / blue, white (bottom row), shown upright from +z."""
import base64, copy, json, os, struct, zlib

ROOT = os.path.join(os.path.dirname(__file__), "..")

def png(w, h, rows):  # rows of (r, g, b) tuples, top row first; 8-bit RGB, no filter
    raw = b"".join(b"\0" + bytes(c for px in row for c in px) for row in rows)
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))

R, G, B, W = (255, 0, 0), (0, 255, 0), (0, 0, 255), (255, 255, 255)
PNG = png(4, 4, [[R, R, G, G], [R, R, G, G], [B, B, W, W], [B, B, W, W]])
POS = [(-1, -1, 0), (1, -1, 0), (1, 1, 0), (-1, 1, 0)]
NOR = [(0, 0, 1)] * 4
UV = [(0, 1), (1, 1), (1, 0), (0, 0)]  # glTF uv: v down from the image's top row
IDX = [0, 1, 2, 0, 2, 3]

def pad4(b):
    return b + b"\0" * (-len(b) % 4)

def model(with_image=True, pos=POS, idx=IDX):
    blobs = [b"".join(struct.pack("<3f", *p) for p in pos), b"".join(struct.pack("<3f", *n) for n in NOR),
             b"".join(struct.pack("<2f", *t) for t in UV), struct.pack("<%dH" % len(idx), *idx)]
    views, buf = [], b""
    for b in blobs:
        views.append({"buffer": 0, "byteOffset": len(buf), "byteLength": len(b)})
        buf = pad4(buf + b)
    g = {
        "asset": {"version": "2.0", "generator": "pathtracer tools/make_gltf_tests.py"},
        "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}, "indices": 3, "material": 0}]}],
        "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [1, 1, 1, 1], "metallicFactor": 0.0, "roughnessFactor": 1.0}}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": len(pos), "type": "VEC3", "min": [-1, -1, 0], "max": [1, 1, 0]},
            {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3"},
            {"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC2"},
            {"bufferView": 3, "componentType": 5123, "count": len(idx), "type": "SCALAR"},
        ],
        "bufferViews": views,
    }
    if with_image:
        g["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {"index": 0}
        g["textures"] = [{"source": 0, "sampler": 0}]
        g["samplers"] = [{"magFilter": 9728, "minFilter": 9728}]
    return g, buf

def as_gltf(g, buf, image=PNG, indent=1):
    g = copy.deepcopy(g)
    g["buffers"] = [{"byteLength": len(buf), "uri": "data:application/octet-stream;base64," + base64.b64encode(buf).decode()}]
    if "textures" in g:
        g["images"] = [{"uri": "data:image/png;base64," + base64.b64encode(image).decode()}]
    return json.dumps(g, indent=indent).encode() + b"\n"

def as_glb(g, buf, image=PNG):
    g = copy.deepcopy(g)
    if "textures" in g:
        g["bufferViews"].append({"buffer": 0, "byteOffset": len(buf), "byteLength": len(image)})
        g["images"] = [{"bufferView": len(g["bufferViews"]) - 1, "mimeType": "image/png"}]
        buf = pad4(buf + image)
    g["buffers"] = [{"byteLength": len(buf)}]
    js = json.dumps(g, separators=(",", ":")).encode()
    js += b" " * (-len(js) % 4)
    out = struct.pack("<III", 0x46546C67, 2, 12 + 8 + len(js) + 8 + len(buf))
    return out + struct.pack("<II", len(js), 0x4E4F534A) + js + struct.pack("<II", len(buf), 0x004E4942) + buf

def write(rel, data):
    with open(os.path.join(ROOT, rel), "wb") as f:
        f.write(data)

g, buf = model()
seeds = "tests/fuzz/corpus/mesh_gltf/"
write(seeds + "quad-textured.gltf", as_gltf(g, buf, indent=None))
write(seeds + "quad-textured.glb", as_glb(g, buf))
plain, pbuf = model(with_image=False)
write(seeds + "quad.glb", as_glb(plain, pbuf))

bad = "tests/malformed/gltf/"
glb = as_glb(plain, pbuf)
write(bad + "truncated.glb", glb[: len(glb) // 2])
b = bytearray(glb)  # the BIN chunk claims every byte after its length field (tinygltf read 8 past the end)
at = 20 + struct.unpack_from("<I", glb, 12)[0]
struct.pack_into("<I", b, at, len(glb) - at - 4 - (len(glb) - at - 4) % 4)
write(bad + "bin-chunk-overrun.glb", bytes(b))
text = as_gltf(plain, pbuf).decode()
write(bad + "bad-json.gltf", text.replace('"nodes": [\n  0\n ]', '"nodes": [\n  0\n ]\n "nodes": []', 1).replace('"scene": 0,', '"scene": 0', 1).encode())
g2 = copy.deepcopy(plain); g2["accessors"][0]["count"] = 40
write(bad + "accessor-out-of-range.gltf", as_gltf(g2, pbuf))
g3, b3 = model(with_image=False, idx=[0, 1, 2, 0, 2, 9])
write(bad + "index-out-of-range.gltf", as_gltf(g3, b3))
g4 = json.loads(as_gltf(plain, pbuf)); g4["buffers"][0]["uri"] = "no-such.bin"
write(bad + "missing-buffer.gltf", json.dumps(g4, indent=1).encode() + b"\n")
g5 = copy.deepcopy(plain); g5["meshes"][0]["primitives"][0]["mode"] = 1
write(bad + "lines-mode.gltf", as_gltf(g5, pbuf))
nan = struct.unpack("<f", b"\0\0\xc0\x7f")[0]
g6, b6 = model(with_image=False, pos=[POS[0], (nan, -1, 0), POS[2], POS[3]])
write(bad + "nan-position.glb", as_glb(g6, b6))
g7 = copy.deepcopy(plain); g7["nodes"] = [{"mesh": 0, "children": [1]}, {"children": [0]}]
write(bad + "node-cycle.gltf", as_gltf(g7, pbuf))
g8 = copy.deepcopy(plain); g8["materials"][0]["pbrMetallicRoughness"]["baseColorFactor"] = [2, 1, 1, 1]
write(bad + "base-color-above-one.gltf", as_gltf(g8, pbuf))
g9 = copy.deepcopy(plain); g9["extras"] = "@"
write(bad + "deep-nesting.gltf", as_gltf(g9, pbuf).replace(b'"@"', b"[" * 100 + b"]" * 100))
g10 = copy.deepcopy(plain); g10["nodes"][0]["translation"] = [1e30, 0, 0]
write(bad + "absurd-translation.gltf", as_gltf(g10, pbuf))
g11 = json.loads(as_gltf(g, buf)); g11["images"][0]["uri"] = "no-such.png"
write(bad + "missing-image.gltf", json.dumps(g11, indent=1).encode() + b"\n")
write(bad + "bad-image.gltf", as_gltf(g, buf, image=b"this is not a PNG file at all"))
g12 = json.loads(as_gltf(g, buf)); g12["textures"][0]["source"] = 3
write(bad + "no-such-image.gltf", json.dumps(g12, indent=1).encode() + b"\n")
g13 = copy.deepcopy(g); del g13["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"]
write(bad + "texture-without-uv.gltf", as_gltf(g13, buf))

# The buffers parse_gltf_steps reads itself (the BIN chunk, buffer files), checked there.
g14 = json.loads(glb[20:20 + struct.unpack_from("<I", glb, 12)[0]])
g14["buffers"][0]["byteLength"] = len(pbuf) + 4  # more than the BIN chunk holds
js = json.dumps(g14, separators=(",", ":")).encode(); js += b" " * (-len(js) % 4)
write(bad + "bytelength-past-bin.glb", struct.pack("<III", 0x46546C67, 2, 28 + len(js) + len(pbuf)) +
      struct.pack("<II", len(js), 0x4E4F534A) + js + struct.pack("<II", len(pbuf), 0x004E4942) + pbuf)
g15 = json.loads(as_gltf(plain, pbuf)); g15["buffers"][0]["uri"] = "short-buffer-file.bin"
write(bad + "short-buffer-file.gltf", json.dumps(g15, indent=1).encode() + b"\n")
write(bad + "short-buffer-file.bin", pbuf[: len(pbuf) // 2])
g16 = copy.deepcopy(g); g16["extras"] = {}
t16 = bytearray(as_glb(g16, buf))  # the image's bufferView (the last) made to reach past the buffer
j16 = json.loads(bytes(t16[20:20 + struct.unpack_from("<I", t16, 12)[0]]))
j16["bufferViews"][-1]["byteLength"] += 64
js = json.dumps(j16, separators=(",", ":")).encode(); js += b" " * (-len(js) % 4)
binc = bytes(t16[20 + struct.unpack_from("<I", t16, 12)[0]:])
write(bad + "image-view-past-buffer.glb", struct.pack("<III", 0x46546C67, 2, 20 + len(js) + len(binc)) +
      struct.pack("<II", len(js), 0x4E4F534A) + js + binc)

models = "assets/models/"
write(models + "textured-quad.png", PNG)
q = json.loads(as_gltf(g, buf, indent=None)); q["images"][0]["uri"] = "textured-quad.png"
write(models + "textured-quad.gltf", json.dumps(q, separators=(",", ":")).encode() + b"\n")
write(models + "textured-quad.glb", as_glb(g, buf))
print("wrote", seeds, bad, models)
