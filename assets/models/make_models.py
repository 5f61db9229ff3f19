#!/usr/bin/env python3
"""Writes the small glTF models shadelab ships in assets/models/ (made by this project; CC0).

  python3 assets/models/make_models.py      # rewrites the .gltf files beside this script

- lowpoly_gem.gltf: a 12-sided bipyramid ("gem") with smooth normals and a wide, flat belt, so a
  highlight falls between vertices: Gouraud loses it, Phong keeps it, flat shows the facets.
- coarse_torus_no_normals.gltf: an 8 x 6 torus without a NORMAL attribute: shadelab computes
  angle-weighted normals (see --info), and its coarse tube shows Gouraud's Mach bands.
- checker_globe.gltf: a 32 x 16 UV sphere with a base colour texture (a checkerboard with a red
  meridian, embedded as a PNG data: URI) and vertex colours (COLOR_0, lighter toward the top): the
  object texture of the lecture's C, read per fragment in every mode.
- checker_globe_transform.gltf: the same globe with its texture coordinates stored transformed back
  and KHR_texture_transform (offset, rotation, scale) restoring them, its texture beside it in
  checker_globe.png: it must draw exactly like checker_globe.gltf.
- spot_stage.gltf: the gem on a floor, lit by the file's own lights (KHR_lights_punctual): a spot
  light from above (800 cd, cone 12 to 28 degrees) and a dim directional fill (0.3 lux), as an
  exporter writes them in physical units; shadelab converts them to the lecture's L_l.
- material_panels.gltf: three unit quads facing +z, each showing what a glTF material adds to the
  lecture's C: a cut-out (alphaMode MASK: an orange 4 x 4 checker whose dark squares have alpha 0,
  COLOR_0 as RGBA), a half-transparent blue pane (alphaMode BLEND, factor alpha 0.5), and a dark
  panel that gives off light (emissiveFactor x emissiveTexture, a 2 x 2 stripe read at TEXCOORD_1
  turned a quarter, x KHR_materials_emissive_strength 2). tests/scenes/material_panels.json puts
  them before a wall.
Only the Python standard library is used; buffers are embedded as base64 data: URIs.
"""
import base64
import json
import math
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))


def save(name, doc, blob):
    """Writes NAME.gltf beside this script with `blob` as its one buffer, embedded as a data: URI."""
    buffers = [{"byteLength": len(blob), "uri": "data:application/octet-stream;base64," + base64.b64encode(blob).decode()}]
    ordered = {}  # "buffers" just before "bufferViews", as the files have always had it
    for key, value in doc.items():
        if key == "bufferViews":
            ordered["buffers"] = buffers
        ordered[key] = value
    with open(os.path.join(HERE, name + ".gltf"), 'w') as f:
        json.dump(ordered, f, indent=1)
        f.write('\n')


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
        "bufferViews": views, "accessors": accessors,
    }
    save(name, doc, blob)


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


def floor(n=8, size=6.0, y=-0.8):
    positions, normals, indices = [], [], []
    for i in range(n + 1):
        for k in range(n + 1):
            positions.append((-size / 2 + size * k / n, y, -size / 2 + size * i / n))
            normals.append((0.0, 1.0, 0.0))
    for i in range(n):
        for k in range(n):
            a = i * (n + 1) + k
            indices += [a, a + n + 1, a + 1, a + 1, a + n + 1, a + n + 2]  # counter-clockwise seen from above
    return positions, normals, indices


def write_stage(name):
    """The gem and the floor as two meshes, and two lights on nodes of their own."""
    gp, gn, gi = gem()
    fp, fn, fi = floor()
    blobs, views, accessors, meshes = [], [], [], []
    offset = 0
    for mesh_index, (p, n, idx) in enumerate(((gp, gn, gi), (fp, fn, fi))):
        parts = [b''.join(struct.pack('<3f', *v) for v in p), b''.join(struct.pack('<3f', *v) for v in n),
                 b''.join(struct.pack('<H', i) for i in idx)]
        parts[2] += b'\0' * ((4 - len(parts[2]) % 4) % 4)
        first = len(accessors)
        for k, data in enumerate(parts):
            views.append({"buffer": 0, "byteOffset": offset, "byteLength": len(data) if k < 2 else 2 * len(idx),
                          "target": 34963 if k == 2 else 34962})
            offset += len(data)
            blobs.append(data)
        accessors.append({"bufferView": first, "componentType": 5126, "count": len(p), "type": "VEC3",
                          "min": [min(v[c] for v in p) for c in range(3)], "max": [max(v[c] for v in p) for c in range(3)]})
        accessors.append({"bufferView": first + 1, "componentType": 5126, "count": len(n), "type": "VEC3"})
        accessors.append({"bufferView": first + 2, "componentType": 5123, "count": len(idx), "type": "SCALAR"})
        meshes.append({"primitives": [{"attributes": {"POSITION": first, "NORMAL": first + 1}, "indices": first + 2,
                                       "material": mesh_index, "mode": 4}]})
    blob = b''.join(blobs)
    # The spot 3 m above and 1.5 m in front, turned to look at the gem: its -Z toward (0, 0, 0).
    sx, sy, sz = 0.0, 3.0, 1.5
    pitch = math.atan2(sy, sz)  # rotate -Z about x by -pitch to point down toward the origin
    spot_rotation = [-math.sin(pitch / 2), 0.0, 0.0, math.cos(pitch / 2)]
    sun_rotation = [-math.sin(math.radians(60) / 2), 0.0, 0.0, math.cos(math.radians(60) / 2)]
    doc = {
        "asset": {"version": "2.0", "generator": "shadelab assets/models/make_models.py", "copyright": "CC0-1.0"},
        "extensionsUsed": ["KHR_lights_punctual"],
        "extensions": {"KHR_lights_punctual": {"lights": [
            {"name": "spot", "type": "spot", "intensity": 800.0, "color": [1.0, 0.95, 0.85],
             "spot": {"innerConeAngle": math.radians(12), "outerConeAngle": math.radians(28)}},
            {"name": "fill", "type": "directional", "intensity": 0.3, "color": [0.7, 0.8, 1.0]}]}},
        "scene": 0, "scenes": [{"nodes": [0, 1, 2, 3]}],
        "nodes": [{"mesh": 0, "name": "gem"}, {"mesh": 1, "name": "floor"},
                  {"name": "spot", "translation": [sx, sy, sz], "rotation": spot_rotation,
                   "extensions": {"KHR_lights_punctual": {"light": 0}}},
                  {"name": "fill", "rotation": sun_rotation, "extensions": {"KHR_lights_punctual": {"light": 1}}}],
        "materials": [{"name": "gem", "pbrMetallicRoughness": {"baseColorFactor": [0.25, 0.55, 0.9, 1.0],
                                                               "metallicFactor": 0.0, "roughnessFactor": 0.5}},
                      {"name": "floor", "pbrMetallicRoughness": {"baseColorFactor": [0.75, 0.75, 0.72, 1.0],
                                                                 "metallicFactor": 0.0, "roughnessFactor": 0.9}}],
        "meshes": meshes,
        "bufferViews": views, "accessors": accessors,
    }
    save(name, doc, blob)


def png(width, height, rows):
    """An 8-bit PNG of rows of (r, g, b) or (r, g, b, a) tuples (RGB or RGBA by the tuples' length)."""
    raw = b''.join(b'\0' + bytes(c for px in row for c in px) for row in rows)
    color_type = 6 if len(rows[0][0]) == 4 else 2
    def chunk(kind, data):
        return struct.pack('>I', len(data)) + kind + data + struct.pack('>I', zlib.crc32(kind + data) & 0xffffffff)
    return (b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', width, height, 8, color_type, 0, 0, 0)) +
            chunk(b'IDAT', zlib.compress(raw, 9)) + chunk(b'IEND', b''))


def checker_image(width=256, height=128, squares=(8, 4)):
    cream, teal, red = (236, 226, 196), (40, 120, 130), (200, 40, 30)
    rows = []
    for y in range(height):
        row = []
        for x in range(width):
            if x < width // 32:
                row.append(red)  # the meridian at u = 0
            else:
                row.append(cream if (x * squares[0] // width + y * squares[1] // height) % 2 == 0 else teal)
        rows.append(row)
    return png(width, height, rows)


def globe(slices=32, stacks=16, radius=1.0):
    positions, normals, uvs, colors, indices = [], [], [], [], []
    for i in range(stacks + 1):
        v = i / stacks
        theta = math.pi * v
        for j in range(slices + 1):
            u = j / slices
            phi = 2 * math.pi * u
            n = (math.sin(theta) * math.cos(phi), math.cos(theta), -math.sin(theta) * math.sin(phi))
            positions.append(tuple(radius * c for c in n))
            normals.append(n)
            uvs.append((u, v))
            g = 0.6 + 0.4 * (1.0 - v)  # lighter toward the top
            colors.append((g, g, 1.0))
    for i in range(stacks):
        for j in range(slices):
            a = i * (slices + 1) + j
            b = a + slices + 1
            # counter-clockwise seen from outside; one triangle per pole quad (the other has no area)
            if i > 0:
                indices += [a, b, a + 1]
            if i < stacks - 1:
                indices += [a + 1, b, b + 1]
    return positions, normals, uvs, colors, indices


def write_globe(name, uvs_stored, transform=None, image_uri=None):
    positions, normals, _, colors, indices = globe()
    pos = b''.join(struct.pack('<3f', *p) for p in positions)
    nrm = b''.join(struct.pack('<3f', *n) for n in normals)
    uv = b''.join(struct.pack('<2f', *t) for t in uvs_stored)
    col = b''.join(struct.pack('<3f', *c) for c in colors)
    idx = b''.join(struct.pack('<H', i) for i in indices)
    parts = [pos, nrm, uv, col, idx]
    views, offset = [], 0
    for k, data in enumerate(parts):
        views.append({"buffer": 0, "byteOffset": offset, "byteLength": len(data),
                      "target": 34963 if k == len(parts) - 1 else 34962})
        offset += len(data)
    blob = b''.join(parts)
    accessors = [
        {"bufferView": 0, "componentType": 5126, "count": len(positions), "type": "VEC3",
         "min": [min(p[k] for p in positions) for k in range(3)], "max": [max(p[k] for p in positions) for k in range(3)]},
        {"bufferView": 1, "componentType": 5126, "count": len(normals), "type": "VEC3"},
        {"bufferView": 2, "componentType": 5126, "count": len(uvs_stored), "type": "VEC2"},
        {"bufferView": 3, "componentType": 5126, "count": len(colors), "type": "VEC3"},
        {"bufferView": 4, "componentType": 5123, "count": len(indices), "type": "SCALAR"},
    ]
    texture_info = {"index": 0}
    doc = {
        "asset": {"version": "2.0", "generator": "shadelab assets/models/make_models.py", "copyright": "CC0-1.0"},
        "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0, "name": name}],
        "materials": [{"name": name, "pbrMetallicRoughness": {"baseColorFactor": [1.0, 0.95, 0.9, 1.0],
                                                               "baseColorTexture": texture_info,
                                                               "metallicFactor": 0.0, "roughnessFactor": 0.5}}],
        "meshes": [{"name": name, "primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2, "COLOR_0": 3},
                                                  "indices": 4, "material": 0, "mode": 4}]}],
        "samplers": [{"magFilter": 9729, "minFilter": 9987, "wrapS": 10497, "wrapT": 10497}],
        "textures": [{"sampler": 0, "source": 0}],
        "images": [{"uri": image_uri or "data:image/png;base64," + base64.b64encode(checker_image()).decode()}],
        "bufferViews": views, "accessors": accessors,
    }
    if transform:
        texture_info["extensions"] = {"KHR_texture_transform": transform}
        doc["extensionsUsed"] = ["KHR_texture_transform"]
    save(name, doc, blob)


def write_material_panels(name):
    """Three quads at x = -1.2, 0, 1.2: MASK, BLEND and emissive (see the docstring at the top)."""
    def data_uri(png_bytes):
        return "data:image/png;base64," + base64.b64encode(png_bytes).decode()
    orange, clear = (230, 120, 40, 255), (30, 30, 30, 0)
    checker = [[orange if (x + y) % 2 == 0 else clear for x in range(4)] for y in range(4)]
    stripes = png(2, 2, [[(255, 255, 255), (0, 0, 0)], [(255, 255, 255), (0, 0, 0)]])
    blob, views, accessors = b'', [], []

    def add(data, count, kind, target=34962, bounds=None):
        nonlocal blob
        views.append({"buffer": 0, "byteOffset": len(blob), "byteLength": len(data), "target": target})
        accessor = {"bufferView": len(views) - 1, "componentType": 5123 if target == 34963 else 5126,
                    "count": count, "type": kind}
        if bounds:
            accessor["min"], accessor["max"] = bounds
        accessors.append(accessor)
        blob += data + b'\0' * ((4 - len(data) % 4) % 4)
        return len(accessors) - 1

    meshes, nodes = [], []
    corners = [(-0.5, -0.5), (0.5, -0.5), (0.5, 0.5), (-0.5, 0.5)]
    uv0 = [(0.0, 1.0), (1.0, 1.0), (1.0, 0.0), (0.0, 0.0)]
    uv1 = [(0.0, 0.0), (0.0, 1.0), (1.0, 1.0), (1.0, 0.0)]  # a quarter turn: the stripes run across
    for k, x in enumerate((-1.2, 0.0, 1.2)):
        positions = [(x + cx, cy, 0.0) for cx, cy in corners]
        attributes = {
            "POSITION": add(b''.join(struct.pack('<3f', *p) for p in positions), 4, "VEC3",
                            bounds=([x - 0.5, -0.5, 0.0], [x + 0.5, 0.5, 0.0])),
            "NORMAL": add(struct.pack('<3f', 0, 0, 1) * 4, 4, "VEC3"),
            "TEXCOORD_0": add(b''.join(struct.pack('<2f', *t) for t in uv0), 4, "VEC2"),
        }
        if k == 0:
            attributes["COLOR_0"] = add(struct.pack('<4f', 1, 1, 1, 1) * 4, 4, "VEC4")
        if k == 2:
            attributes["TEXCOORD_1"] = add(b''.join(struct.pack('<2f', *t) for t in uv1), 4, "VEC2")
        indices = add(struct.pack('<6H', 0, 1, 2, 0, 2, 3), 6, "SCALAR", target=34963)
        meshes.append({"name": ["cut-out", "pane", "lamp"][k],
                       "primitives": [{"attributes": attributes, "indices": indices, "material": k, "mode": 4}]})
        nodes.append({"mesh": k, "name": meshes[-1]["name"]})
    materials = [
        {"name": "cut-out", "alphaMode": "MASK", "alphaCutoff": 0.5,
         "pbrMetallicRoughness": {"baseColorTexture": {"index": 0}, "metallicFactor": 0.0}},
        {"name": "pane", "alphaMode": "BLEND",
         "pbrMetallicRoughness": {"baseColorFactor": [0.2, 0.4, 0.9, 0.5], "metallicFactor": 0.0}},
        {"name": "lamp", "emissiveFactor": [1.0, 0.5, 0.25], "emissiveTexture": {"index": 1, "texCoord": 1},
         "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 2.0}},
         "pbrMetallicRoughness": {"baseColorFactor": [0.1, 0.1, 0.1, 1.0], "metallicFactor": 0.0}},
    ]
    doc = {
        "asset": {"version": "2.0", "generator": "shadelab assets/models/make_models.py", "copyright": "CC0-1.0"},
        "extensionsUsed": ["KHR_materials_emissive_strength"],
        "scene": 0, "scenes": [{"nodes": [0, 1, 2]}], "nodes": nodes, "meshes": meshes, "materials": materials,
        "samplers": [{"magFilter": 9728, "minFilter": 9728, "wrapS": 33071, "wrapT": 33071}],
        "textures": [{"sampler": 0, "source": 0}, {"sampler": 0, "source": 1}],
        "images": [{"uri": data_uri(png(4, 4, checker))}, {"uri": data_uri(stripes)}],
        "bufferViews": views, "accessors": accessors,
    }
    save(name, doc, blob)


def texture_transform_inverse(uv, offset, rotation, scale):
    # KHR_texture_transform: uv' = T(offset) R(rotation) S(scale) uv, R = [[c, s], [-s, c]]; this is
    # the uv that the transform takes to `uv`.
    x, y = uv[0] - offset[0], uv[1] - offset[1]
    c, s = math.cos(rotation), math.sin(rotation)
    # R^-1 = [[c, -s], [s, c]]
    x, y = c * x - s * y, s * x + c * y
    return (x / scale[0], y / scale[1])


if __name__ == '__main__':
    p, n, i = gem()
    write("lowpoly_gem", p, i, n, color=(0.25, 0.55, 0.9))
    p, i = torus()
    write("coarse_torus_no_normals", p, i, color=(0.9, 0.65, 0.2))
    _, _, uvs, _, _ = globe()
    write_globe("checker_globe", uvs)
    t = {"offset": [0.25, -0.125], "rotation": 0.5, "scale": [2.0, 0.5]}
    write_globe("checker_globe_transform", [texture_transform_inverse(uv, t["offset"], t["rotation"], t["scale"]) for uv in uvs],
                transform=t, image_uri="checker_globe.png")
    with open(os.path.join(HERE, "checker_globe.png"), 'wb') as f:
        f.write(checker_image())
    write_stage("spot_stage")
    write_material_panels("material_panels")
    print("wrote lowpoly_gem.gltf, coarse_torus_no_normals.gltf, checker_globe.gltf, checker_globe_transform.gltf, "
          "checker_globe.png, spot_stage.gltf, material_panels.gltf")
