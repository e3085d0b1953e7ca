"""A control architecture for the room in the manner of the Multilevel Darwinist Brain, over HABLA's sockets.

It knows four sockets of config/room.json and nothing of the devices behind them: `occupancy` (which zones
someone is in), `light` (every zone's illuminance), the teacher's `reward` and the `action` it writes
("desk on", "sofa off"). What lamps do and when the teacher is pleased it learns, with the same parts as
examples/mdb/mdb.py, whose evolutionary search it reuses:

* a short-term memory of experiences: the zone's perception before, the switch, the perception after, the
  reward heard for it;
* a world model: what switching a zone's lamp does to the zone's light (one gain per zone);
* a satisfaction model with two parts: while the teacher is there, the relevance of a switch in a perception
  (the reward the teacher is expected to give); and the induced model, which predicts the reward from the
  perception after the switch alone (is the person's zone lit, is an empty zone's lamp off) and so keeps
  working when nobody rewards any more;
* action selection: for the zone it looks at, predict the perception after switching its lamp and after
  leaving it, score both, and switch if that is better (with an exploration rate that decays).

While rewards keep coming, the relevance drives it; when none came for `--absent-after-s`, the induced model
does, and the room should go on lighting the zone the person is in and darkening the others.

    python3 room_mdb.py --occupancy 7201 --light 7202 --reward 7204 --action 7205 --log decisions.jsonl
"""

import argparse
import collections
import json
import math
import os
import random
import signal
import sys
import threading
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "mdb"))
try:
    import habla
except ImportError:  # not installed: the client of this checkout
    sys.path.insert(0, os.path.join(HERE, "..", "..", "clients", "python", "src"))
    import habla

from mdb import Evolution, clamp  # noqa: E402

LIT_LUX = 200.0  # the light a person needs (the controller's own threshold, not the teacher's)
WEIGHT_COST = 0.01  # the satisfaction models pay for large weights, so they do not saturate on a few noisy rewards
LUX_SCALE = 400.0  # light is modelled in units of this many lux


class Perception(collections.namedtuple("Perception", "occupied lux lamp")):
    """One zone at one instant: someone there (0/1), its illuminance (lx), its lamp (0/1) as last switched."""


class Experience(collections.namedtuple("Experience", "zone before switched after reward")):
    """One decision: the zone, the perception before, whether the lamp was switched, after, the reward (or None)."""


class RoomLink:
    """The four sockets, read in background threads; the latest occupancy and light, and numbered rewards."""

    def __init__(self, host, ports):
        self.host, self.ports = host, ports
        self.cv = threading.Condition()
        self.occupancy, self.light = {}, {}
        self.rewards = []  # (number, arrived, value)
        self.stale = False
        self.action = None
        self.closed = False
        for name in ("occupancy", "light", "reward"):
            threading.Thread(target=self._read, args=(name,), daemon=True).start()

    def _read(self, name):
        while not self.closed:
            try:
                with habla.connect(self.host, self.ports[name], timeout=5.0) as s:
                    if name != "reward":
                        s.send({"op": "latest"})
                    while not self.closed:
                        try:
                            self._take(name, s.read_frame(timeout=30.0))
                        except TimeoutError:
                            s.keep_alive()   # a quiet socket (the reward): stay a client the daemon keeps
            except (OSError, habla.HablaError):  # the daemon went away: connect again
                time.sleep(0.5)

    def _take(self, name, line):
        with self.cv:
            if line.get("type") == "stale":
                self.stale = bool(line.get("stale"))
            elif line.get("type") == "sample":
                value = line.get("value")
                if name == "occupancy":
                    self.occupancy = dict(value.get("zones", {}))
                elif name == "light":
                    self.light = dict(value.get("lux", {}))
                elif name == "reward" and isinstance(value, (int, float)):
                    self.rewards.append((len(self.rewards) + 1, time.monotonic(), float(value)))
            self.cv.notify_all()

    def wait(self, test, seconds):
        end = time.monotonic() + max(0.0, seconds)
        with self.cv:
            while not test() and time.monotonic() < end:
                self.cv.wait(max(0.0, end - time.monotonic()))
            return test()

    def act(self, text):
        """Writes one action; False if the daemon is not there (the next step tries again)."""
        try:
            if self.action is None:
                self.action = habla.connect(self.host, self.ports["action"], timeout=5.0)
            self.action.write_and_wait(text)
            return True
        except (OSError, Exception):  # a refused value or a lost socket: reconnect next time
            try:
                if self.action is not None:
                    self.action.close()
            finally:
                self.action = None
            return False


def relevance_features(p, switch):
    """What the teacher's judgement of a switch may depend on: someone there, dark without the lamp, the lamp."""
    on_after = p.lamp if not switch else 1 - p.lamp
    return [1.0, p.occupied, p.lux / LUX_SCALE, on_after, p.occupied * on_after, (p.lux / LUX_SCALE) * on_after,
            p.lamp * on_after]


def after_features(p, gain):
    """The induced model's inputs: the perception after, alone (no teacher): is an occupied zone lit, is a lamp on
    where nobody is, and how much light there would be without the lamp (the world model's gain takes it out)."""
    lit = 1.0 if p.lux >= LIT_LUX else 0.0
    without = max(0.0, p.lux - p.lamp * gain * LUX_SCALE) / LUX_SCALE
    return [1.0, p.occupied * lit, p.occupied * (1 - lit), p.lamp * (1 - p.occupied), p.lamp * without,
            (1 - p.lamp) * (1 - p.occupied)]


def dot(w, x):
    return sum(a * b for a, b in zip(w, x))


class Brain:
    def __init__(self, zones, seed=0, memory=200, population=16, generations=3, epsilon=0.3, epsilon_decay=0.97,
                 epsilon_min=0.05):
        self.rng = random.Random(seed)
        self.zones = list(zones)
        self.memory = collections.deque(maxlen=memory)
        self.generations = generations
        self._epsilon, self.epsilon_decay, self.epsilon_min = epsilon, epsilon_decay, epsilon_min
        self.world = Evolution(len(self.zones), self.rng, size=population, init_scale=0.1)
        self.relevance = Evolution(7, self.rng, size=population)
        self.induced = Evolution(6, self.rng, size=population)

    @property
    def epsilon(self):
        return self._epsilon

    def gain(self, zone):
        """What switching the zone's lamp on adds to its light, in LUX_SCALE units (world model)."""
        return self.world.best[self.zones.index(zone)]

    def predict(self, zone, p, switch):
        """The perception after switching (or not) the zone's lamp: occupancy stays, light moves by the gain."""
        if not switch:
            return p
        lamp = 1 - p.lamp
        return Perception(p.occupied, max(0.0, p.lux + (lamp - p.lamp) * self.gain(zone) * LUX_SCALE), lamp)

    def relevance_of(self, p, switch):
        return math.tanh(dot(self.relevance.best, relevance_features(p, switch)))

    def satisfaction_of(self, zone, p):
        return math.tanh(dot(self.induced.best, after_features(p, self.gain(zone))))

    def decide(self, zone, p, teacher):
        """Whether to switch the zone's lamp, whether that was exploration, and the two scores."""
        if teacher:
            scores = {"switch": self.relevance_of(p, True), "hold": 0.0}
        else:
            scores = {"switch": self.satisfaction_of(zone, self.predict(zone, p, True)),
                      "hold": self.satisfaction_of(zone, self.predict(zone, p, False))}
        # Alone it still tries a switch now and then: a teacher who came back shows himself only by rewarding one.
        explored = self.rng.random() < (self._epsilon if teacher else self.epsilon_min / 2)
        if explored:
            switch = True  # holding teaches nothing: the teacher judges switches
            if teacher:
                self._epsilon = max(self.epsilon_min, self._epsilon * self.epsilon_decay)
        else:
            switch = scores["switch"] > scores["hold"] + (0.0 if teacher else 0.05)
        return switch, explored, scores

    def remember(self, e):
        """Keeps switches only: a lamp left as it was teaches neither the world model nor the satisfaction model."""
        if e.switched:
            self.memory.append(e)

    def learn(self):
        switched = [e for e in self.memory if e.switched]
        rewarded = [e for e in switched if e.reward is not None]
        errors = {}
        if switched:
            def world_error(w):
                err = 0.0
                for e in switched:
                    g = w[self.zones.index(e.zone)]
                    predicted = e.before.lux / LUX_SCALE + (e.after.lamp - e.before.lamp) * g
                    err += min(4.0, (predicted - e.after.lux / LUX_SCALE) ** 2)
                return err / len(switched)
            errors["world"] = self.world.run(world_error, self.generations)
        if rewarded:
            def relevance_error(w):
                return sum((math.tanh(dot(w, relevance_features(e.before, True))) - e.reward) ** 2
                           for e in rewarded) / len(rewarded) + WEIGHT_COST * dot(w, w)

            def induced_error(w):
                return sum((math.tanh(dot(w, after_features(e.after, self.gain(e.zone)))) - e.reward) ** 2
                           for e in rewarded) / len(rewarded) + WEIGHT_COST * dot(w, w)
            errors["relevance"] = self.relevance.run(relevance_error, self.generations)
            errors["induced"] = self.induced.run(induced_error, self.generations)
        return errors


def run(link, brain, step_s, reward_wait_s, absent_after_s, max_seconds, log):
    """The decision loop. The teacher counts as present while one of the last three switches earned a reward, or
    while a reward came within `absent_after_s` (and at the start, until three switches went unrewarded)."""
    start = time.monotonic()
    last_reward_at = None
    outcomes = collections.deque(maxlen=3)  # whether each recent switch earned a reward
    turn = 0
    lamps = {z: 0 for z in brain.zones}
    link.act("all off")
    while max_seconds is None or time.monotonic() - start < max_seconds:
        if not link.wait(lambda: link.occupancy and link.light and not link.stale, 1.0):
            continue
        zone = brain.zones[turn % len(brain.zones)]
        turn += 1
        with link.cv:
            before = Perception(float(link.occupancy.get(zone, 0)), float(link.light.get(zone, 0.0)), lamps[zone])
            heard = len(link.rewards)
        recent = last_reward_at is not None and time.monotonic() - last_reward_at < absent_after_s
        teacher = recent or len(outcomes) < outcomes.maxlen or any(outcomes)
        switch, explored, scores = brain.decide(zone, before, teacher)
        reward = None
        if switch:
            lamp = 1 - lamps[zone]
            if not link.act("%s %s" % (zone, "on" if lamp else "off")):
                continue
            lamps[zone] = lamp
            link.wait(lambda: len(link.rewards) > heard, reward_wait_s)
            with link.cv:
                if len(link.rewards) > heard:
                    reward = link.rewards[heard][2]
                    last_reward_at = link.rewards[heard][1]
            outcomes.append(reward is not None)
        link.wait(lambda: False, step_s)
        with link.cv:
            after = Perception(float(link.occupancy.get(zone, 0)), float(link.light.get(zone, 0.0)), lamps[zone])
        brain.remember(Experience(zone, before, switch, after, reward))
        errors = brain.learn()
        log({"t": round(time.monotonic() - start, 3), "zone": zone, "before": before._asdict(), "switch": switch,
             "explored": explored, "teacher": teacher, "scores": {k: round(v, 4) for k, v in scores.items()},
             "after": after._asdict(), "reward": reward, "epsilon": round(brain.epsilon, 4),
             "gain": round(brain.gain(zone), 3), "errors": {k: round(v, 5) for k, v in errors.items()}})


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--host", default="127.0.0.1")
    ap.add_argument("--occupancy", type=int, default=7201)
    ap.add_argument("--light", type=int, default=7202)
    ap.add_argument("--reward", type=int, default=7204)
    ap.add_argument("--action", type=int, default=7205)
    ap.add_argument("--zones", default="desk,sofa,kitchen")
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--speed", type=float, default=1.0, help="the room's time scale: waits shrink by it")
    ap.add_argument("--step-s", type=float, default=2.0, help="room seconds between decisions")
    ap.add_argument("--reward-wait-s", type=float, default=1.5, help="room seconds to wait for a reward")
    ap.add_argument("--absent-after-s", type=float, default=20.0, help="room seconds without a reward: alone")
    ap.add_argument("--max-seconds", type=float, default=None)
    ap.add_argument("--log", default=None)
    a = ap.parse_args(argv)
    signal.signal(signal.SIGTERM, lambda s, f: sys.exit(0))
    out = open(a.log, "a", encoding="utf-8") if a.log else sys.stderr

    def log(record):
        out.write(json.dumps(record) + "\n")
        out.flush()

    link = RoomLink(a.host, {"occupancy": a.occupancy, "light": a.light, "reward": a.reward, "action": a.action})
    brain = Brain(a.zones.split(","), seed=a.seed)
    try:
        run(link, brain, a.step_s / a.speed, a.reward_wait_s / a.speed, a.absent_after_s / a.speed, a.max_seconds, log)
    except KeyboardInterrupt:
        pass
    finally:
        link.closed = True
    return 0


if __name__ == "__main__":
    sys.exit(main())
