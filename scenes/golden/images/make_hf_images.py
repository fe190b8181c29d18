#!/usr/bin/env python3
"""Writes the small height_field test images (hf_*.png, hf_*.ppm, hf_*.tga, hf_*.pot,
and with oiiotool hf_*.tif, hf_*.exr, hf_*.hdr) beside this script: deterministic terrains
in each container POV-Ray 3.7 derives heights from differently (8- and 16-bit grey,
palette, 8- and 16-bit colour, Targa, Netpbm, POT, TIFF, float)."""
import math
import os
import struct
import subprocess
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))


def png(name, width, height, colour_type, bits, rows, palette=None):
    def chunk(kind, data):
        c = struct.pack(">I", len(data)) + kind + data
        return c + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

    raw = b"".join(b"\0" + r for r in rows)
    out = b"\x89PNG\r\n\x1a\n"
    out += chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, bits, colour_type, 0, 0, 0))
    if palette is not None:
        out += chunk(b"PLTE", b"".join(bytes(c) for c in palette))
    out += chunk(b"IDAT", zlib.compress(raw, 9))
    out += chunk(b"IEND", b"")
    with open(os.path.join(HERE, name), "wb") as f:
        f.write(out)


def terrain(x, z, w, h):
    """A hill, a ridge and ripples, in [0, 1]."""
    u, v = x / (w - 1), z / (h - 1)
    hill = math.exp(-((u - 0.35) ** 2 + (v - 0.6) ** 2) * 9)
    ridge = 0.5 * math.exp(-((u + v - 1.3) ** 2) * 40)
    ripple = 0.08 * math.sin(u * 17) * math.cos(v * 13)
    return min(1.0, max(0.0, 0.1 + 0.7 * hill + ridge * 0.6 + ripple))


def grey8(name, w, h):
    rows = [bytes(int(round(terrain(x, z, w, h) * 255)) for x in range(w)) for z in range(h)]
    png(name, w, h, 0, 8, rows)


def grey16(name, w, h):
    rows = []
    for z in range(h):
        r = b""
        for x in range(w):
            r += struct.pack(">H", int(round(terrain(x, z, w, h) * 65535)) ^ (x * 37 % 256))
        rows.append(r)
    png(name, w, h, 0, 16, rows)


def palette8(name, w, h):
    # 40 distinct grey-ish colours, not in index order, so index != brightness.
    pal = [((i * 97) % 256, (i * 53 + 20) % 256, (i * 31 + 90) % 256) for i in range(40)]
    rows = [bytes(min(39, int(terrain(x, z, w, h) * 40)) for x in range(w)) for z in range(h)]
    png(name, w, h, 3, 8, rows, pal)


def rgb8(name, w, h):
    rows = []
    for z in range(h):
        r = b""
        for x in range(w):
            v = int(terrain(x, z, w, h) * 65535)
            r += bytes((v >> 8, v & 255, (x * 40 + z * 7) % 256))
        rows.append(r)
    png(name, w, h, 2, 8, rows)


def rgb16(name, w, h):
    rows = []
    for z in range(h):
        r = b""
        for x in range(w):
            v = int(terrain(x, z, w, h) * 65535)
            r += struct.pack(">HHH", v, max(0, v - 3000), (x * 1000) % 65536)
        rows.append(r)
    png(name, w, h, 2, 16, rows)


def tga(name, w, h):
    # Uncompressed true colour, bottom-up rows (the Targa default); BGR order.
    head = struct.pack("<BBBHHBHHHHBB", 0, 0, 2, 0, 0, 0, 0, 0, w, h, 24, 0)
    body = b""
    for z in range(h - 1, -1, -1):
        for x in range(w):
            v = int(terrain(w - 1 - x, z, w, h) * 65535)
            body += bytes((17, v & 255, v >> 8))
    with open(os.path.join(HERE, name), "wb") as f:
        f.write(head + body)


def pgm(name, w, h):
    body = bytes(int(round(terrain(z, x, h, w) * 255)) for z in range(h) for x in range(w))
    with open(os.path.join(HERE, name), "wb") as f:
        f.write(b"P5\n%d %d\n255\n" % (w, h) + body)


def spikes(name, w, h):
    # Random-looking spikes on a flat floor (a stress case): a linear congruential
    # sequence, so the file is the same everywhere.
    s = 12345
    rows = []
    for z in range(h):
        r = b""
        for x in range(w):
            s = (s * 1103515245 + 12345) % 2**31
            v = 65535 if s % 7 == 0 else (s >> 8) % 3000
            r += struct.pack(">H", v)
        rows.append(r)
    png(name, w, h, 0, 16, rows)


def gif(name, w, h, indices, palette):
    # 8-bit LZW codes kept at 9 bits by a clear code before the table would grow.
    codes, bits = [256], []
    for n, i in enumerate(indices):
        if n % 250 == 249:
            codes.append(256)
        codes.append(i)
    codes.append(257)
    acc = nbits = 0
    data = b""
    for c in codes:
        acc |= c << nbits
        nbits += 9
        while nbits >= 8:
            data += bytes([acc & 255])
            acc >>= 8
            nbits -= 8
    if nbits:
        data += bytes([acc & 255])
    blocks = b"".join(bytes([len(data[i:i + 255])]) + data[i:i + 255]
                      for i in range(0, len(data), 255))
    out = b"GIF87a" + struct.pack("<HHBBB", w, h, 0xF7, 0, 0)
    out += b"".join(bytes(c) for c in palette)
    out += b"," + struct.pack("<HHHHB", 0, 0, w, h, 0) + b"\x08" + blocks + b"\x00;"
    with open(os.path.join(HERE, name), "wb") as f:
        f.write(out)


def pot(name, w, h):
    # POV-Ray's 16-bit heights in a GIF twice as wide: high bytes left, low bytes right.
    # The palette names 256 different colours (povwall recovers indices from colours).
    palette = [(i, 255 - i, (i * 7) % 256) for i in range(256)]
    indices = []
    for z in range(h):
        row = [int(terrain(x, z, w, h) * 65535) ^ (x * 91 % 256) for x in range(w)]
        indices += [v >> 8 for v in row] + [v & 255 for v in row]
    gif(name, 2 * w, h, indices, palette)


def oiio(source, name, *options):
    subprocess.run(["oiiotool", os.path.join(HERE, source), *options, "-o",
                    os.path.join(HERE, name)], check=True)


grey8("hf_grey8.png", 33, 25)
grey16("hf_grey16.png", 40, 40)
palette8("hf_palette.png", 24, 30)
rgb8("hf_rgb8.png", 28, 28)
rgb16("hf_rgb16.png", 20, 26)
tga("hf_rgb8.tga", 30, 22)
pgm("hf_grey8.pgm", 26, 34)
spikes("hf_spikes.png", 64, 64)
png("hf_flat.png", 16, 16, 0, 8, [bytes([128] * 16)] * 16)
pot("hf_heights.pot", 30, 26)
oiio("hf_grey8.png", "hf_grey8.tif")
oiio("hf_grey16.png", "hf_grey16.tif")
oiio("hf_rgb8.png", "hf_rgb8.tif")
oiio("hf_rgb16.png", "hf_rgb16.tif")
oiio("hf_grey16.png", "hf_float.exr", "-d", "float")
oiio("hf_rgb16.png", "hf_half.exr", "-d", "half")
oiio("hf_rgb16.png", "hf_rgbe.hdr")
# With an alpha channel (opacity 0.6), which POV-Ray's heights ignore.
oiio("hf_rgb8.png", "hf_rgba8.png", "--ch", "R,G,B,A=0.6", "-d", "uint8")
oiio("hf_grey8.png", "hf_greya8.png", "--ch", "Y,A=0.6", "-d", "uint8")
oiio("hf_rgb16.png", "hf_rgba16.png", "--ch", "R,G,B,A=0.6", "-d", "uint16")
oiio("hf_rgb8.png", "hf_rgba8.tga", "--ch", "R,G,B,A=0.6", "-d", "uint8")
oiio("hf_rgb8.png", "hf_rgba8.bmp", "--ch", "R,G,B,A=0.6", "-d", "uint8")
