#!/usr/bin/env python3
"""Writes the benchmarks' mesh: a bumpy sphere of 2 * SEGMENTS * (RINGS - 1)
triangles (by default exactly 1,000,000: 1000 segments around, 501 bands from
pole to pole), with a normal at every vertex unless --no-normals, as a binary
little-endian PLY that RISE (through Assimp), the OSMesa and the Embree
programs read. Neighbouring triangles share their vertices, and the surface is
closed, so the renderers may cull its back faces."""
import argparse
import math
import struct


def point(theta, phi):
    radius = 1.0 + 0.04 * math.sin(9.0 * theta) * math.sin(7.0 * phi)
    return (radius * math.sin(phi) * math.cos(theta), radius * math.cos(phi),
            radius * math.sin(phi) * math.sin(theta))


def normal(theta, phi):
    # Across the two tangents, found by central differences; outward.
    h = 1e-4
    a = point(theta + h, phi)
    b = point(theta - h, phi)
    c = point(theta, phi + h)
    d = point(theta, phi - h)
    du = [a[i] - b[i] for i in range(3)]
    dv = [c[i] - d[i] for i in range(3)]
    n = (dv[1] * du[2] - dv[2] * du[1], dv[2] * du[0] - dv[0] * du[2],
         dv[0] * du[1] - dv[1] * du[0])
    length = math.sqrt(sum(x * x for x in n))
    p = point(theta, phi)
    sign = 1.0 if sum(n[i] * p[i] for i in range(3)) > 0.0 else -1.0
    return tuple(sign * x / length for x in n)


def main(path, segments, rings, with_normals):
    def pole(y):
        return ((0.0, y, 0.0), (0.0, y, 0.0) if with_normals else ())

    vertices = [pole(1.0)]
    for ring in range(1, rings):
        phi = math.pi * ring / rings
        for segment in range(segments):
            theta = 2.0 * math.pi * segment / segments
            vertices.append((point(theta, phi), normal(theta, phi) if with_normals else ()))
    vertices.append(pole(-1.0))
    south = len(vertices) - 1

    def at(ring, segment):  # rings 1 .. rings - 1
        return 1 + (ring - 1) * segments + segment % segments

    # With theta turning from +x towards +z, (lower k, lower k+1, upper k+1)
    # turns clockwise seen from outside: the corners are listed the other way.
    triangles = []
    for k in range(segments):
        triangles.append((0, at(1, k + 1), at(1, k)))
        triangles.append((south, at(rings - 1, k), at(rings - 1, k + 1)))
    for ring in range(1, rings - 1):
        for k in range(segments):
            upper, upper_next = at(ring, k), at(ring, k + 1)
            lower, lower_next = at(ring + 1, k), at(ring + 1, k + 1)
            triangles.append((lower, upper, upper_next))
            triangles.append((lower, upper_next, lower_next))

    normal_properties = "property float nx\nproperty float ny\nproperty float nz\n"
    with open(path, "wb") as out:
        out.write(("ply\nformat binary_little_endian 1.0\n"
                   f"element vertex {len(vertices)}\n"
                   "property float x\nproperty float y\nproperty float z\n"
                   f"{normal_properties if with_normals else ''}"
                   f"element face {len(triangles)}\n"
                   "property list uchar int vertex_indices\nend_header\n").encode())
        floats = 6 if with_normals else 3
        out.write(b"".join(struct.pack(f"<{floats}f", *p, *n) for p, n in vertices))
        out.write(b"".join(struct.pack("<B3i", 3, *t) for t in triangles))
    print(f"{path}: {len(vertices)} vertices, {len(triangles)} triangles")


if __name__ == "__main__":
    arguments = argparse.ArgumentParser(description=__doc__)
    arguments.add_argument("path")
    arguments.add_argument("--segments", type=int, default=1000, help="around the axis")
    arguments.add_argument("--rings", type=int, default=501, help="bands from pole to pole")
    arguments.add_argument("--no-normals", action="store_true",
                           help="leave the normals to the reader")
    options = arguments.parse_args()
    main(options.path, options.segments, options.rings, not options.no_normals)
