#!/usr/bin/env python3
"""Writes the glTF validation corpus: malformed and extreme glTF 2.0 files (and OBJ / MTL / scene files for the
same classes: file kinds, limits), each with the outcome the glTF 2.0
specification (and lidr's documented limits, doc/scene-format.md) asks for.

    python3 tests/gltf_corpus/make_corpus.py OUT_DIR [--fuzz-seeds DIR]

OUT_DIR/<case>/ holds each case's files (a case may need a .bin, an image, a directory, a FIFO or a symbolic
link next to it); OUT_DIR/cases.json lists {"name", "file", "expect": "error"|"ok"|"warning", "message"}: an
error's message must contain the file name and `message` (the JSON pointer and the rule); a warning case loads
and one Scene::warnings line contains `message`. --fuzz-seeds also writes every self-contained case under 8 KiB
into DIR (the seed corpus of tests/fuzz/fuzz_gltf). Python 3 standard library only.
"""
import base64
import copy
import json
import os
import struct
import sys
import zlib


def png(width, height, declared=None):
    """An RGBA8 PNG of width x height (solid grey); `declared` overrides the size in the IHDR header only."""
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)
    w, h = declared or (width, height)
    ihdr = struct.pack(">IIBBBBB", w, h, 8, 6, 0, 0, 0)
    raw = b"".join(b"\x00" + b"\x80\x80\x80\xff" * width for _ in range(height))
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b"")


def jpeg_header(width, height):
    """The start of a baseline JPEG: SOI, an APP0 segment, then SOF0 with the size (enough for a header check)."""
    app0 = b"\xff\xe0" + struct.pack(">H", 16) + b"JFIF\x00\x01\x01\x00\x00\x01\x00\x01\x00\x00"
    sof0 = b"\xff\xc0" + struct.pack(">HBHHB", 11, 8, height, width, 1) + b"\x01\x11\x00"
    return b"\xff\xd8" + app0 + sof0 + b"\xff\xd9"


def data_uri(mime, data):
    return "data:%s;base64,%s" % (mime, base64.b64encode(data).decode())


# One triangle: 3 float positions (36 bytes), 3 unsigned short indices (6 bytes, padded to 8).
POSITIONS = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0)
INDICES = struct.pack("<3H", 0, 1, 2) + b"\x00\x00"
BIN = POSITIONS + INDICES


def triangle():
    return {
        "asset": {"version": "2.0", "generator": "lidr make_corpus.py"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
            {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"},
        ],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
        "buffers": [{"byteLength": len(BIN), "uri": data_uri("application/octet-stream", BIN)}],
    }


def textured():
    doc = triangle()
    doc["meshes"][0]["primitives"][0]["material"] = 0
    doc["materials"] = [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}]
    doc["textures"] = [{"source": 0, "sampler": 0}]
    doc["samplers"] = [{"magFilter": 9729, "minFilter": 9987, "wrapS": 10497, "wrapT": 10497}]
    doc["images"] = [{"uri": data_uri("image/png", png(2, 2))}]
    return doc


def lit():
    doc = triangle()
    doc["extensionsUsed"] = ["KHR_lights_punctual"]
    doc["extensions"] = {"KHR_lights_punctual": {"lights": [{"type": "point", "color": [1, 1, 1], "intensity": 1, "range": 5}]}}
    doc["nodes"].append({"translation": [0, 1, 1], "extensions": {"KHR_lights_punctual": {"light": 0}}})
    doc["scenes"][0]["nodes"].append(1)
    return doc


def full():
    """Every kind of object lidr's index rules reach: material, texture, sampler, image, camera, light, skin,
    animation, children."""
    doc = textured()
    doc["extensionsUsed"] = ["KHR_lights_punctual"]
    doc["extensions"] = {"KHR_lights_punctual": {"lights": [{"type": "point", "range": 5}]}}
    doc["cameras"] = [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1}}]
    doc["nodes"] = [{"mesh": 0, "children": [1, 2]}, {"camera": 0, "translation": [0, 0, 3]},
                    {"extensions": {"KHR_lights_punctual": {"light": 0}}, "translation": [0, 0, 1]}]
    return doc


def animated(times=(0.0, 1.0), values=((0, 0, 0), (1, 0, 0)), path="translation", interpolation="LINEAR",
             value_type="VEC3", component_type=5126):
    """The triangle's node moved by one channel: key times and values in a second buffer (floats)."""
    doc = triangle()
    data = struct.pack("<%df" % len(times), *times)
    flat = [x for v in values for x in v]
    data += struct.pack("<%df" % len(flat), *flat)
    doc["buffers"].append({"byteLength": len(data), "uri": data_uri("application/octet-stream", data)})
    doc["bufferViews"] += [{"buffer": 1, "byteOffset": 0, "byteLength": 4 * len(times)},
                           {"buffer": 1, "byteOffset": 4 * len(times), "byteLength": 4 * len(flat)}]
    doc["accessors"] += [{"bufferView": 2, "componentType": 5126, "count": len(times), "type": "SCALAR",
                          "min": [min(times)], "max": [max(times)]},
                         {"bufferView": 3, "componentType": component_type, "count": len(values), "type": value_type}]
    doc["animations"] = [{"samplers": [{"input": 2, "output": 3, "interpolation": interpolation}],
                          "channels": [{"sampler": 0, "target": {"node": 0, "path": path}}]}]
    return doc


def instanced(primitives, corners, nodes):
    """One triangle strip of `corners` u8 indices, `primitives` times in one mesh, instanced by `nodes` nodes:
    a small file declaring nodes x primitives x (corners - 2) triangles."""
    strip = bytes(i % 3 for i in range(corners))
    data = POSITIONS + strip
    doc = triangle()
    doc["accessors"][1] = {"bufferView": 1, "componentType": 5121, "count": corners, "type": "SCALAR"}
    doc["bufferViews"][1] = {"buffer": 0, "byteOffset": 36, "byteLength": corners}
    doc["buffers"] = [{"byteLength": len(data), "uri": data_uri("application/octet-stream", data)}]
    doc["meshes"][0]["primitives"] = [{"attributes": {"POSITION": 0}, "indices": 1, "mode": 5}] * primitives
    doc["nodes"] = [{"mesh": 0} for _ in range(nodes)]
    doc["scenes"][0]["nodes"] = list(range(nodes))
    return doc


def glb(doc, bin_chunk=BIN, version=2, length_delta=0, json_type=b"JSON", bin_type=b"BIN\x00", swap=False,
        json_pad=b" ", extra=b"", byte_length=None, text=None):
    """A GLB of `doc` (its buffer 0 made the BIN chunk) or of JSON `text`, with the given defects."""
    doc = copy.deepcopy(doc)
    if bin_chunk is not None and doc is not None:
        doc["buffers"] = [{"byteLength": byte_length or len(bin_chunk)}]
    text = text if text is not None else json.dumps(doc).encode()
    while len(text) % 4:
        text += json_pad
    chunks = [struct.pack("<I", len(text)) + json_type + text]
    if bin_chunk is not None:
        chunks.append(struct.pack("<I", len(bin_chunk)) + bin_type + bin_chunk)
    if swap:
        chunks.reverse()
    body = b"".join(chunks) + extra
    return b"glTF" + struct.pack("<II", version, 12 + len(body) + length_delta) + body


class Corpus:
    def __init__(self):
        self.cases = []
        self.names = set()

    def add(self, name, doc, expect, message="", main="case.gltf", files=None, raw=None, setup=None):
        """doc: a dict written as JSON (or raw: the main file's bytes); files: other files {name: bytes};
        setup: a function(dir) making special files (FIFO, links, directories)."""
        assert name not in self.names, name
        self.names.add(name)
        self.cases.append(dict(name=name, doc=doc, raw=raw, main=main, files=files or {}, setup=setup,
                               expect=expect, message=message))

    def error(self, name, doc, message, **kw):
        self.add(name, doc, "error", message, **kw)


def mutate(base, change):
    doc = base()
    change(doc)
    return doc


def set_at(doc, pointer, value):
    keys = [int(k) if k.isdigit() else k for k in pointer.strip("/").split("/")]
    node = doc
    for k in keys[:-1]:
        node = node[k]
    node[keys[-1]] = value


def remove_at(doc, pointer):
    keys = [int(k) if k.isdigit() else k for k in pointer.strip("/").split("/")]
    node = doc
    for k in keys[:-1]:
        node = node[k]
    del node[keys[-1]]


def build():
    c = Corpus()
    ok = lambda name, doc, **kw: c.add(name, doc, "ok", **kw)

    # ---- valid files ------------------------------------------------------------------------------------------
    ok("valid-triangle", triangle())
    ok("valid-textured", textured())
    ok("valid-lit", lit())
    ok("valid-full", full())
    ok("valid-no-scenes", mutate(triangle, lambda d: (d.pop("scene"), d.pop("scenes"))))
    ok("valid-version-2.1", mutate(triangle, lambda d: set_at(d, "/asset/version", "2.1")))
    ok("valid-minversion-2.0", mutate(triangle, lambda d: set_at(d, "/asset/minVersion", "2.0")))
    ok("valid-stride-12", mutate(triangle, lambda d: set_at(d, "/bufferViews/0/byteStride", 12)))
    ok("valid-matrix-affine", mutate(triangle, lambda d: set_at(d, "/nodes/0/matrix",
                                                                [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 2, 3, 4, 1])))
    ok("valid-unit-quaternion", mutate(triangle, lambda d: set_at(d, "/nodes/0/rotation", [0, 0.7071068, 0, 0.7071068])))
    ok("valid-deep-extras", mutate(triangle, lambda d: set_at(d, "/extras", json.loads("[" * 100 + "]" * 100))))
    ok("valid-strip", mutate(triangle, lambda d: set_at(d, "/meshes/0/primitives/0/mode", 5)))
    ok("valid-fan", mutate(triangle, lambda d: set_at(d, "/meshes/0/primitives/0/mode", 6)))
    ok("valid-no-indices", mutate(triangle, lambda d: remove_at(d, "/meshes/0/primitives/0/indices")))
    # Valid, but all-zero positions draw nothing: the primitive is left out with a warning (lights keep the file).
    c.add("valid-zero-positions", mutate(lit, lambda d: remove_at(d, "/accessors/0/bufferView")), "warning",
          "POSITION has no buffer view (all zeros)")
    ok("valid-external-bin", mutate(triangle, lambda d: set_at(d, "/buffers/0/uri", "tri.bin")), files={"tri.bin": BIN})
    ok("valid-external-bin-space", mutate(triangle, lambda d: set_at(d, "/buffers/0/uri", "my%20tri.bin")),
       files={"my tri.bin": BIN})
    ok("valid-external-png", mutate(textured, lambda d: set_at(d, "/images/0/uri", "grey.png")), files={"grey.png": png(2, 2)})
    ok("valid-gltf-buffer-mime", mutate(triangle, lambda d: set_at(d, "/buffers/0/uri", data_uri("application/gltf-buffer", BIN))))
    ok("valid-glb", None, main="case.glb", raw=glb(triangle()))
    ok("valid-glb-lit", None, main="case.glb", raw=glb(lit()))
    ok("valid-glb-unknown-chunk", None, main="case.glb", raw=glb(triangle(), extra=struct.pack("<I", 4) + b"XTRA" + b"\x00" * 4))
    ok("valid-alpha-blend", mutate(textured, lambda d: set_at(d, "/materials/0/alphaMode", "BLEND")))
    ok("valid-light-no-range", mutate(lit, lambda d: remove_at(d, "/extensions/KHR_lights_punctual/lights/0/range")))
    ok("valid-camera-zfar", mutate(full, lambda d: set_at(d, "/cameras/0/perspective/zfar", 100)))

    # ---- warnings: allowed by the specification, not drawn by lidr --------------------------------------------
    c.add("warn-extension-used", mutate(triangle, lambda d: set_at(d, "/extensionsUsed", ["EXT_unknown_feature"])),
          "warning", "extension EXT_unknown_feature")
    c.add("warn-skin", mutate(triangle, lambda d: (set_at(d, "/skins", [{"joints": [0], "name": "rig"}]),
                                                   set_at(d, "/nodes/0/skin", 0))),
          "warning", "skin 0 'rig' (1 joints) is not applied: its meshes are drawn in their bind pose")
    c.add("warn-animation-weights", animated(values=((0, 0, 0), (1, 0, 0)), path="weights"),
          "warning", "animation 0: 1 morph target weight channel not played (the base shape is drawn)")
    ok("valid-animation-translation", animated())
    ok("valid-animation-rotation-step", animated(values=((0, 0, 0, 1), (0, 0, 1, 0)), path="rotation",
                                                 interpolation="STEP", value_type="VEC4"))
    ok("valid-animation-cubic", animated(values=((0, 0, 0), (0, 0, 0), (1, 0, 0), (1, 0, 0), (2, 0, 0), (0, 0, 0)),
                                         interpolation="CUBICSPLINE"))
    c.add("warn-morph", mutate(triangle, lambda d: set_at(d, "/meshes/0/primitives/0/targets", [{"POSITION": 0}])),
          "warning", "morph targets are not applied")
    ok("valid-alpha-mask", mutate(textured, lambda d: (set_at(d, "/materials/0/alphaMode", "MASK"),
                                                        set_at(d, "/materials/0/alphaCutoff", 0.3))))
    c.add("warn-texcoord1-missing", mutate(textured, lambda d: set_at(d, "/materials/0/pbrMetallicRoughness/baseColorTexture/texCoord", 1)),
          "warning", "reads TEXCOORD_1, which the primitive does not have")
    # Spot lights are drawn (issue 29): a valid one loads without a warning.
    ok("valid-spot-light", mutate(lit, lambda d: set_at(d, "/extensions/KHR_lights_punctual/lights/0",
                                                        {"type": "spot", "spot": {"outerConeAngle": 0.5}})))
    c.add("warn-orthographic", mutate(full, lambda d: set_at(d, "/cameras/0", {
        "type": "orthographic", "orthographic": {"xmag": 1, "ymag": 1, "znear": 0, "zfar": 10}})),
          "warning", "orthographic cameras are not supported")

    # ---- asset ------------------------------------------------------------------------------------------------
    c.error("asset-missing", mutate(triangle, lambda d: d.pop("asset")), "/asset: required property missing")
    c.error("asset-not-object", mutate(triangle, lambda d: set_at(d, "/asset", "2.0")), "/asset: must be an object, got string")
    c.error("asset-version-missing", mutate(triangle, lambda d: set_at(d, "/asset", {})), "/asset/version: required property missing")
    c.error("asset-version-number", mutate(triangle, lambda d: set_at(d, "/asset/version", 2.0)), "/asset/version: must be a string")
    c.error("asset-version-1", mutate(triangle, lambda d: set_at(d, "/asset/version", "1.0")), "/asset/version: glTF 1.0 is not 2.x")
    c.error("asset-version-3", mutate(triangle, lambda d: set_at(d, "/asset/version", "3.0")), "/asset/version: glTF 3.0 is not 2.x")
    c.error("asset-version-garbage", mutate(triangle, lambda d: set_at(d, "/asset/version", "two")), "is not a version MAJOR.MINOR")
    c.error("asset-minversion-2.1", mutate(triangle, lambda d: (set_at(d, "/asset/version", "2.1"), set_at(d, "/asset/minVersion", "2.1"))),
            "/asset/minVersion: the file needs glTF 2.1")
    c.error("asset-minversion-above-version", mutate(triangle, lambda d: set_at(d, "/asset/minVersion", "2.1")),
            "/asset/minVersion: minVersion 2.1 is above version 2.0")
    c.error("root-array", None, "/: the document must be a JSON object", raw=b"[]")
    c.error("root-empty-file", None, "the file is empty", raw=b"")
    c.error("json-syntax", None, "/: malformed JSON", raw=b'{"asset": {"version": "2.0"},')
    c.error("json-deep-extras-100000", None, "JSON nested deeper than 128",
            raw=b'{"asset":{"version":"2.0"},"extras":' + b"[" * 100000 + b"]" * 100000 + b"}")
    c.error("json-deep-objects", None, "JSON nested deeper than 128",
            raw=b'{"asset":{"version":"2.0"},"extras":' + b'{"a":' * 200 + b"1" + b"}" * 200 + b"}")
    c.error("json-deep-unclosed", None, "JSON nested deeper than 128", raw=b"[" * 1000000)

    # ---- top-level arrays and JSON types ------------------------------------------------------------------------
    for array in ["accessors", "buffers", "bufferViews", "meshes", "nodes", "scenes", "materials", "textures", "images",
                  "samplers", "cameras", "skins", "animations"]:
        c.error("type-%s-object" % array, mutate(triangle, lambda d, a=array: set_at(d, "/" + a, {})),
                "/%s: must be an array, got object" % array)
        c.error("type-%s-entry-number" % array, mutate(triangle, lambda d, a=array: set_at(d, "/" + a, [1])),
                "/%s/0: must be an object, got number" % array)
    c.error("type-children-string", mutate(triangle, lambda d: set_at(d, "/nodes/0/children", "1")),
            "/nodes/0/children: must be an array, got string")
    c.error("type-primitives-object", mutate(triangle, lambda d: set_at(d, "/meshes/0/primitives", {"attributes": {"POSITION": 0}})),
            "/meshes/0/primitives: must be an array, got object")
    c.error("type-primitives-empty", mutate(triangle, lambda d: set_at(d, "/meshes/0/primitives", [])),
            "/meshes/0/primitives: must have at least one primitive")
    c.error("type-primitives-missing", mutate(triangle, lambda d: set_at(d, "/meshes/0", {})),
            "/meshes/0/primitives: required property missing")
    c.error("type-attributes-array", mutate(triangle, lambda d: set_at(d, "/meshes/0/primitives/0/attributes", [0])),
            "/meshes/0/primitives/0/attributes: must be an object, got array")
    c.error("type-mesh-index-string", mutate(triangle, lambda d: set_at(d, "/nodes/0/mesh", "0")),
            "/nodes/0/mesh: must be an integer, got string")
    c.error("type-mesh-index-float", mutate(triangle, lambda d: set_at(d, "/nodes/0/mesh", 0.0)),
            "/nodes/0/mesh: must be an integer, got number 0")
    c.error("type-mesh-index-fraction", mutate(triangle, lambda d: set_at(d, "/nodes/0/mesh", 0.5)),
            "/nodes/0/mesh: must be an integer, got number 0.5")
    c.error("type-count-string", mutate(triangle, lambda d: set_at(d, "/accessors/0/count", "3")),
            "/accessors/0/count: must be an integer, got string")
    c.error("type-normalized-number", mutate(triangle, lambda d: set_at(d, "/accessors/1/normalized", 1)),
            "/accessors/1/normalized: must be true or false")
    c.error("type-translation-string", mutate(triangle, lambda d: set_at(d, "/nodes/0/translation", "0 0 0")),
            "/nodes/0/translation: must be an array, got string")
    c.error("type-translation-2", mutate(triangle, lambda d: set_at(d, "/nodes/0/translation", [0, 0])),
            "/nodes/0/translation: must have 3 numbers, got 2")
    c.error("type-translation-null", mutate(triangle, lambda d: set_at(d, "/nodes/0/translation", [0, None, 0])),
            "/nodes/0/translation/1: must be a number, got null")
    c.error("type-scale-4", mutate(triangle, lambda d: set_at(d, "/nodes/0/scale", [1, 1, 1, 1])),
            "/nodes/0/scale: must have 3 numbers, got 4")
    c.error("type-matrix-15", mutate(triangle, lambda d: set_at(d, "/nodes/0/matrix", [1] * 15)),
            "/nodes/0/matrix: must have 16 numbers, got 15")
    c.error("type-name-number", mutate(triangle, lambda d: set_at(d, "/meshes/0/name", 7)), "/meshes/0/name: must be a string, got number")
    c.error("type-node-extensions-array", mutate(triangle, lambda d: set_at(d, "/nodes/0/extensions", [])),
            "/nodes/0/extensions: must be an object, got array")
    c.error("type-scene-string", mutate(triangle, lambda d: set_at(d, "/scene", "0")), "/scene: must be an integer, got string")
    c.error("type-extensions-array", mutate(triangle, lambda d: set_at(d, "/extensions", [])), "/extensions: must be an object")
    c.error("type-uri-number", mutate(triangle, lambda d: set_at(d, "/buffers/0/uri", 5)), "/buffers/0/uri: must be a string")
    c.error("type-alphamode-number", mutate(textured, lambda d: set_at(d, "/materials/0/alphaMode", 1)),
            "/materials/0/alphaMode: must be a string")
    c.error("type-doublesided-string", mutate(textured, lambda d: set_at(d, "/materials/0/doubleSided", "yes")),
            "/materials/0/doubleSided: must be true or false")
    c.error("type-pbr-array", mutate(textured, lambda d: set_at(d, "/materials/0/pbrMetallicRoughness", [])),
            "/materials/0/pbrMetallicRoughness: must be an object")
    c.error("type-extensions-used-number", mutate(triangle, lambda d: set_at(d, "/extensionsUsed", [1])),
            "/extensionsUsed/0: must be a string")

    # ---- indices: out of range, negative, wrong type, for every kind of index -----------------------------------
    index_properties = [
        ("mesh", triangle, "/nodes/0/mesh", "meshes"),
        ("position-accessor", triangle, "/meshes/0/primitives/0/attributes/POSITION", "accessors"),
        ("indices-accessor", triangle, "/meshes/0/primitives/0/indices", "accessors"),
        ("accessor-bufferview", triangle, "/accessors/0/bufferView", "bufferViews"),
        ("bufferview-buffer", triangle, "/bufferViews/0/buffer", "buffers"),
        ("child-node", full, "/nodes/0/children/0", "nodes"),
        ("scene-node", triangle, "/scenes/0/nodes/0", "nodes"),
        ("default-scene", triangle, "/scene", "scenes"),
        ("material", textured, "/meshes/0/primitives/0/material", "materials"),
        ("base-color-texture", textured, "/materials/0/pbrMetallicRoughness/baseColorTexture/index", "textures"),
        ("normal-texture", lambda: mutate(textured, lambda d: set_at(d, "/materials/0/normalTexture", {"index": 0})),
         "/materials/0/normalTexture/index", "textures"),
        ("emissive-texture", lambda: mutate(textured, lambda d: set_at(d, "/materials/0/emissiveTexture", {"index": 0})),
         "/materials/0/emissiveTexture/index", "textures"),
        ("texture-sampler", textured, "/textures/0/sampler", "samplers"),
        ("texture-source", textured, "/textures/0/source", "images"),
        ("camera", full, "/nodes/1/camera", "cameras"),
        ("light", full, "/nodes/2/extensions/KHR_lights_punctual/light", "lights"),
        ("skin", lambda: mutate(triangle, lambda d: (set_at(d, "/skins", [{"joints": [0]}]), set_at(d, "/nodes/0/skin", 0))),
         "/nodes/0/skin", "skins"),
        ("skin-joint", lambda: mutate(triangle, lambda d: set_at(d, "/skins", [{"joints": [0]}])), "/skins/0/joints/0", "nodes"),
        ("skin-matrices", lambda: mutate(triangle, lambda d: set_at(d, "/skins", [{"joints": [0], "inverseBindMatrices": 0}])),
         "/skins/0/inverseBindMatrices", "accessors"),
        ("animation-target", animated, "/animations/0/channels/0/target/node", "nodes"),
        ("image-bufferview", lambda: mutate(textured, lambda d: set_at(d, "/images/0", {"bufferView": 0, "mimeType": "image/png"})),
         "/images/0/bufferView", "bufferViews"),
    ]
    for name, base, pointer, target in index_properties:
        c.error("index-%s-out-of-range" % name, mutate(base, lambda d, p=pointer: set_at(d, p, 99)),
                "%s: index 99 is out of range" % pointer)
        c.error("index-%s-negative" % name, mutate(base, lambda d, p=pointer: set_at(d, p, -1)), "%s: index -1 is negative" % pointer)
        c.error("index-%s-string" % name, mutate(base, lambda d, p=pointer: set_at(d, p, "0")),
                "%s: must be an integer, got string" % pointer)
    c.error("index-mesh-huge", mutate(triangle, lambda d: set_at(d, "/nodes/0/mesh", 2 ** 40)), "/nodes/0/mesh: index 1.09951e+12 is out of range")

    # ---- buffers ----------------------------------------------------------------------------------------------
    c.error("buffer-bytelength-missing", mutate(triangle, lambda d: remove_at(d, "/buffers/0/byteLength")),
            "/buffers/0/byteLength: required property missing")
    c.error("buffer-bytelength-zero", mutate(triangle, lambda d: set_at(d, "/buffers/0/byteLength", 0)),
            "/buffers/0/byteLength: must be >= 1")
    c.error("buffer-bytelength-over-limit", mutate(triangle, lambda d: set_at(d, "/buffers/0/byteLength", 2 ** 31)),
            "/buffers/0/byteLength: 2147483648 bytes is over lidr's limit")
    c.error("buffer-bytelength-over-data", mutate(triangle, lambda d: set_at(d, "/buffers/0/byteLength", 100)),
            "/buffers/0/byteLength: 100 bytes, but the data: URI holds 44")
    c.error("buffer-total-over-limit", mutate(triangle, lambda d: set_at(d, "/buffers", [
        {"byteLength": 2 ** 30, "uri": "a.bin"}] * 3)), "for all buffers of a file")
    c.error("buffer-no-uri-in-gltf", mutate(triangle, lambda d: remove_at(d, "/buffers/0/uri")),
            "/buffers/0: buffer without uri")
    c.error("buffer-uri-http", mutate(triangle, lambda d: set_at(d, "/buffers/0/uri", "http://example.com/a.bin")),
            "/buffers/0/uri: URI 'http://example.com/a.bin' is not a relative path")
    c.error("buffer-uri-empty", mutate(triangle, lambda d: set_at(d, "/buffers/0/uri", "")), "/buffers/0/uri: empty URI")
    c.error("buffer-uri-missing-file", mutate(triangle, lambda d: set_at(d, "/buffers/0/uri", "missing.bin")),
            "/buffers/0/uri: buffer file")
    c.error("buffer-uri-directory", mutate(triangle, lambda d: set_at(d, "/buffers/0/uri", "folder")), "is a directory",
            setup=lambda d: os.mkdir(os.path.join(d, "folder")))
    c.error("buffer-uri-dev-zero", mutate(triangle, lambda d: set_at(d, "/buffers/0/uri", "/dev/zero")),
            "buffer file '/dev/zero' is not a regular file")
    c.error("buffer-uri-dev-urandom-link", mutate(triangle, lambda d: set_at(d, "/buffers/0/uri", "random.bin")),
            "random.bin' is not a regular file", setup=lambda d: os.symlink("/dev/urandom", os.path.join(d, "random.bin")))
    c.error("buffer-uri-fifo", mutate(triangle, lambda d: set_at(d, "/buffers/0/uri", "pipe.bin")),
            "pipe.bin' is not a regular file", setup=lambda d: os.mkfifo(os.path.join(d, "pipe.bin")))
    c.error("buffer-uri-symlink-loop", mutate(triangle, lambda d: set_at(d, "/buffers/0/uri", "loop.bin")),
            "loop.bin' Too many levels of symbolic links", setup=lambda d: (os.symlink("loop2.bin", os.path.join(d, "loop.bin")),
                                                                          os.symlink("loop.bin", os.path.join(d, "loop2.bin"))))
    c.error("buffer-file-short", mutate(triangle, lambda d: set_at(d, "/buffers/0/uri", "short.bin")),
            "/buffers/0/byteLength: 44 bytes, but", files={"short.bin": BIN[:20]})
    c.error("buffer-datauri-not-base64", mutate(triangle, lambda d: set_at(d, "/buffers/0/uri", "data:application/octet-stream,abc")),
            "/buffers/0/uri: data: URI is not base64")
    c.error("buffer-datauri-bad-char", mutate(triangle, lambda d: set_at(d, "/buffers/0/uri", "data:application/octet-stream;base64,AAA*" + "A" * 60)),
            "/buffers/0/uri: data: URI has a character that is not base64")
    c.error("buffer-datauri-cut", mutate(triangle, lambda d: set_at(d, "/buffers/0/uri", d["buffers"][0]["uri"][:-3])),
            "/buffers/0/uri: data: URI base64 text")
    c.error("buffer-datauri-no-comma", mutate(triangle, lambda d: set_at(d, "/buffers/0/uri", "data:application/octet-stream;base64")),
            "/buffers/0/uri: data: URI without ','")
    c.error("buffer-datauri-wrong-mime", mutate(triangle, lambda d: set_at(d, "/buffers/0/uri", data_uri("image/png", BIN))),
            "/buffers/0/uri: data: URI type 'image/png'")
    c.error("buffer-datauri-padding-inside", mutate(triangle, lambda d: set_at(d, "/buffers/0/uri",
                                                                              "data:application/octet-stream;base64,AA==AAAA")),
            "data: URI has a character that is not base64")

    # ---- buffer views -----------------------------------------------------------------------------------------
    c.error("bufferview-past-buffer", mutate(triangle, lambda d: set_at(d, "/bufferViews/1/byteLength", 40)),
            "/bufferViews/1/byteLength: bytes 36 + 40 lie outside buffer 0")
    c.error("bufferview-offset-past-buffer", mutate(triangle, lambda d: set_at(d, "/bufferViews/1/byteOffset", 2 ** 40)),
            "lie outside buffer 0")
    c.error("bufferview-offset-negative", mutate(triangle, lambda d: set_at(d, "/bufferViews/1/byteOffset", -4)),
            "/bufferViews/1/byteOffset: must be >= 0")
    c.error("bufferview-length-zero", mutate(triangle, lambda d: set_at(d, "/bufferViews/1/byteLength", 0)),
            "/bufferViews/1/byteLength: must be >= 1")
    c.error("bufferview-length-missing", mutate(triangle, lambda d: remove_at(d, "/bufferViews/1/byteLength")),
            "/bufferViews/1/byteLength: required property missing")
    c.error("bufferview-buffer-missing", mutate(triangle, lambda d: remove_at(d, "/bufferViews/1/buffer")),
            "/bufferViews/1/buffer: required property missing")
    for stride, name in [(2, "2"), (6, "not-multiple-of-4"), (256, "over-252"), (0, "zero"), (-4, "negative")]:
        c.error("bufferview-stride-" + name, mutate(triangle, lambda d, s=stride: set_at(d, "/bufferViews/0/byteStride", s)),
                "/bufferViews/0/byteStride: must be a multiple of 4 in [4, 252], got %d" % stride)
    c.error("bufferview-stride-below-element", mutate(triangle, lambda d: set_at(d, "/bufferViews/0/byteStride", 8)),
            "/bufferViews/0/byteStride: stride 8 is smaller than the 12-byte elements")
    c.error("bufferview-target-bad", mutate(triangle, lambda d: set_at(d, "/bufferViews/0/target", 1234)),
            "/bufferViews/0/target: must be 34962 (ARRAY_BUFFER) or 34963")
    c.error("bufferview-indices-stride", mutate(triangle, lambda d: set_at(d, "/bufferViews/1", {
        "buffer": 0, "byteOffset": 32, "byteLength": 12, "byteStride": 4})),
            "/meshes/0/primitives/0/indices: accessor 1's bufferView 1 has a byteStride")

    # ---- accessors --------------------------------------------------------------------------------------------
    c.error("accessor-count-2^31-no-bufferview", mutate(triangle, lambda d: (remove_at(d, "/accessors/0/bufferView"),
                                                                            set_at(d, "/accessors/0/count", 2 ** 31))),
            "/accessors/0/count: 2147483648 elements is over lidr's limit of 60000000")
    c.error("accessor-count-huge", mutate(triangle, lambda d: set_at(d, "/accessors/0/count", 2 ** 62)),
            "/accessors/0/count: 4611686018427387904 elements is over lidr's limit")
    c.error("accessor-count-2^53", mutate(triangle, lambda d: set_at(d, "/accessors/0/count", 1e300)),
            "/accessors/0/count: must be an integer, got number 1e+300")
    c.error("accessor-count-zero", mutate(triangle, lambda d: set_at(d, "/accessors/0/count", 0)), "/accessors/0/count: must be >= 1")
    c.error("accessor-count-negative", mutate(triangle, lambda d: set_at(d, "/accessors/0/count", -3)), "/accessors/0/count: must be >= 1")
    c.error("accessor-count-missing", mutate(triangle, lambda d: remove_at(d, "/accessors/0/count")),
            "/accessors/0/count: required property missing")
    c.error("accessor-count-past-view", mutate(triangle, lambda d: set_at(d, "/accessors/0/count", 4)),
            "/accessors/0/count: 4 elements of 12 bytes (stride 12) from byte 0 do not fit bufferView 0 (36 bytes)")
    c.error("accessor-offset-past-view", mutate(triangle, lambda d: set_at(d, "/accessors/0/byteOffset", 4)),
            "/accessors/0/count: 3 elements of 12 bytes (stride 12) from byte 4 do not fit bufferView 0")
    c.error("accessor-offset-misaligned", mutate(triangle, lambda d: set_at(d, "/accessors/0/byteOffset", 2)),
            "/accessors/0/byteOffset: 2 is not a multiple of the component size 4")
    c.error("accessor-view-offset-misaligned", mutate(triangle, lambda d: (set_at(d, "/bufferViews/1/byteOffset", 37),
                                                                          set_at(d, "/bufferViews/1/byteLength", 6))),
            "/accessors/1/byteOffset: bufferView 1 offset 37 + 0 is not a multiple of the component size 2")
    c.error("accessor-attribute-unaligned", mutate(triangle, lambda d: (
        d["accessors"].append({"bufferView": 1, "byteOffset": 2, "componentType": 5123, "count": 1, "type": "VEC2"}),
        set_at(d, "/meshes/0/primitives/0/attributes/TEXCOORD_0", 2), set_at(d, "/accessors/0/count", 1),
        set_at(d, "/meshes/0/primitives/0/mode", 5), remove_at(d, "/meshes/0/primitives/0/indices"))),
            "/meshes/0/primitives/0/attributes/TEXCOORD_0: accessor 2 starts at byte 36 + 2; vertex attributes must be 4-byte aligned")
    c.error("accessor-offset-negative", mutate(triangle, lambda d: set_at(d, "/accessors/0/byteOffset", -12)),
            "/accessors/0/byteOffset: must be >= 0")
    c.error("accessor-offset-without-view", mutate(triangle, lambda d: (remove_at(d, "/accessors/0/bufferView"),
                                                                       set_at(d, "/accessors/0/byteOffset", 0))),
            "/accessors/0/byteOffset: must not be given without a bufferView")
    # Amplification: a few hundred bytes that would expand into millions of triangles (fuzz.gltf found the first).
    c.error("accessor-position-zeros-30m", mutate(triangle, lambda d: (
        remove_at(d, "/accessors/0/bufferView"), set_at(d, "/accessors/0/count", 30000000),
        remove_at(d, "/meshes/0/primitives/0/indices"))), "no triangles and no lights")
    c.add("accessor-position-zeros-warning", mutate(lit, lambda d: (
        remove_at(d, "/accessors/0/bufferView"), set_at(d, "/accessors/0/count", 30000000),
        remove_at(d, "/meshes/0/primitives/0/indices"))), "warning", "POSITION has no buffer view (all zeros)")
    c.error("accessor-indices-zeros-30m", mutate(triangle, lambda d: (
        remove_at(d, "/accessors/1/bufferView"), set_at(d, "/accessors/1/count", 30000000))), "accessor[1] invalid bufferView")
    c.error("nodes-instance-over-limit", instanced(primitives=1000, corners=1000, nodes=25),
            "the scene would have at least 20")
    c.error("accessor-componenttype-bad", mutate(triangle, lambda d: set_at(d, "/accessors/0/componentType", 5124)),
            "/accessors/0/componentType: must be 5120, 5121, 5122, 5123, 5125 or 5126, got 5124")
    c.error("accessor-componenttype-missing", mutate(triangle, lambda d: remove_at(d, "/accessors/0/componentType")),
            "/accessors/0/componentType: required property missing")
    c.error("accessor-type-bad", mutate(triangle, lambda d: set_at(d, "/accessors/0/type", "VEC5")),
            "/accessors/0/type: 'VEC5' is not SCALAR")
    c.error("accessor-type-missing", mutate(triangle, lambda d: remove_at(d, "/accessors/0/type")),
            "/accessors/0/type: required property missing")
    c.error("accessor-normalized-float", mutate(triangle, lambda d: set_at(d, "/accessors/0/normalized", True)),
            "/accessors/0/normalized: only byte and short components can be normalized")
    c.error("accessor-min-wrong-size", mutate(triangle, lambda d: set_at(d, "/accessors/0/min", [0, 0])),
            "/accessors/0/min: must have 3 numbers, got 2")
    c.error("accessor-max-string", mutate(triangle, lambda d: set_at(d, "/accessors/0/max", [1, "1", 0])),
            "/accessors/0/max/1: must be a number, got string")
    c.error("accessor-sparse-count-bad", mutate(triangle, lambda d: set_at(d, "/accessors/0/sparse", {
        "count": 10, "indices": {"bufferView": 1, "componentType": 5123}, "values": {"bufferView": 0}})),
            "/accessors/0/sparse/count: must be in [1, 3], got 10")
    c.error("accessor-sparse-view-out-of-range", mutate(triangle, lambda d: set_at(d, "/accessors/0/sparse", {
        "count": 1, "indices": {"bufferView": 7, "componentType": 5123}, "values": {"bufferView": 0}})),
            "/accessors/0/sparse/indices/bufferView: index 7 is out of range")
    c.error("accessor-unequal-counts", mutate(triangle, lambda d: (
        d["accessors"].append({"componentType": 5126, "count": 4, "type": "VEC3"}),
        set_at(d, "/meshes/0/primitives/0/attributes/NORMAL", 2))),
            "/meshes/0/primitives/0/attributes/POSITION: accessor 0 has 3 elements; the primitive's other attributes have 4")
    c.error("accessor-indices-float", mutate(triangle, lambda d: set_at(d, "/meshes/0/primitives/0/indices", 0)),
            "/meshes/0/primitives/0/indices: accessor 0 must be SCALAR of unsigned byte, short or int")
    c.error("accessor-mat3-byte-padding", mutate(triangle, lambda d: (
        d["accessors"].append({"bufferView": 0, "componentType": 5121, "count": 4, "type": "MAT3"}),)),
            "/accessors/2/count: 4 elements of 12 bytes")
    c.error("primitive-mode-bad", mutate(triangle, lambda d: set_at(d, "/meshes/0/primitives/0/mode", 7)),
            "/meshes/0/primitives/0/mode: must be 0..6, got 7")
    c.error("primitive-mode-points", mutate(triangle, lambda d: set_at(d, "/meshes/0/primitives/0/mode", 0)),
            "primitive mode 0 (POINTS) is not triangles")
    c.error("primitive-targets-object", mutate(triangle, lambda d: set_at(d, "/meshes/0/primitives/0/targets", {})),
            "/meshes/0/primitives/0/targets: must be an array")

    # ---- node graph and transforms ----------------------------------------------------------------------------
    def two_nodes(d):
        d["nodes"] = [{"mesh": 0, "children": [1]}, {"mesh": 0}]
    c.error("graph-two-parents", mutate(triangle, lambda d: (two_nodes(d), d["nodes"].append({"children": [1]}),
                                                            set_at(d, "/scenes/0/nodes", [0, 2]))),
            "/nodes/2/children/0: node 1 already has parent node 0")
    c.error("graph-child-twice", mutate(triangle, lambda d: (two_nodes(d), set_at(d, "/nodes/0/children", [1, 1]))),
            "/nodes/0/children/1: node 1 is listed twice")
    c.error("graph-own-child", mutate(triangle, lambda d: set_at(d, "/nodes/0/children", [0])),
            "/nodes/0/children/0: node 0 is its own child")
    c.error("graph-cycle-2", mutate(triangle, lambda d: (set_at(d, "/nodes", [{"mesh": 0, "children": [1]}, {"children": [0]}]),
                                                        set_at(d, "/scenes/0/nodes", []))),
            "is its own ancestor (a cycle)")
    c.error("graph-cycle-3", mutate(triangle, lambda d: (set_at(d, "/nodes", [{"mesh": 0}, {"children": [2]}, {"children": [3]},
                                                                             {"children": [1]}]))),
            "is its own ancestor (a cycle)")
    c.error("graph-root-is-child", mutate(triangle, lambda d: (two_nodes(d), set_at(d, "/scenes/0/nodes", [0, 1]))),
            "/scenes/0/nodes/1: node 1 is a child of node 0; a scene's nodes must be roots")
    c.error("graph-root-twice", mutate(triangle, lambda d: set_at(d, "/scenes/0/nodes", [0, 0])),
            "/scenes/0/nodes/1: node 0 is listed twice")
    ok("graph-deep-chain-200", mutate(triangle, lambda d: set_at(d, "/nodes", [{"children": [i + 1]} for i in range(199)] + [{"mesh": 0}])))
    c.error("graph-chain-past-256", mutate(triangle, lambda d: set_at(d, "/nodes", [{"children": [i + 1]} for i in range(299)] + [{"mesh": 0}])),
            "node hierarchy deeper than 256 levels")
    c.error("transform-matrix-and-trs", mutate(triangle, lambda d: (set_at(d, "/nodes/0/matrix", [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]),
                                                                   set_at(d, "/nodes/0/translation", [1, 0, 0]))),
            "/nodes/0/matrix: a node has matrix or translation/rotation/scale, not both")
    c.error("transform-matrix-and-scale", mutate(triangle, lambda d: (set_at(d, "/nodes/0/matrix", [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]),
                                                                     set_at(d, "/nodes/0/scale", [1, 1, 1]))),
            "/nodes/0/matrix: a node has matrix or translation/rotation/scale, not both")
    c.error("transform-projective", mutate(triangle, lambda d: set_at(d, "/nodes/0/matrix", [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, -1, 0, 0, 0, 0])),
            "/nodes/0/matrix: the last row must be 0 0 0 1")
    c.error("transform-matrix-w2", mutate(triangle, lambda d: set_at(d, "/nodes/0/matrix", [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 2])),
            "/nodes/0/matrix: the last row must be 0 0 0 1")
    c.error("transform-zero-quaternion", mutate(triangle, lambda d: set_at(d, "/nodes/0/rotation", [0, 0, 0, 0])),
            "/nodes/0/rotation: must be a unit quaternion, its length is 0")
    c.error("transform-long-quaternion", mutate(triangle, lambda d: set_at(d, "/nodes/0/rotation", [0, 0, 0, 2])),
            "/nodes/0/rotation: must be a unit quaternion, its length is 2")
    c.error("transform-skin-without-mesh", mutate(triangle, lambda d: (set_at(d, "/skins", [{"joints": [0]}]),
                                                                      d["nodes"].append({"skin": 0}))),
            "/nodes/1/skin: a node with a skin must have a mesh")

    # ---- extensions -------------------------------------------------------------------------------------------
    for ext, purpose in [("KHR_draco_mesh_compression", "Draco"), ("EXT_meshopt_compression", "meshoptimizer"),
                         ("KHR_mesh_quantization", "quantized"), ("KHR_texture_basisu", "KTX2"), ("EXT_unknown_thing", "")]:
        c.error("extension-required-" + ext, mutate(triangle, lambda d, e=ext: (set_at(d, "/extensionsUsed", [e]),
                                                                                 set_at(d, "/extensionsRequired", [e]))),
                "/extensionsRequired/0: required extension %s%s" % (ext, " (" + purpose if purpose else " is not implemented"))
    c.error("extension-required-not-used", mutate(triangle, lambda d: set_at(d, "/extensionsRequired", ["KHR_lights_punctual"])),
            "/extensionsRequired/0: required extension KHR_lights_punctual is not in extensionsUsed")
    c.error("extension-used-twice", mutate(triangle, lambda d: set_at(d, "/extensionsUsed", ["A_b", "A_b"])),
            "/extensionsUsed/1: extension listed twice")
    ok("extension-required-lights", mutate(lit, lambda d: set_at(d, "/extensionsRequired", ["KHR_lights_punctual"])))
    ok("extension-required-texture-transform", mutate(textured, lambda d: (
        set_at(d, "/extensionsUsed", ["KHR_texture_transform"]), set_at(d, "/extensionsRequired", ["KHR_texture_transform"]),
        set_at(d, "/materials/0/pbrMetallicRoughness/baseColorTexture/extensions",
               {"KHR_texture_transform": {"offset": [0.5, 0], "rotation": 0.5, "scale": [2, 2]}}))))

    # ---- KHR_lights_punctual ----------------------------------------------------------------------------------
    L = "/extensions/KHR_lights_punctual/lights/0"
    for value, name in [(0, "zero"), (-1, "negative")]:
        c.error("light-range-" + name, mutate(lit, lambda d, v=value: set_at(d, L + "/range", v)), L + "/range: must be > 0")
    c.error("light-color-2", mutate(lit, lambda d: set_at(d, L + "/color", [1, 1])), L + "/color: must have 3 numbers, got 2")
    c.error("light-color-negative", mutate(lit, lambda d: set_at(d, L + "/color", [1, -1, 1])), L + "/color/1: must be in [0, 1]")
    c.error("light-color-over-1", mutate(lit, lambda d: set_at(d, L + "/color", [2, 1, 1])), L + "/color/0: must be in [0, 1]")
    c.error("light-intensity-negative", mutate(lit, lambda d: set_at(d, L + "/intensity", -2)), L + "/intensity: must be >= 0")
    c.error("light-type-unknown", mutate(lit, lambda d: set_at(d, L + "/type", "area")), L + "/type: 'area' is not point, spot or directional")
    c.error("light-type-missing", mutate(lit, lambda d: remove_at(d, L + "/type")), L + "/type: required property missing")
    c.error("light-spot-missing", mutate(lit, lambda d: set_at(d, L + "/type", "spot")), L + "/spot: required property missing")
    c.error("light-spot-cones", mutate(lit, lambda d: set_at(d, L, {"type": "spot", "spot": {"innerConeAngle": 1, "outerConeAngle": 0.5}})),
            L + "/spot: cone angles must satisfy")
    c.error("light-lights-missing", mutate(lit, lambda d: set_at(d, "/extensions/KHR_lights_punctual", {})),
            "/extensions/KHR_lights_punctual/lights: required property missing")
    c.error("light-100000", mutate(lit, lambda d: set_at(d, "/extensions/KHR_lights_punctual/lights", [{"type": "point"}] * 100000)),
            "/extensions/KHR_lights_punctual/lights: 100000 lights; lidr draws at most 65535")
    c.error("light-node-light-missing", mutate(lit, lambda d: set_at(d, "/nodes/1/extensions/KHR_lights_punctual", {})),
            "/nodes/1/extensions/KHR_lights_punctual/light: required property missing")

    # ---- numbers past the float range: JSON has no infinity, but 1e39 is a finite double that becomes +inf as a
    # float; every number lidr reads is refused with its pointer (1e400 does not even parse) -------------------
    F = "is not finite as a 32-bit float"
    for name, base, pointer in [
            ("light-intensity", lit, L + "/intensity"), ("light-color", lit, L + "/color/1"),
            ("light-range", lit, L + "/range"),
            ("light-spot-inner", lambda: mutate(lit, lambda d: set_at(d, L, {"type": "spot", "spot": {"outerConeAngle": 0.5}})),
             L + "/spot/innerConeAngle"),
            ("light-spot-outer", lambda: mutate(lit, lambda d: set_at(d, L, {"type": "spot", "spot": {}})), L + "/spot/outerConeAngle"),
            ("node-translation", triangle, "/nodes/0/translation/2"), ("node-scale", triangle, "/nodes/0/scale/0"),
            ("node-rotation", triangle, "/nodes/0/rotation/3"), ("node-matrix", triangle, "/nodes/0/matrix/12"),
            ("camera-yfov", full, "/cameras/0/perspective/yfov"), ("camera-zfar", full, "/cameras/0/perspective/zfar"),
            ("camera-aspect", full, "/cameras/0/perspective/aspectRatio"),
            ("material-basecolor", textured, "/materials/0/pbrMetallicRoughness/baseColorFactor/0"),
            ("material-metallic", textured, "/materials/0/pbrMetallicRoughness/metallicFactor"),
            ("material-alphacutoff", textured, "/materials/0/alphaCutoff"),
            ("accessor-max", triangle, "/accessors/0/max/1")]:
        def change(d, pointer=pointer):
            keys = pointer.strip("/").split("/")
            if keys[-1].isdigit():  # a vector: give it its length, one component 1e39
                length = {"translation": 3, "scale": 3, "rotation": 4, "matrix": 16, "baseColorFactor": 4, "color": 3,
                          "max": 3}[keys[-2]]
                vector = {"rotation": [0, 0, 0, 1], "matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]}.get(
                    keys[-2], [1] * length)
                vector[int(keys[-1])] = 1e39
                set_at(d, "/" + "/".join(keys[:-1]), vector)
            else:
                set_at(d, pointer, 1e39)
        c.error("float-range-" + name, mutate(base, change), pointer + ": 1e+39 " + F)
    c.error("float-range-light-intensity-negative", mutate(lit, lambda d: set_at(d, L + "/intensity", -1e39)),
            L + "/intensity: -1e+39 " + F)
    c.error("float-range-json-1e400", mutate(lit, lambda d: set_at(d, L + "/intensity", 1)), "/: malformed JSON: number overflow",
            raw=json.dumps(lit()).replace('"intensity": 1', '"intensity": 1e400').encode())
    c.error("light-range-past-limit", mutate(lit, lambda d: set_at(d, L + "/range", 1e20)),
            L + "/range: must be at most 1e+18 (lidr's largest light radius), got 1e+20")
    # Rules on the floats lidr keeps: a znear that is 0 as a float, a zfar that rounds to znear.
    c.error("camera-znear-underflow", mutate(full, lambda d: set_at(d, "/cameras/0/perspective/znear", 1e-50)),
            "/cameras/0/perspective/znear: must be > 0, got 1e-50")
    c.error("camera-zfar-rounds-to-znear", mutate(full, lambda d: (set_at(d, "/cameras/0/perspective/znear", 1),
                                                                  set_at(d, "/cameras/0/perspective/zfar", 1.00000001))),
            "/cameras/0/perspective/zfar: must be > znear (1)")

    # ---- materials, textures, samplers, images ----------------------------------------------------------------
    M = "/materials/0"
    c.error("material-alphamode-bad", mutate(textured, lambda d: set_at(d, M + "/alphaMode", "blend")),
            M + "/alphaMode: 'blend' is not OPAQUE, MASK or BLEND")
    c.error("material-alphacutoff-negative", mutate(textured, lambda d: set_at(d, M + "/alphaCutoff", -0.5)), M + "/alphaCutoff: must be >= 0")
    c.error("material-basecolor-3", mutate(textured, lambda d: set_at(d, M + "/pbrMetallicRoughness/baseColorFactor", [1, 1, 1])),
            M + "/pbrMetallicRoughness/baseColorFactor: must have 4 numbers, got 3")
    c.error("material-basecolor-over-1", mutate(textured, lambda d: set_at(d, M + "/pbrMetallicRoughness/baseColorFactor", [1, 1, 1, 2])),
            M + "/pbrMetallicRoughness/baseColorFactor/3: must be in [0, 1]")
    c.error("material-metallic-over-1", mutate(textured, lambda d: set_at(d, M + "/pbrMetallicRoughness/metallicFactor", 1.5)),
            M + "/pbrMetallicRoughness/metallicFactor: must be in [0, 1]")
    c.error("material-roughness-negative", mutate(textured, lambda d: set_at(d, M + "/pbrMetallicRoughness/roughnessFactor", -1)),
            M + "/pbrMetallicRoughness/roughnessFactor: must be in [0, 1]")
    c.error("material-emissive-negative", mutate(textured, lambda d: set_at(d, M + "/emissiveFactor", [0, -1, 0])),
            M + "/emissiveFactor/1: must be in [0, 1]")
    c.error("material-occlusion-strength-over-1", mutate(textured, lambda d: set_at(d, M + "/occlusionTexture", {"index": 0, "strength": 2})),
            M + "/occlusionTexture/strength: must be in [0, 1], got 2")
    c.error("material-normal-scale-1e39", mutate(textured, lambda d: set_at(d, M + "/normalTexture", {"index": 0, "scale": -1e39})),
            M + "/normalTexture/scale: -1e+39 is not finite as a 32-bit float")
    ES = M + "/extensions/KHR_materials_emissive_strength"
    emissive_strength = lambda value: mutate(textured, lambda d: (
        set_at(d, "/extensionsUsed", ["KHR_materials_emissive_strength"]), set_at(d, M + "/emissiveFactor", [1, 0.5, 0]),
        set_at(d, M + "/extensions", {"KHR_materials_emissive_strength": {"emissiveStrength": value}})))
    ok("valid-emissive-strength", emissive_strength(40))
    c.error("material-emissive-strength-negative", emissive_strength(-1), ES + "/emissiveStrength: must be >= 0, got -1")
    c.error("material-emissive-strength-1e39", emissive_strength(1e39), ES + "/emissiveStrength: 1e+39 is not finite as a 32-bit float")
    c.error("material-emissive-strength-string", emissive_strength("2"), ES + "/emissiveStrength: must be a number, got string")
    c.error("material-emissive-strength-not-object", mutate(textured, lambda d: set_at(d, M + "/extensions", {
        "KHR_materials_emissive_strength": 2})), ES + ": must be an object, got number")
    TT = M + "/pbrMetallicRoughness/baseColorTexture/extensions/KHR_texture_transform"
    transform = lambda t: mutate(textured, lambda d: (set_at(d, "/extensionsUsed", ["KHR_texture_transform"]), set_at(
        d, M + "/pbrMetallicRoughness/baseColorTexture/extensions", {"KHR_texture_transform": t})))
    ok("valid-texture-transform", transform({"offset": [0.5, -2], "rotation": -7.5, "scale": [-1, 3], "texCoord": 0}))
    c.add("warn-texture-transform-texcoord-2", transform({"texCoord": 2}), "warning",
          "uses TEXCOORD_2; lidr reads TEXCOORD_0 and TEXCOORD_1, drawn with TEXCOORD_0")
    c.error("texture-transform-offset-1", transform({"offset": [1]}), TT + "/offset: must have 2 numbers, got 1")
    c.error("texture-transform-scale-string", transform({"scale": [1, "2"]}), TT + "/scale/1: must be a number, got string")
    c.error("texture-transform-rotation-1e39", transform({"rotation": 1e39}), TT + "/rotation: 1e+39 is not finite as a 32-bit float")
    c.error("texture-transform-scale-1e39", transform({"scale": [1, -1e39]}), TT + "/scale/1: -1e+39 is not finite as a 32-bit float")
    c.error("texture-transform-offset-1e39", transform({"offset": [1e39, 0]}), TT + "/offset/0: 1e+39 is not finite as a 32-bit float")
    c.error("texture-transform-texcoord-negative", transform({"texCoord": -1}), TT + "/texCoord: must be >= 0")
    c.error("texture-transform-texcoord-float", transform({"texCoord": 1.5}), TT + "/texCoord: must be an integer, got number 1.5")
    c.error("texture-transform-not-object", transform([1, 2]), TT + ": must be an object, got array")
    c.error("texture-transform-matrix-overflow", transform({"offset": [0, 3e38], "scale": [1, 3e38]}),
            "base colour texture: KHR_texture_transform (offset 0 3e+38, rotation 0, scale 1 3e+38) is not finite as a float matrix")
    c.error("texture-transform-emissive-1e39", mutate(textured, lambda d: set_at(d, M + "/emissiveTexture", {
        "index": 0, "extensions": {"KHR_texture_transform": {"rotation": 1e39}}})),
            M + "/emissiveTexture/extensions/KHR_texture_transform/rotation: 1e+39 is not finite")
    IOR = M + "/extensions/KHR_materials_ior"
    SPEC = M + "/extensions/KHR_materials_specular"
    dielectric = lambda ext: mutate(textured, lambda d: (
        set_at(d, "/extensionsUsed", ["KHR_materials_ior", "KHR_materials_specular"]), set_at(d, M + "/extensions", ext)))
    ok("valid-ior-specular", dielectric({"KHR_materials_ior": {"ior": 1.33},
                                         "KHR_materials_specular": {"specularFactor": 0.3, "specularColorFactor": [4, 1, 0]}}))
    ok("valid-ior-0", dielectric({"KHR_materials_ior": {"ior": 0}}))
    c.add("warn-specular-texture", dielectric({"KHR_materials_specular": {"specularTexture": {"index": 0}}}), "warning",
          "KHR_materials_specular specularTexture is not drawn")
    c.error("material-ior-below-1", dielectric({"KHR_materials_ior": {"ior": 0.5}}), IOR + "/ior: must be >= 1, or 0, got 0.5")
    c.error("material-ior-1e39", dielectric({"KHR_materials_ior": {"ior": 1e39}}), IOR + "/ior: 1e+39 is not finite as a 32-bit float")
    c.error("material-ior-not-object", dielectric({"KHR_materials_ior": 1.5}), IOR + ": must be an object, got number")
    c.error("material-specular-factor-over-1", dielectric({"KHR_materials_specular": {"specularFactor": 1.5}}),
            SPEC + "/specularFactor: must be in [0, 1], got 1.5")
    c.error("material-specular-color-negative", dielectric({"KHR_materials_specular": {"specularColorFactor": [1, -0.5, 1]}}),
            SPEC + "/specularColorFactor/1: must be >= 0, got -0.5")
    c.error("material-specular-color-2", dielectric({"KHR_materials_specular": {"specularColorFactor": [1, 1]}}),
            SPEC + "/specularColorFactor: must have 3 numbers, got 2")
    c.error("material-specular-color-1e39", dielectric({"KHR_materials_specular": {"specularColorFactor": [1, 1, 1e39]}}),
            SPEC + "/specularColorFactor/2: 1e+39 is not finite as a 32-bit float")
    c.error("material-specular-texture-index", dielectric({"KHR_materials_specular": {"specularColorTexture": {"index": 4}}}),
            SPEC + "/specularColorTexture/index: index 4 is out of range (1 textures)")
    ok("extension-required-ior-specular", mutate(textured, lambda d: (
        set_at(d, "/extensionsUsed", ["KHR_materials_ior", "KHR_materials_specular"]),
        set_at(d, "/extensionsRequired", ["KHR_materials_ior", "KHR_materials_specular"]),
        set_at(d, M + "/extensions", {"KHR_materials_ior": {"ior": 1.7}}))))
    c.error("material-texcoord-negative", mutate(textured, lambda d: set_at(d, M + "/pbrMetallicRoughness/baseColorTexture/texCoord", -1)),
            M + "/pbrMetallicRoughness/baseColorTexture/texCoord: must be >= 0")
    c.error("material-textureinfo-no-index", mutate(textured, lambda d: set_at(d, M + "/pbrMetallicRoughness/baseColorTexture", {})),
            M + "/pbrMetallicRoughness/baseColorTexture/index: required property missing")
    c.error("sampler-magfilter-bad", mutate(textured, lambda d: set_at(d, "/samplers/0/magFilter", 9987)),
            "/samplers/0/magFilter: 9987 is not a GL filter")
    c.error("sampler-wrap-bad", mutate(textured, lambda d: set_at(d, "/samplers/0/wrapS", 1)), "/samplers/0/wrapS: 1 is not a GL filter or wrap mode")
    I = "/images/0"
    c.error("image-uri-and-bufferview", mutate(textured, lambda d: set_at(d, I + "/bufferView", 0)), I + ": has both uri and bufferView")
    c.error("image-neither", mutate(textured, lambda d: set_at(d, I, {})), I + ": has neither uri nor bufferView")
    c.error("image-bufferview-no-mime", mutate(textured, lambda d: set_at(d, I, {"bufferView": 0})), I + "/mimeType: required with bufferView")
    c.error("image-mime-gif", mutate(textured, lambda d: set_at(d, I + "/mimeType", "image/gif")), I + "/mimeType: 'image/gif' is not image/png or image/jpeg")
    c.error("image-datauri-mime-mismatch", mutate(textured, lambda d: set_at(d, I + "/uri", data_uri("image/jpeg", png(2, 2)))),
            I + "/uri: image 0 (data: URI) is image/png but declared image/jpeg")
    c.error("image-datauri-mime-text", mutate(textured, lambda d: set_at(d, I + "/uri", data_uri("text/plain", png(2, 2)))),
            I + "/uri: data: URI type 'text/plain' is not image/png or image/jpeg")
    c.error("image-datauri-not-image", mutate(textured, lambda d: set_at(d, I + "/uri", data_uri("image/png", b"hello, world"))),
            I + "/uri: image 0 (data: URI) is neither PNG nor JPEG")
    c.error("image-png-100000", mutate(textured, lambda d: set_at(d, I + "/uri", "huge.png")),
            "huge.png' is 100000x100000; textures must be 1..16384 pixels per side", files={"huge.png": png(2, 2, declared=(100000, 100000))})
    c.error("image-png-zero", mutate(textured, lambda d: set_at(d, I + "/uri", data_uri("image/png", png(2, 2, declared=(0, 4))))),
            "is 0x4; textures must be 1..16384")
    c.error("image-jpeg-20000", mutate(textured, lambda d: set_at(d, I + "/uri", "wide.jpg")),
            "wide.jpg' is 20000x100; textures must be 1..16384", files={"wide.jpg": jpeg_header(20000, 100)})
    c.error("image-jpeg-declared-png", mutate(textured, lambda d: (set_at(d, I + "/uri", "photo.png"), set_at(d, I + "/mimeType", "image/png"))),
            "photo.png' is image/jpeg but declared image/png", files={"photo.png": jpeg_header(8, 8)})
    c.error("image-png-cut", mutate(textured, lambda d: set_at(d, I + "/uri", "cut.png")), "cut.png': the image/png header gives no size",
            files={"cut.png": png(2, 2)[:12]})
    c.error("image-png-corrupt-data", mutate(textured, lambda d: set_at(d, I + "/uri", "corrupt.png")),
            "image 0 'corrupt.png' cannot be decoded", files={"corrupt.png": png(2, 2)[:33] + b"\x00" * 40})
    c.error("image-uri-directory", mutate(textured, lambda d: set_at(d, I + "/uri", "pics")), "image file",
            setup=lambda d: os.mkdir(os.path.join(d, "pics")))
    c.error("image-uri-dev-zero", mutate(textured, lambda d: set_at(d, I + "/uri", "/dev/zero")), "image file '/dev/zero' is not a regular file")
    c.error("image-uri-missing", mutate(textured, lambda d: set_at(d, I + "/uri", "nothere.png")), "nothere.png' not found")
    c.error("image-uri-loop", mutate(textured, lambda d: set_at(d, I + "/uri", "l.png")), "l.png' Too many levels of symbolic links",
            setup=lambda d: os.symlink("l.png", os.path.join(d, "l.png")))
    c.error("image-bufferview-wrong-kind", mutate(textured, lambda d: set_at(d, I, {"bufferView": 0, "mimeType": "image/png"})),
            I + "/bufferView: image 0 is neither PNG nor JPEG")

    # ---- cameras ----------------------------------------------------------------------------------------------
    C = "/cameras/0"
    c.error("camera-yfov-missing", mutate(full, lambda d: remove_at(d, C + "/perspective/yfov")), C + "/perspective/yfov: required property missing")
    c.error("camera-yfov-zero", mutate(full, lambda d: set_at(d, C + "/perspective/yfov", 0)), C + "/perspective/yfov: must be in (0, pi)")
    c.error("camera-yfov-4", mutate(full, lambda d: set_at(d, C + "/perspective/yfov", 4)), C + "/perspective/yfov: must be in (0, pi)")
    c.error("camera-znear-missing", mutate(full, lambda d: remove_at(d, C + "/perspective/znear")), C + "/perspective/znear: required property missing")
    c.error("camera-znear-zero", mutate(full, lambda d: set_at(d, C + "/perspective/znear", 0)), C + "/perspective/znear: must be > 0")
    c.error("camera-zfar-below-znear", mutate(full, lambda d: set_at(d, C + "/perspective/zfar", 0.05)), C + "/perspective/zfar: must be > znear")
    c.error("camera-aspect-negative", mutate(full, lambda d: set_at(d, C + "/perspective/aspectRatio", -1)), C + "/perspective/aspectRatio: must be > 0")
    c.error("camera-perspective-missing", mutate(full, lambda d: set_at(d, C, {"type": "perspective"})), C + "/perspective: required property missing")
    c.error("camera-type-bad", mutate(full, lambda d: set_at(d, C + "/type", "fisheye")), C + "/type: 'fisheye' is not perspective or orthographic")
    c.error("camera-type-missing", mutate(full, lambda d: remove_at(d, C + "/type")), C + "/type: required property missing")
    c.error("camera-ortho-xmag-zero", mutate(full, lambda d: set_at(d, C, {"type": "orthographic", "orthographic": {
        "xmag": 0, "ymag": 1, "znear": 0, "zfar": 1}})), C + "/orthographic: xmag and ymag must not be 0")
    c.error("camera-ortho-zfar-missing", mutate(full, lambda d: set_at(d, C, {"type": "orthographic", "orthographic": {
        "xmag": 1, "ymag": 1, "znear": 0}})), C + "/orthographic/zfar: required property missing")

    # ---- animations -------------------------------------------------------------------------------------------
    c.error("animation-channels-missing", mutate(triangle, lambda d: set_at(d, "/animations", [{"samplers": []}])),
            "/animations/0/channels: required property missing")
    c.error("animation-sampler-out-of-range", mutate(triangle, lambda d: set_at(d, "/animations", [
        {"samplers": [], "channels": [{"sampler": 0, "target": {"node": 0, "path": "scale"}}]}])),
            "/animations/0/channels/0/sampler: index 0 is out of range (0 samplers)")
    c.error("animation-input-not-float", mutate(animated, lambda d: set_at(d, "/animations/0/samplers/0/input", 1)),
            "/animations/0/samplers/0/input: accessor 1 must be SCALAR of float (the key times)")
    c.error("animation-interpolation", animated(interpolation="SMOOTH"),
            "/animations/0/samplers/0/interpolation: must be LINEAR, STEP or CUBICSPLINE, got 'SMOOTH'")
    c.error("animation-path", animated(path="colour"),
            "/animations/0/channels/0/target/path: must be translation, rotation, scale or weights, got 'colour'")
    c.error("animation-path-missing", mutate(animated, lambda d: remove_at(d, "/animations/0/channels/0/target/path")),
            "/animations/0/channels/0/target/path: required property missing")
    c.error("animation-times-decrease", animated(times=(1.0, 0.5)),
            "animation 0 channel 0: key 1's time 0.500000 does not follow the previous key's 1.000000")
    c.error("animation-output-count", animated(values=((0, 0, 0),)),
            "animation 0 channel 0: output accessor 3 has 1 elements; 2 are needed for the input's keys")
    c.error("animation-cubic-count", animated(interpolation="CUBICSPLINE"),
            "animation 0 channel 0: output accessor 3 has 2 elements; 6 are needed")
    c.error("animation-output-type", animated(path="rotation"),
            "animation 0 channel 0 output accessor 3: type 3 is not the type")
    c.error("animation-rotation-zero", animated(values=((0, 0, 0, 0), (0, 0, 0, 1)), path="rotation", value_type="VEC4"),
            "animation 0 channel 0: output rotation 0 is zero (not a rotation)")
    c.error("animation-matrix-node", mutate(animated, lambda d: set_at(d, "/nodes/0/matrix",
                                                                   [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1])),
            "animation 0 channel 0: node 0 has a matrix; an animated node must give translation, rotation and scale")
    c.error("animation-value-nan", animated(values=((0, 0, 0), (float("nan"), 0, 0))),
            "animation 0 channel 0: output value 1 is not finite")

    # ---- limits -----------------------------------------------------------------------------------------------
    c.error("limit-nodes-200001", None, "/nodes: 200001 entries; lidr reads at most 200000",
            raw=b'{"asset":{"version":"2.0"},"nodes":[' + b",".join([b"{}"] * 200001) + b"]}")
    ok("limit-nodes-200000", mutate(triangle, lambda d: set_at(d, "/nodes", [{"mesh": 0}] + [{}] * 199999)))
    c.error("limit-json-values", None, "/: JSON of about 2000003 values; lidr reads at most 2000000",
            raw=b'{"asset":{"version":"2.0"},"extras":[' + b",".join([b"0"] * 2000000) + b"]}")
    c.error("limit-triangles-strip", mutate(triangle, lambda d: (remove_at(d, "/accessors/0/bufferView"),
                                                               set_at(d, "/accessors/0/count", 30000000),
                                                               remove_at(d, "/meshes/0/primitives/0/indices"),
                                                               set_at(d, "/meshes/0/primitives/0/mode", 5))),
            "the scene would have at least 29999998 triangles; at most 20000000")

    # ---- GLB container ----------------------------------------------------------------------------------------
    G = "GLB header: "
    c.error("glb-version-1", None, G + "version 1 is not 2", main="case.glb", raw=glb(triangle(), version=1))
    c.error("glb-magic", None, G + "magic is not 'glTF'", main="case.glb", raw=b"gltf" + glb(triangle())[4:])
    c.error("glb-length-short", None, G + "length", main="case.glb", raw=glb(triangle(), length_delta=-4))
    c.error("glb-length-long", None, G + "length", main="case.glb", raw=glb(triangle(), length_delta=4))
    c.error("glb-truncated-header", None, G + "the file has 8 bytes", main="case.glb", raw=b"glTF\x02\x00\x00\x00")
    c.error("glb-empty", None, G + "the file has 0 bytes", main="case.glb", raw=b"")
    c.error("glb-json-not-first", None, G + "the first chunk is not JSON", main="case.glb", raw=glb(triangle(), swap=True))
    c.error("glb-json-type-wrong", None, G + "the first chunk is not JSON", main="case.glb", raw=glb(triangle(), json_type=b"JSOM"))
    c.error("glb-second-json", None, G + "chunk 1 is a second JSON chunk", main="case.glb", raw=glb(triangle(), bin_type=b"JSON"))
    data = bytearray(glb(triangle()))
    data[12:16] = struct.pack("<I", 0xFFFFFFFF)
    c.error("glb-json-length-huge", None, G + "JSON chunk length 4294967295 runs past the end of the file", main="case.glb", raw=bytes(data))
    data = bytearray(glb(triangle()))
    json_length = struct.unpack("<I", data[12:16])[0]
    data[20 + json_length:24 + json_length] = struct.pack("<I", 0xFFFFFFFF)
    c.error("glb-bin-length-huge", None, G + "chunk 1 length 4294967295 runs past the end of the file", main="case.glb", raw=bytes(data))
    c.error("glb-bin-unaligned", None, G + "chunk 1 length 43 is not a multiple of 4", main="case.glb", raw=glb(triangle(), bin_chunk=BIN[:43]))
    data = bytearray(glb(triangle()))
    data[12:16] = struct.pack("<I", json_length - 1)
    c.error("glb-json-unaligned", None, G + "JSON chunk length", main="case.glb", raw=bytes(data))
    c.error("glb-bin-shorter-than-buffer", None, "/buffers/0/byteLength: 48 bytes, but the GLB BIN chunk has 44", main="case.glb",
            raw=glb(triangle(), byte_length=48))
    c.error("glb-no-bin-no-uri", None, "/buffers/0: buffer without uri", main="case.glb",
            raw=glb(mutate(triangle, lambda d: remove_at(d, "/buffers/0/uri")), bin_chunk=None))
    c.error("glb-cut-chunk-header", None, G + "chunk 1 header is cut off", main="case.glb",
            raw=glb(triangle(), bin_chunk=None, extra=struct.pack("<I", 4)))
    c.error("glb-deep-json", None, "JSON nested deeper than 128", main="case.glb",
            raw=glb(None, bin_chunk=None, text=b'{"asset":{"version":"2.0"},"extras":' + b"[" * 50000 + b"]" * 50000 + b"}"))

    # ---- the scene file itself --------------------------------------------------------------------------------
    c.error("file-directory", None, "glTF file is a directory", main="dir.gltf", setup=lambda d: os.mkdir(os.path.join(d, "dir.gltf")))
    c.error("file-fifo", None, "glTF file is not a regular file", main="pipe.gltf", setup=lambda d: os.mkfifo(os.path.join(d, "pipe.gltf")))
    c.error("file-dev-zero-link", None, "glTF file is not a regular file", main="zero.glb",
            setup=lambda d: os.symlink("/dev/zero", os.path.join(d, "zero.glb")))
    c.error("file-symlink-loop", None, "glTF file Too many levels of symbolic links", main="loop.gltf",
            setup=lambda d: os.symlink("loop.gltf", os.path.join(d, "loop.gltf")))
    c.error("file-missing", None, "glTF file not found", main="absent.gltf", setup=lambda d: None)

    # ---- the same classes for OBJ / MTL and lidr scene files (doc/scene-format.md, "Limits") -------------------
    obj = b"mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nusemtl a\nf 1/1 2/1 3/1\n"
    mtl = b"newmtl a\nKd 1 1 1\nmap_Kd tex.png\n"
    link = lambda target, name: (lambda d: os.symlink(target, os.path.join(d, name)))
    ok("obj-valid", None, main="m.obj", raw=obj, files={"m.mtl": mtl, "tex.png": png(2, 2)})
    c.add("obj-mtl-missing", None, "warning", "m.mtl", main="m.obj", raw=obj)
    c.error("obj-mtl-directory", None, "line 1: MTL file", main="m.obj", raw=obj, setup=lambda d: os.mkdir(os.path.join(d, "m.mtl")))
    c.error("obj-mtl-dev-zero", None, "m.mtl' is not a regular file", main="m.obj", raw=obj, setup=link("/dev/zero", "m.mtl"))
    c.error("obj-mtl-fifo", None, "m.mtl' is not a regular file", main="m.obj", raw=obj, setup=lambda d: os.mkfifo(os.path.join(d, "m.mtl")))
    c.error("obj-mtl-loop", None, "m.mtl' Too many levels of symbolic links", main="m.obj", raw=obj, setup=link("m.mtl", "m.mtl"))
    c.error("obj-texture-png-100000", None, "tex.png' is 100000x100000, over the texture limit of 16384", main="m.obj", raw=obj,
            files={"m.mtl": mtl, "tex.png": png(2, 2, declared=(100000, 100000))})
    c.error("obj-texture-jpeg-20000", None, "tex.png' is 20000x100, over the texture limit of 16384", main="m.obj", raw=obj,
            files={"m.mtl": mtl, "tex.png": jpeg_header(20000, 100)})
    c.error("obj-texture-directory", None, "tex.png' is a directory", main="m.obj", raw=obj, files={"m.mtl": mtl},
            setup=lambda d: os.mkdir(os.path.join(d, "tex.png")))
    c.error("obj-texture-dev-zero", None, "tex.png' is not a regular file", main="m.obj", raw=obj, files={"m.mtl": mtl},
            setup=link("/dev/zero", "tex.png"))
    c.error("obj-texture-not-image", None, "tex.png' cannot be read", main="m.obj", raw=obj, files={"m.mtl": mtl, "tex.png": b"not an image"})
    c.error("obj-nan", None, "line 3: vertex 2 coordinate 'nan' is not finite", main="m.obj", raw=obj.replace(b"v 1 0 0", b"v nan 0 0"),
            files={"m.mtl": mtl, "tex.png": png(2, 2)})
    c.error("obj-face-index", None, "vertex index 9 out of range", main="m.obj", raw=obj.replace(b"f 1/1 2/1 3/1", b"f 1/1 2/1 9/1"),
            files={"m.mtl": mtl, "tex.png": png(2, 2)})
    c.error("obj-file-directory", None, "OBJ file is a directory", main="d.obj", setup=lambda d: os.mkdir(os.path.join(d, "d.obj")))
    c.error("obj-file-fifo", None, "OBJ file is not a regular file", main="p.obj", setup=lambda d: os.mkfifo(os.path.join(d, "p.obj")))
    c.error("obj-file-dev-zero", None, "OBJ file is not a regular file", main="z.obj", setup=link("/dev/zero", "z.obj"))
    scene = lambda extra: ('{"lights": [{"position": [0, 1, 0], "radius": 2}]%s}' % extra).encode()
    ok("scene-valid", None, main="s.json", raw=scene(', "models": [{"file": "t.gltf"}]'), files={"t.gltf": json.dumps(triangle()).encode()})
    c.error("scene-gltf-model-invalid", None, "models[0].file: ", main="s.json", raw=scene(', "models": [{"file": "t.gltf"}]'),
            files={"t.gltf": json.dumps(mutate(triangle, lambda d: set_at(d, "/nodes/0/rotation", [0, 0, 0, 0]))).encode()})
    c.error("scene-gltf-model-rule", None, "t.gltf: /nodes/0/rotation: must be a unit quaternion", main="s.json",
            raw=scene(', "models": [{"file": "t.gltf"}]'),
            files={"t.gltf": json.dumps(mutate(triangle, lambda d: set_at(d, "/nodes/0/rotation", [0, 0, 0, 0]))).encode()})
    c.error("scene-obj-model-mtl-fifo", None, "m.mtl' is not a regular file", main="s.json", raw=scene(', "models": [{"file": "m.obj"}]'),
            files={"m.obj": obj}, setup=lambda d: os.mkfifo(os.path.join(d, "m.mtl")))
    c.error("scene-texture-png-100000", None, "materials[0].texture: texture", main="s.json",
            raw=scene(', "materials": [{"name": "m", "texture": "big.png"}]'), files={"big.png": png(2, 2, declared=(100000, 100000))})
    c.error("scene-texture-jpeg-20000", None, "is 20000x100, over the texture limit", main="s.json",
            raw=scene(', "materials": [{"name": "m", "texture": "big.jpg"}]'), files={"big.jpg": jpeg_header(20000, 100)})
    c.error("scene-deep-json", None, "nested deeper than 64", main="s.json", raw=b'{"description": ' + b"[" * 100000 + b"]" * 100000 + b"}")
    c.error("scene-file-directory", None, "scene file is a directory", main="d.json", setup=lambda d: os.mkdir(os.path.join(d, "d.json")))
    c.error("scene-file-fifo", None, "scene file is not a regular file", main="p.json", setup=lambda d: os.mkfifo(os.path.join(d, "p.json")))
    c.error("scene-file-loop", None, "Too many levels of symbolic links", main="l.json", setup=link("l.json", "l.json"))
    c.error("scene-lights-over-limit", None, "generate.count: must be in [0, 65535], got 70000", main="s.json",
            raw=b'{"generate": {"count": 70000, "bounds_min": [0, 0, 0], "bounds_max": [1, 1, 1], "radius_min": 1, "radius_max": 1}}')
    return c


def write(corpus, out_dir, fuzz_seeds=None):
    os.makedirs(out_dir, exist_ok=True)
    manifest = []
    for case in corpus.cases:
        folder = os.path.join(out_dir, case["name"])
        if os.path.lexists(folder):
            for root, dirs, files in os.walk(folder, topdown=False):
                for f in files:
                    os.unlink(os.path.join(root, f))
                for d in dirs:
                    p = os.path.join(root, d)
                    os.unlink(p) if os.path.islink(p) else os.rmdir(p)
            os.rmdir(folder)
        os.makedirs(folder)
        main = os.path.join(folder, case["main"])
        data = case["raw"] if case["raw"] is not None else (json.dumps(case["doc"], indent=1).encode() if case["doc"] is not None else None)
        if data is not None:
            with open(main, "wb") as f:
                f.write(data)
        for name, content in case["files"].items():
            with open(os.path.join(folder, name), "wb") as f:
                f.write(content)
        if case["setup"]:
            case["setup"](folder)
        manifest.append({"name": case["name"], "file": os.path.relpath(main, out_dir), "expect": case["expect"],
                         "message": case["message"]})
        if fuzz_seeds and data is not None and not case["files"] and not case["setup"] and len(data) <= 8192:
            os.makedirs(fuzz_seeds, exist_ok=True)
            with open(os.path.join(fuzz_seeds, case["name"] + os.path.splitext(case["main"])[1]), "wb") as f:
                f.write(data)
    with open(os.path.join(out_dir, "cases.json"), "w") as f:
        json.dump(manifest, f, indent=1)
    return manifest


def main(argv):
    if len(argv) < 2:
        print(__doc__, file=sys.stderr)
        return 2
    seeds = argv[argv.index("--fuzz-seeds") + 1] if "--fuzz-seeds" in argv else None
    manifest = write(build(), argv[1], seeds)
    print("%d cases written to %s" % (len(manifest), argv[1]))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
