#!/usr/bin/env python3
"""The root-mean-square difference of two linear OpenEXR images, over R, G and B.

  bench/cycles/rmse.py A.exr B.exr            # prints the RMSE of A against B
  bench/cycles/rmse.py --mean A.exr           # the mean of R, G and B, each
  bench/cycles/rmse.py --brightest A.exr      # the R, G, B of the brightest pixel
  bench/cycles/rmse.py --preview A.exr A.png  # an sRGB PNG to look at

RMSE = sqrt(sum over the pixels and the three channels of (a - b)^2 / (3 W H)),
in the images' own linear units (radiance): no tone mapping, no clamping.
`--below L A B` takes only the pixels where each channel of both is under L
(a room's walls, without its lamp), and prints the RMSE there, the relative
error (the sum of |a - b| over the sum of b), and how many pixels it left out
where A alone reaches L. `--half-difference A1 A2`
prints RMSE(A1, A2) / 2, the noise (standard
error) that the mean of two independent renders A1 and A2 keeps, for a
reference made of two halves. `--average A1 A2 OUT` writes their mean.

Debian 12's python3 has no OpenEXR module (and Blender's Python no NumPy), so
the few OpenEXR files read here are read by the standard library alone: the
scan-line files that RISE (OpenEXR's default ZIP compression) and Blender
(ZIP as bench/cycles/cornell_box.py asks, or none, RLE or ZIPS) write, of HALF
or FLOAT channels. Tiled, multi-part, deep and PIZ/B44/DWA files are refused.
"""

import argparse
import itertools
import math
import operator
import struct
import sys
import zlib
from array import array

MAGIC = 20000630
# OpenEXR's compression numbers, and the scan lines each block holds.
LINES_PER_BLOCK = {0: 1, 1: 1, 2: 1, 3: 16}  # NONE, RLE, ZIPS, ZIP
PIXEL_BYTES = {1: 2, 2: 4}  # HALF, FLOAT (UINT, 0, is not a colour)


def fail(message):
    sys.exit(f"rmse.py: {message}")


def read_header(data, path):
    magic, version = struct.unpack_from("<ii", data, 0)
    if magic != MAGIC:
        fail(f"{path} is not an OpenEXR file")
    if version & 0x1A00:  # tiled, deep or multi-part (long names, 0x400, are fine)
        fail(f"{path}: only single-part scan-line OpenEXR files are read (flags {version:#x})")
    offset, header = 8, {}
    while data[offset] != 0:
        name_end = data.index(0, offset)
        type_end = data.index(0, name_end + 1)
        name = data[offset:name_end].decode()
        kind = data[name_end + 1 : type_end].decode()
        (size,) = struct.unpack_from("<i", data, type_end + 1)
        value = data[type_end + 5 : type_end + 5 + size]
        header[name] = (kind, value)
        offset = type_end + 5 + size
    return header, offset + 1


def channels_of(value):
    """The channel list: (name, pixel type), in the file's (alphabetical) order."""
    channels, offset = [], 0
    while value[offset] != 0:
        end = value.index(0, offset)
        name = value[offset:end].decode()
        pixel_type, _, _, x_sampling, y_sampling = struct.unpack_from("<iB3sii", value, end + 1)
        if (x_sampling, y_sampling) != (1, 1):
            fail(f"channel {name} is subsampled")
        channels.append((name, pixel_type))
        offset = end + 1 + 16
    return channels


def undo_predictor(data):
    """OpenEXR's ZIP and RLE store the bytes reordered (the first halves of
    every value, then the second halves) and delta-coded (each byte minus the
    one before, plus 128): undo both."""
    if not data:
        return b""
    # A running sum of (byte - 128) from the first byte, modulo 256:
    # accumulate and map run in C, not in a Python loop.
    running = itertools.accumulate(
        itertools.chain((data[0],), map(operator.sub, data[1:], itertools.repeat(128))))
    undone = bytes(map((255).__and__, running))
    half = (len(data) + 1) // 2
    out = bytearray(len(data))
    out[0::2] = undone[:half]
    out[1::2] = undone[half:]
    return bytes(out)


def undo_zip(raw, expected):
    data = zlib.decompress(raw)
    if len(data) != expected:
        fail(f"a ZIP block holds {len(data)} bytes, not {expected}")
    return undo_predictor(data)


def undo_rle(raw, expected):
    out, offset = bytearray(), 0
    while offset < len(raw):
        count = struct.unpack_from("<b", raw, offset)[0]
        offset += 1
        if count < 0:  # -count bytes as they are
            out += raw[offset : offset - count]
            offset -= count
        else:  # one byte, count + 1 times
            out += raw[offset : offset + 1] * (count + 1)
            offset += 1
    if len(out) != expected:
        fail(f"an RLE block holds {len(out)} bytes, not {expected}")
    return undo_predictor(bytes(out))


def read_exr(path):
    """(width, height, {channel name: array of floats, row by row from the top})."""
    with open(path, "rb") as file:
        data = file.read()
    header, offset = read_header(data, path)
    compression = header["compression"][1][0]
    if compression not in LINES_PER_BLOCK:
        fail(f"{path}: compression {compression} is not read (only NONE, RLE, ZIPS and ZIP)")
    x_min, y_min, x_max, y_max = struct.unpack("<iiii", header["dataWindow"][1])
    width, height = x_max - x_min + 1, y_max - y_min + 1
    channels = channels_of(header["channels"][1])
    for name, pixel_type in channels:
        if pixel_type not in PIXEL_BYTES:
            fail(f"{path}: channel {name} is not HALF or FLOAT")
    lines = LINES_PER_BLOCK[compression]
    blocks = (height + lines - 1) // lines
    offsets = struct.unpack_from(f"<{blocks}Q", data, offset)
    row_bytes = sum(PIXEL_BYTES[t] for _, t in channels) * width
    planes = {name: array("f") for name, _ in channels}
    for block_offset in offsets:
        y, size = struct.unpack_from("<ii", data, block_offset)
        raw = data[block_offset + 8 : block_offset + 8 + size]
        rows = min(lines, y_max - y + 1)
        expected = row_bytes * rows
        if size == expected:  # stored as it is when compressing did not help
            block = raw
        elif compression == 1:
            block = undo_rle(raw, expected)
        else:
            block = undo_zip(raw, expected)
        at = 0
        for _ in range(rows):  # each row holds each channel's values in turn
            for name, pixel_type in channels:
                count = PIXEL_BYTES[pixel_type] * width
                chunk = block[at : at + count]
                if pixel_type == 2:
                    values = array("f")
                    values.frombytes(chunk)
                    if sys.byteorder != "little":
                        values.byteswap()
                else:
                    values = array("f", struct.unpack(f"<{width}e", chunk))
                planes[name].extend(values)
                at += count
    # Blocks may be stored in any order: put the rows in order by their y.
    order = sorted(range(len(offsets)), key=lambda i: struct.unpack_from("<i", data, offsets[i])[0])
    if order != list(range(len(offsets))):
        fail(f"{path}: blocks out of order are not read")
    return width, height, planes


def rgb(path):
    width, height, planes = read_exr(path)
    missing = [c for c in "RGB" if c not in planes]
    if missing:
        fail(f"{path} has no channel {', '.join(missing)}")
    return width, height, [planes[c] for c in "RGB"]


def rmse(path_a, path_b):
    wa, ha, a = rgb(path_a)
    wb, hb, b = rgb(path_b)
    if (wa, ha) != (wb, hb):
        fail(f"{path_a} is {wa}x{ha}, {path_b} is {wb}x{hb}")
    total = 0.0
    for plane_a, plane_b in zip(a, b):
        difference = map(operator.sub, plane_a, plane_b)
        total += math.fsum(map(operator.mul, *itertools.tee(difference)))
    return math.sqrt(total / (3 * wa * ha))


def errors_below(path_a, path_b, limit):
    """Over the pixels where each channel of both images is under `limit`: the
    RMSE and the relative error, the sum of |a - b| over the sum of b; and the
    pixels left out where b alone is under it (a bright rim that a shows and b
    does not)."""
    wa, ha, a = rgb(path_a)
    wb, hb, b = rgb(path_b)
    if (wa, ha) != (wb, hb):
        fail(f"{path_a} is {wa}x{ha}, {path_b} is {wb}x{hb}")
    squares, absolute, total, count, bright = 0.0, 0.0, 0.0, 0, 0
    for pixel in range(wa * ha):
        if not all(plane[pixel] < limit for plane in b):
            continue
        if not all(plane[pixel] < limit for plane in a):
            bright += 1
            continue
        for plane_a, plane_b in zip(a, b):
            difference = plane_a[pixel] - plane_b[pixel]
            squares += difference * difference
            absolute += abs(difference)
            total += plane_b[pixel]
        count += 3
    if count == 0 or total <= 0.0:
        fail(f"no lit pixel of {path_b} is under {limit}")
    return math.sqrt(squares / count), absolute / total, bright


def write_exr(path, width, height, planes):
    """An uncompressed scan-line OpenEXR file of FLOAT R, G and B."""
    def attribute(name, kind, value):
        return name.encode() + b"\0" + kind.encode() + b"\0" + struct.pack("<i", len(value)) + value

    channels = b"".join(c.encode() + b"\0" + struct.pack("<iB3sii", 2, 0, b"\0\0\0", 1, 1)
                        for c in "BGR") + b"\0"
    window = struct.pack("<iiii", 0, 0, width - 1, height - 1)
    header = (struct.pack("<ii", MAGIC, 2)
              + attribute("channels", "chlist", channels)
              + attribute("compression", "compression", b"\0")
              + attribute("dataWindow", "box2i", window)
              + attribute("displayWindow", "box2i", window)
              + attribute("lineOrder", "lineOrder", b"\0")
              + attribute("pixelAspectRatio", "float", struct.pack("<f", 1.0))
              + attribute("screenWindowCenter", "v2f", struct.pack("<ff", 0.0, 0.0))
              + attribute("screenWindowWidth", "float", struct.pack("<f", 1.0))
              + b"\0")
    row_bytes = 3 * 4 * width
    first = len(header) + 8 * height
    offsets = struct.pack(f"<{height}Q", *(first + y * (8 + row_bytes) for y in range(height)))
    body = bytearray()
    for y in range(height):
        body += struct.pack("<ii", y, row_bytes)
        for name in "BGR":
            row = planes[name][y * width : (y + 1) * width]
            if sys.byteorder != "little":
                row = array("f", row)
                row.byteswap()
            body += row.tobytes()
    with open(path, "wb") as file:
        file.write(header + offsets + body)


def average(path_a, path_b, path_out):
    wa, ha, a = rgb(path_a)
    wb, hb, b = rgb(path_b)
    if (wa, ha) != (wb, hb):
        fail(f"{path_a} is {wa}x{ha}, {path_b} is {wb}x{hb}")
    planes = {c: array("f", ((x + y) * 0.5 for x, y in zip(pa, pb))) for c, pa, pb in zip("RGB", a, b)}
    write_exr(path_out, wa, ha, planes)


def srgb_byte(value):
    value = min(max(value, 0.0), 1.0)
    value = 12.92 * value if value <= 0.0031308 else 1.055 * value ** (1 / 2.4) - 0.055
    return int(value * 255 + 0.5)


def preview(path, png_path):
    """The image as sRGB, clamped to [0, 1]: to look at, not to measure."""
    width, height, (r, g, b) = rgb(path)
    rows = bytearray()
    for y in range(height):
        rows.append(0)  # no filter
        for x in range(y * width, (y + 1) * width):
            rows += bytes((srgb_byte(r[x]), srgb_byte(g[x]), srgb_byte(b[x])))

    def chunk(kind, body):
        return (struct.pack(">I", len(body)) + kind + body
                + struct.pack(">I", zlib.crc32(kind + body) & 0xFFFFFFFF))

    with open(png_path, "wb") as file:
        file.write(b"\x89PNG\r\n\x1a\n"
                   + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
                   + chunk(b"IDAT", zlib.compress(bytes(rows), 6)) + chunk(b"IEND", b""))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    group = parser.add_mutually_exclusive_group()
    group.add_argument("--mean", action="store_true", help="print each image's mean R, G, B")
    group.add_argument("--preview", action="store_true", help="A.exr OUT.png: an sRGB PNG")
    group.add_argument("--half-difference", action="store_true",
                       help="A1 A2: RMSE(A1, A2) / 2, the noise of their mean")
    group.add_argument("--average", action="store_true", help="A1 A2 OUT.exr: their mean")
    group.add_argument("--pixel", metavar="X,Y", help="print the R, G, B of one pixel of each image")
    group.add_argument("--brightest", action="store_true",
                       help="print the R, G, B of each image's brightest pixel (largest R + G + B)")
    group.add_argument("--below", type=float, metavar="L",
                       help="A B: the RMSE and relative error where B is under L")
    parser.add_argument("images", nargs="+")
    args = parser.parse_args()
    if args.mean or args.pixel or args.brightest:
        for path in args.images:
            width, height, planes = rgb(path)
            if args.mean:
                values = [math.fsum(p) / (width * height) for p in planes]
            elif args.brightest:
                sums = list(map(operator.add, map(operator.add, planes[0], planes[1]), planes[2]))
                at = max(range(len(sums)), key=sums.__getitem__)
                values = [p[at] for p in planes]
            else:
                x, y = (int(v) for v in args.pixel.split(","))
                values = [p[y * width + x] for p in planes]
            print(" ".join(f"{v:.6f}" for v in values), path)
    elif args.preview:
        if len(args.images) != 2:
            fail("--preview takes A.exr OUT.png")
        preview(*args.images)
    elif args.below is not None:
        if len(args.images) != 2:
            fail("--below takes A.exr B.exr")
        value, relative, bright = errors_below(*args.images, args.below)
        print(f"{value:.6f} {relative:.6f} {bright}")
    elif args.average:
        if len(args.images) != 3:
            fail("--average takes A1.exr A2.exr OUT.exr")
        average(*args.images)
    else:
        if len(args.images) != 2:
            fail("give two images")
        value = rmse(*args.images)
        print(f"{value / 2 if args.half_difference else value:.6f}")


if __name__ == "__main__":
    main()
