#!/usr/bin/env python3
"""Writes the benchmark's mesh: a bumpy sphere of exactly 1,000,000 triangles
(1000 segments around, 501 bands from pole to pole), with a normal at every
vertex, as a binary little-endian PLY that RISE (through Assimp) and the
OSMesa program both read. Neighbouring triangles share their vertices, and the
surface is closed, so both renderers may cull its back faces."""
import math
import struct
import sys

SEGMENTS = 1000
RINGS = 501


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


def main(path):
    vertices = [((0.0, 1.0, 0.0), (0.0, 1.0, 0.0))]
    for ring in range(1, RINGS):
        phi = math.pi * ring / RINGS
        for segment in range(SEGMENTS):
            theta = 2.0 * math.pi * segment / SEGMENTS
            vertices.append((point(theta, phi), normal(theta, phi)))
    vertices.append(((0.0, -1.0, 0.0), (0.0, -1.0, 0.0)))
    south = len(vertices) - 1

    def at(ring, segment):  # rings 1 .. RINGS - 1
        return 1 + (ring - 1) * SEGMENTS + segment % SEGMENTS

    # With theta turning from +x towards +z, (lower k, lower k+1, upper k+1)
    # turns clockwise seen from outside: the corners are listed the other way.
    triangles = []
    for k in range(SEGMENTS):
        triangles.append((0, at(1, k + 1), at(1, k)))
        triangles.append((south, at(RINGS - 1, k), at(RINGS - 1, k + 1)))
    for ring in range(1, RINGS - 1):
        for k in range(SEGMENTS):
            upper, upper_next = at(ring, k), at(ring, k + 1)
            lower, lower_next = at(ring + 1, k), at(ring + 1, k + 1)
            triangles.append((lower, upper, upper_next))
            triangles.append((lower, upper_next, lower_next))

    with open(path, "wb") as out:
        out.write(("ply\nformat binary_little_endian 1.0\n"
                   f"element vertex {len(vertices)}\n"
                   "property float x\nproperty float y\nproperty float z\n"
                   "property float nx\nproperty float ny\nproperty float nz\n"
                   f"element face {len(triangles)}\n"
                   "property list uchar int vertex_indices\nend_header\n").encode())
        out.write(b"".join(struct.pack("<6f", *p, *n) for p, n in vertices))
        out.write(b"".join(struct.pack("<B3i", 3, *t) for t in triangles))
    print(f"{path}: {len(vertices)} vertices, {len(triangles)} triangles")


if __name__ == "__main__":
    main(sys.argv[1])
