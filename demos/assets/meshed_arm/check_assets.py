#!/usr/bin/env python3
"""Check the files make_assets.py wrote, reading them back from disk (standard library and numpy only).

Meshes (STL, OBJ, COLLADA): every edge shared by exactly two triangles with opposite orientation, no degenerate
triangle, positive volume, one shell per mesh with Euler characteristic 2, at most 2000 triangles, the STL normals
agreeing with the vertex order. URDFs and SRDF: well formed, every mesh reference resolving (package:// against this
folder, a plain path against the URDF's folder), the two URDFs with identical joints, the hand-made collision
primitives covering every mesh vertex. Runs `check_urdf` on both URDFs where it is installed. Exits 1 on a failure.
"""

import os
import shutil
import struct
import subprocess
import sys
import xml.dom.minidom
import xml.etree.ElementTree as ET

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
FAILURES = []


def fail(msg):
    FAILURES.append(msg)
    print("FAIL:", msg)


def read_stl(path):
    data = open(path, "rb").read()
    if data[:5] == b"solid":
        fail("%s: header starts with 'solid' (looks like ASCII STL)" % path)
    (n,) = struct.unpack("<I", data[80:84])
    if len(data) != 84 + 50 * n:
        fail("%s: %d bytes, expected %d for %d triangles" % (path, len(data), 84 + 50 * n, n))
    rec = np.frombuffer(data, dtype=[("n", "<f4", 3), ("v", "<f4", (3, 3)), ("attr", "<u2")], count=n, offset=84)
    corners = rec["v"].reshape(-1, 3).astype(np.float64)
    verts, inverse = np.unique(corners, axis=0, return_inverse=True)  # weld identical coordinates
    return verts, inverse.reshape(-1, 3), rec["n"].astype(np.float64)


def read_obj(path):
    verts, tris = [], []
    for line in open(path):
        f = line.split()
        if not f or f[0].startswith("#"):
            continue
        if f[0] == "v":
            verts.append([float(c) for c in f[1:4]])
        elif f[0] == "f":
            if len(f) != 4:
                fail("%s: a face that is not a triangle" % path)
            tris.append([int(c.split("/")[0]) - 1 for c in f[1:4]])
    return np.array(verts), np.array(tris), None


def read_dae(path):
    ns = {"c": "http://www.collada.org/2005/11/COLLADASchema"}
    root = ET.parse(path).getroot()
    if root.get("version") != "1.4.1":
        fail("%s: COLLADA version %s" % (path, root.get("version")))
    unit = root.find("c:asset/c:unit", ns)
    up = root.find("c:asset/c:up_axis", ns)
    if unit is None or float(unit.get("meter")) != 1.0 or up is None or up.text != "Z_UP":
        fail("%s: unit or up axis missing or not metres / Z_UP" % path)
    geoms = root.findall("c:library_geometries/c:geometry", ns)
    if len(geoms) != 1:
        fail("%s: %d geometries" % (path, len(geoms)))
    mesh = geoms[0].find("c:mesh", ns)
    arr = mesh.find("c:source/c:float_array", ns)
    verts = np.array(arr.text.split(), float).reshape(-1, 3)
    if int(arr.get("count")) != verts.size:
        fail("%s: float_array count" % path)
    tri = mesh.find("c:triangles", ns)
    tris = np.array(tri.find("c:p", ns).text.split(), int).reshape(-1, 3)
    if int(tri.get("count")) != len(tris):
        fail("%s: triangles count" % path)
    node = root.find("c:library_visual_scenes/c:visual_scene/c:node/c:instance_geometry", ns)
    if node is None or node.get("url") != "#" + geoms[0].get("id"):
        fail("%s: the visual scene does not instance the geometry" % path)
    if root.find("c:scene/c:instance_visual_scene", ns) is None:
        fail("%s: no <scene>" % path)
    return verts, tris, None


def read_mesh(path):
    ext = os.path.splitext(path)[1].lower()
    return {".stl": read_stl, ".obj": read_obj, ".dae": read_dae}[ext](path)


def check_mesh(path, max_tris=2000):
    verts, tris, normals = read_mesh(path)
    rel = os.path.relpath(path, HERE)
    a, b, c = verts[tris[:, 0]], verts[tris[:, 1]], verts[tris[:, 2]]
    cross = np.cross(b - a, c - a)
    area = 0.5 * np.linalg.norm(cross, axis=1)
    # closed and consistently oriented: each directed edge once, and its reverse once
    directed = np.concatenate([tris[:, [0, 1]], tris[:, [1, 2]], tris[:, [2, 0]]])
    keys = directed[:, 0] * len(verts) + directed[:, 1]
    rkeys = directed[:, 1] * len(verts) + directed[:, 0]
    uniq, counts = np.unique(keys, return_counts=True)
    if (counts != 1).any():
        fail("%s: %d directed edges used more than once" % (rel, int((counts != 1).sum())))
    if not np.isin(rkeys, uniq).all():
        fail("%s: %d edges without an oppositely oriented partner" % (rel, int((~np.isin(rkeys, uniq)).sum())))
    if (directed[:, 0] == directed[:, 1]).any() or area.min() < 1e-10:
        fail("%s: degenerate triangle (min area %.3g m^2)" % (rel, area.min()))
    volume = np.einsum("ij,ij->i", a, np.cross(b, c)).sum() / 6.0
    if volume <= 0:
        fail("%s: signed volume %.6g is not positive" % (rel, volume))
    # shells (connected components) and Euler characteristic
    parent = np.arange(len(verts))

    def find(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    for u, v in directed:
        ru, rv = find(u), find(v)
        if ru != rv:
            parent[ru] = rv
    used = np.unique(tris)
    shells = len({find(i) for i in used})
    euler = len(used) - len(uniq) // 2 + len(tris)
    if shells != 1 or euler != 2:
        fail("%s: %d shells, Euler characteristic %d (expected one sphere-like shell)" % (rel, shells, euler))
    if len(tris) > max_tris:
        fail("%s: %d triangles" % (rel, len(tris)))
    if normals is not None:
        unit = cross / np.linalg.norm(cross, axis=1)[:, None]
        if (np.einsum("ij,ij->i", unit, normals) < 0.99).any():
            fail("%s: stored normals disagree with the vertex order" % rel)
    e = np.stack([np.linalg.norm(b - a, axis=1), np.linalg.norm(c - b, axis=1), np.linalg.norm(a - c, axis=1)], 1)
    print("%-22s %5d tris %5d verts  volume %9.2f cm^3  min area %.1e m^2  min edge %.1e m  bbox %s .. %s" % (
        rel, len(tris), len(verts), volume * 1e6, area.min(), e.min(), np.round(verts.min(0), 4),
        np.round(verts.max(0), 4)))
    return verts, tris


def rpy_matrix(rpy):
    r, p, y = rpy
    rx = np.array([[1, 0, 0], [0, np.cos(r), -np.sin(r)], [0, np.sin(r), np.cos(r)]])
    ry = np.array([[np.cos(p), 0, np.sin(p)], [0, 1, 0], [-np.sin(p), 0, np.cos(p)]])
    rz = np.array([[np.cos(y), -np.sin(y), 0], [np.sin(y), np.cos(y), 0], [0, 0, 1]])
    return rz @ ry @ rx


def floats(text, default):
    return np.array([float(c) for c in text.split()]) if text else np.array(default, float)


def primitive_distance(points, collision):
    """Signed distance (approximate outside, exact sign) of link-frame points to one URDF collision primitive."""
    origin = collision.find("origin")
    xyz = floats(origin.get("xyz") if origin is not None else None, (0, 0, 0))
    rpy = floats(origin.get("rpy") if origin is not None else None, (0, 0, 0))
    local = (points - xyz) @ rpy_matrix(rpy)  # rows: R^T (p - xyz)
    geom = collision.find("geometry")[0]
    if geom.tag == "box":
        q = np.abs(local) - 0.5 * floats(geom.get("size"), None)
        return np.linalg.norm(np.maximum(q, 0), axis=1) + np.minimum(q.max(axis=1), 0)
    if geom.tag == "cylinder":
        r, h = float(geom.get("radius")), float(geom.get("length"))
        q = np.stack([np.hypot(local[:, 0], local[:, 1]) - r, np.abs(local[:, 2]) - 0.5 * h], 1)
        return np.linalg.norm(np.maximum(q, 0), axis=1) + np.minimum(q.max(axis=1), 0)
    if geom.tag == "sphere":
        return np.linalg.norm(local, axis=1) - float(geom.get("radius"))
    raise ValueError("unexpected collision geometry <%s>" % geom.tag)


def primitive_volume(collision):
    geom = collision.find("geometry")[0]
    if geom.tag == "box":
        return float(np.prod(floats(geom.get("size"), None)))
    if geom.tag == "cylinder":
        return np.pi * float(geom.get("radius")) ** 2 * float(geom.get("length"))
    return 4.0 / 3.0 * np.pi * float(geom.get("radius")) ** 3


def resolve(uri, urdf_dir):
    prefix = "package://meshed_arm/"
    if uri.startswith("package://"):
        if not uri.startswith(prefix):
            fail("unexpected package in %s" % uri)
        return os.path.join(HERE, uri[len(prefix):])
    return os.path.join(urdf_dir, uri)


def check_urdf_pair():
    meshed = os.path.join(HERE, "meshed_arm.urdf")
    capsules = os.path.join(HERE, "meshed_arm_primitives.urdf")
    for path in (meshed, capsules, os.path.join(HERE, "meshed_arm.srdf"), os.path.join(HERE, "package.xml")):
        xml.dom.minidom.parse(path)  # raises on malformed XML
    robot = ET.parse(meshed).getroot()
    robot_c = ET.parse(capsules).getroot()
    if robot.get("name") != "meshed_arm" or robot_c.get("name") != "meshed_arm":
        fail("robot name is not meshed_arm")
    joints = [ET.tostring(j) for j in robot.findall("joint")]
    if joints != [ET.tostring(j) for j in robot_c.findall("joint")]:
        fail("the two URDFs' joints differ")
    links = {l.get("name"): l for l in robot.findall("link")}
    links_c = {l.get("name"): l for l in robot_c.findall("link")}
    if set(links) != set(links_c):
        fail("the two URDFs' links differ")
    # tree: every joint's parent and child exist, every link but the root is a child once
    children = [j.find("child").get("link") for j in robot.findall("joint")]
    parents = [j.find("parent").get("link") for j in robot.findall("joint")]
    roots = set(links) - set(children)
    if roots != {"base_link"} or len(children) != len(set(children)) or not set(parents) <= set(links):
        fail("the URDF is not a tree rooted at base_link")
    kinds = {"package": 0, "relative": 0}
    print("\n%-13s %-28s %6s %8s %8s %6s" % ("link", "mesh", "prims", "mesh cm3", "prim cm3", "ratio"))
    for name, link in links.items():
        for tag in ("inertial", "visual", "collision"):
            if link.find(tag) is None:
                fail("link %s has no <%s>" % (name, tag))
        inertia = link.find("inertial/inertia")
        m = np.array([[float(inertia.get(k)) for k in row] for row in
                      (("ixx", "ixy", "ixz"), ("ixy", "iyy", "iyz"), ("ixz", "iyz", "izz"))])
        ev = np.linalg.eigvalsh(m)
        if ev.min() <= 0 or ev[0] + ev[1] < ev[2] * (1 - 1e-6):
            fail("link %s: inertia not physical (eigenvalues %s)" % (name, ev))
        uris = {c.find("geometry/mesh").get("filename") for c in link.findall("visual") + link.findall("collision")}
        uris |= {c.find("geometry/mesh").get("filename") for c in links_c[name].findall("visual")}
        if len(uris) != 1:
            fail("link %s: visual and collision meshes differ: %s" % (name, uris))
        uri = uris.pop()
        kinds["package" if uri.startswith("package://") else "relative"] += 1
        path = resolve(uri, os.path.dirname(meshed))
        if not os.path.isfile(path):
            fail("link %s: %s does not resolve (%s)" % (name, uri, path))
            continue
        verts, tris = read_mesh(path)[:2]
        a, b, c = verts[tris[:, 0]], verts[tris[:, 1]], verts[tris[:, 2]]
        volume = np.einsum("ij,ij->i", a, np.cross(b, c)).sum() / 6.0
        prims = links_c[name].findall("collision")
        if not 1 <= len(prims) <= 3:
            fail("link %s: %d hand-made primitives" % (name, len(prims)))
        # coverage: every vertex, edge midpoint and triangle centroid inside some primitive (0.1 mm tolerance)
        pts = np.concatenate([verts, (a + b) / 2.0, (b + c) / 2.0, (c + a) / 2.0, (a + b + c) / 3.0])
        dist = np.min([primitive_distance(pts, p) for p in prims], axis=0)
        if dist.max() > 1e-4:
            fail("link %s: mesh sticks out of the hand-made primitives by %.4f m" % (name, dist.max()))
        pvol = sum(primitive_volume(p) for p in prims)
        print("%-13s %-28s %6d %8.1f %8.1f %6.2f" % (name, uri[-28:], len(prims), volume * 1e6, pvol * 1e6,
                                                   pvol / volume))
    if kinds["relative"] < 1 or kinds["package"] < 1:
        fail("expected both package:// and relative mesh paths, got %s" % kinds)
    # SRDF links exist
    srdf = ET.parse(os.path.join(HERE, "meshed_arm.srdf")).getroot()
    names = [e.get(k) for e in srdf.iter("disable_collisions") for k in ("link1", "link2")]
    names += [e.get("name") for e in srdf.iter("link")]
    names += [e.get(k) for e in srdf.iter("chain") for k in ("base_link", "tip_link")]
    if not set(names) <= set(links):
        fail("the SRDF names links the URDF does not have: %s" % (set(names) - set(links)))
    if shutil.which("check_urdf"):
        for path in (meshed, capsules):
            r = subprocess.run(["check_urdf", path], capture_output=True, text=True)
            print("check_urdf %s: exit %d" % (os.path.basename(path), r.returncode))
            if r.returncode != 0:
                fail("check_urdf %s: %s" % (path, r.stdout + r.stderr))
    else:
        print("check_urdf not installed: skipped")


def main():
    mesh_dir = os.path.join(HERE, "meshes")
    for name in sorted(os.listdir(mesh_dir)):
        if os.path.splitext(name)[1] in (".stl", ".obj", ".dae"):  # not the fits cached beside them
            check_mesh(os.path.join(mesh_dir, name))
    # the same link written in several formats must be the same mesh
    for stem in ("link5", "link6"):
        got = [read_mesh(os.path.join(mesh_dir, stem + ext))[:2] for ext in (".stl", ".obj" if stem == "link5"
                                                                                else ".dae")]
        (v0, t0), (v1, t1) = got
        if len(t0) != len(t1) or abs(np.sort(v0[t0].reshape(-1)) - np.sort(v1[t1].reshape(-1))).max() > 1e-6:
            fail("%s: the STL and the other format differ" % stem)
    check_urdf_pair()
    print("\n%s" % ("all checks passed" if not FAILURES else "%d failures" % len(FAILURES)))
    return 1 if FAILURES else 0


if __name__ == "__main__":
    sys.exit(main())
