#!/usr/bin/env python3
"""Regenerate the meshed_arm robot package: link meshes, URDFs, SRDF, package.xml and a table mesh.

Run with `python3 make_assets.py` (standard library and numpy only). Every file is written next to this script and
is deterministic: there is no randomness, vertices are rounded to micrometres, and the COLLADA file carries a fixed
date. `check_assets.py` verifies the output (closed, outward-oriented meshes, well-formed XML, the hand-made
collision primitives covering the meshes).

How a link mesh is made: each link is a smooth union of a few primitives (rounded cylinders, rounded boxes, tapered
rounded boxes) described by a signed distance function. The surface is found by casting rays outward from a
skeleton segment inside the link (perpendicular rays from points along the segment, hemispherical fans at its ends)
and bisecting for the boundary. The mesh therefore has the connectivity of a capsule surface: one closed genus-0
shell, consistently oriented, never self-intersecting. The shapes are designed to be star-shaped with respect to
their skeleton, so the rays see all of the link.
"""

import math
import os
import struct

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
MESH_DIR = os.path.join(HERE, "meshes")
PACKAGE = "meshed_arm"
FILLET = 0.006  # blend radius of smooth unions between a link's parts [m]

# ----------------------------------------------------------------------------------------------------------------
# Signed distance functions (points as an (N, 3) array). Where a function is not an exact distance its sign is still
# exact, which is all the surface needs; the blends only use the magnitude near the surface.


def _norm(v):
    return np.sqrt(np.sum(v * v, axis=1))


def sd_rounded_box(center, half, rounding):
    c = np.asarray(center, float)
    h = np.asarray(half, float) - rounding

    def f(p):
        q = np.abs(p - c) - h
        return _norm(np.maximum(q, 0.0)) + np.minimum(q.max(axis=1), 0.0) - rounding

    return f


def sd_rounded_cylinder(a, b, radius, rounding):
    """Cylinder from a to b with edges rounded by `rounding` (its outer size is exactly radius and |b - a|)."""
    a = np.asarray(a, float)
    b = np.asarray(b, float)
    length = np.linalg.norm(b - a)
    axis = (b - a) / length
    half = 0.5 * length - rounding
    mid = 0.5 * (a + b)
    r = radius - rounding

    def f(p):
        d = p - mid
        h = d @ axis
        radial = _norm(d - h[:, None] * axis)
        q = np.stack([radial - r, np.abs(h) - half], axis=1)
        return _norm(np.maximum(q, 0.0)) + np.minimum(q.max(axis=1), 0.0) - rounding

    return f


def sd_tapered_box(z0, z1, half_x0, half_x1, half_y, center_xy, rounding):
    """Box along z from z0 to z1 whose half width in x goes linearly from half_x0 to half_x1 (rounded section)."""
    cx, cy = center_xy

    def f(p):
        t = np.clip((p[:, 2] - z0) / (z1 - z0), 0.0, 1.0)
        hx = half_x0 + (half_x1 - half_x0) * t - rounding
        hy = half_y - rounding
        qx = np.abs(p[:, 0] - cx) - hx
        qy = np.abs(p[:, 1] - cy) - hy
        q2 = np.stack([qx, qy], axis=1)
        section = _norm(np.maximum(q2, 0.0)) + np.minimum(q2.max(axis=1), 0.0) - rounding
        along = np.abs(p[:, 2] - 0.5 * (z0 + z1)) - 0.5 * (z1 - z0)
        q = np.stack([section, along], axis=1)
        return _norm(np.maximum(q, 0.0)) + np.minimum(q.max(axis=1), 0.0)

    return f


def sd_tapered_cylinder(x0, x1, r0, r1, rounding):
    """Round rod along x from x0 to x1 whose radius goes linearly from r0 to r1, end edges rounded."""

    def f(p):
        t = np.clip((p[:, 0] - x0) / (x1 - x0), 0.0, 1.0)
        r = r0 + (r1 - r0) * t - rounding
        radial = np.sqrt(p[:, 1] ** 2 + p[:, 2] ** 2) - r
        along = np.abs(p[:, 0] - 0.5 * (x0 + x1)) - (0.5 * (x1 - x0) - rounding)
        q = np.stack([radial, along], axis=1)
        return _norm(np.maximum(q, 0.0)) + np.minimum(q.max(axis=1), 0.0) - rounding

    return f


def smooth_union(*parts, k=FILLET):
    def f(p):
        d = parts[0](p)
        for g in parts[1:]:
            e = g(p)
            h = np.clip(0.5 + 0.5 * (e - d) / k, 0.0, 1.0)
            d = e * (1.0 - h) + d * h - k * h * (1.0 - h)
        return d

    return f


# ----------------------------------------------------------------------------------------------------------------
# Meshing by rays from a skeleton segment


def _ray_cast(sdf, origins, dirs, t_max=0.6, step=0.0005):
    ts = np.arange(0.0, t_max + step, step)
    pts = origins[:, None, :] + ts[None, :, None] * dirs[:, None, :]
    vals = sdf(pts.reshape(-1, 3)).reshape(len(origins), len(ts))
    if not (vals[:, 0] < 0.0).all():
        raise RuntimeError("a skeleton point is not inside its link")
    outside = vals > 0.0
    if not outside.any(axis=1).all():
        raise RuntimeError("a ray did not leave its link within t_max")
    k = outside.argmax(axis=1)
    lo = ts[k - 1].copy()
    hi = ts[k].copy()
    for _ in range(48):
        mid = 0.5 * (lo + hi)
        inside = sdf(origins + mid[:, None] * dirs) <= 0.0
        lo = np.where(inside, mid, lo)
        hi = np.where(inside, hi, mid)
    return origins + (0.5 * (lo + hi))[:, None] * dirs


def skeleton_mesh(sdf, p0, p1, ref, n_phi=32, stations=12, n_cap=6, cap_power=(1, 1)):
    """Closed mesh of the region sdf <= 0 seen from the segment p0-p1 (see the module comment).

    ref: a direction not parallel to the segment; the first ray of every ring points along its perpendicular part.
    stations: how many rings of perpendicular rays, evenly spaced, or their distances from p0.
    cap_power: how the latitudes of the end fans are spaced at (p0, p1): 1 evenly (for a rounded end), 2 closer
    to the equator (for a flat end face just beyond the segment's end, so that its rim is sampled).
    Returns (vertices (V, 3), triangles (T, 3) int), outward (counter-clockwise seen from outside).
    """
    p0 = np.asarray(p0, float)
    p1 = np.asarray(p1, float)
    a = (p1 - p0) / np.linalg.norm(p1 - p0)
    u = np.asarray(ref, float) - (np.asarray(ref, float) @ a) * a
    u /= np.linalg.norm(u)
    v = np.cross(a, u)  # (u, v, a) right-handed
    phi = 2.0 * np.pi * np.arange(n_phi) / n_phi
    ring_dirs = np.cos(phi)[:, None] * u + np.sin(phi)[:, None] * v
    length = np.linalg.norm(p1 - p0)
    if np.isscalar(stations):
        stations = np.linspace(0.0, 1.0, int(stations))
    else:  # distances from p0 along the segment, placed at the link's features
        stations = np.asarray(stations, float) / length
    if not (np.diff(stations) > 0).all() or abs(stations[0]) > 1e-9 or abs(stations[-1] - 1.0) > 1e-9:
        raise ValueError("stations must increase from p0 to p1")
    lat0 = 0.5 * np.pi * (np.arange(1, n_cap) / n_cap) ** cap_power[0]
    lat1 = 0.5 * np.pi * (np.arange(1, n_cap) / n_cap) ** cap_power[1]

    origins, dirs = [], []

    def add_ring(origin, d):
        origins.append(np.repeat(origin[None, :], n_phi, axis=0))
        dirs.append(d)

    # rings ordered from the p0 pole to the p1 pole
    for t in lat0[::-1]:
        add_ring(p0, np.cos(t) * ring_dirs - np.sin(t) * a)
    for s in stations:
        add_ring(p0 + s * (p1 - p0), ring_dirs)
    for t in lat1:
        add_ring(p1, np.cos(t) * ring_dirs + np.sin(t) * a)
    n_rings = len(origins)
    origins = np.concatenate(origins + [p0[None, :], p1[None, :]])
    dirs = np.concatenate(dirs + [-a[None, :], a[None, :]])
    verts = _ray_cast(sdf, origins, dirs)
    pole0 = n_rings * n_phi
    pole1 = pole0 + 1

    tris = []
    for j in range(n_phi):
        jn = (j + 1) % n_phi
        tris.append((pole0, jn, j))
        for i in range(n_rings - 1):
            a0, b0 = i * n_phi + j, i * n_phi + jn
            a1, b1 = (i + 1) * n_phi + j, (i + 1) * n_phi + jn
            tris.append((a0, b0, b1))
            tris.append((a0, b1, a1))
        last = (n_rings - 1) * n_phi
        tris.append((last + j, last + jn, pole1))
    return verts, np.array(tris, dtype=np.int64)


def box_mesh(lo, hi):
    lo = np.asarray(lo, float)
    hi = np.asarray(hi, float)
    verts = np.array([[hi[0] if i & 1 else lo[0], hi[1] if i & 2 else lo[1], hi[2] if i & 4 else lo[2]]
                      for i in range(8)])
    quads = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
    tris = []
    for q in quads:
        tris.append((q[0], q[1], q[2]))
        tris.append((q[0], q[2], q[3]))
    return verts, np.array(tris, dtype=np.int64)


def table_mesh(size=(1.2, 0.8), top_height=0.4, top_thickness=0.04, leg=0.05, leg_inset=0.05):
    """One closed genus-0 shell: the table top with four legs joined to its underside (no overlapping shells).

    The top is gridded at the legs' edges on every face so that there are no T-junctions; the underside has a square
    hole under each leg, and the leg's four sides and foot close it.
    """
    hx, hy = 0.5 * size[0], 0.5 * size[1]
    cx, cy = hx - leg_inset, hy - leg_inset
    xs = [-hx, -cx - leg / 2, -cx + leg / 2, cx - leg / 2, cx + leg / 2, hx]
    ys = [-hy, -cy - leg / 2, -cy + leg / 2, cy - leg / 2, cy + leg / 2, hy]
    z0, z1 = top_height - top_thickness, top_height
    index = {}
    verts = []

    def vid(p):
        key = tuple(round(c, 9) for c in p)
        if key not in index:
            index[key] = len(verts)
            verts.append(key)
        return index[key]

    tris = []

    def quad(p, q, r, s, outward):
        ids = [vid(x) for x in (p, q, r, s)]
        pts = np.array([verts[i] for i in ids])
        n = np.cross(pts[1] - pts[0], pts[2] - pts[0])
        if n @ np.asarray(outward, float) < 0:
            ids = ids[::-1]
        tris.append((ids[0], ids[1], ids[2]))
        tris.append((ids[0], ids[2], ids[3]))

    holes = {(1, 1), (1, 3), (3, 1), (3, 3)}
    for i in range(5):
        for j in range(5):
            x0, x1, y0, y1 = xs[i], xs[i + 1], ys[j], ys[j + 1]
            quad((x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1), (0, 0, 1))
            if (i, j) not in holes:
                quad((x0, y0, z0), (x1, y0, z0), (x1, y1, z0), (x0, y1, z0), (0, 0, -1))
    for k in range(5):
        y0, y1 = ys[k], ys[k + 1]
        quad((-hx, y0, z0), (-hx, y1, z0), (-hx, y1, z1), (-hx, y0, z1), (-1, 0, 0))
        quad((hx, y0, z0), (hx, y1, z0), (hx, y1, z1), (hx, y0, z1), (1, 0, 0))
        x0, x1 = xs[k], xs[k + 1]
        quad((x0, -hy, z0), (x1, -hy, z0), (x1, -hy, z1), (x0, -hy, z1), (0, -1, 0))
        quad((x0, hy, z0), (x1, hy, z0), (x1, hy, z1), (x0, hy, z1), (0, 1, 0))
    for i, j in sorted(holes):
        x0, x1, y0, y1 = xs[i], xs[i + 1], ys[j], ys[j + 1]
        quad((x0, y0, 0), (x0, y1, 0), (x0, y1, z0), (x0, y0, z0), (-1, 0, 0))
        quad((x1, y0, 0), (x1, y1, 0), (x1, y1, z0), (x1, y0, z0), (1, 0, 0))
        quad((x0, y0, 0), (x1, y0, 0), (x1, y0, z0), (x0, y0, z0), (0, -1, 0))
        quad((x0, y1, 0), (x1, y1, 0), (x1, y1, z0), (x0, y1, z0), (0, 1, 0))
        quad((x0, y0, 0), (x1, y0, 0), (x1, y1, 0), (x0, y1, 0), (0, 0, -1))
    return np.array(verts, float), np.array(tris, dtype=np.int64)


# ----------------------------------------------------------------------------------------------------------------
# The robot. Frames: every joint frame has the identity rotation at zero configuration, so a link's frame is the
# sum of the joint offsets above it. Zero configuration: upper arm vertical, forearm horizontal along +x.

JOINTS = [
    # name, type, parent, child, origin xyz, axis, (lower, upper, velocity, effort) or None
    ("joint1", "revolute", "base_link", "link1", (0.0, 0.0, 0.10), (0, 0, 1), (-2.9, 2.9, 2.5, 60.0)),
    ("joint2", "revolute", "link1", "link2", (0.0, 0.0, 0.19), (0, 1, 0), (-2.0, 2.0, 2.5, 60.0)),
    ("joint3", "revolute", "link2", "link3", (0.0, 0.0, 0.35), (0, 1, 0), (-2.0, 2.0, 2.5, 30.0)),
    ("joint4", "revolute", "link3", "link4", (0.07, 0.0, 0.0), (1, 0, 0), (-2.9, 2.9, 3.0, 10.0)),
    ("joint5", "revolute", "link4", "link5", (0.23, 0.0, 0.0), (0, 1, 0), (-2.0, 2.0, 3.0, 10.0)),
    ("joint6", "revolute", "link5", "link6", (0.05, 0.0, 0.0), (1, 0, 0), (-2.9, 2.9, 3.0, 5.0)),
    ("hand_joint", "fixed", "link6", "hand", (0.04, 0.0, 0.0), None, None),
    ("finger_left_joint", "prismatic", "hand", "finger_left", (0.05, 0.012, 0.0), (0, 1, 0), (0.0, 0.04, 0.2, 20.0)),
    ("finger_right_joint", "prismatic", "hand", "finger_right", (0.05, -0.012, 0.0), (0, -1, 0),
     (0.0, 0.04, 0.2, 20.0)),
]
MIMIC = {"finger_right_joint": ("finger_left_joint", 1.0, 0.0)}
LINK_ORDER = ["base_link", "link1", "link2", "link3", "link4", "link5", "link6", "hand", "finger_left",
              "finger_right"]
MASS = {"base_link": 4.0, "link1": 3.0, "link2": 2.5, "link3": 1.5, "link4": 1.2, "link5": 0.6, "link6": 0.3,
        "hand": 0.4, "finger_left": 0.03, "finger_right": 0.03}
# mesh file of each link, relative to the package root; base_link is referenced by a plain relative path
MESH_FILE = {name: "meshes/%s.stl" % name for name in LINK_ORDER}
MESH_FILE["link5"] = "meshes/link5.obj"
MESH_FILE["link6"] = "meshes/link6.dae"
RELATIVE_PATH_LINKS = {"base_link"}
MATERIAL = {name: "orange" for name in LINK_ORDER}
MATERIAL.update({"base_link": "dark_grey", "link4": "orange", "hand": "dark_grey", "finger_left": "light_grey",
                 "finger_right": "light_grey", "link6": "dark_grey"})

X, Y, Z = (1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0)


def link_geometry():
    """Per link: (signed distance function or None, mesh builder arguments, hand-made collision primitives).

    Primitives: ("cylinder", radius, length, xyz, rpy) with the URDF cylinder along its frame's z, ("box", size, xyz),
    ("sphere", radius, xyz). They are drawn to enclose the link's parts as a careful person would by hand.
    """
    R90X = (-1.5707963267948966, 0.0, 0.0)  # URDF cylinder z -> link y
    R90Y = (0.0, 1.5707963267948966, 0.0)  # URDF cylinder z -> link x
    g = {}

    # base: a cylinder with a narrower collar on top and a cable connector at the back
    g["base_link"] = (
        smooth_union(sd_rounded_cylinder((0, 0, 0), (0, 0, 0.075), 0.12, 0.004),
                     sd_rounded_cylinder((0, 0, 0.06), (0, 0, 0.10), 0.10, 0.008),
                     sd_rounded_box((-0.11, 0.0, 0.04), (0.025, 0.03, 0.022), 0.004)),
        dict(p0=(0, 0, 0.001), p1=(0, 0, 0.099), ref=X, cap_power=(2, 2),
             stations=[0, 0.004, 0.011, 0.017, 0.023, 0.039, 0.055, 0.061, 0.067, 0.071, 0.074, 0.079, 0.087, 0.093, 0.098]),
        [("cylinder", 0.12, 0.10, (0, 0, 0.05), (0, 0, 0)),
         ("box", (0.045, 0.09, 0.06), (-0.1125, 0.0, 0.04))])

    # shoulder turret: column on the base, a neck, and the shoulder motor housing along y (the upper arm sits at +y
    # beside it)
    g["link1"] = (
        smooth_union(sd_rounded_cylinder((0, 0, 0.004), (0, 0, 0.115), 0.085, 0.008),
                     sd_rounded_box((0.0, -0.0025, 0.15), (0.05, 0.0525, 0.05), 0.008),
                     sd_rounded_cylinder((0, -0.06, 0.19), (0, 0.055, 0.19), 0.07, 0.008)),
        dict(p0=(0, 0, 0.005), p1=(0, 0, 0.19), ref=X, cap_power=(2, 1),
             stations=[0, 0.007, 0.025, 0.045, 0.065, 0.085, 0.095, 0.1, 0.105, 0.11, 0.115, 0.12, 0.13, 0.145, 0.16, 0.175, 0.185]),
        [("cylinder", 0.085, 0.118, (0, 0, 0.063), (0, 0, 0)),
         ("box", (0.12, 0.115, 0.085), (0.0, -0.0025, 0.1425)),
         ("cylinder", 0.07, 0.115, (0, -0.0025, 0.19), R90X)])

    # upper arm: shoulder hub, tapered beam, elbow hub, all at y = 0.06 .. 0.12
    g["link2"] = (
        smooth_union(sd_rounded_cylinder((0, 0.06, 0), (0, 0.12, 0), 0.065, 0.008),
                     sd_tapered_box(0.0, 0.35, 0.045, 0.035, 0.025, (0.0, 0.09), 0.01),
                     sd_rounded_cylinder((0, 0.06, 0.35), (0, 0.12, 0.35), 0.055, 0.008)),
        dict(p0=(0, 0.09, 0.0), p1=(0, 0.09, 0.35), ref=X, stations=18),
        [("cylinder", 0.065, 0.06, (0, 0.09, 0.0), R90X),
         ("box", (0.1, 0.06, 0.35), (0.0, 0.09, 0.175)),
         ("cylinder", 0.055, 0.06, (0, 0.09, 0.35), R90X)])

    # elbow: motor housing along y and the stub carrying the forearm roll
    g["link3"] = (
        smooth_union(sd_rounded_cylinder((0, -0.055, 0), (0, 0.055, 0), 0.06, 0.008),
                     sd_rounded_cylinder((0, 0, 0), (0.065, 0, 0), 0.05, 0.006)),
        dict(p0=(-0.01, 0, 0), p1=(0.064, 0, 0), ref=Z, cap_power=(1, 2),
             stations=10),
        [("cylinder", 0.06, 0.11, (0, 0, 0), R90X),
         ("cylinder", 0.058, 0.065, (0.0325, 0, 0), R90Y)])

    # forearm: roll flange, tapered tube, and a motor housing on top
    g["link4"] = (
        smooth_union(sd_rounded_cylinder((0.004, 0, 0), (0.03, 0, 0), 0.05, 0.006),
                     sd_tapered_cylinder(0.02, 0.185, 0.045, 0.038, 0.008),
                     sd_rounded_box((0.10, 0.0, 0.03), (0.045, 0.03, 0.028), 0.01)),
        dict(p0=(0.005, 0, 0), p1=(0.184, 0, 0), ref=Z, cap_power=(2, 2),
             stations=[0, 0.005, 0.013, 0.017, 0.025, 0.029, 0.04, 0.05, 0.055, 0.06, 0.075, 0.095, 0.115, 0.13, 0.135, 0.14, 0.15, 0.173, 0.179]),
        [("cylinder", 0.05, 0.181, (0.0945, 0, 0), R90Y),
         ("box", (0.1, 0.07, 0.04), (0.10, 0.0, 0.038))])

    # wrist (pitch): hub along y and a short round body along x
    g["link5"] = (
        smooth_union(sd_rounded_cylinder((0, -0.04, 0), (0, 0.04, 0), 0.04, 0.006),
                     sd_rounded_cylinder((0, 0, 0), (0.045, 0, 0), 0.035, 0.005)),
        dict(p0=(-0.01, 0, 0), p1=(0.044, 0, 0), ref=Z, cap_power=(1, 2),
             stations=10),
        [("cylinder", 0.041, 0.08, (0, 0, 0), R90X),
         ("cylinder", 0.04, 0.045, (0.0225, 0, 0), R90Y)])

    # wrist (roll) with the tool flange
    g["link6"] = (
        smooth_union(sd_rounded_cylinder((0.003, 0, 0), (0.03, 0, 0), 0.033, 0.004),
                     sd_rounded_cylinder((0.026, 0, 0), (0.038, 0, 0), 0.042, 0.003)),
        dict(p0=(0.004, 0, 0), p1=(0.0375, 0, 0), ref=Z, cap_power=(2, 2), n_cap=5,
             stations=[0, 0.004, 0.009, 0.014, 0.018, 0.021, 0.022, 0.023, 0.025, 0.028, 0.031, 0.0335]),
        [("cylinder", 0.042, 0.035, (0.0205, 0, 0), R90Y)])

    # gripper body: mount on the flange and the palm
    g["hand"] = (
        smooth_union(sd_rounded_cylinder((0.002, 0, 0), (0.016, 0, 0), 0.035, 0.003),
                     sd_rounded_box((0.031, 0.0, 0.0), (0.019, 0.05, 0.025), 0.006)),
        dict(p0=(0.003, 0, 0), p1=(0.049, 0, 0), ref=Z, cap_power=(2, 2), n_cap=5,
             stations=[0, 0.003, 0.007, 0.01, 0.013, 0.015, 0.019, 0.027, 0.035, 0.039, 0.043, 0.046]),
        [("cylinder", 0.038, 0.022, (0.013, 0, 0), R90Y),
         ("box", (0.042, 0.1, 0.052), (0.029, 0.0, 0.0))])

    for finger in ("finger_left", "finger_right"):
        g[finger] = (None, dict(lo=(0.001, -0.01, -0.01), hi=(0.061, 0.01, 0.01)),
                     [("box", (0.06, 0.02, 0.02), (0.031, 0.0, 0.0))])
    return g


# ----------------------------------------------------------------------------------------------------------------
# Writers


def _round(verts):
    out = np.round(np.asarray(verts, float), 6)
    out[out == 0.0] = 0.0  # no negative zeros
    return out


def _fmt(x):
    s = ("%.6f" % x).rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


def write_stl(path, verts, tris, name):
    v = verts.astype(np.float32)
    tri = v[tris]
    n = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0]).astype(np.float64)
    n /= np.linalg.norm(n, axis=1)[:, None]
    header = ("meshed_arm %s, binary STL in metres, written by make_assets.py" % name).encode("ascii")
    with open(path, "wb") as f:
        f.write(header.ljust(80, b" ")[:80])
        f.write(struct.pack("<I", len(tris)))
        rec = np.zeros(len(tris), dtype=[("n", "<f4", 3), ("v", "<f4", (3, 3)), ("attr", "<u2")])
        rec["n"] = n.astype(np.float32)
        rec["v"] = tri
        f.write(rec.tobytes())


def write_obj(path, verts, tris, name):
    lines = ["# meshed_arm %s, Wavefront OBJ in metres, written by make_assets.py" % name,
             "# %d vertices, %d triangles, counter-clockwise seen from outside" % (len(verts), len(tris)),
             "o %s" % name]
    lines += ["v %s %s %s" % tuple(_fmt(c) for c in p) for p in verts]
    lines += ["f %d %d %d" % tuple(int(i) + 1 for i in t) for t in tris]
    with open(path, "w", newline="\n") as f:
        f.write("\n".join(lines) + "\n")


def write_dae(path, verts, tris, name):
    pos = " ".join(_fmt(c) for c in verts.reshape(-1))
    idx = " ".join(str(int(i)) for i in tris.reshape(-1))
    text = f"""<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset>
    <contributor>
      <authoring_tool>ompl_parc demos/assets/meshed_arm/make_assets.py</authoring_tool>
    </contributor>
    <created>2024-01-01T00:00:00Z</created>
    <modified>2024-01-01T00:00:00Z</modified>
    <unit name="meter" meter="1"/>
    <up_axis>Z_UP</up_axis>
  </asset>
  <library_geometries>
    <geometry id="{name}-mesh" name="{name}">
      <mesh>
        <source id="{name}-mesh-positions">
          <float_array id="{name}-mesh-positions-array" count="{verts.size}">{pos}</float_array>
          <technique_common>
            <accessor source="#{name}-mesh-positions-array" count="{len(verts)}" stride="3">
              <param name="X" type="float"/>
              <param name="Y" type="float"/>
              <param name="Z" type="float"/>
            </accessor>
          </technique_common>
        </source>
        <vertices id="{name}-mesh-vertices">
          <input semantic="POSITION" source="#{name}-mesh-positions"/>
        </vertices>
        <triangles count="{len(tris)}">
          <input semantic="VERTEX" source="#{name}-mesh-vertices" offset="0"/>
          <p>{idx}</p>
        </triangles>
      </mesh>
    </geometry>
  </library_geometries>
  <library_visual_scenes>
    <visual_scene id="Scene" name="Scene">
      <node id="{name}" name="{name}" type="NODE">
        <instance_geometry url="#{name}-mesh" name="{name}"/>
      </node>
    </visual_scene>
  </library_visual_scenes>
  <scene>
    <instance_visual_scene url="#Scene"/>
  </scene>
</COLLADA>
"""
    with open(path, "w", newline="\n") as f:
        f.write(text)


def mass_properties(verts, tris, mass):
    """Centre of mass and inertia about it (link frame axes) of the closed mesh filled with uniform density."""
    a, b, c = verts[tris[:, 0]], verts[tris[:, 1]], verts[tris[:, 2]]
    vol6 = np.einsum("ij,ij->i", a, np.cross(b, c))
    volume = vol6.sum() / 6.0
    com = ((vol6[:, None] * (a + b + c)).sum(axis=0) / 24.0) / volume
    # second moments int x_i x_j dV over the tetrahedra (origin, a, b, c)
    s = np.zeros((3, 3))
    for i in range(3):
        for j in range(3):
            terms = (2 * (a[:, i] * a[:, j] + b[:, i] * b[:, j] + c[:, i] * c[:, j])
                     + a[:, i] * b[:, j] + a[:, j] * b[:, i] + a[:, i] * c[:, j] + a[:, j] * c[:, i]
                     + b[:, i] * c[:, j] + b[:, j] * c[:, i])
            s[i, j] = (vol6 * terms).sum() / 120.0
    density = mass / volume
    s *= density
    inertia_origin = np.trace(s) * np.eye(3) - s
    inertia = inertia_origin - mass * (com @ com * np.eye(3) - np.outer(com, com))
    return volume, com, inertia


def _vec(v):
    return " ".join(_fmt(float(c)) for c in v)


def _geometry_xml(prim):
    if prim[0] == "cylinder":
        _, r, length, xyz, rpy = prim
        return xyz, rpy, '<cylinder radius="%s" length="%s"/>' % (_fmt(r), _fmt(length))
    if prim[0] == "box":
        _, size, xyz = prim
        return xyz, (0, 0, 0), '<box size="%s"/>' % _vec(size)
    _, r, xyz = prim
    return xyz, (0, 0, 0), '<sphere radius="%s"/>' % _fmt(r)


def _sig(x):
    return "%.6g" % x


def urdf_text(inertials, collision_prims, description):
    out = ['<?xml version="1.0" encoding="utf-8"?>',
           "<!-- %s Generated by make_assets.py; edit that script, not this file. -->" % description,
           '<robot name="%s">' % PACKAGE,
           '  <material name="orange"><color rgba="0.95 0.45 0.1 1"/></material>',
           '  <material name="dark_grey"><color rgba="0.25 0.25 0.27 1"/></material>',
           '  <material name="light_grey"><color rgba="0.7 0.7 0.72 1"/></material>']
    for name in LINK_ORDER:
        mass, com, inertia = inertials[name]
        rel = MESH_FILE[name]
        uri = rel if name in RELATIVE_PATH_LINKS else "package://%s/%s" % (PACKAGE, rel)
        mesh = '<mesh filename="%s"/>' % uri
        out.append('  <link name="%s">' % name)
        out.append("    <inertial>")
        out.append('      <origin xyz="%s" rpy="0 0 0"/>' % _vec(com))
        out.append('      <mass value="%s"/>' % _fmt(mass))
        out.append('      <inertia ixx="%s" ixy="%s" ixz="%s" iyy="%s" iyz="%s" izz="%s"/>' % tuple(
            _sig(inertia[i, j]) if abs(inertia[i, j]) > 1e-12 else "0"
            for i, j in ((0, 0), (0, 1), (0, 2), (1, 1), (1, 2), (2, 2))))
        out.append("    </inertial>")
        out.append("    <visual>")
        out.append('      <origin xyz="0 0 0" rpy="0 0 0"/>')
        out.append("      <geometry>%s</geometry>" % mesh)
        out.append('      <material name="%s"/>' % MATERIAL[name])
        out.append("    </visual>")
        if collision_prims is None:
            out.append("    <collision>")
            out.append('      <origin xyz="0 0 0" rpy="0 0 0"/>')
            out.append("      <geometry>%s</geometry>" % mesh)
            out.append("    </collision>")
        else:
            for prim in collision_prims[name]:
                xyz, rpy, geom = _geometry_xml(prim)
                out.append("    <collision>")
                out.append('      <origin xyz="%s" rpy="%s"/>' % (_vec(xyz), _vec(rpy)))
                out.append("      <geometry>%s</geometry>" % geom)
                out.append("    </collision>")
        out.append("  </link>")
    for name, jtype, parent, child, xyz, axis, limit in JOINTS:
        out.append('  <joint name="%s" type="%s">' % (name, jtype))
        out.append('    <parent link="%s"/>' % parent)
        out.append('    <child link="%s"/>' % child)
        out.append('    <origin xyz="%s" rpy="0 0 0"/>' % _vec(xyz))
        if axis is not None:
            out.append('    <axis xyz="%s"/>' % _vec(axis))
        if limit is not None:
            lo, hi, vel, eff = limit
            out.append('    <limit lower="%s" upper="%s" velocity="%s" effort="%s"/>' % (
                _fmt(lo), _fmt(hi), _fmt(vel), _fmt(eff)))
        if name in MIMIC:
            m = MIMIC[name]
            out.append('    <mimic joint="%s" multiplier="%s" offset="%s"/>' % (m[0], _fmt(m[1]), _fmt(m[2])))
        out.append("  </joint>")
    out.append("</robot>")
    return "\n".join(out) + "\n"


def srdf_text():
    out = ['<?xml version="1.0" encoding="utf-8"?>',
           "<!-- Semantic description of meshed_arm. Generated by make_assets.py; edit that script. -->",
           '<robot name="%s">' % PACKAGE,
           '  <group name="arm">',
           '    <chain base_link="base_link" tip_link="hand"/>',
           "  </group>",
           '  <group name="arm_with_gripper">',
           '    <chain base_link="base_link" tip_link="finger_left"/>',
           "  </group>",
           '  <group name="gripper">',
           '    <link name="hand"/>',
           '    <link name="finger_left"/>',
           '    <link name="finger_right"/>',
           "  </group>"]
    for _, _, parent, child, _, _, _ in JOINTS:
        out.append('  <disable_collisions link1="%s" link2="%s" reason="Adjacent"/>' % (parent, child))
    out.append('  <disable_collisions link1="finger_left" link2="finger_right" reason="Never"/>')
    out.append("</robot>")
    return "\n".join(out) + "\n"


PACKAGE_XML = """<?xml version="1.0"?>
<?xml-model href="http://download.ros.org/schema/package_format2.xsd" schematypens="http://www.w3.org/2001/XMLSchema"?>
<package format="2">
  <name>meshed_arm</name>
  <version>0.1.0</version>
  <description>A small six-joint arm with a parallel gripper (meshes, URDF, SRDF), generated by make_assets.py for
    the ompl_parc tests and demos.</description>
  <maintainer email="ompl_parc@example.org">ompl_parc</maintainer>
  <license>BSD-3-Clause</license>
  <buildtool_depend>ament_cmake</buildtool_depend>
  <exec_depend>urdf</exec_depend>
  <export>
    <build_type>ament_cmake</build_type>
  </export>
</package>
"""


# ----------------------------------------------------------------------------------------------------------------


def capsule_prims(prims):
    """The hand-made capsule model: each primitive as the capsule a person would draw around it for a planner that
    checks capsules (ompl_parc reads a <cylinder> as the capsule of its axis and radius): a cylinder of radius r
    and length L becomes one of length L - 2r, so that its capsule spans L; a box the capsule along its longest
    side whose radius is its larger other half-side. Unlike the primitives, these do not all enclose the mesh."""
    out = []
    for prim in prims:
        if prim[0] == "cylinder":
            _, r, length, xyz, rpy = prim
            out.append(("cylinder", r, max(length - 2 * r, 0.002), xyz, rpy))
        elif prim[0] == "box":
            _, size, xyz = prim
            longest = int(np.argmax(size))
            r = max(size[k] for k in range(3) if k != longest) / 2
            rpy = [(0, math.pi / 2, 0), (-math.pi / 2, 0, 0), (0, 0, 0)][longest]
            out.append(("cylinder", r, max(size[longest] - 2 * r, 0.002), xyz, rpy))
        else:
            out.append(prim)
    return out


def zero_config_origins():
    origin = {"base_link": np.zeros(3)}
    for _, _, parent, child, xyz, _, _ in JOINTS:
        origin[child] = origin[parent] + np.asarray(xyz, float)
    return origin


def main():
    os.makedirs(MESH_DIR, exist_ok=True)
    geometry = link_geometry()
    meshes, inertials, prims = {}, {}, {}
    for name in LINK_ORDER:
        sdf, args, collision = geometry[name]
        if sdf is None:
            verts, tris = box_mesh(**args)
        else:
            verts, tris = skeleton_mesh(sdf, **args)
        verts = _round(verts)
        meshes[name] = (verts, tris)
        _, com, inertia = mass_properties(verts, tris, MASS[name])
        inertials[name] = (MASS[name], np.round(com, 6), inertia)
        prims[name] = collision
        rel = MESH_FILE[name]
        path = os.path.join(HERE, rel)
        if rel.endswith(".stl"):
            write_stl(path, verts, tris, name)
        elif rel.endswith(".obj"):
            write_obj(path, verts, tris, name)
            write_stl(path[:-4] + ".stl", verts, tris, name)  # the same mesh, for comparing loaders
        else:
            write_dae(path, verts, tris, name)
            write_stl(path[:-4] + ".stl", verts, tris, name)
    tverts, ttris = table_mesh()
    write_stl(os.path.join(MESH_DIR, "table.stl"), _round(tverts), ttris, "table")

    with open(os.path.join(HERE, "meshed_arm.urdf"), "w", newline="\n") as f:
        f.write(urdf_text(inertials, None, "meshed_arm: collision geometry is the link meshes."))
    with open(os.path.join(HERE, "meshed_arm_primitives.urdf"), "w", newline="\n") as f:
        f.write(urdf_text(inertials, prims, "meshed_arm with hand-made collision primitives (boxes, cylinders) "
                                           "enclosing each mesh; kinematics identical to meshed_arm.urdf."))
    capsules = {name: capsule_prims(p) for name, p in prims.items()}
    with open(os.path.join(HERE, "meshed_arm_capsules.urdf"), "w", newline="\n") as f:
        f.write(urdf_text(inertials, capsules, "meshed_arm with a hand-made capsule model (each <cylinder> read as "
                                              "the capsule of its axis); kinematics identical to meshed_arm.urdf."))
    with open(os.path.join(HERE, "meshed_arm.srdf"), "w", newline="\n") as f:
        f.write(srdf_text())
    with open(os.path.join(HERE, "package.xml"), "w", newline="\n") as f:
        f.write(PACKAGE_XML)

    # report: sizes, and clearance between links at zero configuration (by the links' distance functions)
    origin = zero_config_origins()
    print("%-13s %5s %5s  %-40s" % ("link", "verts", "tris", "bounding box [m]"))
    for name in LINK_ORDER:
        v, t = meshes[name]
        print("%-13s %5d %5d  %s .. %s" % (name, len(v), len(t), _vec(v.min(axis=0)), _vec(v.max(axis=0))))
    print("table         %5d %5d" % (len(tverts), len(ttris)))
    adjacent = {(p, c) for _, _, p, c, _, _, _ in JOINTS}
    for a in LINK_ORDER:
        for b in LINK_ORDER:
            sdf_a = geometry[a][0]
            if sdf_a is None or a == b:
                continue
            pts = meshes[b][0] + origin[b] - origin[a]
            depth = -sdf_a(pts).min()
            if depth > -0.002:
                kind = "adjacent" if (a, b) in adjacent or (b, a) in adjacent else "NOT adjacent"
                print("zero configuration: %s vertices reach %.4f m into %s (%s)" % (b, depth, a, kind))


if __name__ == "__main__":
    main()
