#!/usr/bin/python3
"""Draw a 3D multi-robot problem (Panda Cage) from the geometry file ompl_parc_demo --geometry writes.

Two views side by side, the team at its starts and at its goals: obstacles in grey, each robot's capsules
(the shapes collision checking uses) in its own colour, the same in both views, its end effector as a dot.
With a solution in the file, each end effector's path is drawn too (thin, in both views).
No kinematics here: every point comes from the C++ side (GeometryFile).

Usage: scripts/draw_panda_cage.py GEOMETRY.json PICTURE.png [--title TEXT]
(Debian's /usr/bin/python3 with python3-matplotlib, from scripts/setup.sh; another python3 without matplotlib
hands over to it, or exits 2 when it is not there)
"""
import argparse
import json

from debian_matplotlib import pyplot

plt = pyplot()

FORMAT = "ompl_parc.geometry"
BOX_EDGES = [(a, b) for a in range(8) for b in range(a + 1, 8) if bin(a ^ b).count("1") == 1]


def read_geometry(path):
    with open(path) as f:
        doc = json.load(f)
    if doc.get("format") != FORMAT or doc.get("version") != 1:
        raise SystemExit(f"draw_panda_cage.py: {path} is not an {FORMAT} version 1 file")
    return doc


def segments_of(obstacle):
    """The obstacle as (segments, radius): a cylinder is its axis, a box its 12 edges, a sphere a point."""
    shape = obstacle["shape"]
    if shape == "cylinder":
        return [(obstacle["a"], obstacle["b"])], obstacle["radius"]
    if shape == "sphere":
        return [(obstacle["center"], obstacle["center"])], obstacle["radius"]
    corners = obstacle["corners"]
    return [(corners[a], corners[b]) for a, b in BOX_EDGES], 0.005


def scene_bounds(doc):
    points = []
    for obstacle in doc["obstacles"]:
        for a, b in segments_of(obstacle)[0]:
            points += [a, b]
    for robot in doc["robots"]:
        for end in ("start", "goal"):
            for c in robot[end]:
                points += [c[0:3], c[3:6]]
    lo = [min(p[k] for p in points) - 0.1 for k in range(3)]
    hi = [max(p[k] for p in points) + 0.1 for k in range(3)]
    return lo, hi


def draw_segment(ax, a, b, radius, color, points_per_metre, alpha=1.0):
    # A capsule seen from afar: its axis as a line as wide as the capsule.
    ax.plot([a[0], b[0]], [a[1], b[1]], [a[2], b[2]], color=color, alpha=alpha,
            linewidth=max(0.5, 2 * radius * points_per_metre), solid_capstyle="round")


def draw_view(ax, doc, end, colors, lo, hi, points_per_metre):
    for obstacle in doc["obstacles"]:
        segments, radius = segments_of(obstacle)
        for a, b in segments:
            draw_segment(ax, a, b, radius, "0.55", points_per_metre)
    for robot, color in zip(doc["robots"], colors):
        for c in robot[end]:
            draw_segment(ax, c[0:3], c[3:6], c[6], color, points_per_metre, alpha=0.85)
        tip = robot[end + "_tip"]
        ax.scatter([tip[0]], [tip[1]], [tip[2]], color="black", s=12, depthshade=False, zorder=5)
        if "tip_path" in robot:
            path = robot["tip_path"]
            ax.plot([p[0] for p in path], [p[1] for p in path], [p[2] for p in path], color=color,
                    linewidth=0.8, linestyle=":")
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1], hi[1])
    ax.set_zlim(lo[2], hi[2])
    ax.set_box_aspect([hi[k] - lo[k] for k in range(3)])
    ax.view_init(elev=20, azim=-25)
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.set_zlabel("z (m)")
    ax.set_title(end)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("geometry", help="geometry file from ompl_parc_demo --geometry")
    parser.add_argument("picture", help="PNG to write")
    parser.add_argument("--title", help="figure title (default: the problem's name)")
    args = parser.parse_args()
    doc = read_geometry(args.geometry)
    lo, hi = scene_bounds(doc)
    palette = plt.get_cmap("tab20" if len(doc["robots"]) > 10 else "tab10")
    colors = [palette(i % palette.N) for i in range(len(doc["robots"]))]

    width = 14.0
    fig = plt.figure(figsize=(width, 7.0))
    # Line widths are in points (72 per inch): the scene spans about a sixth of the figure width in a view.
    points_per_metre = 0.16 * width * 72 / max(hi[k] - lo[k] for k in range(3))
    for k, end in enumerate(("start", "goal")):
        draw_view(fig.add_subplot(1, 2, k + 1, projection="3d"), doc, end, colors, lo, hi, points_per_metre)
    fig.suptitle(args.title or doc.get("name", ""))
    fig.tight_layout(rect=(0, 0, 1, 0.95))  # room for the title
    fig.savefig(args.picture, dpi=90)


if __name__ == "__main__":
    main()
