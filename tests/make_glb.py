#!/usr/bin/env python3
"""Writes a glTF 2.0 binary (.glb) test model: a floor, four boxes and a sphere with five materials and no
lights, so a viewer or page has to scatter its lights (lidr::scatterLights). --triangles N adds a finely
tessellated sphere to reach about N triangles (the page's large-model check). --textured gives the parts
texture coordinates and glTF textures, embedded as PNG: the floor a base colour checker, a normal texture of
grooves, metallic-roughness and occlusion (repeated by KHR_texture_transform), the sphere emissive stripes
with emissiveFactor 1 and a metallic-roughness texture, one box an alpha MASK cut-out, double-sided.
--punctual adds KHR_lights_punctual lights in the specification's units: a warm 30 cd point light with range 5,
a blue 8 cd point light without range, an 80 cd spot light shining straight down and a 0.8 lux directional sun.
--metal-showcase writes another model instead, a helmet-like one without lights for the environment light
(issue 39): a metal shell with a panel texture (painted dielectric stripes on metal, roughness varying with
scratches, panel grooves in a normal texture, occlusion in them), a gold visor (smooth metal), a dark rough
metal neck ring and two ear pods with emissive strips: metallic, rough, textured and emissive, as the glTF
sample DamagedHelmet is, so a viewer without an environment shows its metal near-black.
Python's standard library only.

    python3 tests/make_glb.py OUT.glb [--triangles N] [--textured] [--punctual]
    python3 tests/make_glb.py OUT.glb --metal-showcase
"""
import argparse
import json
import math
import struct
import zlib


def png(width, height, texel):
    """An RGBA8 PNG of texel(x, y) -> (r, g, b, a), rows top to bottom."""
    rows = b"".join(b"\0" + bytes(c for x in range(width) for c in texel(x, y)) for y in range(height))

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b""))


def textures():
    """The --textured model's images: checker, grooves (normal), MR, occlusion, emissive stripes, cut-out."""
    def grooves(x, y):  # tangent-space normals of a groove every 16 texels in x and y
        gx = math.sin(2 * math.pi * x / 16) * 0.6 if x % 16 < 4 else 0.0
        gy = math.sin(2 * math.pi * y / 16) * 0.6 if y % 16 < 4 else 0.0
        n = (-gx, gy, 1.0)
        length = math.sqrt(sum(c * c for c in n))
        return tuple(int(round((c / length * 0.5 + 0.5) * 255)) for c in n) + (255,)
    return [
        png(64, 64, lambda x, y: (200, 190, 170, 255) if (x // 16 + y // 16) % 2 else (90, 60, 50, 255)),
        png(64, 64, grooves),
        png(64, 64, lambda x, y: (0, 60 if (x // 16 + y // 16) % 2 else 220, 0, 255)),
        png(64, 64, lambda x, y: ((90 if x % 16 < 4 or y % 16 < 4 else 255), 0, 0, 255)),
        png(64, 16, lambda x, y: (255, 160, 40, 255) if x % 16 < 3 else (0, 0, 0, 255)),
        png(32, 32, lambda x, y: (230, 230, 240, 0 if ((x - 16) ** 2 + (y - 16) ** 2) < 64 or x % 8 < 2 else 255)),
        png(8, 8, lambda x, y: (0, 90, 255, 255)),  # sphere: smooth metal
    ]


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


def grid_indices(rows, columns):
    """Two triangles per cell of a (rows + 1) x (columns + 1) vertex grid stored row by row."""
    idx = []
    for i in range(rows):
        for j in range(columns):
            a = i * (columns + 1) + j
            b = a + columns + 1
            idx += [a, b, a + 1, a + 1, b, b + 1]
    return idx


def floor(size, cells):
    pos, nor, idx = [], [], []
    for i in range(cells + 1):
        for j in range(cells + 1):
            pos.append((-size + 2 * size * j / cells, 0.0, -size + 2 * size * i / cells))
            nor.append((0.0, 1.0, 0.0))
    idx += grid_indices(cells, cells)
    return pos, nor, idx


class Glb:
    """A binary buffer, its views and accessors, written out as one .glb."""

    def __init__(self):
        self.binary = bytearray()
        self.views, self.accessors = [], []

    def view(self, data, target):
        while len(self.binary) % 4:
            self.binary.append(0)
        self.views.append({"buffer": 0, "byteOffset": len(self.binary), "byteLength": len(data)})
        if target:
            self.views[-1]["target"] = target
        self.binary.extend(data)
        return len(self.views) - 1

    def attributes(self, pos, nor, idx, uvs=None):
        """POSITION, NORMAL (and TEXCOORD_0) accessors and the index accessor of one primitive."""
        lo = [min(p[i] for p in pos) for i in range(3)]
        hi = [max(p[i] for p in pos) for i in range(3)]
        pv = self.view(struct.pack("<%df" % (3 * len(pos)), *[c for p in pos for c in p]), 34962)
        nv = self.view(struct.pack("<%df" % (3 * len(nor)), *[c for n in nor for c in n]), 34962)
        iv = self.view(struct.pack("<%dI" % len(idx), *idx), 34963)
        attributes = {"POSITION": len(self.accessors), "NORMAL": len(self.accessors) + 1}
        self.accessors += [
            {"bufferView": pv, "componentType": 5126, "count": len(pos), "type": "VEC3", "min": lo, "max": hi},
            {"bufferView": nv, "componentType": 5126, "count": len(nor), "type": "VEC3"},
            {"bufferView": iv, "componentType": 5125, "count": len(idx), "type": "SCALAR"},
        ]
        indices = len(self.accessors) - 1
        if uvs is not None:
            flat = [c for uv in uvs for c in uv]
            attributes["TEXCOORD_0"] = len(self.accessors)
            self.accessors.append({"bufferView": self.view(struct.pack("<%df" % len(flat), *flat), 34962),
                                   "componentType": 5126, "count": len(pos), "type": "VEC2"})
        return attributes, indices

    def write(self, path, doc):
        while len(self.binary) % 4:
            self.binary.append(0)
        doc.update({"accessors": self.accessors, "bufferViews": self.views,
                    "buffers": [{"byteLength": len(self.binary)}]})
        text = json.dumps(doc, separators=(",", ":")).encode()
        text += b" " * (-len(text) % 4)
        total = 12 + 8 + len(text) + 8 + len(self.binary)
        with open(path, "wb") as f:
            f.write(struct.pack("<III", 0x46546C67, 2, total))
            f.write(struct.pack("<II", len(text), 0x4E4F534A) + text)
            f.write(struct.pack("<II", len(self.binary), 0x004E4942) + bytes(self.binary))
        return total


def torus(cx, cy, cz, major, minor, rings, segments):
    """A ring about the y axis."""
    pos, nor, idx = [], [], []
    for i in range(rings + 1):
        u = 2 * math.pi * i / rings
        for j in range(segments + 1):
            v = 2 * math.pi * j / segments
            n = (math.cos(v) * math.cos(u), math.sin(v), math.cos(v) * math.sin(u))
            pos.append((cx + (major + minor * math.cos(v)) * math.cos(u), cy + minor * math.sin(v),
                        cz + (major + minor * math.cos(v)) * math.sin(u)))
            nor.append(n)
    idx += grid_indices(rings, segments)
    return pos, nor, idx


def metal_showcase(out):
    """The --metal-showcase helmet: see the module's text."""
    glb = Glb()
    size = 128

    def panel(x, y):  # panel edges every 32 texels; a painted stripe band; scratches
        edge = x % 32 < 2 or y % 32 < 2
        stripe = 40 <= y < 56
        scratch = (x * 7 + y * 13) % 29 == 0 or (x + 3 * y) % 37 == 0
        return edge, stripe, scratch

    def base(x, y):
        edge, stripe, _ = panel(x, y)
        if stripe:
            return (200, 40, 30, 255)  # red paint
        return (70, 70, 75, 255) if edge else (190, 190, 195, 255)

    def metal_rough(x, y):
        edge, stripe, scratch = panel(x, y)
        roughness = 200 if scratch else (150 if edge else 90)
        return (0, 150 if stripe else roughness, 0 if stripe else 255, 255)

    def normal(x, y):  # grooves at the panel edges
        gx = (0.7 if x % 32 == 0 else -0.7 if x % 32 == 1 else 0.0)
        gy = (0.7 if y % 32 == 0 else -0.7 if y % 32 == 1 else 0.0)
        n = (gx, gy, 1.0)
        length = math.sqrt(sum(c * c for c in n))
        return tuple(int(round((c / length * 0.5 + 0.5) * 255)) for c in n) + (255,)

    def occlusion(x, y):
        edge, _, _ = panel(x, y)
        return (110 if edge else 255, 0, 0, 255)

    images = [png(size, size, base), png(size, size, metal_rough), png(size, size, normal), png(size, size, occlusion),
              png(32, 8, lambda x, y: (40, 230, 255, 255) if 2 <= y < 6 and x % 8 < 5 else (0, 0, 0, 255))]
    image_list = [{"bufferView": glb.view(data, None), "mimeType": "image/png"} for data in images]

    def sphere_uv(pos, c):
        uv = []
        for p in pos:
            d = [p[i] - c[i] for i in range(3)]
            r = math.sqrt(sum(x * x for x in d)) or 1.0
            uv.append((math.atan2(d[2], d[0]) / (2 * math.pi) * 3.0 + 0.5,
                       math.acos(max(-1.0, min(1.0, d[1] / r))) / math.pi * 1.5))
        return uv

    def cut(part, keep):
        """The triangles of (pos, nor, idx) whose centroid passes keep(x, y, z)."""
        pos, nor, idx = part
        kept = []
        for t in range(0, len(idx), 3):
            c = [sum(pos[idx[t + k]][i] for k in range(3)) / 3 for i in range(3)]
            if keep(*c):
                kept += idx[t:t + 3]
        return pos, nor, kept

    shell = cut(sphere(0.0, 0.0, 0.0, 1.0, 48, 64), lambda x, y, z: y > -0.55 and not (z > 0.45 and -0.35 < y < 0.45))
    visor = cut(sphere(0.0, 0.02, 0.04, 0.96, 48, 64), lambda x, y, z: z > 0.4 and -0.4 < y < 0.5)
    ring = torus(0.0, -0.62, 0.0, 0.78, 0.14, 48, 16)
    ear_l, ear_r = box(-1.0, 0.05, 0.0, 0.12, 0.28, 0.28), box(1.0, 0.05, 0.0, 0.12, 0.28, 0.28)

    def ear_uv(pos):
        return [((p[2] + 0.28) / 0.56, (p[1] + 0.23) / 0.56) for p in pos]

    textured = {"baseColorTexture": {"index": 0}, "metallicRoughnessTexture": {"index": 1},
                "metallicFactor": 1.0, "roughnessFactor": 1.0, "baseColorFactor": [1, 1, 1, 1]}
    materials = [
        {"name": "shell", "pbrMetallicRoughness": textured, "normalTexture": {"index": 2, "scale": 1.0},
         "occlusionTexture": {"index": 3, "strength": 1.0}},
        {"name": "gold visor", "pbrMetallicRoughness": {"baseColorFactor": [1.0, 0.78, 0.34, 1.0],
                                                         "metallicFactor": 1.0, "roughnessFactor": 0.12}},
        {"name": "neck ring", "pbrMetallicRoughness": {"baseColorFactor": [0.35, 0.35, 0.38, 1.0],
                                                        "metallicFactor": 1.0, "roughnessFactor": 0.5}},
        {"name": "ear pods", "pbrMetallicRoughness": {"baseColorFactor": [0.55, 0.56, 0.6, 1.0],
                                                       "metallicFactor": 1.0, "roughnessFactor": 0.35},
         "emissiveFactor": [1, 1, 1], "emissiveTexture": {"index": 4}},
    ]
    parts = [(shell, 0, sphere_uv(shell[0], (0, 0, 0))), (visor, 1, None), (ring, 2, None),
             (ear_l, 3, ear_uv(ear_l[0])), (ear_r, 3, ear_uv(ear_r[0]))]
    meshes, nodes = [], []
    for k, ((pos, nor, idx), material, uvs) in enumerate(parts):
        attributes, indices = glb.attributes(pos, nor, idx, uvs)
        meshes.append({"name": "part%d" % k, "primitives": [{"attributes": attributes, "indices": indices,
                                                              "material": material}]})
        nodes.append({"mesh": k})
    doc = {"asset": {"version": "2.0", "generator": "lidr tests/make_glb.py --metal-showcase"},
           "scene": 0, "scenes": [{"nodes": list(range(len(nodes)))}], "nodes": nodes, "meshes": meshes,
           "materials": materials, "images": image_list,
           "textures": [{"source": i} for i in range(len(image_list))]}
    total = glb.write(out, doc)
    triangles = sum(len(p[0][2]) // 3 for p in parts)
    print("make_glb.py: wrote %s (%d triangles, %d bytes, --metal-showcase)" % (out, triangles, total))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out")
    ap.add_argument("--triangles", type=int, default=0,
                    help="add a tessellated sphere so the model has about this many triangles")
    ap.add_argument("--textured", action="store_true", help="texture coordinates and glTF textures (see above)")
    ap.add_argument("--punctual", action="store_true", help="KHR_lights_punctual point and spot lights (see above)")
    ap.add_argument("--metal-showcase", action="store_true",
                    help="a helmet-like metallic, rough, textured, emissive model without lights (see above)")
    args = ap.parse_args()
    if args.metal_showcase:
        metal_showcase(args.out)
        return

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

    glb = Glb()
    meshes, materials, nodes = [], [], []

    images = []
    if args.textured:
        for data in textures():
            images.append({"bufferView": glb.view(data, None), "mimeType": "image/png"})

    def uv_of(k, p, n):
        """Texture coordinates: the floor's world x, z; the sphere's longitude, latitude; a box's face plane."""
        if k == 0:
            return ((p[0] + 4.0) / 8.0, (p[2] + 4.0) / 8.0)
        if k == 5:
            d = [p[0] - 0.0, p[1] - 1.0, p[2] - 0.0]
            return (math.atan2(d[2], d[0]) / (2 * math.pi) + 0.5, math.acos(max(-1.0, min(1.0, d[1]))) / math.pi)
        axis = max(range(3), key=lambda i: abs(n[i]))
        a, b = [i for i in range(3) if i != axis]
        return (p[a] * 0.8, p[b] * 0.8)

    for k, ((pos, nor, idx), colour) in enumerate(parts):
        uvs = [uv_of(k, p, n) for p, n in zip(pos, nor)] if args.textured else None
        attributes, indices = glb.attributes(pos, nor, idx, uvs)
        material = {"name": "material%d" % k,
                    "pbrMetallicRoughness": {"baseColorFactor": list(colour) + [1.0],
                                             "metallicFactor": 0.0, "roughnessFactor": 0.6}}
        if args.textured:
            repeat = {"extensions": {"KHR_texture_transform": {"scale": [4, 4]}}}
            pbr = material["pbrMetallicRoughness"]
            if k == 0:  # floor: checker, grooves, MR, occlusion, repeated 4 times
                pbr.update({"baseColorFactor": [1, 1, 1, 1], "baseColorTexture": dict({"index": 0}, **repeat),
                            "metallicRoughnessTexture": dict({"index": 2}, **repeat), "metallicFactor": 1.0,
                            "roughnessFactor": 1.0})
                material["normalTexture"] = dict({"index": 1, "scale": 1.0}, **repeat)
                material["occlusionTexture"] = dict({"index": 3, "strength": 1.0}, **repeat)
            elif k == 5:  # sphere: emissive stripes at factor 1, smooth metal
                material["emissiveFactor"] = [1, 1, 1]
                material["emissiveTexture"] = {"index": 4}
                pbr.update({"metallicRoughnessTexture": {"index": 6}, "metallicFactor": 1.0, "roughnessFactor": 1.0})
            elif k == 1:  # a cut-out box, seen through its holes
                pbr["baseColorTexture"] = {"index": 5}
                material.update({"alphaMode": "MASK", "alphaCutoff": 0.5, "doubleSided": True})
        materials.append(material)
        meshes.append({"name": "part%d" % k, "primitives": [
            {"attributes": attributes, "indices": indices, "material": k}]})
        nodes.append({"mesh": k})

    doc = {"asset": {"version": "2.0", "generator": "lidr tests/make_glb.py"},
           "scene": 0, "scenes": [{"nodes": list(range(len(nodes)))}], "nodes": nodes, "meshes": meshes,
           "materials": materials}
    if images:
        doc.update({"images": images, "textures": [{"source": i} for i in range(len(images))],
                    "extensionsUsed": ["KHR_texture_transform"]})
    if args.punctual:
        doc["extensions"] = {"KHR_lights_punctual": {"lights": [
            {"name": "warm", "type": "point", "color": [1.0, 0.85, 0.7], "intensity": 30.0, "range": 5.0},
            {"name": "blue, no range", "type": "point", "color": [0.5, 0.7, 1.0], "intensity": 8.0},
            {"name": "spot", "type": "spot", "intensity": 80.0,
             "spot": {"innerConeAngle": 0.25, "outerConeAngle": 0.5}},
            {"name": "sun", "type": "directional", "color": [1.0, 0.95, 0.85], "intensity": 0.8}]}}
        down = [-math.sqrt(0.5), 0.0, 0.0, math.sqrt(0.5)]  # -90 degrees about x: the spot's -z points down
        slant = [-0.5, 0.5, 0.0, math.sqrt(0.5)]  # the sun's -z tilted down and sideways (a unit quaternion)
        for light, node in enumerate([{"translation": [-1.0, 2.2, 1.2]}, {"translation": [2.2, 1.2, 0.5]},
                                      {"translation": [1.5, 3.5, -1.2], "rotation": down}, {"rotation": slant}]):
            node["extensions"] = {"KHR_lights_punctual": {"light": light}}
            nodes.append(node)
        doc["scenes"][0]["nodes"] = list(range(len(nodes)))
        doc["extensionsUsed"] = doc.get("extensionsUsed", []) + ["KHR_lights_punctual"]
    total = glb.write(args.out, doc)
    triangles = sum(len(p[0][2]) // 3 for p in parts)
    print("make_glb.py: wrote %s (%d triangles, %d bytes)" % (args.out, triangles, total))


if __name__ == "__main__":
    main()
