#!/usr/bin/python3
"""Wrote the cylinderTank3D surfaces in constant/geometry/ (run it again after changing R, H,
HT or SIDES): tank.stl (ASCII STL), the closed tank (radius R, height HT, its axis the z axis,
floor at z = 0), and water.obj (Wavefront OBJ), the water at rest (radius R, depth H). 48
sides: the facets stand R (1 - cos(pi/48)) = 0.0021 R = 0.017 dx inside the circle.
Usage: makeGeometry.py [case]
"""
import math
import os
import sys

R, H, HT, SIDES = 0.3, 0.3, 0.5, 48


def cylinder(radius, height):
    """Triangles of a closed cylinder, counter-clockwise seen from outside."""
    ring = [(radius * math.cos(2 * math.pi * k / SIDES), radius * math.sin(2 * math.pi * k / SIDES)) for k in range(SIDES)]
    triangles = []
    for k in range(SIDES):
        (x0, y0), (x1, y1) = ring[k], ring[(k + 1) % SIDES]
        triangles += [((x0, y0, 0), (x1, y1, 0), (x1, y1, height)), ((x0, y0, 0), (x1, y1, height), (x0, y0, height))]
        triangles += [((0, 0, 0), (x1, y1, 0), (x0, y0, 0)), ((0, 0, height), (x0, y0, height), (x1, y1, height))]
    return triangles


def write_stl(path, name, triangles):
    with open(path, "w") as f:
        f.write("solid %s\n" % name)
        for a, b, c in triangles:
            u = [b[i] - a[i] for i in range(3)]
            v = [c[i] - a[i] for i in range(3)]
            n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
            length = math.sqrt(sum(x * x for x in n))
            f.write("  facet normal %.9g %.9g %.9g\n    outer loop\n" % tuple(x / length for x in n))
            for p in (a, b, c):
                f.write("      vertex %.9g %.9g %.9g\n" % p)
            f.write("    endloop\n  endfacet\n")
        f.write("endsolid %s\n" % name)


def write_obj(path, triangles):
    """Shared vertices, each written once, 1-based indices."""
    index = {}
    with open(path, "w") as f:
        for triangle in triangles:
            for p in triangle:
                if p not in index:
                    index[p] = len(index) + 1
                    f.write("v %.9g %.9g %.9g\n" % p)
        for a, b, c in triangles:
            f.write("f %d %d %d\n" % (index[a], index[b], index[c]))


def main():
    case = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
    directory = os.path.join(case, "constant", "geometry")
    os.makedirs(directory, exist_ok=True)
    write_stl(os.path.join(directory, "tank.stl"), "tank", cylinder(R, HT))
    write_obj(os.path.join(directory, "water.obj"), cylinder(R, H))


main()
