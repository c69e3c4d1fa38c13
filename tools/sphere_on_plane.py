#!/usr/bin/env python3
"""Writes a probe scene for the cones' bounce light off a curved object: a red Lambertian sphere
(radius 0.5 m) resting on a 4 m grey ground under a sun, seen from straight above.

    python3 tools/sphere_on_plane.py sphere.gltf
    build/vct render --scene sphere.gltf --preset balanced --mode indirect --width 128 --height 128 --out vct.pfm
    build/tools/vct_pathtrace --scene sphere.gltf --mode indirect --width 128 --height 128 --spp 4096 --out pt.pfm

Compare the ground's indirect light ring by ring around the sphere (the camera sees ±1.93 m).
"""
import base64
import json
import math
import struct
import sys

RADIUS, RINGS, SEGMENTS, HALF_GROUND = 0.5, 24, 48, 2.0

positions, normals, indices = [], [], []
for x, z in [(-1, -1), (-1, 1), (1, 1), (1, -1)]:  # the ground, facing up (counter-clockwise from above)
    positions += [x * HALF_GROUND, 0.0, z * HALF_GROUND]
    normals += [0.0, 1.0, 0.0]
indices += [0, 1, 2, 0, 2, 3]
first = len(positions) // 3
for i in range(RINGS + 1):  # the sphere, triangles wound to face outwards
    theta = math.pi * i / RINGS
    for j in range(SEGMENTS + 1):
        phi = 2 * math.pi * j / SEGMENTS
        n = [math.sin(theta) * math.cos(phi), math.cos(theta), math.sin(theta) * math.sin(phi)]
        positions += [RADIUS * n[0], RADIUS + RADIUS * n[1], RADIUS * n[2]]
        normals += n
for i in range(RINGS):
    for j in range(SEGMENTS):
        a = first + i * (SEGMENTS + 1) + j
        b = a + SEGMENTS + 1
        indices += [a, a + 1, b, a + 1, b + 1, b]

data = (struct.pack(f"<{len(positions)}f", *positions) + struct.pack(f"<{len(normals)}f", *normals) +
        struct.pack(f"<{len(indices)}I", *indices))
count = len(positions) // 3
floats = 4 * len(positions)
lambertian = {"metallicFactor": 0, "roughnessFactor": 1}
no_specular = {"KHR_materials_specular": {"specularFactor": 0}}
document = {
    "asset": {"version": "2.0"},
    "buffers": [{"byteLength": len(data), "uri": "data:application/octet-stream;base64," + base64.b64encode(data).decode()}],
    "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": floats},
                    {"buffer": 0, "byteOffset": floats, "byteLength": floats},
                    {"buffer": 0, "byteOffset": 2 * floats, "byteLength": 4 * len(indices)}],
    "accessors": [
        {"bufferView": 0, "componentType": 5126, "count": count, "type": "VEC3",
         "min": [min(positions[k::3]) for k in range(3)], "max": [max(positions[k::3]) for k in range(3)]},
        {"bufferView": 1, "componentType": 5126, "count": count, "type": "VEC3"},
        {"bufferView": 2, "componentType": 5125, "count": 6, "type": "SCALAR"},
        {"bufferView": 2, "byteOffset": 24, "componentType": 5125, "count": len(indices) - 6, "type": "SCALAR"}],
    "materials": [
        {"name": "grey ground", "pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.5, 0.5, 1], **lambertian},
         "extensions": no_specular},
        {"name": "red sphere", "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.1, 0.1, 1], **lambertian},
         "extensions": no_specular}],
    "extensionsUsed": ["KHR_lights_punctual", "KHR_materials_specular"],
    "extensions": {"KHR_lights_punctual": {"lights": [{"name": "sun", "type": "directional", "intensity": 3.0}]}},
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2, "material": 0},
                               {"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 3, "material": 1}]}],
    "cameras": [{"type": "perspective", "perspective": {"yfov": 0.9, "znear": 0.01, "aspectRatio": 1}}],
    "nodes": [{"mesh": 0},
              {"camera": 0, "translation": [0, 4, 0], "rotation": [-0.7071068, 0, 0, 0.7071068]},  # looking down
              {"extensions": {"KHR_lights_punctual": {"light": 0}}, "rotation": [-0.3826834, 0, 0, 0.9238795]}],
    "scenes": [{"nodes": [0, 1, 2]}],
    "scene": 0,
}
with open(sys.argv[1] if len(sys.argv) > 1 else "sphere_on_plane.gltf", "w") as out:
    json.dump(document, out)
