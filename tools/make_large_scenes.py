#!/usr/bin/env python3
"""Writes the two large scenes the cascades are measured on (issue 40), procedurally, into assets/scenes/:

  courtyard.gltf  a building about 40 x 25 x 15 m in the spirit of Sponza: a courtyard open to the sun,
                  ringed by two storeys of arcaded galleries (square columns, round arches), outer walls
                  with two faces, curtains (double-sided sheets) hanging in the upper arches, emissive
                  lamps on the ground galleries' floor and a closed room (two-faced walls, no opening)
                  against the east wall, whose truth is black;
  landscape.gltf  1 km of rolling ground under a low sun, with houses whose rooms are lit through their
                  doors; the camera looks into one of them.

    python3 tools/make_large_scenes.py [OUT_DIR]        (default: assets/scenes)

Metres, +Y up, glTF's conventions (KHR_lights_punctual sun, KHR_materials_emissive_strength lamps).
Deterministic: the same files every run (tests/cpu/large_scenes_test.cpp loads them).
"""
import base64
import json
import math
import os
import struct
import sys


class Builder:
    """Triangles grouped by material; quads and boxes with flat normals."""

    def __init__(self):
        self.materials = []
        self.parts = {}  # material index -> (positions, normals, indices)

    def material(self, name, colour, double_sided=False, emission=None, strength=1.0):
        entry = {"name": name, "pbrMetallicRoughness": {"baseColorFactor": list(colour) + [1.0],
                                                        "metallicFactor": 0.0, "roughnessFactor": 0.9}}
        if double_sided:
            entry["doubleSided"] = True
        if emission:
            entry["emissiveFactor"] = list(emission)
            entry["extensions"] = {"KHR_materials_emissive_strength": {"emissiveStrength": strength}}
        self.materials.append(entry)
        return len(self.materials) - 1

    def quad(self, material, a, b, c, d):
        """a, b, c, d counter-clockwise seen from the side the face looks at."""
        positions, normals, indices = self.parts.setdefault(material, ([], [], []))
        u = [b[i] - a[i] for i in range(3)]
        v = [d[i] - a[i] for i in range(3)]
        n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
        length = math.sqrt(sum(x * x for x in n))
        if length == 0.0:
            return
        n = [x / length for x in n]
        first = len(positions) // 3
        for p in (a, b, c, d):
            positions += [round(x, 5) for x in p]
            normals += n
        indices += [first, first + 1, first + 2, first, first + 2, first + 3]

    def box(self, material, lo, hi):
        """An axis-aligned box, faces outwards."""
        x0, y0, z0 = lo
        x1, y1, z1 = hi
        self.quad(material, (x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1))  # +z
        self.quad(material, (x1, y0, z0), (x0, y0, z0), (x0, y1, z0), (x1, y1, z0))  # -z
        self.quad(material, (x1, y0, z1), (x1, y0, z0), (x1, y1, z0), (x1, y1, z1))  # +x
        self.quad(material, (x0, y0, z0), (x0, y0, z1), (x0, y1, z1), (x0, y1, z0))  # -x
        self.quad(material, (x0, y1, z1), (x1, y1, z1), (x1, y1, z0), (x0, y1, z0))  # +y
        self.quad(material, (x0, y0, z0), (x1, y0, z0), (x1, y0, z1), (x0, y0, z1))  # -y

    def write(self, path, name, camera, sun_travel, sun_illuminance, yfov_degrees):
        data = bytearray()
        views, accessors, primitives = [], [], []

        def view(payload):
            views.append({"buffer": 0, "byteOffset": len(data), "byteLength": len(payload)})
            data.extend(payload)
            return len(views) - 1

        for material in sorted(self.parts):
            positions, normals, indices = self.parts[material]
            count = len(positions) // 3
            accessors.append({"bufferView": view(struct.pack(f"<{len(positions)}f", *positions)),
                              "componentType": 5126, "count": count, "type": "VEC3",
                              "min": [min(positions[k::3]) for k in range(3)],
                              "max": [max(positions[k::3]) for k in range(3)]})
            accessors.append({"bufferView": view(struct.pack(f"<{len(normals)}f", *normals)),
                              "componentType": 5126, "count": count, "type": "VEC3"})
            accessors.append({"bufferView": view(struct.pack(f"<{len(indices)}I", *indices)),
                              "componentType": 5125, "count": len(indices), "type": "SCALAR"})
            first = len(accessors) - 3
            primitives.append({"attributes": {"POSITION": first, "NORMAL": first + 1}, "indices": first + 2,
                               "material": material})
        position, target = camera
        document = {
            "asset": {"version": "2.0", "generator": "tools/make_large_scenes.py"},
            "extensionsUsed": ["KHR_lights_punctual", "KHR_materials_emissive_strength"],
            "extensions": {"KHR_lights_punctual": {"lights": [
                {"name": "sun", "type": "directional", "intensity": sun_illuminance}]}},
            "scene": 0,
            "scenes": [{"name": name, "nodes": [0, 1, 2]}],
            "nodes": [{"name": name, "mesh": 0},
                      {"name": "camera", "camera": 0, "translation": list(position),
                       "rotation": look_rotation([target[i] - position[i] for i in range(3)])},
                      {"name": "sun", "rotation": look_rotation(sun_travel),
                       "extensions": {"KHR_lights_punctual": {"light": 0}}}],
            "cameras": [{"type": "perspective", "perspective": {"yfov": math.radians(yfov_degrees),
                                                                "aspectRatio": 1.0, "znear": 0.05}}],
            "meshes": [{"name": name, "primitives": primitives}],
            "materials": self.materials,
            "buffers": [{"byteLength": len(data),
                         "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(data)).decode()}],
            "bufferViews": views,
            "accessors": accessors,
        }
        with open(path, "w") as out:
            json.dump(document, out, indent=1)
            out.write("\n")
        triangles = sum(len(part[2]) // 3 for part in self.parts.values())
        print(f"wrote {path}: {triangles} triangles, {len(self.materials)} materials, {len(data)} bytes of buffer")


def look_rotation(forward):
    """The unit quaternion (x, y, z, w) that turns -Z to `forward` with +Y kept up (yaw, then pitch)."""
    fx, fy, fz = forward
    length = math.sqrt(fx * fx + fy * fy + fz * fz)
    fx, fy, fz = fx / length, fy / length, fz / length
    yaw = math.atan2(-fx, -fz)
    pitch = math.asin(max(-1.0, min(1.0, fy)))
    qy = (0.0, math.sin(yaw / 2), 0.0, math.cos(yaw / 2))
    qx = (math.sin(pitch / 2), 0.0, 0.0, math.cos(pitch / 2))
    x1, y1, z1, w1 = qy
    x2, y2, z2, w2 = qx
    return [round(v, 7) for v in (w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2, w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2,
                                  w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2, w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2)]


def arcade(builder, material, start, end, bays, column, spring, top, depth, inward):
    """Columns and round arches along the line start -> end at floor height start[1]: `bays` arches
    between bays + 1 square columns (`column` wide), arches springing at `spring` above the floor,
    the wall above them up to `top`, `depth` thick towards `inward` (a unit vector in the floor plane)."""
    sx, floor, sz = start
    ex, _, ez = end
    length = math.hypot(ex - sx, ez - sz)
    ux, uz = (ex - sx) / length, (ez - sz) / length
    wx, wz = inward

    def at(u, y, w):
        return (sx + ux * u + wx * w, floor + y, sz + uz * u + wz * w)

    def block(u0, u1, y0, y1):  # a box spanning u0..u1 along the line, the arcade's depth
        corners = [at(u, y, w) for u in (u0, u1) for y in (y0, y1) for w in (0.0, depth)]
        xs, ys, zs = zip(*corners)
        builder.box(material, (min(xs), min(ys), min(zs)), (max(xs), max(ys), max(zs)))

    spacing = length / bays
    for i in range(bays + 1):
        u = i * spacing
        block(max(u - column / 2, 0.0), min(u + column / 2, length), 0.0, top)
    segments = 12
    for i in range(bays):
        u0, u1 = i * spacing + column / 2, (i + 1) * spacing - column / 2
        centre, radius = (u0 + u1) / 2, (u1 - u0) / 2
        arc = [(centre - radius * math.cos(math.pi * k / segments), spring + radius * math.sin(math.pi * k / segments))
               for k in range(segments + 1)]
        # The face at w = 0 must look away from `inward`: wound along +u it looks along u x up,
        # (-uz, ux) in the floor plane, so it is reversed where that points inwards.
        reversed_ = ux * wz - uz * wx > 0.0
        for (ua, ya), (ub, yb) in zip(arc, arc[1:]):
            outer = [at(ua, ya, 0.0), at(ub, yb, 0.0), at(ub, top, 0.0), at(ua, top, 0.0)]
            inner = [at(ub, yb, depth), at(ua, ya, depth), at(ua, top, depth), at(ub, top, depth)]
            soffit = [at(ua, ya, depth), at(ub, yb, depth), at(ub, yb, 0.0), at(ua, ya, 0.0)]
            if reversed_:
                outer, inner, soffit = outer[::-1], inner[::-1], soffit[::-1]
            builder.quad(material, *outer)
            builder.quad(material, *inner)
            builder.quad(material, *soffit)


def courtyard(path):
    b = Builder()
    stone = b.material("stone", (0.62, 0.57, 0.48))
    floor = b.material("floor", (0.45, 0.42, 0.38))
    plaster = b.material("plaster", (0.75, 0.72, 0.66))
    curtains = [b.material("red curtain", (0.62, 0.09, 0.07), double_sided=True),
                b.material("blue curtain", (0.08, 0.16, 0.55), double_sided=True),
                b.material("green curtain", (0.10, 0.45, 0.12), double_sided=True)]
    lamp = b.material("lamp", (0.8, 0.8, 0.8), emission=(1.0, 0.82, 0.55), strength=40.0)

    X, Z, H, T = 20.0, 12.5, 15.0, 0.3  # the building's half extents and height; wall thickness
    IX, IZ = 14.0, 6.5  # the open courtyard's half extents (the arcades' outer line)
    STOREY, SLAB = 6.0, 0.3
    b.box(floor, (-X, -0.3, -Z), (X, 0.0, Z))
    # Outer walls: two faces each, a wall's thickness apart.
    b.box(plaster, (-X, 0.0, -Z), (X, H, -Z + T))
    b.box(plaster, (-X, 0.0, Z - T), (X, H, Z))
    b.box(plaster, (-X, 0.0, -Z + T), (-X + T, H, Z - T))
    b.box(plaster, (X - T, 0.0, -Z + T), (X, H, Z - T))
    # The galleries' floor and roof slabs: a ring between the arcades and the outer walls.
    for level in (STOREY, 2 * STOREY):
        y0, y1 = level - SLAB, level
        b.box(stone, (-X + T, y0, -Z + T), (X - T, y1, -IZ))
        b.box(stone, (-X + T, y0, IZ), (X - T, y1, Z - T))
        b.box(stone, (-X + T, y0, -IZ), (-IX, y1, IZ))
        b.box(stone, (IX, y0, -IZ), (X - T, y1, IZ))
    # Two storeys of arcades on the courtyard's four sides, and a parapet on the roof.
    for storey in range(2):
        y = storey * STOREY
        spring, top = 3.6, STOREY - SLAB
        arcade(b, stone, (-IX, y, IZ), (IX, y, IZ), 7, 0.6, spring, top, 0.6, (0.0, 1.0))
        arcade(b, stone, (IX, y, -IZ), (-IX, y, -IZ), 7, 0.6, spring, top, 0.6, (0.0, -1.0))
        arcade(b, stone, (-IX, y, -IZ), (-IX, y, IZ), 3, 0.6, spring, top, 0.6, (-1.0, 0.0))
        arcade(b, stone, (IX, y, IZ), (IX, y, -IZ), 3, 0.6, spring, top, 0.6, (1.0, 0.0))
    for lo, hi in [((-IX, 2 * STOREY, IZ), (IX, 2 * STOREY + 1.2, IZ + 0.3)),
                   ((-IX, 2 * STOREY, -IZ - 0.3), (IX, 2 * STOREY + 1.2, -IZ)),
                   ((-IX - 0.3, 2 * STOREY, -IZ), (-IX, 2 * STOREY + 1.2, IZ)),
                   ((IX, 2 * STOREY, -IZ), (IX + 0.3, 2 * STOREY + 1.2, IZ))]:
        b.box(stone, lo, hi)
    # Curtains in every other upper arch of the long sides, a metre behind the arcade.
    spacing = 2 * IX / 7
    for i in range(7):
        if i % 2 == 1:
            continue
        u0, u1 = -IX + i * spacing + 0.5, -IX + (i + 1) * spacing - 0.5
        colour = curtains[(i // 2) % 3]
        top, bottom = 2 * STOREY - SLAB - 0.4, STOREY + 0.6
        for z in (IZ + 1.6, -IZ - 1.6):
            b.quad(colour, (u0, bottom, z), (u1, bottom, z), (u1, top, z), (u0, top, z))
    # Lamps on the ground galleries' floor, in the shade of the slabs.
    for x in (-17.0, -9.0, -1.0, 7.0, 15.0):
        for z in (-9.5, 9.5):
            b.box(lamp, (x - 0.15, 0.0, z - 0.15), (x + 0.15, 0.3, z + 0.15))
    # A closed room against the east wall: two-faced walls 20 cm thick, no opening. Its truth is black.
    W = 0.2
    b.box(plaster, (15.5, 0.0, -3.0), (15.5 + W, 4.0, 3.0))
    b.box(plaster, (15.5 + W, 0.0, -3.0), (X - T, 4.0, -3.0 + W))
    b.box(plaster, (15.5 + W, 0.0, 3.0 - W), (X - T, 4.0, 3.0))
    b.box(plaster, (15.5, 4.0, -3.0), (X - T, 4.0 + W, 3.0))
    # Seen from the south-west gallery, looking across the sunlit courtyard to the far arcades.
    b.write(path, "courtyard", ((-16.5, 1.8, 9.5), (8.0, 5.0, -4.0)), (-0.35, -0.8, -0.48), 8.0, 65.0)


def landscape(path):
    b = Builder()
    ground = b.material("grass", (0.22, 0.32, 0.12))
    walls = b.material("whitewash", (0.78, 0.76, 0.70))
    roof = b.material("roof tiles", (0.45, 0.20, 0.12))
    inside = b.material("wooden floor", (0.55, 0.38, 0.22))

    def height(x, z):
        return 6.0 * math.sin(x / 95.0) * math.cos(z / 120.0) + 2.5 * math.sin(x / 41.0 + z / 57.0)

    half, cells = 500.0, 40
    step = 2 * half / cells
    for i in range(cells):
        for j in range(cells):
            x0, z0 = -half + i * step, -half + j * step
            x1, z1 = x0 + step, z0 + step
            b.quad(ground, (x0, height(x0, z1), z1), (x1, height(x1, z1), z1), (x1, height(x1, z0), z0),
                   (x0, height(x0, z0), z0))
    houses = [(0.0, 0.0), (-40.0, -25.0), (35.0, -60.0), (-120.0, 80.0), (150.0, 30.0), (-200.0, -150.0),
              (260.0, -210.0), (-310.0, 240.0), (90.0, 300.0), (380.0, 120.0), (-400.0, -60.0), (200.0, -380.0)]
    for cx, cz in houses:
        base = height(cx, cz)
        w, d, h, t = 4.0, 3.0, 3.2, 0.25  # half width, half depth, wall height, wall thickness
        y0, y1 = base - 2.0, base + h  # walls reach into the ground: no gap under them on a slope
        # The floor stops half a wall inside the walls' outer faces: sharing them, it z-fought with
        # the walls' feet where the ground falls away (seen at 960x540; the path tracer averaged the
        # two surfaces into noise).
        b.box(inside, (cx - w + t / 2, y0, cz - d + t / 2), (cx + w - t / 2, base + 0.05, cz + d - t / 2))
        b.box(walls, (cx - w, y0, cz - d), (cx + w, y1, cz - d + t))  # back
        b.box(walls, (cx - w, y0, cz - d + t), (cx - w + t, y1, cz + d - t))  # west
        b.box(walls, (cx + w - t, y0, cz - d + t), (cx + w, y1, cz + d - t))  # east
        door = 0.7  # half width of the door in the front (+z) wall, 2.2 m high
        b.box(walls, (cx - w, y0, cz + d - t), (cx - door, y1, cz + d))
        b.box(walls, (cx + door, y0, cz + d - t), (cx + w, y1, cz + d))
        b.box(walls, (cx - door, base + 2.2, cz + d - t), (cx + door, y1, cz + d))
        b.box(roof, (cx - w - 0.4, y1, cz - d - 0.4), (cx + w + 0.4, y1 + 0.3, cz + d + 0.4))
    # Eye height, 9 m in front of the first house's door, looking in; the sun low behind the camera.
    eye = (1.5, height(1.5, 12.0) + 1.7, 12.0)
    b.write(path, "landscape", (eye, (0.0, height(0.0, 0.0) + 1.0, 0.0)), (-0.15, -0.45, -0.88), 6.0, 50.0)


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "assets", "scenes")
    os.makedirs(out, exist_ok=True)
    courtyard(os.path.join(out, "courtyard.gltf"))
    landscape(os.path.join(out, "landscape.gltf"))


if __name__ == "__main__":
    main()
