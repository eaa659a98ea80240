#!/usr/bin/env python3
"""Writes the control meshes of the adaptive subdivision scenes (scenes/subdiv-adaptive-*.dat).

Deterministic (no randomness): running it again rewrites the same files byte for byte.
    python3 scenes/models/adaptive_cages.py        # from the repository root

- serpent.obj: a tube winding away from the camera, its ends closed by octagons (figure 51:
  one object seen partly close and partly far, so its edges need different levels).
- gourd.obj: a ribbed gourd with a stalk, a lathe of 16 segments (figure 55: a smooth organic
  surface close to the camera).
- terrain.obj: a hilly landscape of 128 x 128 quads seen from just above it out to its far edge
  (figure 56: its 1-pixel tessellation does not fit in a 2 GB heap). Numbers are written with
  few digits to keep the file small; the cage need not be more exact than that.
"""
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))


def num(x):
    s = "%.4f" % x
    s = s.rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


def write(name, header, verts, faces):
    with open(os.path.join(HERE, name), "w", newline="\n") as out:
        for line in header:
            out.write("# " + line + "\n")
        for v in verts:
            out.write("v " + " ".join(num(c) for c in v) + "\n")
        for f in faces:
            out.write("f " + " ".join(str(i + 1) for i in f) + "\n")


def lathe_faces(rings, seg, verts_before=0):
    faces = []
    for r in range(rings - 1):
        for s in range(seg):
            a = verts_before + r * seg + s
            b = verts_before + r * seg + (s + 1) % seg
            faces.append([a, b, b + seg, a + seg])
    return faces


def path(t):
    """The serpent's spine at t in [0, 1]: from beside the camera, winding away to 45 units."""
    z = -1 + 46 * t ** 1.2
    x = 3.2 * math.sin(2.4 * math.pi * t) * (0.3 + t)
    return x, z


def serpent():
    seg, rings = 8, 56
    verts = []
    for i in range(rings):
        t = i / (rings - 1)
        x, z = path(t)
        # A head, a neck, then a taper to the tail.
        radius = 0.5 * (1 - 0.6 * t) + 0.22 * math.exp(-((t - 0.02) / 0.025) ** 2)
        y = radius + 0.35 * math.sin(6 * math.pi * t) ** 2
        (x1, z1), (x2, z2) = path(max(0.0, t - 1e-3)), path(min(1.0, t + 1e-3))
        n = math.hypot(x2 - x1, z2 - z1)
        sx, sz = (z2 - z1) / n, -(x2 - x1) / n  # across the path, horizontal
        for s in range(seg):
            a = 2 * math.pi * s / seg
            verts.append((x + radius * math.cos(a) * sx, y + radius * math.sin(a), z + radius * math.cos(a) * sz))
    faces = lathe_faces(rings, seg)
    faces.append(list(reversed(range(seg))))
    faces.append([(rings - 1) * seg + s for s in range(seg)])
    write("serpent.obj", ["A winding tube for scenes/subdiv-adaptive-distances.dat, written by adaptive_cages.py."], verts, faces)


def gourd():
    seg = 16
    # (radius, height) of each ring, bottom to top; the last rings make the stalk.
    profile = [(0.3, 0.02), (0.8, 0.12), (1.1, 0.45), (1.18, 0.9), (1.02, 1.3), (0.62, 1.58), (0.26, 1.68),
               (0.13, 1.8), (0.12, 2.05), (0.16, 2.22)]
    verts = []
    for k, (r, y) in enumerate(profile):
        ribbed = k < 7
        for s in range(seg):
            a = 2 * math.pi * s / seg
            rr = r * (1 - 0.16 * (s % 2)) if ribbed else r
            lean = 0.12 * max(0, k - 6)  # the stalk bends a little
            verts.append((rr * math.cos(a) + lean, y, rr * math.sin(a)))
    rings = len(profile)
    faces = lathe_faces(rings, seg)
    faces.append(list(range(seg)))
    faces.append(list(reversed([(rings - 1) * seg + s for s in range(seg)])))
    write("gourd.obj", ["A ribbed gourd for scenes/subdiv-adaptive-close.dat, written by adaptive_cages.py."], verts, faces)


def terrain():
    n, size = 128, 256.0
    verts = []
    for j in range(n + 1):
        for i in range(n + 1):
            x = -size / 2 + size * i / n
            z = -size / 2 + size * j / n
            h = (7.0 * math.sin(0.045 * x + 0.5) * math.cos(0.06 * z)
                 + 3.0 * math.sin(0.13 * x - 0.09 * z + 1.0)
                 + 1.2 * math.sin(0.31 * x + 0.27 * z) * math.cos(0.23 * x - 0.35 * z)
                 + 22.0 * math.exp(-((x - 40) ** 2 + (z - 70) ** 2) / 900.0)
                 + 14.0 * math.exp(-((x + 70) ** 2 + (z - 20) ** 2) / 600.0))
            verts.append((x, h, z))
    faces = []
    for j in range(n):
        for i in range(n):
            a = j * (n + 1) + i
            faces.append([a, a + n + 1, a + n + 2, a + 1])
    write("terrain.obj", ["Hills for scenes/subdiv-adaptive-huge.dat, written by adaptive_cages.py."], verts, faces)


if __name__ == "__main__":
    serpent()
    gourd()
    terrain()
