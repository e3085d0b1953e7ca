"""A simulated world read from the world files habla-sim uses (docs/simulator.md#world-files): walls as
segments, the target as a disc, the robot's start and the teacher's settings. Ray casting and clearance are
numpy over all walls at once."""

import json
import math
import os

import numpy as np

BUILT_IN = os.path.join("habla-sim", "src", "main", "resources", "worlds")
LABELS = ("forward", "left", "right", "back")
TEACHER_DEFAULTS = {"present": True, "commandEveryS": 3.0, "judgeAfterS": 1.5, "turnThresholdRad": 0.35,
                    "minTurnRad": 0.05, "minMoveM": 0.02,
                    "notes": {"forward": "C5", "left": "E5", "right": "G5", "back": "C6"},
                    "phrases": {"forward": "go forward", "left": "turn left", "right": "turn right", "back": "go back"}}
KEYS = {"name", "description", "arena", "target", "robot", "teacher"}


def find_world(name):
    """A world file, or the built-in world of that name from the HABLA checkout this package sits in."""
    if os.path.isfile(name):
        return name
    base = name if name.endswith(".json") else name + ".json"
    here = os.path.dirname(os.path.abspath(__file__))
    for up in range(8):
        candidate = os.path.join(here, *[".."] * up, BUILT_IN, base)
        if os.path.isfile(candidate):
            return os.path.normpath(candidate)
    raise FileNotFoundError("'%s' is neither a world file nor a built-in world of habla-sim" % name)


class World:
    """The world's fixed parts and the target's current place."""

    def __init__(self, path):
        with open(path) as f:
            root = json.load(f)
        unknown = set(root) - KEYS
        if unknown:
            raise ValueError("%s: unknown keys %s" % (path, sorted(unknown)))
        self.name = root["name"]
        walls = np.array(root["arena"]["walls"], dtype=float).reshape(-1, 4)
        self.a, self.b = walls[:, :2], walls[:, 2:]
        t = root["target"]
        self.target = (float(t["xM"]), float(t["yM"]), float(t["radiusM"]))
        r = root["robot"]
        self.start = (float(r["xM"]), float(r["yM"]), float(r["thetaRad"]))
        self.teacher = dict(TEACHER_DEFAULTS, **root.get("teacher", {}))

    def ranges(self, x, y, angles, max_range):
        """How far rays from (x, y) along angles (world frame, radians) travel before a wall or the target."""
        d = np.stack([np.cos(angles), np.sin(angles)], axis=1)                       # (n, 2)
        best = np.full(len(angles), float(max_range))
        e = self.b - self.a                                                            # (w, 2)
        ox, oy = self.a[:, 0] - x, self.a[:, 1] - y                                    # (w,)
        den = d[:, 0:1] * e[None, :, 1] - d[:, 1:2] * e[None, :, 0]                    # (n, w)
        with np.errstate(divide="ignore", invalid="ignore"):
            t = (ox[None, :] * e[None, :, 1] - oy[None, :] * e[None, :, 0]) / den       # along the ray
            u = (ox[None, :] * d[:, 1:2] - oy[None, :] * d[:, 0:1]) / den               # along the wall
        hit = (np.abs(den) > 1e-12) & (t >= 0) & (u >= 0) & (u <= 1)
        if hit.any():
            best = np.minimum(best, np.where(hit, t, np.inf).min(axis=1))
        tx, ty, tr = self.target
        cx, cy = tx - x, ty - y
        proj = d[:, 0] * cx + d[:, 1] * cy
        disc = proj ** 2 - (cx * cx + cy * cy - tr * tr)
        ok = disc >= 0
        near = proj - np.sqrt(np.where(ok, disc, 0))
        best = np.where(ok & (near >= 0), np.minimum(best, near), best)
        return best

    def clearance(self, x, y):
        """Distance from (x, y) to the nearest wall or the target's edge."""
        e = self.b - self.a
        p = np.array([x, y])
        f = np.clip(((p - self.a) * e).sum(axis=1) / np.maximum((e * e).sum(axis=1), 1e-12), 0, 1)
        closest = self.a + f[:, None] * e
        walls = np.sqrt(((closest - p) ** 2).sum(axis=1)).min() if len(e) else math.inf
        tx, ty, tr = self.target
        return min(float(walls), math.hypot(tx - x, ty - y) - tr)
