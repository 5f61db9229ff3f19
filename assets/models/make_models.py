#!/usr/bin/env python3
"""Writes the small glTF models shadelab ships in assets/models/ (made by this project; CC0).

  python3 assets/models/make_models.py      # rewrites the .gltf files beside this script

- lowpoly_gem.gltf: a 12-sided bipyramid ("gem") with smooth normals and a wide, flat belt, so a
  highlight falls between vertices: Gouraud loses it, Phong keeps it, flat shows the facets.
- coarse_torus_no_normals.gltf: an 8 x 6 torus without a NORMAL attribute: shadelab computes
  angle-weighted normals (see --info), and its coarse tube shows Gouraud's Mach bands.
Only the Python standard library is used; buffers are embedded as base64 data: URIs.
"""
import base64
import json
import math
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))


def write(name, positions, indices, normals=None, color=(0.8, 0.8, 0.8)):
    pos = b''.join(struct.pack('<3f', *p) for p in positions)
    nrm = b''.join(struct.pack('<3f', *n) for n in normals) if normals else b''
    idx = b''.join(struct.pack('<H', i) for i in indices)
    idx += b'\0' * ((4 - len(idx) % 4) % 4)
    blob = pos + nrm + idx
    views = [{"buffer": 0, "byteOffset": 0, "byteLength": len(pos), "target": 34962}]
    accessors = [{"bufferView": 0, "componentType": 5126, "count": len(positions), "type": "VEC3",
                  "min": [min(p[k] for p in positions) for k in range(3)],
                  "max": [max(p[k] for p in positions) for k in range(3)]}]
    attributes = {"POSITION": 0}
    if normals:
        views.append({"buffer": 0, "byteOffset": len(pos), "byteLength": len(nrm), "target": 34962})
        accessors.append({"bufferView": 1, "componentType": 5126, "count": len(normals), "type": "VEC3"})
        attributes["NORMAL"] = 1
    views.append({"buffer": 0, "byteOffset": len(pos) + len(nrm), "byteLength": 2 * len(indices), "target": 34963})
    accessors.append({"bufferView": len(views) - 1, "componentType": 5123, "count": len(indices), "type": "SCALAR"})
    doc = {
        "asset": {"version": "2.0", "generator": "shadelab assets/models/make_models.py", "copyright": "CC0-1.0"},
        "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0, "name": name}],
        "materials": [{"name": name, "pbrMetallicRoughness": {"baseColorFactor": list(color) + [1.0],
                                                               "metallicFactor": 0.0, "roughnessFactor": 0.5}}],
        "meshes": [{"name": name, "primitives": [{"attributes": attributes, "indices": len(accessors) - 1,
                                                  "material": 0, "mode": 4}]}],
        "buffers": [{"byteLength": len(blob),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(blob).decode()}],
        "bufferViews": views, "accessors": accessors,
    }
    with open(os.path.join(HERE, name + ".gltf"), 'w') as f:
        json.dump(doc, f, indent=1)
        f.write('\n')


def normalize(v):
    l = math.sqrt(sum(c * c for c in v))
    return tuple(c / l for c in v)


def gem(sides=12, radius=1.0, height=0.8):
    # apex, belt ring, bottom apex; the belt normals are horizontal, the apex normals vertical
    positions = [(0.0, height, 0.0)]
    normals = [(0.0, 1.0, 0.0)]
    for k in range(sides):
        a = 2 * math.pi * k / sides
        positions.append((radius * math.cos(a), 0.0, radius * math.sin(a)))
        normals.append(normalize((math.cos(a), 0.0, math.sin(a))))
    positions.append((0.0, -height, 0.0))
    normals.append((0.0, -1.0, 0.0))
    bottom = sides + 1
    indices = []
    for k in range(sides):
        a, b = 1 + k, 1 + (k + 1) % sides
        indices += [0, b, a]          # counter-clockwise seen from outside (upper cone)
        indices += [bottom, a, b]     # lower cone
    return positions, normals, indices


def torus(major=8, minor=6, r_major=1.0, r_minor=0.4):
    positions, indices = [], []
    for i in range(major):
        u = 2 * math.pi * i / major
        for j in range(minor):
            v = 2 * math.pi * j / minor
            positions.append(((r_major + r_minor * math.cos(v)) * math.cos(u), r_minor * math.sin(v),
                              (r_major + r_minor * math.cos(v)) * math.sin(u)))
    for i in range(major):
        for j in range(minor):
            a = i * minor + j
            b = ((i + 1) % major) * minor + j
            c = ((i + 1) % major) * minor + (j + 1) % minor
            d = i * minor + (j + 1) % minor
            indices += [a, d, b, b, d, c]   # counter-clockwise seen from outside the tube
    return positions, indices


if __name__ == '__main__':
    p, n, i = gem()
    write("lowpoly_gem", p, i, n, color=(0.25, 0.55, 0.9))
    p, i = torus()
    write("coarse_torus_no_normals", p, i, color=(0.9, 0.65, 0.2))
    print("wrote lowpoly_gem.gltf, coarse_torus_no_normals.gltf")
