"""The meshes and number formatting of tools/gen_scenes.py (the NaN hunt's random scenes):
a small mesh file per call, with degenerate and sliver triangles and shading normals that
are flipped, zero or not unit length, as OBJ or the seed's JSON."""
import os


def fmt(x):
    return "%.7g" % x


def vec(v):
    return " ".join(fmt(c) for c in v)


def write_mesh(c):
    """A small mesh file: a jittered grid with degenerate and sliver triangles and normals
    that are flipped, zero or unnormalised; OBJ or the seed's JSON."""
    rng = c.rng
    n = rng.randint(2, 5)
    verts, normals, uvs = [], [], []
    for y in range(n + 1):
        for x in range(n + 1):
            verts.append([x / n - 0.5 + rng.uniform(-0.05, 0.05), rng.uniform(-0.2, 0.2), y / n - 0.5 + rng.uniform(-0.05, 0.05)])
            nn = [rng.uniform(-0.3, 0.3), 1.0, rng.uniform(-0.3, 0.3)]
            kind = rng.random()
            if kind < 0.2:
                nn = [-x for x in nn]  # opposite the geometric normal
            elif kind < 0.3:
                nn = [x * rng.choice((1e-3, 7.0)) for x in nn]  # not unit length
            normals.append(nn)
            uvs.append([x / n, y / n])
    tris = []
    for y in range(n):
        for x in range(n):
            a = y * (n + 1) + x
            b, cc, d = a + 1, a + n + 1, a + n + 2
            tris += [[a, b, d], [a, d, cc]]
    # Degenerate triangles (repeated vertex, collinear) and slivers (a vertex moved almost onto an edge).
    tris.append([0, 0, 1])
    tris.append([0, 1, 2] if n >= 2 else [0, 1, 1])
    verts.append([verts[0][i] + 1e-6 * (verts[1][i] - verts[0][i]) for i in range(3)])
    normals.append([0.0, -1.0, 0.0])
    uvs.append([0.0, 0.0])
    tris.append([0, 1, len(verts) - 1])
    verts.append([0.5 * (verts[0][i] + verts[1][i]) + (1e-7 if i == 1 else 0.0) for i in range(3)])
    normals.append([0.0, 1.0, 0.0])
    uvs.append([0.5, 0.0])
    tris.append([0, 1, len(verts) - 1])
    json = rng.random() < 0.5
    if json and rng.random() < 0.3:
        normals[rng.randrange(len(normals))] = [0.0, 0.0, 0.0]  # the seed's format allows a zero normal
    name = "gen-%d-%d.%s" % (c.seed, c.meshes, "json" if json else "obj")
    c.meshes += 1
    path = os.path.join(c.outdir, name)
    with open(path, "w") as f:
        if json:
            flat = lambda rows: ", ".join(fmt(x) for r in rows for x in r)
            f.write('{\n  "vertex": [%s],\n  "normal": [%s],\n  "uv": [%s],\n  "indices": [%s]\n}\n' % (
                flat(verts), flat(normals), flat(uvs), ", ".join(str(i) for t in tris for i in t)))
        else:
            for v in verts:
                f.write("v %s\n" % vec(v))
            for v in normals:
                f.write("vn %s\n" % vec(v))
            for v in uvs:
                f.write("vt %s\n" % vec(v))
            for t in tris:
                f.write("f %s\n" % " ".join("%d/%d/%d" % (i + 1, i + 1, i + 1) for i in t))
    return name
