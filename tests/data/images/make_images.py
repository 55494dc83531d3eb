#!/usr/bin/env python3
"""Writes the small image files the tests and the image fuzzers start from: one of every format
stb_image 2.27 would have decoded (rtcli reads PNG and JPEG only and must name the others), the
hostile files issue 17 found, and PNG/JPEG variants. Run from this folder; needs cjpeg, djpeg and
jpegtran (Debian's libjpeg-turbo-progs) for the JPEG, GIF, BMP and TGA files. The outputs are
committed, so the test suite needs none of these tools."""
import struct
import subprocess
import zlib


def png(w, h, depth=8, colour=2, rows=None, interlace=0, extra=b""):
    channels = {0: 1, 2: 3, 3: 1, 4: 2, 6: 4}[colour]
    row_bytes = (w * channels * depth + 7) // 8
    raw = b"".join(b"\0" + (rows[y] if rows else bytes((x * 37 + y * 11) % 256 for x in range(row_bytes)))
                   for y in range(h))
    if interlace:  # Adam7: seven passes over sub-images, 8-bit RGB only here
        raw = b""
        for x0, y0, dx, dy in ((0, 0, 8, 8), (4, 0, 8, 8), (0, 4, 4, 8), (2, 0, 4, 4), (0, 2, 2, 4), (1, 0, 2, 2),
                               (0, 1, 1, 2)):
            xs, ys = range(x0, w, dx), range(y0, h, dy)
            if len(xs) and len(ys):
                raw += b"".join(b"\0" + bytes((x * 3 * 37 + c * 37 + y * 11) % 256 for x in xs for c in range(3))
                                for y in ys)

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff)
    ihdr = struct.pack(">IIBBBBB", w, h, depth, colour, 0, 0, interlace)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + extra + chunk(b"IDAT", zlib.compress(raw, 9)) +
            chunk(b"IEND", b""))


def ppm(w, h):
    return b"P6\n%d %d\n255\n" % (w, h) + bytes((x * 5 + y * 3 + c * 60) % 256
                                                for y in range(h) for x in range(w) for c in range(3))


def run(args, data):
    return subprocess.run(args, input=data, stdout=subprocess.PIPE, check=True).stdout


def write(name, data):
    with open(name, "wb") as f:
        f.write(data)


write("rgb8.png", png(8, 8))
write("grey16.png", png(4, 4, depth=16, colour=0))
write("rgba16.png", png(3, 2, depth=16, colour=6))
write("palette.png", png(4, 4, depth=8, colour=3,
                         extra=struct.pack(">I", 6) + b"PLTE" + b"\xff\0\0\0\xff\0" +
                         struct.pack(">I", zlib.crc32(b"PLTE\xff\0\0\0\xff\0") & 0xffffffff),
                         rows=[bytes([x % 2 for x in range(4)])] * 4))
write("interlaced.png", png(9, 7, interlace=1))
image = ppm(16, 16)
write("baseline.jpg", run(["cjpeg", "-quality", "90"], image))
write("progressive.jpg", run(["cjpeg", "-progressive"], image))
write("grey.jpg", run(["cjpeg", "-grayscale"], image))
write("image.gif", run(["djpeg", "-gif"], run(["cjpeg"], image)))
write("image.bmp", run(["djpeg", "-bmp"], run(["cjpeg"], image)))
write("image.tga", run(["djpeg", "-targa"], run(["cjpeg"], image)) + b"\0" * 8 + b"TRUEVISION-XFILE.\0")
write("image.ppm", image)
# A Radiance .hdr of one run-length-encoded scanline pair, and the truncated one that makes
# stb_image 2.27 loop forever (CVE-2021-42715).
scan = bytes([2, 2, 0, 8]) + b"".join(bytes([0x80 + 8, v]) for v in (128, 64, 32, 129))
write("image.hdr", b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 8\n" + scan * 2)
write("truncated-rle.hdr", (b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 8 +X 8\n" + bytes([2, 2, 0, 8]))[:49].ljust(49, b"\x80"))
write("grey16.pgm", b"P5 2 2 65535\n" + bytes(8))  # 21 bytes: stb_image 2.27 over-reads it
write("huge-header.ppm", b"P6 99999999999 99999999999 255\n" + bytes(16))
# Photoshop: signature, version 1, 6 reserved, 3 channels, 2 x 2, 8 bits, RGB; empty sections; raw data.
write("image.psd", b"8BPS\0\1" + bytes(6) + struct.pack(">HIIHH", 3, 2, 2, 8, 3) + bytes(12) + b"\0\0" + bytes(12))
# Softimage PIC: magic, version, 80-byte comment, "PICT", 2 x 2, ratio, fields, pad, one channel packet.
write("image.pic", b"\x53\x80\xf6\x34" + struct.pack(">f", 3.71) + bytes(80) + b"PICT" +
      struct.pack(">HHfHH", 2, 2, 1.0, 3, 0) + bytes([0, 8, 0, 0xe0]) + bytes(16))
# A 1 x 1 PNG whose image data inflates to 1 MiB (a zlib bomb in small: stb_image 2.27 would
# inflate any amount).
write("inflates-too-far.png", b"\x89PNG\r\n\x1a\n" + png(1, 1)[8:33] +
      struct.pack(">I", len(zlib.compress(bytes(1 << 20), 9))) + b"IDAT" + zlib.compress(bytes(1 << 20), 9) +
      b"\0\0\0\0" + png(1, 1)[-12:])
# A progressive JPEG with 80 scans: its last scan repeated (each a pass over the image).
jpeg = run(["cjpeg", "-progressive"], ppm(16, 16))
last = jpeg.rfind(b"\xff\xda")
write("eighty-scans.jpg", jpeg[:last] + jpeg[last:-2] * (80 - jpeg.count(b"\xff\xda") + 1) + b"\xff\xd9")
