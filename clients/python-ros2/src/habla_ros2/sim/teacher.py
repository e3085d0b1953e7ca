"""The scripted teacher of the paper's Pioneer experiment, as habla-sim's Teacher: while present, every
commandEveryS it gives the command that brings the robot towards the target (|bearing| above
turnThresholdRad -> left/right, else forward), and judgeAfterS after the command got across (the end of the
note) judges what the robot did meanwhile: +1 if it turned the commanded way or moved forward/back as
commanded, -1 otherwise. Its voice plays notes and types rewards (voice.command(label) -> seconds the command
takes, voice.reward(value))."""

import math

LABELS = ("forward", "left", "right", "back")


def bearing(pose, tx, ty):
    x, y, theta = pose
    return math.atan2(math.sin(math.atan2(ty - y, tx - x) - theta), math.cos(math.atan2(ty - y, tx - x) - theta))


class Teacher:
    def __init__(self, settings, voice):
        self.s, self.voice = settings, voice
        self.present = bool(settings["present"])
        self.now = 0.0
        self.next_command = settings["commandEveryS"]
        self.pending = None          # (label, pose when given)
        self.judge_at = 0.0
        self.last_command = None
        self.last_reward = None
        self.episode = [0, 0, 0]     # commands, plus, minus

    def command_towards(self, pose, target):
        b = bearing(pose, target[0], target[1])
        if b > self.s["turnThresholdRad"]:
            return "left"
        if b < -self.s["turnThresholdRad"]:
            return "right"
        return "forward"

    def step(self, now, pose, target):
        self.now = now
        if self.pending is not None and now >= self.judge_at - 1e-9:
            label, start = self.pending
            self.pending = None
            self._reward(1.0 if self.obeyed(label, start, pose) else -1.0)
        if self.present and self.pending is None and now >= self.next_command - 1e-9:
            self._command(self.command_towards(pose, target), pose)

    def command_now(self, label, pose):
        if label not in LABELS:
            raise ValueError("unknown command label '%s' (labels: %s)" % (label, ", ".join(LABELS)))
        self._command(label, pose)

    def reward_now(self, value):
        if not -1 <= value <= 1:
            raise ValueError("a reward must be a number in [-1, 1], was %s" % value)
        self._reward(value)

    def set_present(self, present):
        if present and not self.present:
            self.next_command = self.now + self.s["commandEveryS"]
        if not present:
            self.pending = None
        self.present = present

    def new_episode(self):
        self.pending = None
        self.episode = [0, 0, 0]

    def obeyed(self, label, start, end):
        turned = math.atan2(math.sin(end[2] - start[2]), math.cos(end[2] - start[2]))
        advanced = (end[0] - start[0]) * math.cos(start[2]) + (end[1] - start[1]) * math.sin(start[2])
        return {"left": turned > self.s["minTurnRad"], "right": turned < -self.s["minTurnRad"],
                "forward": advanced > self.s["minMoveM"], "back": advanced < -self.s["minMoveM"]}.get(label, False)

    def _command(self, label, pose):
        self.pending = (label, pose)
        self.last_command = label
        self.episode[0] += 1
        sound_s = self.voice.command(label)
        self.judge_at = self.now + sound_s + self.s["judgeAfterS"]
        self.next_command = max(self.now + self.s["commandEveryS"], self.judge_at + 0.5)

    def _reward(self, value):
        self.last_reward = value
        if value > 0:
            self.episode[1] += 1
        elif value < 0:
            self.episode[2] += 1
        self.voice.reward(value)
