#!/usr/bin/env python3
"""Renders the user manual's pictures (doc/figures/*.png) from the geodesic tool's own outputs.

Headless (matplotlib's Agg back end) and with Debian's packages only: python3-matplotlib,
python3-numpy and python3-pil (a dependency of python3-matplotlib), run by Debian's
/usr/bin/python3; about 40 s:

  /usr/bin/python3 doc/make_figures.py [--tool build/src/geodesic] [--out doc/figures] [--only NAME ...]

The meshes are real ones: the bundled data/elephant.off, and armadillo.off and fandisk.off,
unpacked at run time from the data set that CGAL distributes with its demos (Debian package
libcgal-demo, /usr/share/doc/libcgal-demo/data.tar.gz, see --cgal-data), and the golf ball of
bench/plot_patterns.py. Every distance, path, cell, bisector, sample and pattern instance drawn
is read from a file the tool wrote; the two charts read bench/results/lambda_curve.csv and
doc/figures/benchmark.csv.

Figures (NAME: what it shows):
  distance_field     geodesic distance from one vertex of the armadillo, with evenly spaced isolines
  shortest_path      a shortest path on the armadillo, over its distance field
  voronoi            geodesic Voronoi cells on the elephant, their bisectors and the dual graph
  sampling           50 farthest-point samples on the fandisk and their cells, two views
  patterns           the golf ball's dimples found from one marked dimple, and their arrangement
  avtp_error_lambda  AVTP's mean relative error and time against lambda
  benchmark          times of VTP, PVTP, AVTP, CGAL's exact solver and the heat method

How the surfaces are drawn: an orthographic camera, the faces turned towards it sorted back to
front (painter's order) and filled with their own colour (a colour map or a cell's colour times
Lambert shading from the face normal); lines that lie on the surface (isolines, paths,
bisectors, dual edges) are drawn over it, each piece only where a depth buffer of the mesh,
rasterized here, says that it is not behind the surface. A face whose corners lie in different
cells is cut where the cells meet: where the two sources' distances (rows of `geodesic matrix`),
linear on the face, are equal.
"""

import argparse
import csv
import json
import math
import os
import subprocess
import sys
import tarfile
import tempfile
import time
from pathlib import Path

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.colors  # noqa: E402
import matplotlib.ticker  # noqa: E402
from matplotlib.collections import LineCollection, PolyCollection  # noqa: E402

REPO = Path(__file__).resolve().parent.parent
FIGURES = ("distance_field", "shortest_path", "voronoi", "sampling", "patterns", "avtp_error_lambda", "benchmark")
DPI = 100


# ---------------------------------------------------------------------------------------------
# Files: meshes in, the tool's outputs back

def read_off(path):
    """(points (n, 3), triangles (m, 3)) of an OFF file of triangles."""
    words = []
    with open(path) as f:
        for line in f:
            line = line.split("#", 1)[0].split()
            words.extend(line)
    if not words[0].endswith("OFF"):
        raise ValueError("%s: not an OFF file" % path)
    n, m = int(words[1]), int(words[2])
    points = np.array(words[4:4 + 3 * n], dtype=float).reshape(n, 3)
    rest = words[4 + 3 * n:]
    faces, i = [], 0
    for _ in range(m):
        k = int(rest[i])
        if k != 3:
            raise ValueError("%s: a face of %d vertices (triangles only here)" % (path, k))
        faces.append([int(x) for x in rest[i + 1:i + 4]])
        i += 1 + k
    return points, np.array(faces, dtype=np.int64)


def write_off(path, points, triangles):
    with open(path, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(points), len(triangles)))
        for p in points:
            f.write("%.17g %.17g %.17g\n" % tuple(p))
        for t in triangles:
            f.write("3 %d %d %d\n" % tuple(t))


PLY_TYPES = {"char": "i1", "int8": "i1", "uchar": "u1", "uint8": "u1", "short": "i2", "int16": "i2",
             "ushort": "u2", "uint16": "u2", "int": "i4", "int32": "i4", "uint": "u4", "uint32": "u4",
             "float": "f4", "float32": "f4", "double": "f8", "float64": "f8"}


def read_ply(path):
    """The vertex element of a PLY file (ASCII or binary) as {property: array}, and its faces."""
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode("ascii").splitlines()
    fmt, elements = None, []
    for line in header:
        w = line.split()
        if not w:
            continue
        if w[0] == "format":
            fmt = w[1]
        elif w[0] == "element":
            elements.append((w[1], int(w[2]), []))
        elif w[0] == "property":
            elements[-1][2].append(w[1:])
    body = data[end:]
    result, faces = {}, None
    if fmt == "ascii":
        lines = iter(body.decode("ascii").splitlines())
        for name, count, props in elements:
            rows = [next(lines).split() for _ in range(count)]
            if name == "vertex":
                for j, p in enumerate(props):
                    result[p[-1]] = np.array([float(r[j]) for r in rows])
            elif name == "face":
                faces = np.array([[int(x) for x in r[1:4]] for r in rows], dtype=np.int64)
        return result, faces
    order = "<" if fmt == "binary_little_endian" else ">"
    offset = 0
    for name, count, props in elements:
        if all(p[0] != "list" for p in props):
            dtype = np.dtype([(p[1], order + PLY_TYPES[p[0]]) for p in props])
            table = np.frombuffer(body, dtype=dtype, count=count, offset=offset)
            offset += dtype.itemsize * count
            if name == "vertex":
                result = {p[1]: table[p[1]].astype(float) for p in props}
        elif name == "face" and len(props) == 1:
            size_t = np.dtype(order + PLY_TYPES[props[0][1]])
            index_t = np.dtype(order + PLY_TYPES[props[0][2]])
            # triangles only: every record is one count and three indices
            dtype = np.dtype([("n", size_t), ("v", index_t, (3,))])
            table = np.frombuffer(body, dtype=dtype, count=count, offset=offset)
            if np.any(table["n"] != 3):
                raise ValueError("%s: faces other than triangles" % path)
            faces = table["v"].astype(np.int64)
            offset += dtype.itemsize * count
        else:
            raise ValueError("%s: element %s not read here" % (path, name))
    return result, faces


def read_obj_lines(path):
    """(points (n, 3), polylines [index arrays]) of the v and l lines of an OBJ file."""
    points, lines = [], []
    with open(path) as f:
        for line in f:
            w = line.split()
            if not w:
                continue
            if w[0] == "v":
                points.append([float(x) for x in w[1:4]])
            elif w[0] == "l":
                lines.append(np.array([int(x.split("/")[0]) - 1 for x in w[1:]], dtype=np.int64))
    return np.array(points).reshape(-1, 3), lines


def read_points_txt(path):
    return np.loadtxt(path, ndmin=2)


class Tool:
    def __init__(self, path, workdir):
        self.path = str(path)
        self.workdir = Path(workdir)

    def file(self, name):
        return str(self.workdir / name)

    def __call__(self, *args):
        command = [self.path] + [str(a) for a in args]
        print("  $ geodesic " + " ".join(str(a) for a in args).replace(str(self.workdir) + "/", ""), flush=True)
        run = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        if run.returncode != 0:
            raise SystemExit("make_figures.py: %s failed (%d):\n%s" % (" ".join(command), run.returncode, run.stderr))
        return run


def cgal_mesh(name, archive, workdir):
    """data/meshes/NAME from CGAL's demo data set, unpacked into workdir once."""
    target = Path(workdir) / "cgal" / name
    if not target.exists():
        target.parent.mkdir(parents=True, exist_ok=True)
        try:
            with tarfile.open(archive) as tar:
                member = tar.getmember("data/meshes/" + name)
                with tar.extractfile(member) as src, open(target, "wb") as dst:
                    dst.write(src.read())
        except (OSError, KeyError) as e:
            raise SystemExit("make_figures.py: cannot read data/meshes/%s from %s (%s); install Debian's "
                             "libcgal-demo or pass --cgal-data" % (name, archive, e))
    return target


# ---------------------------------------------------------------------------------------------
# Geometry and the camera

def unit(v):
    v = np.asarray(v, dtype=float)
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def face_normals(points, triangles):
    a, b, c = (points[triangles[:, k]] for k in range(3))
    n = np.cross(b - a, c - a)
    length = np.linalg.norm(n, axis=1, keepdims=True)
    return n / np.where(length > 0, length, 1)


def outward(points, triangles):
    """The triangles, reversed if their orientation encloses a negative volume."""
    a, b, c = (points[triangles[:, k]] for k in range(3))
    volume = np.einsum("ij,ij->i", a, np.cross(b, c)).sum()
    return triangles if volume >= 0 else triangles[:, ::-1].copy()


class Camera:
    """Orthographic: `up` is the model's up axis, `front` the direction its front faces; the
    viewer is at azimuth `azim` (degrees, about up, from front towards up x front) and elevation
    `elev` (degrees above the front's horizon)."""

    def __init__(self, up, front, azim=0.0, elev=0.0, light=(-0.35, 0.45)):
        up, front = unit(up), unit(front)
        side = np.cross(up, front)
        a, e = math.radians(azim), math.radians(elev)
        self.eye = unit(math.cos(e) * (math.cos(a) * front + math.sin(a) * side) + math.sin(e) * up)
        self.v = unit(up - np.dot(up, self.eye) * self.eye)  # screen up
        self.u = np.cross(self.v, self.eye)  # screen right
        # the light: from the viewer, a little to the left and above
        self.light = unit(self.eye + light[0] * self.u + light[1] * self.v)

    def project(self, p):
        """(screen x, screen y, depth: larger is nearer) of points (..., 3)."""
        p = np.asarray(p, dtype=float)
        return np.stack([p @ self.u, p @ self.v, p @ self.eye], axis=-1)


class View:
    """A mesh seen by a camera: which faces are drawn in which order, their shading, and a depth
    buffer to tell whether a point on the surface is seen."""

    def __init__(self, points, triangles, camera, resolution=1200, ambient=0.3):
        self.points, self.triangles, self.camera = points, outward(points, triangles), camera
        self.normals = face_normals(points, self.triangles)
        self.screen = camera.project(points)
        facing = self.normals @ camera.eye
        self.front = facing > 0
        depth = self.screen[self.triangles, 2].mean(axis=1)
        self.order = np.flatnonzero(self.front)[np.argsort(depth[self.front], kind="stable")]  # back to front
        self.shade = ambient + (1 - ambient) * np.clip(self.normals @ camera.light, 0, 1)
        xy = self.screen[:, :2]
        self.low, self.high = xy.min(axis=0), xy.max(axis=0)
        self.extent = float(np.max(self.high - self.low))
        self.pixel = self.extent / resolution
        self.size = np.ceil((self.high - self.low) / self.pixel).astype(int) + 3
        self.zbuffer = self._rasterize()
        self.tolerance = max(0.004 * self.extent, 2.5 * self.pixel)

    def _to_pixels(self, xy):
        return (xy - self.low) / self.pixel + 1

    def _rasterize(self):
        """The largest depth of the front faces at every pixel centre (-inf where none)."""
        W, H = self.size
        zb = np.full(W * H, -np.inf)
        tri = self.triangles[self.front]
        P = self._to_pixels(self.screen[:, :2])
        Z = self.screen[:, 2]
        for chunk in np.array_split(np.arange(len(tri)), max(1, len(tri) // 20000)):
            t = tri[chunk]
            a, b, c = P[t[:, 0]], P[t[:, 1]], P[t[:, 2]]
            lo = np.floor(np.minimum(np.minimum(a, b), c)).astype(int)
            hi = np.ceil(np.maximum(np.maximum(a, b), c)).astype(int)
            w, h = hi[:, 0] - lo[:, 0] + 1, hi[:, 1] - lo[:, 1] + 1
            count = w * h
            k = np.repeat(np.arange(len(t)), count)
            offs = np.arange(count.sum()) - np.repeat(np.cumsum(count) - count, count)
            px = lo[k, 0] + offs % w[k]
            py = lo[k, 1] + offs // w[k]
            ak, bk, ck = a[k], b[k], c[k]
            det = (bk[:, 0] - ak[:, 0]) * (ck[:, 1] - ak[:, 1]) - (ck[:, 0] - ak[:, 0]) * (bk[:, 1] - ak[:, 1])
            det = np.where(np.abs(det) > 1e-12, det, np.nan)
            l1 = ((px - ak[:, 0]) * (ck[:, 1] - ak[:, 1]) - (ck[:, 0] - ak[:, 0]) * (py - ak[:, 1])) / det
            l2 = ((bk[:, 0] - ak[:, 0]) * (py - ak[:, 1]) - (px - ak[:, 0]) * (bk[:, 1] - ak[:, 1])) / det
            l0 = 1 - l1 - l2
            eps = 1e-6
            inside = (l0 >= -eps) & (l1 >= -eps) & (l2 >= -eps)
            z = l0 * Z[t[k, 0]] + l1 * Z[t[k, 1]] + l2 * Z[t[k, 2]]
            ok = inside & (px >= 0) & (px < W) & (py >= 0) & (py < H)
            np.maximum.at(zb, py[ok] * W + px[ok], z[ok])
        zb = zb.reshape(H, W)
        # a pixel that no face centre fell in, between faces, takes its neighbours' nearest
        filled = zb.copy()
        for dy in (-1, 0, 1):
            for dx in (-1, 0, 1):
                filled = np.maximum(filled, np.roll(np.roll(zb, dy, axis=0), dx, axis=1))
        return np.where(np.isfinite(zb), zb, filled)

    def visible(self, p):
        """Whether points (..., 3) on the surface are seen (not behind a nearer part of it)."""
        s = self.camera.project(p)
        q = np.rint(self._to_pixels(s[..., :2])).astype(int)
        W, H = self.size
        x, y = np.clip(q[..., 0], 0, W - 1), np.clip(q[..., 1], 0, H - 1)
        return s[..., 2] >= self.zbuffer[y, x] - self.tolerance

    def visible_segments(self, segments, samples=4):
        """Of segments (k, 2, 3) on the surface, those seen along their whole length."""
        segments = np.asarray(segments, dtype=float).reshape(-1, 2, 3)
        t = np.linspace(0, 1, samples + 1)[None, :, None]
        along = segments[:, :1] * (1 - t) + segments[:, 1:] * t
        return segments[self.visible(along).all(axis=1)]

    def face_colors(self, base):
        """Colours (faces, 3 or 4) of the drawn faces in painter's order, times the shading."""
        c = np.array(base, dtype=float)[self.order, :3] * self.shade[self.order, None]
        return np.clip(c, 0, 1)

    def draw(self, ax, base, pieces=None):
        """The surface in painter's order, each face in base[face] (RGB) times its shade; a face
        listed in pieces ({face: [(polygon (k, 3), RGB)]}) is drawn as those polygons instead."""
        polygons = list(self.screen[self.triangles[self.order], :2])
        colours = list(self.face_colors(base))
        if pieces:
            drawn_polygons, drawn_colours = [], []
            for k, f in enumerate(self.order):
                for polygon, colour in pieces.get(f, [(None, None)]):
                    if polygon is None:
                        drawn_polygons.append(polygons[k])
                        drawn_colours.append(colours[k])
                    else:
                        drawn_polygons.append(self.camera.project(polygon)[:, :2])
                        drawn_colours.append(np.clip(np.asarray(colour)[:3] * self.shade[f], 0, 1))
            polygons, colours = drawn_polygons, drawn_colours
        # the edges in the face's colour close the hair-line gaps between faces
        ax.add_collection(PolyCollection(polygons, facecolors=colours, edgecolors=colours, linewidths=0.25,
                                         antialiaseds=True, zorder=1))
        margin = 0.02 * self.extent
        ax.set_xlim(self.low[0] - margin, self.high[0] + margin)
        ax.set_ylim(self.low[1] - margin, self.high[1] + margin)
        ax.set_aspect("equal")
        ax.set_axis_off()

    def lines(self, ax, segments, zorder=3, **style):
        """Segments (k, 2, 3) lying on the surface, drawn where they are seen."""
        seen = self.visible_segments(segments)
        ax.add_collection(LineCollection(self.camera.project(seen)[..., :2], zorder=zorder, **style))
        return len(seen)

    def polyline(self, ax, points, zorder=4, **style):
        points = np.asarray(points, dtype=float)
        return self.lines(ax, np.stack([points[:-1], points[1:]], axis=1), zorder=zorder, **style)

    def dots(self, ax, points, zorder=5, **style):
        """Points on the surface, drawn where they are seen; returns how many."""
        points = np.asarray(points, dtype=float).reshape(-1, 3)
        seen = points[self.visible(points)]
        s = self.camera.project(seen)
        ax.scatter(s[:, 0], s[:, 1], zorder=zorder, **style)
        return len(seen)


def isolines(points, triangles, values, levels):
    """Segments (k, 2, 3) of the level sets of a per-vertex field linear on each triangle
    (marching triangles): on each face, the two points of its edges where the field crosses a
    level, each interpolated linearly between the edge's end values."""
    out = []
    f = values[triangles]  # (m, 3)
    finite = np.isfinite(f).all(axis=1)
    tri, f = triangles[finite], f[finite]
    P = points[tri]  # (m, 3, 3)
    lo, hi = f.min(axis=1), f.max(axis=1)
    for level in levels:
        rows = np.flatnonzero((lo < level) & (hi > level))
        if len(rows) == 0:
            continue
        g, Q = f[rows] - level, P[rows]
        ends = []
        for i, j in ((0, 1), (1, 2), (2, 0)):
            crosses = (g[:, i] < 0) != (g[:, j] < 0)
            t = np.where(crosses, g[:, i] / np.where(crosses, g[:, i] - g[:, j], 1), np.nan)
            ends.append((crosses, Q[:, i] + t[:, None] * (Q[:, j] - Q[:, i])))
        # exactly two of the three edges cross (a vertex at the level counts on one side)
        crossing = np.stack([e[0] for e in ends], axis=1)
        keep = crossing.sum(axis=1) == 2
        pts = np.stack([e[1] for e in ends], axis=1)[keep]  # (k, 3 edges, 3)
        which = crossing[keep]
        first = np.argmax(which, axis=1)
        second = 2 - np.argmax(which[:, ::-1], axis=1)
        k = np.arange(len(pts))
        out.append(np.stack([pts[k, first], pts[k, second]], axis=1))
    return np.concatenate(out) if out else np.zeros((0, 2, 3))


def clip_polygon(polygon, g):
    """The part of a convex polygon (k, 3 barycentric coordinates) where the linear function of
    values g (at the triangle's 3 corners) is >= 0 (Sutherland-Hodgman, one plane)."""
    values = polygon @ g
    out = []
    for i in range(len(polygon)):
        p, q, gp, gq = polygon[i], polygon[(i + 1) % len(polygon)], values[i], values[(i + 1) % len(polygon)]
        if gp >= 0:
            out.append(p)
        if (gp >= 0) != (gq >= 0):
            out.append(p + (q - p) * (gp / (gp - gq)))
    return np.array(out).reshape(-1, 3)


def split_cells(points, triangles, label, score):
    """The faces whose corners lie in different cells, cut where the cells meet: a cell's part of a
    face is where its score, linear on the face, is the largest of the corners' cells' scores.
    score(vertices, cells) -> (len(vertices), len(cells)); e.g. minus the distances to the
    sources, or 1 in the vertex's own cell and 0 elsewhere (then the cut is at the edges' middles).
    Returns {face: [(polygon (k, 3), cell)]} and the segments where two cells meet (m, 2, 3)."""
    L = label[triangles]
    mixed = np.flatnonzero((L[:, 0] != L[:, 1]) | (L[:, 1] != L[:, 2]))
    pieces, boundary = {}, []
    for f in mixed:
        cells = np.unique(L[f])
        if cells[0] < 0:  # unreached corners: the face keeps one colour
            continue
        S = score(triangles[f], cells)  # (3 corners, cells)
        P = points[triangles[f]]
        for i, a in enumerate(cells):
            polygon = np.eye(3)
            for j in range(len(cells)):
                if j != i and len(polygon):
                    polygon = clip_polygon(polygon, S[:, i] - S[:, j])
            if len(polygon) < 3:
                continue
            pieces.setdefault(f, []).append((polygon @ P, a))
            # the polygon's edges on which cell a ties with a later cell j: where they meet
            for j in range(i + 1, len(cells)):
                g = polygon @ (S[:, i] - S[:, j])
                tie = np.abs(g) <= 1e-9 * max(1.0, float(np.abs(S).max()))
                for k in range(len(polygon)):
                    if tie[k] and tie[(k + 1) % len(polygon)]:
                        boundary.append((polygon[k] @ P, polygon[(k + 1) % len(polygon)] @ P))
    return pieces, np.array(boundary).reshape(-1, 2, 3)


def coloured_pieces(pieces, palette):
    return {f: [(polygon, palette[cell]) for polygon, cell in parts] for f, parts in pieces.items()}


def greedy_colours(count, edges, palette_size):
    """A colour index per cell, neighbours (edges) never alike, the colours used evenly."""
    neighbours = [set() for _ in range(count)]
    for a, b in edges:
        if a != b:
            neighbours[a].add(b)
            neighbours[b].add(a)
    colour, used = [-1] * count, [0] * palette_size
    for cell in sorted(range(count), key=lambda c: -len(neighbours[c])):
        taken = {colour[n] for n in neighbours[cell]}
        free = [c for c in range(palette_size) if c not in taken] or list(range(palette_size))
        colour[cell] = min(free, key=lambda c: (used[c], c))
        used[colour[cell]] += 1
    return np.array(colour)


def label_edges(triangles, label):
    """The pairs of cells that meet across an edge of the mesh."""
    L = label[triangles]
    pairs = np.concatenate([L[:, [0, 1]], L[:, [1, 2]], L[:, [2, 0]]])
    pairs = pairs[(pairs[:, 0] != pairs[:, 1]) & (pairs >= 0).all(axis=1)]
    return {tuple(sorted(p)) for p in pairs.tolist()}


def new_figure(width=8.0, height=6.0):
    fig = plt.figure(figsize=(width, height), dpi=DPI)
    fig.patch.set_facecolor("white")
    return fig


def save(fig, path, title=None):
    if title:
        fig.suptitle(title, fontsize=10, y=0.985)
    fig.savefig(str(path), dpi=DPI, facecolor="white", bbox_inches="tight", pad_inches=0.08)
    plt.close(fig)
    from PIL import Image  # python3-pil, a dependency of python3-matplotlib

    # thousands of shaded faces make many colours: rounding each channel to a multiple of 4 or 8
    # (invisible; white stays white, and no colour is lost as a palette would lose a rare one)
    # keeps the file small
    for step in (4, 8):
        if os.path.getsize(path) <= 150 * 1024:
            break
        with Image.open(path) as im:
            a = np.asarray(im.convert("RGB"), dtype=float)
        Image.fromarray(np.minimum(255, np.round(a / step) * step).astype(np.uint8)).save(str(path), optimize=True)
    with Image.open(path) as im:
        print("  wrote %s (%dx%d, %.0f KB)" % (path, im.size[0], im.size[1], os.path.getsize(path) / 1024))


def nearest_vertex(points, p):
    return int(np.argmin(np.linalg.norm(points - np.asarray(p, dtype=float), axis=1)))


def colour_bar(fig, ax, cmap, norm, label, levels=None):
    bar_ax = fig.add_axes([0.86, 0.18, 0.022, 0.55])
    bar = fig.colorbar(matplotlib.cm.ScalarMappable(norm=norm, cmap=cmap), cax=bar_ax)
    bar.set_label(label, fontsize=9)
    bar.ax.tick_params(labelsize=8)
    if levels is not None:
        bar.ax.hlines(levels, 0, 1, colors="black", linewidths=0.5)
    return bar


# ---------------------------------------------------------------------------------------------
# The figures on meshes

ARMADILLO_CAMERA = dict(up=(0, 1, 0), front=(0, 0, -1), azim=-25, elev=8)


def soften(rgb, amount):
    """Colours mixed with white (amount 0: unchanged, 1: white)."""
    return np.asarray(rgb, dtype=float)[..., :3] * (1 - amount) + amount


def distance_colours(values, triangles, cmap, vmax, soft=0.0):
    """Each face's colour: the colour map at the mean of its vertices' distances."""
    f = values[triangles].mean(axis=1)
    c = soften(cmap(np.clip(f / vmax, 0, 1)), soft)
    c[~np.isfinite(f)] = 0.6
    return c


def distance_cmap():
    """viridis without its darkest quarter, so that the shading reads near the source too."""
    return matplotlib.colors.ListedColormap(plt.get_cmap("viridis")(np.linspace(0.25, 1.0, 256)), "viridis_light")


def level_set(vmax, count):
    """count - 1 levels evenly spaced strictly between 0 and vmax, and their spacing."""
    step = vmax / count
    return step, step * np.arange(1, count)


def seen_vertex(view, points, near):
    """The vertex nearest to `near` among those the view shows (on a face turned to the viewer)."""
    shown = np.zeros(len(points), dtype=bool)
    shown[view.triangles[view.front].ravel()] = True
    shown &= view.visible(points)
    candidates = np.flatnonzero(shown)
    return int(candidates[np.argmin(np.linalg.norm(points[candidates] - np.asarray(near, dtype=float), axis=1))])


def fig_distance_field(tool, out, work, args):
    mesh = cgal_mesh("armadillo.off", args.cgal_data, work)
    points, triangles = read_off(mesh)
    view = View(points, triangles, Camera(**ARMADILLO_CAMERA))
    source = seen_vertex(view, points, (0, 75, -60))  # the tip of the snout
    field = tool.file("armadillo_distances.ply")
    tool("distances", mesh, "--source", source, "--output", field)
    props, ply_faces = read_ply(field)
    distance = props["distance"]
    assert len(distance) == len(points) and np.array_equal(ply_faces, triangles)
    vmax = float(np.max(distance[np.isfinite(distance)]))
    count = 24
    step, levels = level_set(vmax, count)
    cmap = distance_cmap()
    fig = new_figure(7.2, 6.0)
    ax = fig.add_axes([0, 0, 0.84, 0.94])
    view.draw(ax, distance_colours(distance, view.triangles, cmap, vmax))
    view.lines(ax, isolines(points, view.triangles, distance, levels), colors="#1a1a1a", linewidths=0.7)
    view.dots(ax, points[source], s=46, color="#e31a1c", edgecolors="white", linewidths=1.0)
    colour_bar(fig, ax, cmap, matplotlib.colors.Normalize(0, vmax), "geodesic distance", levels)
    save(fig, out / "distance_field.png",
         "Exact geodesic distance from the snout (red dot) on armadillo.off (%s vertices),\n"
         "isolines every %.3g, 1/%d of the largest distance" % ("{:,}".format(len(points)), step, count))


def fig_shortest_path(tool, out, work, args):
    mesh = cgal_mesh("armadillo.off", args.cgal_data, work)
    points, triangles = read_off(mesh)
    view = View(points, triangles, Camera(**ARMADILLO_CAMERA))
    # from the right foot (the viewer's right) to the left shoulder: a path that the view shows whole
    source = seen_vertex(view, points, (-42.56, -53.39, -9.41))
    target = seen_vertex(view, points, (19, 77, 9))
    field = tool.file("armadillo_path_field.ply")
    tool("distances", mesh, "--source", source, "--output", field)
    distance = read_ply(field)[0]["distance"]
    path_file = tool.file("armadillo_path.txt")
    run = tool("path", mesh, "--source", source, "--target", target, "--output", path_file, "--stats")
    stats = dict(line.split("=", 1) for line in run.stderr.split() if "=" in line)
    path = read_points_txt(path_file)
    vmax = float(np.max(distance[np.isfinite(distance)]))
    _, levels = level_set(vmax, 24)
    fig = new_figure(7.2, 6.0)
    ax = fig.add_axes([0, 0, 1, 0.94])
    view.draw(ax, distance_colours(distance, view.triangles, distance_cmap(), vmax, soft=0.6))
    view.lines(ax, isolines(points, view.triangles, distance, levels), colors="#8c8c8c", linewidths=0.45)
    drawn = view.polyline(ax, path, colors="#e31a1c", linewidths=2.4, capstyle="round")
    view.dots(ax, points[[source]], s=60, color="#1f78b4", edgecolors="white", linewidths=1.0, zorder=6)
    view.dots(ax, points[[target]], s=60, color="#1f78b4", edgecolors="white", linewidths=1.0, zorder=6,
              marker="s")
    print("  path: %d points, %d of its %d segments seen from this view" % (len(path), drawn, len(path) - 1))
    save(fig, out / "shortest_path.png",
         "Shortest path (red, length %.4g) from the right foot (blue dot) to the left shoulder (blue square)\n"
         "on armadillo.off, over the distance field from the foot" % float(stats.get("length", "nan")))


# light colours, distinct enough for neighbouring cells to be told apart
# (no red: red marks sources and the marked pattern; no grey: outside every pattern instance)
CELL_PALETTE = soften([plt.get_cmap("tab10")(i)[:3] for i in (0, 1, 2, 4, 5, 6, 8, 9)], 0.3).tolist() + \
    [plt.get_cmap("Set3")(i)[:3] for i in (2, 11)]
CELL_PALETTE = np.array(CELL_PALETTE)


def distance_score(matrix):
    """score(vertices, cells): minus the distances from the cells' sources (rows of matrix)."""
    return lambda vertices, cells: -matrix[np.ix_(cells, vertices)].T


def fig_voronoi(tool, out, work, args):
    mesh = REPO / "data" / "elephant.off"
    points, triangles = read_off(mesh)
    samples_file = tool.file("elephant_sources.txt")
    tool("sample", mesh, "--count", 24, "--output", samples_file)
    sources = [int(row[0]) for row in np.loadtxt(samples_file, ndmin=2)]
    cells, bisectors, dual = (tool.file(n) for n in ("elephant_cells.ply", "elephant_bisectors.obj",
                                                     "elephant_dual.obj"))
    listed = ",".join(map(str, sources))
    tool("voronoi", mesh, "--source", listed, "--output", cells, "--bisectors", bisectors, "--dual", dual)
    label = read_ply(cells)[0]["source"].astype(int)
    curve_points, curves = read_obj_lines(bisectors)
    _, dual_edges = read_obj_lines(dual)
    # each source's distances, to cut the faces between cells where the two distances are equal
    matrix_file = tool.file("elephant_sources.npy")
    tool("matrix", mesh, "--source", listed, "--output", matrix_file)
    matrix = np.load(matrix_file)
    view = View(points, triangles, Camera(up=(0, 1, 0), front=(1, 0, 0), azim=70, elev=12, light=(-0.5, 0.6)),
                ambient=0.45)
    colour = CELL_PALETTE[greedy_colours(len(sources), [tuple(e) for e in dual_edges], len(CELL_PALETTE))]
    pieces, _ = split_cells(points, view.triangles, label, distance_score(matrix))
    fig = new_figure(7.6, 6.0)
    ax = fig.add_axes([0, 0, 1, 0.93])
    view.draw(ax, colour[np.maximum(label[view.triangles[:, 0]], 0)], coloured_pieces(pieces, colour))
    segments = np.concatenate([np.stack([curve_points[c[:-1]], curve_points[c[1:]]], axis=1) for c in curves])
    view.lines(ax, segments, colors="black", linewidths=1.4)
    # each dual edge drawn as the geodesic between its two sources, which crosses their common bisector
    for e in dual_edges:
        a, b = (sources[i] for i in e)  # the dual graph's vertices are the sources, in order
        path_file = tool.file("elephant_dual_%d_%d.txt" % (a, b))
        tool("path", mesh, "--source", a, "--target", b, "--output", path_file)
        view.polyline(ax, read_points_txt(path_file), colors="white", linewidths=1.6, linestyles=(0, (3, 1.5)))
    view.dots(ax, points[sources], s=44, color="#e31a1c", edgecolors="white", linewidths=1.0, zorder=6)
    save(fig, out / "voronoi.png",
         "Geodesic Voronoi diagram of %d sources (red) on elephant.off: cells, bisectors (black)\n"
         "and the dual graph, each edge drawn as the geodesic between its two sources (white)" % len(sources))


def fig_sampling(tool, out, work, args):
    mesh = cgal_mesh("fandisk.off", args.cgal_data, work)
    points, triangles = read_off(mesh)
    count = 50
    samples_file, cells = tool.file("fandisk_samples.txt"), tool.file("fandisk_cells.ply")
    tool("sample", mesh, "--count", count, "--output", samples_file, "--labels", cells)
    rows = np.loadtxt(samples_file, ndmin=2)
    samples = rows[:, 0].astype(int)
    label = read_ply(cells)[0]["source"].astype(int)
    matrix_file = tool.file("fandisk_samples.npy")
    tool("matrix", mesh, "--source", ",".join(map(str, samples)), "--output", matrix_file)
    matrix = np.load(matrix_file)
    colour = CELL_PALETTE[greedy_colours(len(samples), label_edges(triangles, label), len(CELL_PALETTE))]
    fig = new_figure(8.0, 4.3)
    cameras = [Camera(up=(0, 1, 0), front=(0, 0, 1), azim=125, elev=25, light=(-0.5, 0.6)),
               Camera(up=(0, 1, 0), front=(0, 0, 1), azim=305, elev=25, light=(-0.5, 0.6))]
    for k, camera in enumerate(cameras):
        view = View(points, triangles, camera, ambient=0.5)
        pieces, boundary = split_cells(points, view.triangles, label, distance_score(matrix))
        ax = fig.add_axes([0.5 * k, 0, 0.5, 0.9])
        view.draw(ax, colour[np.maximum(label[view.triangles[:, 0]], 0)], coloured_pieces(pieces, colour))
        view.lines(ax, boundary, colors="#303030", linewidths=0.6)
        view.dots(ax, points[samples[1:]], s=20, color="black", edgecolors="white", linewidths=0.6)
        view.dots(ax, points[samples[:1]], s=90, color="#e31a1c", edgecolors="white", linewidths=0.8, marker="*")
    save(fig, out / "sampling.png",
         "%d farthest-point samples on fandisk.off (the first: red star) and their cells, two opposite views;\n"
         "every vertex is within %.3g of a sample (%.1f %% of the bounding box's diagonal)"
         % (count, rows[-1, 1], 100 * rows[-1, 1] / np.linalg.norm(points.max(axis=0) - points.min(axis=0))))


def fig_patterns(tool, out, work, args):
    sys.path.insert(0, str(REPO / "bench"))
    from plot_patterns import golf_ball  # the golf ball of doc/images/patterns_golf.png and the tests

    count, angle, depth = 40, 0.24, 0.3
    points, triangles, centres = golf_ball(32, count, angle, depth)
    points, triangles = np.array(points), np.array(triangles, dtype=np.int64)
    mesh = tool.file("golf.off")
    write_off(mesh, points, triangles)
    marked = nearest_vertex(points, np.array(centres[5]) * (1 - depth * angle))  # the bottom of dimple 5
    found_file, labels_file = tool.file("golf_patterns.json"), tool.file("golf_instances.ply")
    tool("patterns", mesh, "--patch-center", marked, "--patch-radius", angle, "--output", found_file,
         "--labels", labels_file)
    found = json.load(open(found_file))
    instance = read_ply(labels_file)[0]["instance"].astype(int)
    # the view: the marked dimple in front, below the middle of the picture; a light from the side
    # so that the dimples show
    c = unit(found["instances"][0]["center"])
    up = np.array([0.0, 0.0, 1.0])
    front = unit(c - np.dot(c, up) * up)
    view = View(points, triangles, Camera(up=up, front=front, azim=0, elev=math.degrees(math.asin(c[2])) + 25,
                                          light=(-0.9, 0.8)), ambient=0.4)
    edges = [tuple(e) for e in found["arrangement"]["edges"]]
    n = len(found["instances"])
    colour = np.vstack([CELL_PALETTE[greedy_colours(n, edges, len(CELL_PALETTE))], [[0.86, 0.86, 0.86]]])
    colour[0] = (0.89, 0.1, 0.11)  # the marked one
    # outside every instance: the last colour; faces cut half way along their edges between instances
    cell = np.where(instance >= 0, instance, n)
    pieces, _ = split_cells(points, view.triangles, cell,
                            lambda vertices, cells: (cell[vertices][:, None] == cells[None, :]).astype(float))
    fig = new_figure(6.4, 6.0)
    ax = fig.add_axes([0, 0, 1, 0.92])
    view.draw(ax, colour[cell[view.triangles[:, 0]]], coloured_pieces(pieces, colour))
    centre_of = [unit(i["center"]) for i in found["instances"]]
    facing = [float(np.dot(p, view.camera.eye)) > 0.15 for p in centre_of]  # not along the silhouette
    arcs = []
    for a, b in edges:
        if facing[a] and facing[b]:
            t = np.linspace(0, 1, 24)[:, None]
            arc = unit(centre_of[a] * (1 - t) + centre_of[b] * t) * 1.004  # on the sphere the dimples are cut in
            arcs.append(np.stack([arc[:-1], arc[1:]], axis=1))
    view.lines(ax, np.concatenate(arcs), colors="black", linewidths=1.2)
    view.dots(ax, np.array([p * 1.004 for p, f in zip(centre_of, facing) if f]), s=16, color="black")
    save(fig, out / "patterns.png",
         "Repetitive patterns: %d of the golf ball's %d dimples found from one marked (red),\n"
         "each instance in its colour; the arrangement (neighbouring instances) in black" % (n, count))


# ---------------------------------------------------------------------------------------------
# The charts

def fig_avtp_error_lambda(tool, out, work, args):
    source = REPO / "bench" / "results" / "lambda_curve.csv"
    rows = [r for r in csv.DictReader(open(source, newline="")) if r.get("status", "ok") == "ok"]
    meshes = list(dict.fromkeys(r["mesh"] for r in rows))
    fig, (ax_err, ax_time) = plt.subplots(1, 2, figsize=(8.0, 3.5), dpi=DPI)
    for k, mesh in enumerate(meshes):
        rs = sorted((r for r in rows if r["mesh"] == mesh), key=lambda r: float(r["lambda"]))
        lam = np.array([float(r["lambda"]) for r in rs])
        mean = np.array([float(r["mean_rel_error_percent"]) for r in rs])
        worst = np.array([float(r["max_rel_error_percent"]) for r in rs])
        seconds = np.array([float(r["seconds_total"]) for r in rs])
        name = "%s, %s vertices" % (mesh, "{:,}".format(int(rs[0]["vertices"])))
        colour = "C%d" % k
        ok = mean > 0
        ax_err.plot(lam[ok], mean[ok], "o-", color=colour, label="mean (%s)" % name)
        ax_err.plot(lam[worst > 0], worst[worst > 0], "s--", color=colour, alpha=0.5, markersize=4, label="max (same runs)")
        ax_time.plot(lam, seconds, "o-", color=colour, label="AVTP")
        vtp = float(rs[0]["vtp_seconds_total"])
        ax_time.axhline(vtp, color=colour, linestyle="--", linewidth=1.2, label="VTP (exact): %.3g s" % vtp)
        default = lam == 8
        ax_err.plot(lam[default], mean[default], "o", markersize=11, markerfacecolor="none", color="black")
        ax_time.plot(lam[default], seconds[default], "o", markersize=11, markerfacecolor="none", color="black",
                     label="λ = 8, the default")
    ticks = sorted({float(r["lambda"]) for r in rows})
    sys.path.insert(0, str(REPO / "bench"))
    from plot_lambda_curve import lambda_axes  # the axes of bench/results/lambda_curve.png
    for ax in (ax_err, ax_time):
        lambda_axes(ax, ticks, "λ (smaller: faster, coarser)")
        ax.tick_params(labelsize=8)
        ax.legend(fontsize=7, loc="upper right" if ax is ax_err else "lower right")
        ax.yaxis.set_major_formatter(matplotlib.ticker.FuncFormatter(lambda y, _: "%g" % y))
        ax.yaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
    fig.canvas.draw()  # the limits, for ticks at the powers of 2 between them
    low, high = ax_time.get_ylim()
    ax_time.set_yticks([2.0 ** k for k in range(math.ceil(math.log2(low)), math.floor(math.log2(high)) + 1)])
    ax_err.set_ylabel("relative error against VTP (%)")
    ax_err.set_title("AVTP's error", fontsize=10)
    ax_time.set_ylabel("time, one source (s)")
    ax_time.set_title("AVTP's time (setup + propagation)", fontsize=10)
    fig.tight_layout()
    save(fig, out / "avtp_error_lambda.png")


def read_benchmark(path):
    """{'meshes': [(name, vertices)], 'methods': [...], 'seconds': {(mesh, method): float or None},
    'caption': lines} from doc/figures/benchmark.csv ('#' lines are comments, those that start with
    '# caption:' printed under the chart; an empty cell or 'skip': not measured)."""
    with open(path, newline="") as f:
        rows = list(csv.reader(line for line in f if line.strip() and not line.startswith("#")))
    head, body = rows[0], rows[1:]
    methods = head[2:]
    with open(path) as f:
        caption = [line.split(":", 1)[1].strip() for line in f if line.startswith("# caption:")]
    result = {"meshes": [], "methods": methods, "seconds": {}, "caption": caption}
    for r in body:
        result["meshes"].append((r[0], int(r[1])))
        for method, cell in zip(methods, r[2:]):
            cell = cell.strip()
            result["seconds"][(r[0], method)] = float(cell) if cell not in ("", "skip") else None
    return result


def fig_benchmark(tool, out, work, args):
    data = read_benchmark(args.benchmark)
    shown = [m for m in ("VTP", "PVTP T=2", "AVTP λ=8", "SMSP", "heat (direct)") if m in data["methods"]]
    colours = {"VTP": "#1f77b4", "PVTP T=2": "#17becf", "AVTP λ=8": "#2ca02c", "SMSP": "#d62728",
               "heat (direct)": "#ff7f0e"}
    names = {"VTP": "VTP (exact)", "PVTP T=2": "PVTP, 2 threads (exact)", "AVTP λ=8": "AVTP, λ = 8",
             "SMSP": "CGAL Surface_mesh_shortest_path (exact)", "heat (direct)": "CGAL heat method (direct)"}
    meshes = data["meshes"]
    fig, ax = plt.subplots(figsize=(8.0, 4.6), dpi=DPI)
    width = 0.8 / len(shown)
    low = min(v for v in data["seconds"].values() if v)
    drawn = set()
    for i, (mesh, _) in enumerate(meshes):
        # the methods measured on this mesh, side by side around its tick
        here = [m for m in shown if data["seconds"].get((mesh, m))]
        for j, method in enumerate(here):
            ax.bar(i + (j - (len(here) - 1) / 2) * width, data["seconds"][(mesh, method)], width,
                   color=colours[method], label=None if method in drawn else names[method])
            drawn.add(method)
    ax.set_yscale("log")
    ax.set_ylim(low * 0.5, None)
    ax.yaxis.set_major_formatter(matplotlib.ticker.FuncFormatter(lambda y, _: "%g" % y))
    ax.set_xticks(np.arange(len(meshes)))
    ax.set_xticklabels(["%s\n%s" % (m, "{:,}".format(v)) for m, v in meshes], fontsize=7)
    ax.set_ylabel("seconds, all distances from one vertex")
    ax.grid(True, axis="y", which="major", alpha=0.3)
    ax.tick_params(axis="y", labelsize=8)
    handles, labels = ax.get_legend_handles_labels()
    order = [labels.index(names[m]) for m in shown if names[m] in labels]
    ax.legend([handles[k] for k in order], [labels[k] for k in order], fontsize=7, loc="upper left", ncol=2)
    ax.set_title("Time to every vertex's distance from vertex 0 (mesh, vertices; log scale)", fontsize=10)
    fig.tight_layout(rect=(0, 0.07, 1, 1))
    fig.text(0.01, 0.01, "\n".join(data["caption"]), fontsize=6.5, va="bottom", color="#404040")
    save(fig, out / "benchmark.png")


# ---------------------------------------------------------------------------------------------

def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter,
                                     epilog=__doc__.split("\n\n", 1)[1])
    parser.add_argument("--tool", default=str(REPO / "build" / "src" / "geodesic"),
                        help="the geodesic tool (default: %(default)s)")
    parser.add_argument("--out", default=str(REPO / "doc" / "figures"), help="the folder of the PNGs (default: %(default)s)")
    parser.add_argument("--only", nargs="+", choices=FIGURES, help="these figures only")
    parser.add_argument("--cgal-data", default="/usr/share/doc/libcgal-demo/data.tar.gz",
                        help="CGAL's demo data set, where armadillo.off and fandisk.off are (default: %(default)s)")
    parser.add_argument("--benchmark", default=str(REPO / "doc" / "figures" / "benchmark.csv"),
                        help="the times of benchmark.png (default: %(default)s)")
    parser.add_argument("--keep", metavar="DIR", help="write the tool's outputs into DIR and keep them")
    args = parser.parse_args()
    chosen = args.only or FIGURES
    needs_tool = [f for f in chosen if f not in ("avtp_error_lambda", "benchmark")]
    if needs_tool and not (os.path.isfile(args.tool) and os.access(args.tool, os.X_OK)):
        parser.error("no geodesic tool at %s (build it, or pass --tool)" % args.tool)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory(prefix="geodesic_figures_") as tmp:
        work = Path(args.keep) if args.keep else Path(tmp)
        work.mkdir(parents=True, exist_ok=True)
        tool = Tool(os.path.abspath(args.tool), work)
        for name in FIGURES:
            if name in chosen:
                start = time.time()
                print("%s:" % name, flush=True)
                globals()["fig_" + name](tool, out, work, args)
                print("  %.1f s" % (time.time() - start), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
