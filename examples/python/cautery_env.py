#!/usr/bin/env python3
"""A minimal gym-style environment around tetcut: a researcher's starting point.

    env = CauteryEnv("corpus/meshes/liver.msh", target_centre=(95, 110, 100), target_radius=20)
    observation = env.reset()
    observation, reward, done, info = env.step(np.array([0.0, 1.0, 0.0]))

reset() loads the mesh and puts the tool at its start; step(action) moves the tool by `action`
(a direction, scaled to at most `step_length` mm, the tool kept inside the organ's bounding box)
and cuts there. The observation is the organ's surface as numpy arrays (points #V by 3,
triangles #F by 3, and the tool's centre); the reward is the volume of tissue the cut removed
inside the target region (a ball), minus a penalty per unit of healthy tissue removed outside it.
No gym dependency (Debian ships none): the method names and return values follow gym's, so a
wrapper is a few lines.

The reward is kept up to date from each cut's change log in O(changed), not recomputed over
the mesh: the volume inside the target of every live tet is held by tet id, the tets the cut
removed are subtracted and the ones it created added.

Run it: `examples/python/cautery_env.py [--steps N]` (a baseline policy that heads for the target
and sweeps it).
"""
import argparse
import pathlib
import sys

import numpy as np

import tetcut

HERE = pathlib.Path(__file__).resolve().parent
LIVER = HERE.parents[1] / "corpus" / "meshes" / "liver.msh"


class CauteryEnv:
    def __init__(self, mesh_path=LIVER, target_centre=(95.0, 110.0, 100.0), target_radius=20.0,
                 tool_diameter=8.0, step_length=4.0, start=(95.0, 40.0, 100.0), max_steps=60,
                 outside_penalty=0.5):
        self.mesh_path = str(mesh_path)
        self.target_centre = np.asarray(target_centre, dtype=float)
        self.target_radius = float(target_radius)
        self.tool_diameter = tool_diameter
        self.step_length = step_length
        self.start = np.asarray(start, dtype=float)
        self.max_steps = max_steps
        self.outside_penalty = outside_penalty

    # ---- gym's interface -------------------------------------------------------------------
    def reset(self, seed=None):
        self.mesh = tetcut.read(self.mesh_path)
        self.cutter = tetcut.Cutter(self.mesh, tool_diameter=self.tool_diameter)
        points = self.mesh.points
        self.box = (points.min(axis=0), points.max(axis=0))
        self.tool = self.start.copy()
        self.steps = 0
        # Per tet id: its volume inside / outside the target (by its centroid).
        self.inside = np.zeros(0)
        self.outside = np.zeros(0)
        self._account(self.mesh.tet_ids)
        self.target_volume = self.inside.sum()
        return self._observation()

    def step(self, action):
        action = np.asarray(action, dtype=float)
        length = np.linalg.norm(action)
        if length > self.step_length:
            action = action * (self.step_length / length)
        self.tool = np.clip(self.tool + action, *self.box)
        report = self.cutter.cut(self.tool)
        changes = report.changes
        removed_inside = self.inside[changes.removed].sum()
        removed_outside = self.outside[changes.removed].sum()
        self.inside[changes.removed] = 0.0
        self.outside[changes.removed] = 0.0
        self._account(changes.created)
        # Net tissue removed: what went minus what the cut's refinement put back in its place.
        removed_inside -= self.inside[changes.created].sum()
        removed_outside -= self.outside[changes.created].sum()
        reward = removed_inside - self.outside_penalty * removed_outside
        self.steps += 1
        done = self.steps >= self.max_steps or self.inside.sum() < 0.05 * self.target_volume
        info = {"report": report, "removed_inside": removed_inside, "removed_outside": removed_outside,
                "target_left": self.inside.sum() / self.target_volume}
        return self._observation(), reward, done, info

    # ---- helpers ---------------------------------------------------------------------------
    def _observation(self):
        return {"points": self.mesh.points, "triangles": self.mesh.surface(), "tool": self.tool.copy()}

    def _account(self, tet_ids):
        """Volumes of these (live) tets inside and outside the target, stored by tet id."""
        slots, positions = self.mesh.slot_tets, self.mesh.slot_points  # views: no copy, mesh locked
        if len(slots) > len(self.inside):
            more = np.zeros(len(slots) + len(slots) // 2 - len(self.inside))
            self.inside = np.concatenate([self.inside, more])
            self.outside = np.concatenate([self.outside, more])
        p = positions[slots[tet_ids].astype(np.int64)]  # #T by 4 by 3
        del slots, positions  # the views go: the mesh may be cut again
        volume = np.einsum("ij,ij->i", np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), p[:, 3] - p[:, 0]) / 6.0
        in_target = np.linalg.norm(p.mean(axis=1) - self.target_centre, axis=1) <= self.target_radius
        self.inside[tet_ids] = np.where(in_target, volume, 0.0)
        self.outside[tet_ids] = np.where(in_target, 0.0, volume)


class RasterPolicy:
    """Head for the target, then sweep it: waypoints on a grid inside the target ball, visited in
    a serpentine order. A baseline to beat, not a learned policy."""

    def __init__(self, env, spacing=None):
        spacing = spacing or 0.75 * env.tool_diameter
        r = env.target_radius
        axis = np.arange(-r, r + 1e-9, spacing)
        points = []
        for i, z in enumerate(axis):
            for j, y in enumerate(axis if i % 2 == 0 else axis[::-1]):
                for x in (axis if j % 2 == 0 else axis[::-1]):
                    if x * x + y * y + z * z <= r * r:
                        points.append(env.target_centre + (x, y, z))
        self.waypoints = points

    def __call__(self, observation):
        while self.waypoints and np.linalg.norm(self.waypoints[0] - observation["tool"]) < 0.5:
            self.waypoints.pop(0)
        return (self.waypoints[0] if self.waypoints else observation["tool"]) - observation["tool"]


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--steps", type=int, default=120)
    args = parser.parse_args(argv)
    env = CauteryEnv(max_steps=args.steps)
    observation = env.reset()
    policy = RasterPolicy(env)
    total = 0.0
    for _ in range(args.steps):
        observation, reward, done, info = env.step(policy(observation))
        total += reward
        print(f"step {env.steps:3d} tool {np.round(env.tool, 1)} reward {reward:9.2f} "
              f"target left {info['target_left']:.3f} surface {len(observation['triangles'])} triangles")
        if done:
            break
    violations = tetcut.check(env.mesh)
    print(f"return {total:.2f}, {env.mesh.num_tets} tets, check: {'valid' if not violations else violations}")
    return 0 if not violations else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
