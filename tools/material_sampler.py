#!/usr/bin/env python3
"""Writes a textured sample model that exercises the glTF material the way public sample models do,
for trying the renderer as a user would where those models are not at hand:

- a "helmet" sphere with every metallic-roughness map: a base colour texture (painted bands), a
  metallic-roughness texture (metal bands, rough and polished), a normal texture (rivets; no
  TANGENT, so the loader generates them) and an occlusion texture (dark seams);
- a "lantern" sphere whose emissiveFactor is 1 and whose emissive texture is black but for one
  glowing band, as DamagedHelmet, Lantern and BoomBox are built (a renderer that ignores the
  texture draws a white silhouette);
- a "fence" quad of alphaMode MASK whose base colour alpha cuts bars out of it;
- a checkered floor; no light, so the renderer adds its default sun and sky.

    python3 tools/material_sampler.py sampler/        (writes sampler/material_sampler.gltf, .bin, PNGs)
    build/vct render --scene sampler/material_sampler.gltf --preset balanced --out sampler.png
"""
import json
import math
import os
import struct
import sys
import zlib

SIZE = 128  # texels per side of every texture


def png(path, pixels, channels):
    """An 8-bit PNG (grey, grey + alpha, RGB or RGBA) of SIZE × SIZE `pixels` (rows of tuples)."""
    color_type = {1: 0, 2: 4, 3: 2, 4: 6}[channels]
    raw = b"".join(b"\0" + bytes(v for texel in row for v in texel) for row in pixels)

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))

    header = struct.pack(">IIBBBBB", SIZE, SIZE, 8, color_type, 0, 0, 0)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def image(texel):
    """SIZE × SIZE texels of texel(u, v), u and v at the texel centres in 0..1."""
    return [[texel((x + 0.5) / SIZE, (y + 0.5) / SIZE) for x in range(SIZE)] for y in range(SIZE)]


def rivet_normal(u, v):
    """A tangent-space normal (OpenGL convention, +Y up the image) of a rivet every 1/8 in u, v."""
    du, dv = (u * 8) % 1 - 0.5, (v * 8) % 1 - 0.5
    r = math.hypot(du, dv)
    if r > 0.3 or r == 0.0:
        n = (0.0, 0.0, 1.0)
    else:
        slope = math.sin(math.pi * r / 0.3) * 0.8  # a dome: tilted outwards from its centre
        n = (slope * du / r, -slope * dv / r, 1.0)  # v grows down the image, +Y is up
    length = math.sqrt(sum(c * c for c in n))
    return tuple(int(round((c / length * 0.5 + 0.5) * 255)) for c in n)


def textures(folder):
    bands = [(200, 40, 30), (230, 200, 60), (40, 70, 160), (220, 220, 220)]
    png(os.path.join(folder, "helmet_basecolor.png"), image(lambda u, v: bands[int(v * 8) % 4]), 3)
    # glTF: green = roughness, blue = metallic. Bands of polished metal between rough paint.
    png(os.path.join(folder, "helmet_metalrough.png"),
        image(lambda u, v: (0, 40, 255) if int(v * 8) % 2 else (0, 200, 0)), 3)
    png(os.path.join(folder, "helmet_normal.png"), image(rivet_normal), 3)
    png(os.path.join(folder, "helmet_occlusion.png"),
        image(lambda u, v: (90,) if (v * 8) % 1 < 0.08 else (255,)), 1)
    png(os.path.join(folder, "lantern_emissive.png"),
        image(lambda u, v: (255, 170, 60) if 0.45 < v < 0.55 else (0, 0, 0)), 3)
    png(os.path.join(folder, "lantern_basecolor.png"), image(lambda u, v: (60, 60, 64)), 3)
    png(os.path.join(folder, "fence_basecolor.png"),
        image(lambda u, v: (150, 100, 60, 255 if (u * 6) % 1 < 0.35 or (v * 3) % 1 < 0.12 else 0)), 4)
    png(os.path.join(folder, "floor_basecolor.png"),
        image(lambda u, v: (180, 180, 170) if (int(u * 8) + int(v * 8)) % 2 else (90, 95, 100)), 3)


class Mesh:
    def __init__(self):
        self.positions, self.normals, self.uvs, self.indices = [], [], [], []

    def vertex(self, position, normal, uv):
        self.positions.append(position)
        self.normals.append(normal)
        self.uvs.append(uv)
        return len(self.positions) - 1


def sphere(center, radius, rings=32, segments=64):
    mesh = Mesh()
    for i in range(rings + 1):
        theta = math.pi * i / rings
        for j in range(segments + 1):
            phi = 2 * math.pi * j / segments
            n = (math.sin(theta) * math.cos(phi), math.cos(theta), -math.sin(theta) * math.sin(phi))
            mesh.vertex(tuple(c + radius * d for c, d in zip(center, n)), n, (j / segments, i / rings))
    for i in range(rings):
        for j in range(segments):
            a, b = i * (segments + 1) + j, (i + 1) * (segments + 1) + j
            mesh.indices += [a, b, a + 1, a + 1, b, b + 1]  # counter-clockwise seen from outside
    return mesh


def quad(corners, normal, uv_scale=1.0):
    """corners counter-clockwise seen from the front: the image's top left, bottom left, bottom right, top right."""
    mesh = Mesh()
    for corner, uv in zip(corners, [(0, 0), (0, 1), (1, 1), (1, 0)]):
        mesh.vertex(corner, normal, (uv[0] * uv_scale, uv[1] * uv_scale))
    mesh.indices = [0, 1, 2, 0, 2, 3]
    return mesh


def main():
    folder = sys.argv[1] if len(sys.argv) > 1 else "material_sampler"
    os.makedirs(folder, exist_ok=True)
    textures(folder)

    meshes = [
        ("helmet", sphere((-0.6, 0.4, 0.0), 0.4), 0),
        ("lantern", sphere((0.45, 0.3, 0.15), 0.3), 1),
        ("fence", quad([(-1.2, 1.0, -0.6), (-1.2, 0.0, -0.6), (1.2, 0.0, -0.6), (1.2, 1.0, -0.6)], (0, 0, 1)), 2),
        ("floor", quad([(-1.5, 0, -1.5), (-1.5, 0, 1.5), (1.5, 0, 1.5), (1.5, 0, -1.5)], (0, 1, 0), 3.0), 3),
    ]
    gltf = {"asset": {"version": "2.0", "generator": "vct tools/material_sampler.py"},
            "scene": 0, "scenes": [{"nodes": list(range(len(meshes) + 1))}],
            "nodes": [], "meshes": [], "accessors": [], "bufferViews": [], "buffers": [],
            "images": [], "textures": [], "samplers": [{"magFilter": 9729, "minFilter": 9987}]}
    binary = bytearray()

    def view(data, target):
        while len(binary) % 4:
            binary.append(0)
        gltf["bufferViews"].append({"buffer": 0, "byteOffset": len(binary), "byteLength": len(data), "target": target})
        binary.extend(data)
        return len(gltf["bufferViews"]) - 1

    def accessor(values, kind, component=5126, extremes=False):
        width = {"VEC2": 2, "VEC3": 3, "SCALAR": 1}[kind]
        flat = [c for value in values for c in (value if width > 1 else (value,))]
        data = struct.pack("<%d%s" % (len(flat), "f" if component == 5126 else "I"), *flat)
        entry = {"bufferView": view(data, 34962 if component == 5126 else 34963), "componentType": component,
                 "count": len(values), "type": kind}
        if extremes:
            entry["min"] = [min(v[k] for v in values) for k in range(width)]
            entry["max"] = [max(v[k] for v in values) for k in range(width)]
        gltf["accessors"].append(entry)
        return len(gltf["accessors"]) - 1

    def texture(name):
        gltf["images"].append({"uri": name})
        gltf["textures"].append({"source": len(gltf["images"]) - 1, "sampler": 0})
        return {"index": len(gltf["textures"]) - 1}

    gltf["materials"] = [
        {"name": "helmet", "pbrMetallicRoughness": {"baseColorTexture": texture("helmet_basecolor.png"),
                                                    "metallicRoughnessTexture": texture("helmet_metalrough.png")},
         "normalTexture": texture("helmet_normal.png"), "occlusionTexture": texture("helmet_occlusion.png")},
        {"name": "lantern", "pbrMetallicRoughness": {"baseColorTexture": texture("lantern_basecolor.png"),
                                                     "metallicFactor": 0.0, "roughnessFactor": 0.6},
         "emissiveFactor": [1.0, 1.0, 1.0], "emissiveTexture": texture("lantern_emissive.png")},
        {"name": "fence", "alphaMode": "MASK", "alphaCutoff": 0.5, "doubleSided": True,
         "pbrMetallicRoughness": {"baseColorTexture": texture("fence_basecolor.png"), "metallicFactor": 0.0,
                                  "roughnessFactor": 0.8}},
        {"name": "floor", "pbrMetallicRoughness": {"baseColorTexture": texture("floor_basecolor.png"),
                                                   "metallicFactor": 0.0, "roughnessFactor": 0.9}},
    ]
    for name, mesh, material in meshes:
        attributes = {"POSITION": accessor(mesh.positions, "VEC3", extremes=True),
                      "NORMAL": accessor(mesh.normals, "VEC3"), "TEXCOORD_0": accessor(mesh.uvs, "VEC2")}
        primitive = {"attributes": attributes, "indices": accessor(mesh.indices, "SCALAR", 5125), "material": material}
        gltf["meshes"].append({"name": name, "primitives": [primitive]})
        gltf["nodes"].append({"name": name, "mesh": len(gltf["meshes"]) - 1})
    # A camera in front, a little above, looking at the middle of the group.
    gltf["cameras"] = [{"type": "perspective", "perspective": {"yfov": 0.7, "znear": 0.05, "zfar": 50}}]
    eye, target = (0.0, 1.3, 3.2), (0.0, 0.35, 0.0)
    forward = [t - e for t, e in zip(target, eye)]
    pitch = math.atan2(forward[1], math.hypot(forward[0], forward[2]))  # negative: looking down
    gltf["nodes"].append({"name": "camera", "camera": 0, "translation": list(eye),
                          "rotation": [math.sin(pitch / 2), 0.0, 0.0, math.cos(pitch / 2)]})
    gltf["buffers"] = [{"uri": "material_sampler.bin", "byteLength": len(binary)}]
    with open(os.path.join(folder, "material_sampler.bin"), "wb") as f:
        f.write(binary)
    with open(os.path.join(folder, "material_sampler.gltf"), "w") as f:
        json.dump(gltf, f, indent=1)
    print("wrote " + os.path.join(folder, "material_sampler.gltf"))


if __name__ == "__main__":
    main()
