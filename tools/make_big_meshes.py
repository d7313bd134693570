#!/usr/bin/env python3
"""The large meshes of the loading figures (docs/benchmarks.md), written reproducibly.

An icosahedron subdivided LEVEL times (default 8: 1,310,720 triangles, 655,362 vertices),
its vertices on the unit sphere (no normals: flat shading), written as
  OUT/million.obj                  OBJ (v, f)
  OUT/million.glb                  binary glTF (one BIN chunk: positions, indices)
  OUT/million.gltf + million.bin   the same glTF with its buffer in a file
and a scene for each (OUT/million-obj.xml, -glb.xml, -gltf.xml) placed as
scenes/bench/million.xml places its generated mesh (which is also displaced).

  python3 tools/make_big_meshes.py [OUT=build/bench-meshes] [LEVEL=8]
  build/native/pathtracer slices build/bench-meshes/million-glb.xml
"""
import json, os, struct, sys
from array import array

out = sys.argv[1] if len(sys.argv) > 1 else "build/bench-meshes"
level = int(sys.argv[2]) if len(sys.argv) > 2 else 8
os.makedirs(out, exist_ok=True)

t = (1 + 5 ** 0.5) / 2
verts = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t), (0, 1, -t),
         (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
def unit(v):
    n = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) ** 0.5
    return (v[0] / n, v[1] / n, v[2] / n)
verts = [unit(v) for v in verts]
faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2), (10, 7, 6),
         (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10),
         (8, 6, 7), (9, 8, 1)]
for _ in range(level):
    mid = {}
    def m(a, b):
        k = (a, b) if a < b else (b, a)
        i = mid.get(k)
        if i is None:
            va, vb = verts[a], verts[b]
            verts.append(unit(((va[0] + vb[0]) / 2, (va[1] + vb[1]) / 2, (va[2] + vb[2]) / 2)))
            i = mid[k] = len(verts) - 1
        return i
    nf = []
    for a, b, c in faces:
        ab, bc, ca = m(a, b), m(b, c), m(c, a)
        nf += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
    faces = nf

pos = array("f", [x for v in verts for x in v])
idx = array("I", [i for f in faces for i in f])
lo = [min(pos[k::3]) for k in range(3)]
hi = [max(pos[k::3]) for k in range(3)]

with open(os.path.join(out, "million.obj"), "w") as f:
    f.write("# icosphere level %d: %d triangles\n" % (level, len(faces)))
    f.write("".join("v %.7g %.7g %.7g\n" % v for v in verts))
    f.write("".join("f %d %d %d\n" % (a + 1, b + 1, c + 1) for a, b, c in faces))

pb, ib = pos.tobytes(), idx.tobytes()  # little-endian on our machines, as glTF
buf = pb + ib  # positions, indices
n = len(verts)
g = {"asset": {"version": "2.0", "generator": "tools/make_big_meshes.py"}, "scene": 0, "scenes": [{"nodes": [0]}],
     "nodes": [{"mesh": 0}],
     "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
     "accessors": [{"bufferView": 0, "componentType": 5126, "count": n, "type": "VEC3", "min": lo, "max": hi},
                   {"bufferView": 1, "componentType": 5125, "count": len(idx), "type": "SCALAR"}],
     "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": len(pb)},
                     {"buffer": 0, "byteOffset": len(pb), "byteLength": len(ib)}],
     "buffers": [{"byteLength": len(buf)}]}
js = json.dumps(g, separators=(",", ":")).encode()
js += b" " * (-len(js) % 4)
with open(os.path.join(out, "million.glb"), "wb") as f:
    f.write(struct.pack("<III", 0x46546C67, 2, 28 + len(js) + len(buf)))
    f.write(struct.pack("<II", len(js), 0x4E4F534A) + js + struct.pack("<II", len(buf), 0x004E4942) + buf)
g["buffers"] = [{"byteLength": len(buf), "uri": "million.bin"}]
with open(os.path.join(out, "million.gltf"), "w") as f:
    json.dump(g, f, indent=1)
with open(os.path.join(out, "million.bin"), "wb") as f:
    f.write(buf)

for kind in ("obj", "glb", "gltf"):
    with open(os.path.join(out, "million-%s.xml" % kind), "w") as f:
        f.write("""<!-- tools/make_big_meshes.py: an icosphere of %d triangles as %s -->
<SceneLevel dotWeight="true">
  <Camera position="0 1.2 3.2" up="0 1 0" yaw="90" pitch="-10"/>
  <Light position="-3 5 3" radius="0.5" color="1 0.95 0.9" intensity="80"/>
  <Environment color="0.3 0.35 0.45"/>
  <Objects>
    <Plane normal="0 1 0" d="-1.1"> <Attenuate color="0.6 0.6 0.6"><Diffuse/></Attenuate> </Plane>
    <Mesh src="million.%s"> <Attenuate color="0.75 0.55 0.4"><Diffuse/></Attenuate> </Mesh>
  </Objects>
</SceneLevel>
""" % (len(faces), kind.upper(), kind))
print("wrote %s: %d triangles, %d vertices; OBJ %.1f MB, GLB %.1f MB" % (
    out, len(faces), n, os.path.getsize(os.path.join(out, "million.obj")) / 1e6, os.path.getsize(os.path.join(out, "million.glb")) / 1e6))
