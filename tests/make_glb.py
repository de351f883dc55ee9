#!/usr/bin/env python3
"""Writes a glTF 2.0 binary (.glb) test model: a floor, four boxes and a sphere with five materials and no
lights, so a viewer or page has to scatter its lights (lidr::scatterLights). --triangles N adds a finely
tessellated sphere to reach about N triangles (the page's large-model check). Python's standard library only.

    python3 tests/make_glb.py OUT.glb [--triangles N]
"""
import argparse
import json
import math
import struct


def box(cx, cy, cz, sx, sy, sz):
    """A closed box: 24 vertices (flat normals), 12 triangles."""
    pos, nor, idx = [], [], []
    faces = [((1, 0, 0), (0, 1, 0), (0, 0, 1)), ((-1, 0, 0), (0, 0, 1), (0, 1, 0)),
             ((0, 1, 0), (0, 0, 1), (1, 0, 0)), ((0, -1, 0), (1, 0, 0), (0, 0, 1)),
             ((0, 0, 1), (1, 0, 0), (0, 1, 0)), ((0, 0, -1), (0, 1, 0), (1, 0, 0))]
    for n, u, v in faces:
        base = len(pos)
        for a, b in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
            p = [n[i] + a * u[i] + b * v[i] for i in range(3)]
            pos.append((cx + p[0] * sx, cy + p[1] * sy, cz + p[2] * sz))
            nor.append(n)
        # counter-clockwise seen from outside: u x v == n for every face above
        idx += [base, base + 1, base + 2, base, base + 2, base + 3]
    return pos, nor, idx


def sphere(cx, cy, cz, r, rings, segments):
    pos, nor, idx = [], [], []
    for i in range(rings + 1):
        t = math.pi * i / rings
        for j in range(segments + 1):
            p = 2 * math.pi * j / segments
            n = (math.sin(t) * math.cos(p), math.cos(t), math.sin(t) * math.sin(p))
            pos.append((cx + r * n[0], cy + r * n[1], cz + r * n[2]))
            nor.append(n)
    for i in range(rings):
        for j in range(segments):
            a = i * (segments + 1) + j
            b = a + segments + 1
            idx += [a, a + 1, b, a + 1, b + 1, b]
    return pos, nor, idx


def floor(size, cells):
    pos, nor, idx = [], [], []
    for i in range(cells + 1):
        for j in range(cells + 1):
            pos.append((-size + 2 * size * j / cells, 0.0, -size + 2 * size * i / cells))
            nor.append((0.0, 1.0, 0.0))
    for i in range(cells):
        for j in range(cells):
            a = i * (cells + 1) + j
            b = a + cells + 1
            idx += [a, b, a + 1, a + 1, b, b + 1]
    return pos, nor, idx


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out")
    ap.add_argument("--triangles", type=int, default=0,
                    help="add a tessellated sphere so the model has about this many triangles")
    args = ap.parse_args()

    parts = [
        (floor(4.0, 8), (0.8, 0.8, 0.8)),
        (box(-2.0, 0.75, -1.5, 0.6, 0.75, 0.6), (0.9, 0.3, 0.25)),
        (box(2.0, 0.5, -1.0, 0.8, 0.5, 0.5), (0.25, 0.8, 0.3)),
        (box(-1.5, 0.4, 2.0, 0.4, 0.4, 0.9), (0.3, 0.4, 0.9)),
        (box(1.5, 1.0, 2.0, 0.5, 1.0, 0.5), (0.9, 0.85, 0.3)),
        (sphere(0.0, 1.0, 0.0, 1.0, 24, 32), (0.85, 0.85, 0.9)),
    ]
    if args.triangles > 0:
        # rings x segments x 2 triangles, indices kept 32-bit
        segments = max(8, int(math.sqrt(args.triangles / 2.0)))
        rings = max(4, args.triangles // (2 * segments))
        parts.append((sphere(0.0, 2.5, -3.0, 0.8, rings, segments), (0.6, 0.6, 0.65)))

    binary = bytearray()
    views, accessors, meshes, materials, nodes = [], [], [], [], []

    def add_view(data, target):
        while len(binary) % 4:
            binary.append(0)
        views.append({"buffer": 0, "byteOffset": len(binary), "byteLength": len(data), "target": target})
        binary.extend(data)
        return len(views) - 1

    for k, ((pos, nor, idx), colour) in enumerate(parts):
        pv = add_view(struct.pack("<%df" % (3 * len(pos)), *[c for p in pos for c in p]), 34962)
        nv = add_view(struct.pack("<%df" % (3 * len(nor)), *[c for n in nor for c in n]), 34962)
        iv = add_view(struct.pack("<%dI" % len(idx), *idx), 34963)
        lo = [min(p[i] for p in pos) for i in range(3)]
        hi = [max(p[i] for p in pos) for i in range(3)]
        accessors += [
            {"bufferView": pv, "componentType": 5126, "count": len(pos), "type": "VEC3", "min": lo, "max": hi},
            {"bufferView": nv, "componentType": 5126, "count": len(nor), "type": "VEC3"},
            {"bufferView": iv, "componentType": 5125, "count": len(idx), "type": "SCALAR"},
        ]
        materials.append({"name": "material%d" % k,
                          "pbrMetallicRoughness": {"baseColorFactor": list(colour) + [1.0],
                                                   "metallicFactor": 0.0, "roughnessFactor": 0.6}})
        meshes.append({"name": "part%d" % k, "primitives": [
            {"attributes": {"POSITION": 3 * k, "NORMAL": 3 * k + 1}, "indices": 3 * k + 2, "material": k}]})
        nodes.append({"mesh": k})
    while len(binary) % 4:
        binary.append(0)

    doc = {"asset": {"version": "2.0", "generator": "lidr tests/make_glb.py"},
           "scene": 0, "scenes": [{"nodes": list(range(len(nodes)))}], "nodes": nodes, "meshes": meshes,
           "materials": materials, "accessors": accessors, "bufferViews": views,
           "buffers": [{"byteLength": len(binary)}]}
    text = json.dumps(doc, separators=(",", ":")).encode()
    text += b" " * (-len(text) % 4)
    total = 12 + 8 + len(text) + 8 + len(binary)
    with open(args.out, "wb") as f:
        f.write(struct.pack("<III", 0x46546C67, 2, total))
        f.write(struct.pack("<II", len(text), 0x4E4F534A) + text)
        f.write(struct.pack("<II", len(binary), 0x004E4942) + bytes(binary))
    triangles = sum(len(p[0][2]) // 3 for p in parts)
    print("make_glb.py: wrote %s (%d triangles, %d bytes)" % (args.out, triangles, total))


if __name__ == "__main__":
    main()
