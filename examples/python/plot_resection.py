#!/usr/bin/env python3
"""Plots a resection with matplotlib: the liver's surface before and after the README's sweep,
the triangles the cuts exposed in another colour, and each cut's time.

    examples/python/plot_resection.py [--out resection.png]

Headless (matplotlib's Agg backend): writes a PNG.
"""
import argparse
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402

import tetcut  # noqa: E402

LIVER = pathlib.Path(__file__).resolve().parents[2] / "corpus" / "meshes" / "liver.msh"


def draw(ax, mesh, original_points, title):
    points, triangles = mesh.points, mesh.surface()
    corners = points[triangles]
    # A triangle is on the original surface when its corners all were input vertices there.
    original = {tuple(p) for p in original_points}
    exposed = np.array([not all(tuple(c) in original for c in tri) for tri in corners])
    colours = np.where(exposed[:, None], [[0.85, 0.2, 0.2, 1.0]], [[0.75, 0.55, 0.45, 0.35]])
    ax.add_collection3d(Poly3DCollection(corners, facecolors=colours, edgecolors="none"))
    lo, hi = points.min(axis=0), points.max(axis=0)
    ax.set_xlim(lo[0], hi[0]), ax.set_ylim(lo[1], hi[1]), ax.set_zlim(lo[2], hi[2])
    ax.set_box_aspect(hi - lo)  # millimetres alike on every axis
    ax.set_title(f"{title}: {mesh.num_tets} tets, {exposed.sum()} cut triangles")
    ax.view_init(elev=25, azim=-60)


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--mesh", default=str(LIVER))
    parser.add_argument("--out", default="resection.png")
    args = parser.parse_args(argv)

    mesh = tetcut.read(args.mesh)
    surface_points = mesh.points[np.unique(mesh.surface())]
    fig = plt.figure(figsize=(15, 5))
    draw(fig.add_subplot(1, 3, 1, projection="3d"), mesh, surface_points, "before")
    reports = tetcut.Cutter(mesh, tool_diameter=8.0).sweep((95, 40, 100), (95, 180, 100), 4.0)
    draw(fig.add_subplot(1, 3, 2, projection="3d"), mesh, surface_points, "after")
    ax = fig.add_subplot(1, 3, 3)
    ax.plot([r.centre[1] for r in reports], [r.wall_us for r in reports], marker="o")
    ax.set_xlabel("tool y (mm)"), ax.set_ylabel("cut time (us)"), ax.set_title("per cut")
    fig.tight_layout()
    fig.savefig(args.out, dpi=80)
    print(f"{len(reports)} cuts, hash {mesh.hash()}, wrote {args.out}")
    return 0 if not tetcut.check(mesh) else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
