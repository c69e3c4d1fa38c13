#!/usr/bin/env python3
"""PFM images side by side in one PNG, to look at renders beside their references.

    tools/side_by_side.py OUT.png SCALE A.pfm B.pfm ...

Each image is shown as linear radiance × SCALE, clamped to 1, with a square-root display curve
(no tone curve, so that equal radiance looks equal in every panel), enlarged ZOOM× with square
pixels, and separated by a red bar. Python's standard library only.
"""
import struct
import sys
import zlib

ZOOM = 4
BAR = 4


def read_pfm(path):
    with open(path, "rb") as f:
        data = f.read()
    header, size, scale, pixels = data.split(b"\n", 3)
    if header != b"PF":
        sys.exit(f"{path}: not an RGB PFM")
    width, height = map(int, size.split())
    order = "<" if float(scale) < 0 else ">"
    values = struct.unpack(order + "f" * (width * height * 3), pixels[: width * height * 12])
    # PFM rows run bottom to top.
    rows = [values[(height - 1 - y) * width * 3 : (height - y) * width * 3] for y in range(height)]
    return width, height, rows


def png_chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    out, scale, paths = sys.argv[1], float(sys.argv[2]), sys.argv[3:]
    images = [read_pfm(p) for p in paths]
    width = sum(w for w, _, _ in images) * ZOOM + BAR * (len(images) - 1)
    height = max(h for _, h, _ in images) * ZOOM
    raw = bytearray()
    for y in range(height):
        raw.append(0)  # no PNG filter
        for k, (w, h, rows) in enumerate(images):
            row = rows[y // ZOOM] if y // ZOOM < h else (0.0,) * (w * 3)
            for x in range(w * ZOOM):
                for c in range(3):
                    v = max(0.0, min(1.0, row[(x // ZOOM) * 3 + c] * scale)) ** 0.5
                    raw.append(int(v * 255 + 0.5))
            if k < len(images) - 1:
                raw.extend(b"\xff\x00\x00" * BAR)
    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)
    with open(out, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + png_chunk(b"IHDR", header) + png_chunk(b"IDAT", zlib.compress(bytes(raw), 9)))
        f.write(png_chunk(b"IEND", b""))


if __name__ == "__main__":
    main()
