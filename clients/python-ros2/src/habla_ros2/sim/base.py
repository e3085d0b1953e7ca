"""The simulated base's body: a disc on differential drive that reaches the commanded speeds within its
acceleration limits, stops translating where it would push into a wall or the target, and stops by itself
when no command comes for cmd_timeout_s (as a base controller's command time-out does)."""

import math


def normalize(a):
    return math.atan2(math.sin(a), math.cos(a))


def ramp(current, wanted, up, down):
    slowing = current != 0 and (wanted * current < 0 or abs(wanted) < abs(current))
    step = down if slowing else up
    d = wanted - current
    return wanted if abs(d) <= step else current + math.copysign(step, d)


class Base:
    # The speeds and accelerations of habla-sim's Pioneer 2 DX (docs/simulator.md): a ROS 2 driver of a Pioneer
    # (or a base like it) under the same experiment.
    def __init__(self, radius_m=0.25, max_v=0.75, max_w=1.74, accel=0.3, decel=0.6, rot_accel=1.74,
                 cmd_timeout_s=0.5):
        self.radius_m, self.max_v, self.max_w = radius_m, max_v, max_w
        self.accel, self.decel, self.rot_accel = accel, decel, rot_accel
        self.cmd_timeout_s = cmd_timeout_s
        self.x = self.y = self.theta = 0.0
        self.v = self.w = 0.0
        self.want_v = self.want_w = 0.0
        self.last_cmd_s = -math.inf
        self.stalled = False
        # odometry: integrated from the wheels' motion, from where the base stood when the simulation began
        self.odom = [0.0, 0.0, 0.0]

    def command(self, v, w, now_s):
        self.want_v = max(-self.max_v, min(self.max_v, v if math.isfinite(v) else 0.0))
        self.want_w = max(-self.max_w, min(self.max_w, w if math.isfinite(w) else 0.0))
        self.last_cmd_s = now_s

    def place(self, x, y, theta):
        """Carried somewhere, at rest (its odometry goes on from where it was, as a robot carried by hand)."""
        self.x, self.y, self.theta = x, y, theta
        self.v = self.w = self.want_v = self.want_w = 0.0
        self.stalled = False

    def step(self, dt, world, now_s):
        if now_s - self.last_cmd_s > self.cmd_timeout_s:
            self.want_v = self.want_w = 0.0
        self.v = ramp(self.v, self.want_v, self.accel * dt, self.decel * dt)
        self.w = ramp(self.w, self.want_w, self.rot_accel * dt, self.rot_accel * dt)
        sign = 1 if self.v >= 0 else -1
        mid = self.theta + self.w * dt / 2
        nx, ny = self.x + self.v * dt * math.cos(mid), self.y + self.v * dt * math.sin(mid)
        before, after = world.clearance(self.x, self.y), world.clearance(nx, ny)
        if self.v != 0 and after < self.radius_m and after < before:
            lo, hi = 0.0, 1.0
            for _ in range(16):
                f = (lo + hi) / 2
                if world.clearance(self.x + f * (nx - self.x), self.y + f * (ny - self.y)) >= self.radius_m:
                    lo = f
                else:
                    hi = f
            nx, ny = self.x + lo * (nx - self.x), self.y + lo * (ny - self.y)
            self.v = 0.0
            self.stalled = True
        else:
            self.stalled = after < self.radius_m + 1e-3 and self.want_v != 0 and after <= before
        dist = math.hypot(nx - self.x, ny - self.y) * sign
        ox, oy, ot = self.odom
        omid = ot + self.w * dt / 2
        self.odom = [ox + dist * math.cos(omid), oy + dist * math.sin(omid), normalize(ot + self.w * dt)]
        self.x, self.y, self.theta = nx, ny, normalize(self.theta + self.w * dt)
