#!/usr/bin/env python3
"""The picture of doc/images/patterns_golf.png: a golf ball with 40 dimples (the test suite's
layout: golden-angle directions, angular radius 0.24, depth 0.3), its dimples found by
`geodesic patterns` from one marked dimple, coloured by instance, and the arrangement.
Usage: plot_patterns.py GEODESIC_TOOL OUTPUT.png"""
import json, math, os, subprocess, sys, tempfile

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
from mpl_toolkits.mplot3d.art3d import Poly3DCollection


def golf_ball(frequency, count, angle, depth):
    t = (1 + 5 ** 0.5) / 2
    corners = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t), (0, 1, -t),
               (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2),
             (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11),
             (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    golden = math.pi * (3 - 5 ** 0.5)
    centres = []
    for i in range(count):
        z = 1 - 2 * (i + 0.5) / count
        r = (1 - z * z) ** 0.5
        centres.append((r * math.cos(golden * i), r * math.sin(golden * i), z))
    points, index, triangles = [], {}, []

    def point(p):
        key = tuple(round(c * 1e9) for c in p)
        if key not in index:
            index[key] = len(points)
            points.append(p)
        return index[key]

    m = frequency
    for a, b, c in faces:
        A, B, C = corners[a], corners[b], corners[c]

        def at(i, j):
            u, v = i / m, j / m
            return point(tuple(A[k] * (1 - u - v) + B[k] * u + C[k] * v for k in range(3)))

        for i in range(m):
            for j in range(m - i):
                triangles.append((at(i, j), at(i + 1, j), at(i, j + 1)))
                if i + j + 1 < m:
                    triangles.append((at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)))
    moved = []
    for p in points:
        n = math.sqrt(sum(c * c for c in p))
        d = tuple(c / n for c in p)
        radius = 1.0
        for c in centres:
            a = math.acos(max(-1.0, min(1.0, sum(d[k] * c[k] for k in range(3)))))
            if a < angle:
                s = a / angle
                radius -= depth * angle * (1 - s * s) ** 2
        moved.append(tuple(radius * c for c in d))
    return moved, triangles, centres


def main():
    tool, output = sys.argv[1], sys.argv[2]
    points, triangles, centres = golf_ball(32, 40, 0.24, 0.3)
    with tempfile.TemporaryDirectory() as tmp:
        mesh = os.path.join(tmp, "golf.off")
        with open(mesh, "w") as f:
            f.write("OFF\n%d %d 0\n" % (len(points), len(triangles)))
            for p in points:
                f.write("%.17g %.17g %.17g\n" % p)
            for t in triangles:
                f.write("3 %d %d %d\n" % t)
        bottom = [c * (1 - 0.3 * 0.24) for c in centres[5]]  # the deepest point of dimple 5
        marked = min(range(len(points)), key=lambda i: sum((points[i][k] - bottom[k]) ** 2 for k in range(3)))
        subprocess.run([tool, "patterns", mesh, "--patch-center", str(marked), "--patch-radius", "0.24",
                        "--output", os.path.join(tmp, "p.json"), "--labels", os.path.join(tmp, "l.txt")],
                       check=True)
        found = json.load(open(os.path.join(tmp, "p.json")))
        labels = [int(line) for line in open(os.path.join(tmp, "l.txt"))]
    palette = [plt.get_cmap("tab20")(i)[:3] for i in range(20) if i not in (6, 7, 14, 15)]  # no reds (the marked one), no greys
    polygons, colours = [], []
    elev, azim = math.radians(60), math.radians(53)
    view = (math.cos(elev) * math.cos(azim), math.cos(elev) * math.sin(azim), math.sin(elev))
    light = view
    for a, b, c in triangles:
        P = [points[a], points[b], points[c]]
        n = [(P[1][(k + 1) % 3] - P[0][(k + 1) % 3]) * (P[2][(k + 2) % 3] - P[0][(k + 2) % 3]) -
             (P[1][(k + 2) % 3] - P[0][(k + 2) % 3]) * (P[2][(k + 1) % 3] - P[0][(k + 1) % 3]) for k in range(3)]
        norm = math.sqrt(sum(x * x for x in n)) or 1
        shade = 0.35 + 0.65 * max(0.0, sum(n[k] * light[k] for k in range(3)) / norm)
        label = max(labels[a], labels[b], labels[c])
        base = (0.82, 0.82, 0.82) if label < 0 else palette[label % len(palette)]
        if label == 0:
            base = (0.9, 0.1, 0.1)
        polygons.append(P)
        colours.append(tuple(min(1.0, shade * x) for x in base))
    fig = plt.figure(figsize=(7, 7))
    ax = fig.add_subplot(projection="3d")
    ax.computed_zorder = False  # the arrangement over the surface
    ax.add_collection3d(Poly3DCollection(polygons, facecolors=colours, edgecolors="none", zorder=1))
    centres_found = [i["center"] for i in found["instances"]]
    for a, b in found["arrangement"]["edges"]:
        P, Q = centres_found[a], centres_found[b]
        # drawn on the near side only, lifted off the surface
        if sum(P[k] * view[k] for k in range(3)) > 0.2 and sum(Q[k] * view[k] for k in range(3)) > 0.2:
            ax.plot(*[[1.02 * P[k], 1.02 * Q[k]] for k in range(3)], color="black", linewidth=1.4, zorder=5)
    front = [c for c in centres_found if sum(c[k] * view[k] for k in range(3)) > 0.2]
    ax.scatter([1.02 * c[0] for c in front], [1.02 * c[1] for c in front], [1.02 * c[2] for c in front],
               color="black", s=8, zorder=6)
    ax.view_init(elev=math.degrees(elev), azim=math.degrees(azim))
    ax.set_box_aspect((1, 1, 1))
    for setter in (ax.set_xlim, ax.set_ylim, ax.set_zlim):
        setter(-0.8, 0.8)
    ax.set_axis_off()
    ax.set_title("%d dimples found from one (red), coloured by instance; arrangement in black"
                 % len(found["instances"]), fontsize=10)
    fig.savefig(output, dpi=110, bbox_inches="tight")


if __name__ == "__main__":
    main()
