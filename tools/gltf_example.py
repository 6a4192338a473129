#!/usr/bin/env python3
"""Writes scenes/glossy-spheres.glb, the glTF 2.0 example scene slc renders
from the command line: a room (floor and three walls), six spheres of glTF
metallic-roughness materials (roughness 0.05, 0.2, 0.5; metallic 0 and 1),
an emissive ceiling panel (KHR_materials_emissive_strength), a point and a
spot light (KHR_lights_punctual) and a camera. Deterministic; only the
Python standard library.

    python3 tools/gltf_example.py            # rewrites scenes/glossy-spheres.glb
    cargo run --release -p slc-cli -- render --app pt --scene scenes/glossy-spheres.glb --spp 256 --out spheres.exr
"""

import json
import math
import os
import struct

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def icosphere(levels):
    t = (1.0 + 5 ** 0.5) / 2.0
    v = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t), (0, 1, -t),
         (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    f = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2), (10, 7, 6),
         (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7),
         (9, 8, 1)]
    norm = lambda p: tuple(c / math.sqrt(sum(x * x for x in p)) for c in p)
    verts = [norm(p) for p in v]
    index = {}
    faces = f
    for _ in range(levels):
        out = []
        for a, b, c in faces:
            def mid(i, j):
                key = (min(i, j), max(i, j))
                if key not in index:
                    verts.append(norm(tuple((x + y) / 2 for x, y in zip(verts[i], verts[j]))))
                    index[key] = len(verts) - 1
                return index[key]
            ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
            out += [(a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca)]
        faces = out
    return verts, faces


class Glb:
    def __init__(self):
        self.bin = bytearray()
        self.views, self.accessors, self.meshes = [], [], []

    def add(self, data, fmt, count, ty, comp, minmax=None):
        while len(self.bin) % 4:
            self.bin.append(0)
        off = len(self.bin)
        self.bin += struct.pack("<%d%s" % (len(data), fmt), *data)
        self.views.append({"buffer": 0, "byteOffset": off, "byteLength": len(self.bin) - off})
        acc = {"bufferView": len(self.views) - 1, "count": count, "type": ty, "componentType": comp}
        if minmax:
            acc["min"], acc["max"] = minmax
        self.accessors.append(acc)
        return len(self.accessors) - 1

    def geometry(self, verts, normals, faces):
        """Accessors of a triangle mesh: (attributes, indices)."""
        flat = [c for p in verts for c in p]
        lo = [min(p[k] for p in verts) for k in range(3)]
        hi = [max(p[k] for p in verts) for k in range(3)]
        attrs = {"POSITION": self.add(flat, "f", len(verts), "VEC3", 5126, (lo, hi))}
        if normals:
            attrs["NORMAL"] = self.add([c for n in normals for c in n], "f", len(normals), "VEC3", 5126)
        return attrs, self.add([i for f in faces for i in f], "H", 3 * len(faces), "SCALAR", 5123)

    def mesh(self, geometry, material):
        attrs, idx = geometry
        self.meshes.append({"primitives": [{"attributes": attrs, "indices": idx, "material": material}]})
        return len(self.meshes) - 1


def main():
    g = Glb()
    materials = [
        {"name": "floor", "pbrMetallicRoughness": {"baseColorFactor": [0.6, 0.6, 0.6, 1], "metallicFactor": 0.0, "roughnessFactor": 0.7}},
        {"name": "wall", "pbrMetallicRoughness": {"baseColorFactor": [0.7, 0.68, 0.62, 1], "metallicFactor": 0.0, "roughnessFactor": 1.0}},
        {"name": "red wall", "pbrMetallicRoughness": {"baseColorFactor": [0.6, 0.1, 0.08, 1], "metallicFactor": 0.0, "roughnessFactor": 1.0}},
        {"name": "panel", "emissiveFactor": [1.0, 0.95, 0.85], "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 4.0}},
         "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.8, 0.8, 1], "metallicFactor": 0.0}},
    ]
    s = 1.5
    quad = lambda pts, m: g.mesh(g.geometry(pts, None, [(0, 1, 2), (0, 2, 3)]), m)
    nodes = [
        {"name": "floor", "mesh": quad([(-s, 0, s), (s, 0, s), (s, 0, -s), (-s, 0, -s)], 0)},
        {"name": "back wall", "mesh": quad([(-s, 0, -s), (s, 0, -s), (s, 2, -s), (-s, 2, -s)], 1)},
        {"name": "left wall", "mesh": quad([(-s, 0, s), (-s, 0, -s), (-s, 2, -s), (-s, 2, s)], 2)},
        {"name": "right wall", "mesh": quad([(s, 0, -s), (s, 0, s), (s, 2, s), (s, 2, -s)], 1)},
        {"name": "panel", "mesh": quad([(-0.5, 1.95, -0.5), (0.5, 1.95, -0.5), (0.5, 1.95, 0.5), (-0.5, 1.95, 0.5)], 3)},
    ]
    verts, faces = icosphere(3)
    ball = g.geometry(verts, verts, faces)  # one mesh, six materials
    for i, rough in enumerate((0.05, 0.2, 0.5)):
        for j, metal in enumerate((0.0, 1.0)):
            base = [1.0, 0.78, 0.34, 1] if metal else [0.75, 0.15, 0.12, 1]
            materials.append({"name": "r%.2f m%d" % (rough, metal),
                              "pbrMetallicRoughness": {"baseColorFactor": base, "metallicFactor": metal, "roughnessFactor": rough}})
            m = g.mesh(ball, len(materials) - 1)
            nodes.append({"name": materials[-1]["name"], "mesh": m, "translation": [-0.8 + 0.8 * i, 0.3, -0.45 + 0.9 * j],
                          "scale": [0.3, 0.3, 0.3]})
    # The camera at (0, 1.7, 3.9) looking at (0, 0.45, 0): a rotation about x.
    pitch = math.atan2(1.7 - 0.45, 3.9)
    nodes.append({"name": "camera", "camera": 0, "translation": [0, 1.7, 3.9],
                  "rotation": [-math.sin(pitch / 2), 0, 0, math.cos(pitch / 2)]})
    nodes.append({"name": "point", "translation": [0.9, 1.1, 1.0], "extensions": {"KHR_lights_punctual": {"light": 0}}})
    # A spot pointing straight down (−z turned to −y).
    nodes.append({"name": "spot", "translation": [-0.9, 1.8, 0.6], "rotation": [-math.sqrt(0.5), 0, 0, math.sqrt(0.5)],
                  "extensions": {"KHR_lights_punctual": {"light": 1}}})
    doc = {
        "asset": {"version": "2.0", "generator": "slc tools/gltf_example.py"},
        "extensionsUsed": ["KHR_lights_punctual", "KHR_materials_emissive_strength"],
        "extensions": {"KHR_lights_punctual": {"lights": [
            {"type": "point", "color": [1.0, 0.85, 0.7], "intensity": 0.8},
            {"type": "spot", "color": [0.7, 0.8, 1.0], "intensity": 2.0, "spot": {"innerConeAngle": 0.3, "outerConeAngle": 0.5}},
        ]}},
        "scene": 0,
        "scenes": [{"nodes": list(range(len(nodes)))}],
        "nodes": nodes,
        "meshes": g.meshes,
        "materials": materials,
        "cameras": [{"type": "perspective", "perspective": {"yfov": math.radians(40), "znear": 0.05}}],
        "buffers": [{"byteLength": len(g.bin)}],
        "bufferViews": g.views,
        "accessors": g.accessors,
    }
    js = json.dumps(doc, separators=(",", ":")).encode()
    js += b" " * (-len(js) % 4)
    b = bytes(g.bin) + b"\0" * (-len(g.bin) % 4)
    out = struct.pack("<4sII", b"glTF", 2, 12 + 8 + len(js) + 8 + len(b))
    out += struct.pack("<I4s", len(js), b"JSON") + js + struct.pack("<I4s", len(b), b"BIN\0") + b
    path = os.path.join(ROOT, "scenes", "glossy-spheres.glb")
    with open(path, "wb") as f:
        f.write(out)
    print("wrote %s (%d bytes)" % (path, len(out)))


if __name__ == "__main__":
    main()
