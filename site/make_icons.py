"""Writes icon-192.png and icon-512.png (the page's favicon drawn as pixels: a dark rounded
square, a blue orbit ellipse, red and green body axes). Pure Python: zlib and struct only.
Run: python3 site/make_icons.py"""
import math, os, struct, zlib

def png(path, size):
    bg, blue, red, green, dot = (27, 35, 48), (88, 166, 255), (255, 123, 114), (126, 231, 135), (230, 237, 243)
    s = size / 32.0
    rows = []
    for y in range(size):
        row = bytearray([0])
        for x in range(size):
            u, v = (x + 0.5) / s, (y + 0.5) / s
            c = bg
            # orbit ellipse rx 11, ry 5, rotated -30° about (16, 16), stroke 2
            a = math.radians(30)
            dx, dy = u - 16, v - 16
            ex, ey = dx * math.cos(a) - dy * math.sin(a), dx * math.sin(a) + dy * math.cos(a)
            r = math.hypot(ex / 11, ey / 5)
            if abs(r - 1) * 8 < 1.0:
                c = blue
            def seg(x2, y2, w):
                px, py = x2 - 16, y2 - 16
                t = max(0, min(1, (dx * px + dy * py) / (px * px + py * py)))
                return math.hypot(dx - t * px, dy - t * py) < w / 2
            if seg(16, 4, 2.5):
                c = red
            if seg(27, 20, 2.5):
                c = green
            if math.hypot(dx, dy) < 2.5:
                c = dot
            row += bytes(c)
        rows.append(bytes(row))
    raw = zlib.compress(b"".join(rows), 9)
    def chunk(t, d):
        return struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d) & 0xffffffff)
    data = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", size, size, 8, 2, 0, 0, 0)) + chunk(b"IDAT", raw) + chunk(b"IEND", b"")
    with open(path, "wb") as f:
        f.write(data)

here = os.path.dirname(os.path.abspath(__file__))
for n in (192, 512):
    png(os.path.join(here, f"icon-{n}.png"), n)
