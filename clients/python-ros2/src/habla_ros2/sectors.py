"""A laser scan as a ring of virtual range sensors on the base's edge, the shape HABLA's range methods take.

The ring has N sensors evenly spaced round the base, sensor k looking out along bearing
c_k = -pi + (k + 1/2) * 2pi/N from the point where that bearing leaves the base's footprint (a circle of radius
R). Each beam of a scan becomes a point in the base's frame (the laser's mount pose applied); its sensor is the
one whose sector holds the point's bearing, and its reading is the point's distance from the footprint's edge,
|p| - R. A sensor reads the nearest of its points, or max_range when none fell in its sector within reach.
So the ring's readings are distances from the robot's edge, as a Pioneer's sonar ring gives them, and its
nearest reading is the laser's nearest point up to the sector's width in bearing.
"""

import math

import numpy as np


class SectorRing:
    def __init__(self, sectors, radius_m, max_range_m, laser_pose=(0.0, 0.0, 0.0)):
        if sectors < 4 or radius_m < 0 or max_range_m <= 0:
            raise ValueError("a ring needs 4 or more sectors, a radius >= 0 and a reach > 0")
        self.n, self.radius, self.max_range = sectors, radius_m, max_range_m
        self.laser = laser_pose
        self.width = 2 * math.pi / sectors
        self.centres = -math.pi + (np.arange(sectors) + 0.5) * self.width

    def meta(self):
        """The channel metadata HABLA's range methods read: each sensor's pose, the reach."""
        return {"maxRangeM": self.max_range, "minRangeM": 0.0,
                "poses": [{"xM": round(self.radius * math.cos(c), 4), "yM": round(self.radius * math.sin(c), 4),
                           "thetaRad": round(float(c), 4)} for c in self.centres]}

    def readings(self, angle_min, angle_increment, ranges, range_min, range_max):
        """One LaserScan's ranges as the ring's N readings."""
        r = np.asarray(ranges, dtype=float)
        a = angle_min + angle_increment * np.arange(len(r)) + self.laser[2]
        ok = np.isfinite(r) & (r >= range_min) & (r <= range_max)
        x = self.laser[0] + r[ok] * np.cos(a[ok])
        y = self.laser[1] + r[ok] * np.sin(a[ok])
        edge = np.maximum(np.hypot(x, y) - self.radius, 0.0)
        k = np.floor((np.arctan2(y, x) + math.pi) / self.width).astype(int) % self.n
        out = np.full(self.n, float(self.max_range))
        np.minimum.at(out, k, edge)
        return [round(float(v), 4) for v in out]
