#!/usr/bin/env python3
"""Writes scenes/images/brick_wall.png, the background of scenes/heat_shimmer.json:
a brick wall (bricks 215 x 65 mm in running bond, 10 mm mortar joints, each
brick its own shade with a fine grain) carrying a white sign with black
lettering, 1.2 m wide at 1 mm a texel. Pure Python (zlib), seeded: the same
file every run.

    tools/make_brick_wall.py [OUT.png]
"""
import random
import struct
import sys
import zlib

WIDTH, HEIGHT = 1200, 900          # texels, 1 mm each
BRICK_W, BRICK_H, JOINT = 215, 65, 10

# 5 x 7 capitals for the sign.
FONT = {
    "H": ["10001", "10001", "10001", "11111", "10001", "10001", "10001"],
    "O": ["01110", "10001", "10001", "10001", "10001", "10001", "01110"],
    "T": ["11111", "00100", "00100", "00100", "00100", "00100", "00100"],
    "G": ["01110", "10001", "10000", "10111", "10001", "10001", "01111"],
    "R": ["11110", "10001", "10001", "11110", "10100", "10010", "10001"],
    "I": ["01110", "00100", "00100", "00100", "00100", "00100", "01110"],
    "L": ["10000", "10000", "10000", "10000", "10000", "10000", "11111"],
    " ": ["00000"] * 7,
}


def wall(rng):
    pixels = bytearray(WIDTH * HEIGHT * 3)
    shades = {}
    for y in range(HEIGHT):
        row, v = divmod(y, BRICK_H + JOINT)
        offset = (BRICK_W + JOINT) // 2 if row % 2 else 0
        for x in range(WIDTH):
            column, u = divmod(x + offset, BRICK_W + JOINT)
            grain = rng.randrange(4) / 3  # four levels: a grain that compresses
            if u >= BRICK_W or v >= BRICK_H:  # mortar
                rgb = (170 + 20 * grain, 165 + 20 * grain, 155 + 20 * grain)
            else:
                if (row, column) not in shades:
                    shades[(row, column)] = 0.55 + 0.45 * rng.random()
                s = shades[(row, column)] * (0.85 + 0.15 * grain)
                rgb = (150 * s, 62 * s, 45 * s)
            i = 3 * (y * WIDTH + x)
            pixels[i:i + 3] = bytes(int(c) for c in rgb)
    return pixels


def sign(pixels, text, left, top, cell):
    """A white board with a black border and `text` in 5 x 7 letters of `cell` texels a dot."""
    width = (6 * len(text) + 3) * cell
    height = 11 * cell
    for y in range(top, top + height):
        for x in range(left, left + width):
            border = min(x - left, left + width - 1 - x, y - top, top + height - 1 - y) < cell // 2
            i = 3 * (y * WIDTH + x)
            pixels[i:i + 3] = b"\x14\x14\x14" if border else b"\xf0\xf0\xea"
    for n, letter in enumerate(text):
        for r, bits in enumerate(FONT[letter]):
            for c, bit in enumerate(bits):
                if bit != "1":
                    continue
                x0, y0 = left + (2 + 6 * n + c) * cell, top + (2 + r) * cell
                for y in range(y0, y0 + cell):
                    i = 3 * (y * WIDTH + x0)
                    pixels[i:i + 3 * cell] = b"\x10\x10\x10" * cell


def png(pixels):
    raw = b"".join(b"\x00" + bytes(pixels[3 * WIDTH * y:3 * WIDTH * (y + 1)]) for y in range(HEIGHT))

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

    header = struct.pack(">IIBBBBB", WIDTH, HEIGHT, 8, 2, 0, 0, 0)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "scenes/images/brick_wall.png"
    pixels = wall(random.Random(1))
    sign(pixels, "HOT GRILL", 144, 362, 16)
    with open(out, "wb") as f:
        f.write(png(pixels))


if __name__ == "__main__":
    main()
