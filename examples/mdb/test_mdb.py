"""Tests of the MDB control architecture: its parts on synthetic data, then whole runs against fake_world
over loopback. Run with `python3 -m unittest` in this directory."""

import concurrent.futures
import json
import math
import os
import random
import socket
import subprocess
import sys
import tempfile
import time
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

import mdb  # noqa: E402
from fake_world import FakeWorld  # noqa: E402
from habla_contract import ContractLink, DistanceAngle, Event  # noqa: E402

RADII_M = 0.3  # robot + target radius in the synthetic world below
SPEEDS = {"forward": (0.2, 0.0), "back": (-0.15, 0.0), "left": (0.0, 0.6), "right": (0.0, -0.6)}


def move(distance_m, angle_rad, action, seconds=1.0):
    """Where a target at (distance, angle) appears after a point robot performs `action` (exact geometry)."""
    v, w = SPEEDS[action]
    centre = distance_m + RADII_M
    tx, ty = centre * math.cos(angle_rad), centre * math.sin(angle_rad)
    tx -= v * seconds
    heading = w * seconds
    rx = tx * math.cos(-heading) - ty * math.sin(-heading)
    ry = tx * math.sin(-heading) + ty * math.cos(-heading)
    return max(0.0, math.hypot(rx, ry) - RADII_M), math.atan2(ry, rx)


def teacher_command(angle_rad):
    return "forward" if abs(angle_rad) <= 0.35 else "left" if angle_rad > 0 else "right"


def experience(rng, action, command=None, reward=None):
    d, a = rng.uniform(0.5, 3.0), rng.uniform(-math.pi, math.pi)
    d2, a2 = move(d, a, action)
    return mdb.Experience(mdb.Perception(d, a, True, command), action, mdb.Perception(d2, a2, True, None), reward)


def taught(rng, n, meaning=None, obedience=0.7):
    """n experiences of a teacher who asks with the contract's rule; `meaning` maps each command to the
    action it wants (itself by default); the pupil obeys with probability `obedience`."""
    meaning = meaning or {c: c for c in mdb.COMMANDS}
    out = []
    for _ in range(n):
        d, a = rng.uniform(0.5, 3.0), rng.uniform(-math.pi, math.pi)
        command = teacher_command(a)
        wanted = meaning[command]
        action = wanted if rng.random() < obedience else rng.choice(mdb.ACTIONS)
        d2, a2 = move(d, a, action)
        out.append(mdb.Experience(mdb.Perception(d, a, True, command), action,
                                  mdb.Perception(d2, a2, True, None), 1.0 if action == wanted else -1.0))
    return out


class EvolutionTest(unittest.TestCase):

    def test_evolution_improves_fitness_and_the_elite_never_gets_worse(self):
        rng = random.Random(3)
        xs = [(rng.uniform(-1, 1), rng.uniform(-1, 1)) for _ in range(40)]
        ys = [0.7 - 1.3 * x + 0.4 * y for x, y in xs]

        def error(p):
            return sum((p[0] + p[1] * x + p[2] * y - t) ** 2 for (x, y), t in zip(xs, ys)) / len(xs)

        evolution = mdb.Evolution(3, rng)
        history = [evolution.run(error, 1) for _ in range(60)]
        self.assertTrue(all(b <= a + 1e-12 for a, b in zip(history, history[1:])), history)
        self.assertLess(history[-1], history[0] / 20)
        self.assertLess(history[-1], 0.01)
        for got, want in zip(evolution.best, (0.7, -1.3, 0.4)):
            self.assertAlmostEqual(got, want, delta=0.1)

    def test_a_population_refuses_impossible_sizes(self):
        with self.assertRaises(ValueError):
            mdb.Evolution(3, random.Random(0), size=4, elite=4)


class WorldModelTest(unittest.TestCase):

    def test_the_world_model_learns_what_each_action_does_to_distance_and_angle(self):
        rng = random.Random(5)
        brain = mdb.Brain(seed=5, memory=200)
        for _ in range(160):
            brain.remember(experience(rng, rng.choice(mdb.ACTIONS)))
        held_out = [experience(rng, a) for a in mdb.ACTIONS for _ in range(10)]

        def mean_error():
            total = 0.0
            for e in held_out:
                p = brain.world.predict(e.before, e.action)
                total += abs(p.distance_m - e.after.distance_m) + abs(mdb.wrap(p.angle_rad - e.after.angle_rad))
            return total / len(held_out)

        before = mean_error()
        for _ in range(40):
            brain.learn()
        after = mean_error()
        self.assertLess(after, before / 4)
        self.assertLess(after, 0.08)
        ahead = mdb.Perception(2.0, 0.0, True, None)
        self.assertLess(brain.world.predict(ahead, "forward").distance_m, 1.9)
        self.assertGreater(brain.world.predict(ahead, "back").distance_m, 2.05)
        self.assertLess(brain.world.predict(ahead, "left").angle_rad, -0.4)
        self.assertGreater(brain.world.predict(ahead, "right").angle_rad, 0.4)

    def test_a_jump_of_the_target_teaches_nothing(self):
        rng = random.Random(1)
        brain = mdb.Brain(seed=1)
        for _ in range(30):
            brain.remember(experience(rng, "forward"))
        before = mdb.Perception(0.1, 0.0, True, None)
        brain.remember(mdb.Experience(before, "forward", mdb.Perception(2.5, 1.0, True, None), 1.0))
        for _ in range(30):
            brain.learn()
        self.assertLess(brain.world.predict(mdb.Perception(1.0, 0.0, True, None), "forward").distance_m, 0.95)


class ActionChoiceTest(unittest.TestCase):

    def test_action_choice_follows_the_command_mapping_it_learned(self):
        meaning = {"forward": "back", "left": "right", "right": "forward", "back": "left"}  # not the labels' own
        rng = random.Random(11)
        brain = mdb.Brain(seed=11, epsilon=0.0, epsilon_min=0.0)
        for command in mdb.COMMANDS:
            for action in mdb.ACTIONS:
                d, a = rng.uniform(0.5, 3), rng.uniform(-3, 3)
                d2, a2 = move(d, a, action)
                brain.remember(mdb.Experience(mdb.Perception(d, a, True, command), action,
                                              mdb.Perception(d2, a2, True, None),
                                              1.0 if meaning[command] == action else -1.0))
        for _ in range(25):
            brain.learn()
        for command, wanted in meaning.items():
            for angle in (-2.0, 0.0, 1.0):
                chosen, explored, scores = brain.decide(mdb.Perception(1.5, angle, True, command))
                self.assertFalse(explored)
                self.assertEqual(wanted, chosen, "command %s: %s" % (command, scores))

    def test_without_a_teacher_the_induced_model_approaches_the_target(self):
        rng = random.Random(4)
        brain = mdb.Brain(seed=4, memory=200, epsilon=0.0, epsilon_min=0.0)
        for e in taught(rng, 120):
            brain.remember(e)
        for _ in range(60):
            brain.learn()
        self.assertEqual("forward", brain.decide(mdb.Perception(2.0, 0.05, True, None))[0])
        self.assertEqual("left", brain.decide(mdb.Perception(2.0, 1.4, True, None))[0])
        self.assertEqual("right", brain.decide(mdb.Perception(2.0, -1.4, True, None))[0])
        # and it gets there: follow its choices through the exact geometry
        d, a = 2.0, 2.5
        for _ in range(40):
            if d <= 0.1:
                break
            d, a = move(d, a, brain.decide(mdb.Perception(d, a, True, None))[0])
        self.assertLessEqual(d, 0.1)


class PlasticityTest(unittest.TestCase):

    def test_punishments_overturn_a_relevance_entry_that_one_mistaken_reward_set(self):
        # One reward judged the wrong step (a command misheard, a reward that belonged to the step before): turning
        # right was asked for and going forward rewarded. The teacher then rarely says "right"; when it does, and
        # punishes forward, the robot must try something else within a few punishments.
        for seed in range(1, 7):
            rng = random.Random(seed)
            brain = mdb.Brain(seed=seed)
            ahead = mdb.Perception(1.0, 0.0, True, "right")
            brain.remember(mdb.Experience(ahead, "forward", mdb.Perception(0.8, 0.0, True, None), 1.0))
            brain.learn()
            for e in taught(rng, 80, obedience=0.9):
                if e.before.command != "right":
                    brain.remember(e)
                    brain.learn()
            punished = 0
            while punished < 10:
                chosen, _, scores = brain.decide(ahead)
                if chosen == "right":
                    break
                brain.remember(mdb.Experience(ahead, chosen, mdb.Perception(1.0, 0.0, True, None), -1.0))
                brain.learn()
                punished += 1
            self.assertLess(punished, 10, "seed %d: still not turning right after 10 punishments: %s" % (seed, scores))

    def test_a_reward_that_came_without_a_heard_command_teaches_nothing(self):
        memory = mdb.ShortTermMemory(capacity=10)
        rng = random.Random(2)
        memory.add(experience(rng, "back", None, 1.0))  # the teacher judged a command the robot did not hear
        memory.add(experience(rng, "forward", "forward", 1.0))
        self.assertEqual([("forward", "forward")], [(e.action, e.before.command) for e in memory.judged()])
        brain = mdb.Brain(seed=2)
        brain.remember(experience(rng, "back", None, 1.0))
        errors = brain.learn()
        self.assertNotIn("satisfaction.induced", errors)
        self.assertNotIn("relevance", errors)


class ScriptedLink:
    """The contract as the runner sees it, scripted: the target stays where it is, every action is judged at once
    (+1 for `wanted`, -1 otherwise) and followed by fresh samples, and no wait ever waits."""

    def __init__(self, wanted):
        self.wanted, self.acted, self.rewards, self.samples = wanted, [], [], []
        self.commands_heard = 0
        self._sample()

    def _sample(self):
        self.samples.append(DistanceAngle(1.5, 0.8, True, len(self.samples) + 1, 0.0, False))

    @property
    def distance_angle(self):
        return self.samples[-1]

    @property
    def rewards_heard(self):
        return len(self.rewards)

    def samples_after(self, number):
        return [s for s in self.samples if s.number > number]

    def rewards_after(self, mark):
        return self.rewards[mark:]

    def wait_until(self, predicate, timeout_s):
        return predicate()

    def act(self, label):
        self.acted.append(label)
        self.rewards.append(Event(len(self.rewards) + 1, 0.0, 1.0 if label == self.wanted else -1.0))
        for _ in range(3):
            self._sample()
        return True


class RunnerTest(unittest.TestCase):

    def test_a_punishment_is_learned_from_before_the_next_command_is_obeyed(self):
        # Told "left" again and again, a robot that learns from each judgement before its next decision never
        # repeats an action it was just punished for (learning only while the next action took effect, it did).
        for seed in range(1, 9):
            link = ScriptedLink("left")
            runner = mdb.Runner(link, mdb.Brain(seed=seed, epsilon=0.0, epsilon_min=0.0), step_s=0.0, reward_wait_s=0.0)
            while "left" not in link.acted and len(link.acted) < 8:
                runner._step(mdb.settled(link.samples[-3:], "left"), link.distance_angle.number, 0.0)
            self.assertEqual(len(set(link.acted)), len(link.acted), "seed %d: %s" % (seed, link.acted))
            self.assertEqual("left", link.acted[-1], "seed %d: %s" % (seed, link.acted))


class CautionTest(unittest.TestCase):

    def test_a_rarely_tried_action_is_not_taken_on_its_models_word(self):
        rng = random.Random(8)
        brain = mdb.Brain(seed=8, memory=200, epsilon=0.0, epsilon_min=0.0)
        for e in taught(rng, 120, obedience=1.0):
            brain.remember(e)
        # and some punished mistakes, never with `back`, so that the induced model has a contrast to learn from
        for e in taught(rng, 40, obedience=0.0):
            if e.action != "back" and e.reward < 0:
                brain.remember(e)
        # two experiences of `back` that look as if it closed in on the target: a model fitted to them alone
        # promises more than forward does
        for d, a in ((1.0, 0.2), (1.6, -0.2)):
            brain.remember(mdb.Experience(mdb.Perception(d, a, True, None), "back",
                                          mdb.Perception(d - 0.4, a, True, None), None))
        for _ in range(40):
            brain.learn()
        here = mdb.Perception(1.2, 0.0, True, None)
        raw = brain.satisfaction.induced_of(here, *brain.world.predict(here, "back")[:2])
        self.assertGreater(raw, brain.satisfaction.induced_of(here, *brain.world.predict(here, "forward")[:2]),
                           "the premise: back's own model promises more")
        self.assertAlmostEqual(0.25, brain.confidence("back"))
        self.assertEqual(1.0, brain.confidence("forward"))
        brain.horizon = 1  # one step: the blend is plain to see
        action, _, scores = brain.decide(here)
        self.assertEqual("forward", action, scores)
        stay = brain.satisfaction.induced_of(here, here.distance_m, here.angle_rad)
        self.assertAlmostEqual(stay + 0.25 * (raw - stay), scores["back"])
        brain.horizon = 2
        self.assertEqual("forward", brain.decide(here)[0])

    def test_a_perception_is_the_median_of_a_few_samples(self):
        da = [mdb.Perception(1.0, 0.0, True, None), mdb.Perception(1.1, 0.34, True, None),
              mdb.Perception(0.9, 0.0, False, None)]
        p = mdb.settled(da, "left")
        self.assertEqual((1.0, 0.0, True, "left"), tuple(p))
        # round +-pi the median is taken round the latest, not through 0
        p = mdb.settled([mdb.Perception(2.0, 3.1, True, None), mdb.Perception(2.0, -3.1, True, None),
                         mdb.Perception(2.0, 3.12, True, None)])
        self.assertAlmostEqual(3.12, p.angle_rad, places=6)
        self.assertFalse(mdb.settled([mdb.Perception(2.0, 0.1, False, None)] * 2 +
                                     [mdb.Perception(2.0, 0.1, True, None)]).seen)


class SonarBearingTest(unittest.TestCase):
    """A sonar ring reports the bearing of the transducer that sees the object: the angle comes in steps."""

    STEP_RAD = 0.35

    def sensed(self, d, a):
        return mdb.Perception(d, self.STEP_RAD * round(a / self.STEP_RAD), True, None)

    def approach(self, seed, horizon):
        rng = random.Random(seed)
        brain = mdb.Brain(seed=seed, memory=200, epsilon=0.0, epsilon_min=0.0, horizon=horizon)
        for e in taught(rng, 150, obedience=0.8):
            b, a = self.sensed(e.before.distance_m, e.before.angle_rad), self.sensed(e.after.distance_m, e.after.angle_rad)
            brain.remember(e._replace(before=b._replace(command=e.before.command), after=a))
        for _ in range(60):
            brain.learn()
        reached = 0
        for start in (0.3, -0.3, 0.45, -0.45, 2.0, -2.0, 2.9, -2.9):
            d, a = 1.6, start
            for _ in range(25):
                if d <= 0.1:
                    reached += 1
                    break
                d, a = move(d, a, brain.decide(self.sensed(d, a))[0])
        return reached

    def test_looking_two_steps_ahead_does_not_dither_between_turns_near_the_object(self):
        one = sum(self.approach(seed, horizon=1) for seed in (1, 2, 3))
        two = sum(self.approach(seed, horizon=2) for seed in (1, 2, 3))
        print("\nMDB sonar bearings: reached from %d of 24 starts looking one step ahead, %d of 24 looking two"
              % (one, two), file=sys.stderr)
        self.assertGreaterEqual(two, 21)
        # One step ahead dithered most (17 of 24) while the satisfaction model had a term for the |angle| after; on
        # changes alone it dithers less (22), and looking two steps ahead is still never worse.
        self.assertGreaterEqual(two, one)


class CameraViewTest(unittest.TestCase):
    """A camera sees the object within a field of view; outside it the perception keeps the last sighting, not
    seen. Near the object a 0.6 rad turn swings the bearing from one side to the other."""

    FOV_RAD = 0.9

    def approach(self, seed):
        rng = random.Random(seed)
        brain = mdb.Brain(seed=seed, epsilon=0.0, epsilon_min=0.0)
        for e in taught(rng, 40, obedience=0.6):  # a first episode's worth of teaching, often disobeyed
            brain.remember(e)
            brain.learn()
        reached, flips = 0, 0
        for start in (0.1, -0.1, 0.2, -0.2, 0.5, -0.5, 0.8, -0.8):
            d, a = 1.3, start
            last = mdb.Perception(d, a, True, None)
            actions = []
            for _ in range(30):
                if d <= 0.15:
                    reached += 1
                    break
                in_view = abs(a) <= self.FOV_RAD
                last = mdb.Perception(d, a, True, None) if in_view else last._replace(seen=False)
                actions.append(brain.decide(last)[0])
                d, a = move(d, a, actions[-1])
            flips += sum(1 for x, y in zip(actions, actions[1:]) if {x, y} == {"left", "right"})
        return reached, flips

    def test_a_plan_is_worth_the_satisfaction_of_each_of_its_steps_so_turning_back_and_forth_gains_nothing(self):
        # Scored by where it ends alone, a turn and its undoing looked like a gain whenever the models' two
        # predictions did not quite cancel, and the robot swung left and right in front of the object
        # (38 of 64 reached, 575 swings); step by step, a plan through a worse bearing pays for it (58, 145).
        results = [self.approach(seed) for seed in range(1, 9)]
        reached, flips = sum(r for r, _ in results), sum(f for _, f in results)
        print("\nMDB camera view: reached from %d of 64 starts, %d swings between left and right" % (reached, flips),
              file=sys.stderr)
        self.assertGreaterEqual(reached, 44)
        self.assertLessEqual(flips, 300)


class ApprovedMovesTest(unittest.TestCase):

    def test_alone_the_robot_makes_only_moves_its_teacher_has_rewarded(self):
        # The teacher never asked for `back`; exploration tried it often enough that its world model is trusted,
        # and those tries happened to close in on the target, so the models rank it first. Alone, the robot
        # does not take it: its teacher never rewarded it after any command.
        rng = random.Random(8)
        brain = mdb.Brain(seed=8, memory=200, epsilon=0.0, epsilon_min=0.0)
        for e in taught(rng, 120, obedience=1.0):
            brain.remember(e)
        for i in range(10):
            d, a = 1.0 + 0.1 * i, 0.1 * (i % 3 - 1)
            brain.remember(mdb.Experience(mdb.Perception(d, a, True, None), "back",
                                          mdb.Perception(d - 0.4, a, True, None), None))
        for _ in range(40):
            brain.learn()
        here = mdb.Perception(1.2, 0.0, True, None)
        _, _, scores = brain.decide(here)
        self.assertEqual("back", max(scores, key=scores.get), "the premise: the models rank back first")
        self.assertNotIn("back", brain.approved())
        self.assertNotEqual("back", brain.decide(here)[0])


class MirrorTest(unittest.TestCase):

    def test_a_turn_its_teacher_never_asked_for_is_approved_with_its_mirror(self):
        # The teacher had the object to the left or ahead every time and never said "right". Alone, with the
        # object on the right, the robot turns right, the mirror of the left turn it was rewarded for; `back`,
        # never rewarded and its own mirror, stays out.
        rng = random.Random(4)
        brain = mdb.Brain(seed=4, epsilon=0.0, epsilon_min=0.0)
        for e in taught(rng, 150, obedience=0.8):
            if e.before.command != "right":
                brain.remember(e)
        for _ in range(20):
            brain.learn()
        self.assertLess(max(brain.world.relevance_of("right", c) for c in mdb.COMMANDS), brain.APPROVED,
                        "the premise: turning right was never rewarded")
        self.assertIn("right", brain.approved())
        self.assertNotIn("back", brain.approved())
        self.assertEqual("right", brain.decide(mdb.Perception(1.4, -1.2, True, None))[0])

    def test_a_turn_made_only_one_way_teaches_the_other_way_too(self):
        # Every left turn was made with the target on the left (a teacher who only said "left"), and the right
        # turn was made twice. With the target 0.4 rad to the right, the world model predicts that a right turn
        # brings it towards the middle as far as the left turn does from 0.4 rad to the left, and trusts it as
        # much: alone near the ball, the Aibo turned away from it on the left turn's model.
        rng = random.Random(5)
        brain = mdb.Brain(seed=5)
        for i in range(12):
            d, a = rng.uniform(0.5, 2.0), rng.uniform(0.2, 0.9)
            action = "right" if i < 2 else "left"
            d2, a2 = move(d, a, action)
            brain.remember(mdb.Experience(mdb.Perception(d, a, True, None), action,
                                          mdb.Perception(d2, a2, True, None), None))
        for _ in range(30):
            brain.learn()
        self.assertEqual(1.0, brain.confidence("right"))
        _, truth = move(1.0, -0.4, "right")
        predicted = brain.world.predict(mdb.Perception(1.0, -0.4, True, None), "right").angle_rad
        self.assertLess(abs(predicted - truth), 0.15,
                        "right turn from -0.4 rad: predicted %.2f, truly %.2f" % (predicted, truth))


class StuckTest(unittest.TestCase):

    def walk_alone(self, brain, d, a, steps):
        for _ in range(steps):
            before = mdb.Perception(d, a, True, None)
            action = brain.decide(before)[0]
            d, a = move(d, a, action)
            brain.remember(mdb.Experience(before, action, mdb.Perception(d, a, True, None), None))
        return d

    def test_a_robot_whose_approved_moves_bring_it_no_closer_makes_the_others_too(self):
        # The teacher's rewards for `forward` never reached the robot (it heard "go forward" late, on a busy
        # computer, and moved too late every time): alone, with the object ahead, the only approved moves were the
        # turns, and the Aibo turned left and right for half a minute. Stuck, it goes forward, and keeps doing so.
        for seed in range(1, 4):
            rng = random.Random(seed)
            brain = mdb.Brain(seed=seed, epsilon=0.0, epsilon_min=0.0)
            for e in taught(rng, 150, obedience=0.8):
                if not (e.action == "forward" and e.reward > 0):
                    brain.remember(e)
            for _ in range(20):
                brain.learn()
            self.assertNotIn("forward", brain.approved(), "seed %d: the premise" % seed)
            end = self.walk_alone(brain, 1.4, 0.1, 30)
            self.assertIn("forward", brain.approved(), "seed %d: forward, made alone, brought it closer" % seed)
            self.assertLess(end, 0.6, "seed %d" % seed)

    def test_a_robot_that_comes_closer_keeps_to_its_approved_moves(self):
        brain = mdb.Brain(seed=1, epsilon=0.0, epsilon_min=0.0)
        for d in (1.4, 1.3, 1.2, 1.1, 1.0, 0.9, 0.8, 0.7):
            brain.decide(mdb.Perception(d, 0.1, True, None))
        self.assertFalse(brain.stuck())
        for a in (0.5, 0.1, 0.5, 0.1, 0.5, 0.1):
            brain.decide(mdb.Perception(0.68, a, True, None))
        self.assertTrue(brain.stuck(), "six decisions 2 cm closer and facing it no better than before them")
        brain = mdb.Brain(seed=1, epsilon=0.0, epsilon_min=0.0)
        for a in (2.9, 2.6, 2.3, 2.0, 1.7, 1.4, 1.1, 0.8, 0.5):
            brain.decide(mdb.Perception(0.9, a, True, None))
            self.assertFalse(brain.stuck(), "turning towards a target behind it")
        brain.decide(mdb.Perception(0.68, 0.1, True, "left"))
        self.assertFalse(brain.stuck(), "a command starts the count again")


class LostTargetTest(unittest.TestCase):

    def test_a_robot_that_has_lost_its_target_tries_other_moves(self):
        # The ball was last seen 0.74 m ahead; the robot, against a wall it cannot see, goes nowhere, and every
        # perception is that last sighting, not seen. Deciding on it the robot walked forward for ever; lost, it
        # tries other moves, turns among them.
        for seed in range(1, 6):
            rng = random.Random(seed)
            brain = mdb.Brain(seed=seed, epsilon=0.0, epsilon_min=0.0)
            for e in taught(rng, 120, obedience=0.9):
                brain.remember(e)
            for _ in range(30):
                brain.learn()
            seen = mdb.Perception(0.74, -0.08, True, None)
            self.assertEqual("forward", brain.decide(seen)[0], "seed %d: the premise" % seed)
            actions = [brain.decide(seen._replace(seen=False))[0] for _ in range(12)]
            self.assertNotEqual(["forward"] * 12, actions, "seed %d" % seed)
            self.assertTrue({"left", "right"} & set(actions), "seed %d: %s" % (seed, actions))


class MemoryTest(unittest.TestCase):

    def test_a_full_memory_forgets_routine_before_rare_lessons(self):
        memory = mdb.ShortTermMemory(capacity=10)
        rng = random.Random(0)
        memory.add(experience(rng, "back", "forward", -1.0))
        for _ in range(30):
            memory.add(experience(rng, "forward", "forward", 1.0))
        self.assertEqual(10, len(memory))
        self.assertIn(("back", -1.0), [(e.action, e.reward) for e in memory.experiences()])


def ports_args(world):
    p = world.ports
    return ["--command-port", str(p["command"]), "--distance-angle-port", str(p["distance_angle"]),
            "--reward-port", str(p["reward"]), "--action-port", str(p["action"])]


class FakeWorldTest(unittest.TestCase):

    def test_the_fake_world_answers_bad_lines_with_errors_and_keeps_serving(self):
        with FakeWorld(seed=1, speed=5.0) as world:
            with socket.create_connection(("127.0.0.1", world.ports["action"]), timeout=5) as s:
                f = s.makefile("rwb")
                self.assertEqual("hello", json.loads(f.readline())["type"])
                for bad, code in ((b"{nope\n", "bad_json"), (b'{"value":"fly"}\n', "bad_value"),
                                  (b'{"op":"dance"}\n', "unknown_op")):
                    f.write(bad)
                    f.flush()
                    line = json.loads(f.readline())
                    while line["type"] == "sample":
                        line = json.loads(f.readline())
                    self.assertEqual(("error", code), (line["type"], line["code"]))
                f.write(b'{"op":"write","value":"forward","id":7}\n')
                f.flush()
                seen = [json.loads(f.readline()) for _ in range(2)]
                self.assertIn({"type": "ok", "id": 7}, seen)
            deadline = time.monotonic() + 5
            while world.results()["actions"] < 1 and time.monotonic() < deadline:
                time.sleep(0.01)
            self.assertEqual(1, world.results()["actions"])


class EndToEndTest(unittest.TestCase):
    SPEED = 12.0
    TEACHER_COMMANDS = 40
    COMMAND_EVERY_S = 2.0
    APPROACH_LIMIT_S = 60.0  # world seconds after the teacher leaves

    def episode(self, seed, log_dir):
        """One episode: a fresh world and a fresh brain with this seed; returns the world's results."""
        with FakeWorld(seed=seed, speed=self.SPEED, command_every_s=self.COMMAND_EVERY_S,
                       teacher_commands=self.TEACHER_COMMANDS) as world:
            log = os.path.join(log_dir, "episode-%d.jsonl" % seed)
            proc = subprocess.Popen([sys.executable, os.path.join(HERE, "mdb.py"), "--seed", str(seed),
                                     "--speed", str(self.SPEED), "--absent-after-s", str(4.5 / self.SPEED),
                                     "--max-seconds", "40", "--log", log] + ports_args(world))
            try:
                deadline = time.monotonic() + 30
                while time.monotonic() < deadline:
                    r = world.results()
                    if r["reachedAfterS"] is not None or (
                            r["teacherLeftAt"] is not None and r["now"] - r["teacherLeftAt"] > self.APPROACH_LIMIT_S):
                        break
                    time.sleep(0.05)
            finally:
                proc.terminate()
                proc.wait(timeout=10)
            r = world.results()
            r["decisions"] = 0
            if os.path.exists(log):
                with open(log) as f:
                    r["decisions"] = sum(1 for line in f if '"step"' in line)
            return r

    def test_after_the_teacher_leaves_the_robot_reaches_the_object_in_most_seeded_episodes(self):
        with tempfile.TemporaryDirectory() as tmp, concurrent.futures.ThreadPoolExecutor(5) as pool:
            results = list(pool.map(lambda s: self.episode(s, tmp), range(1, 11)))
        summary = [(r["teacherLeftAt"] is not None, r["reachedAfterS"], round(r["distanceM"], 2)) for r in results]
        for r in results:
            self.assertIsNotNone(r["teacherLeftAt"], summary)
            self.assertGreater(r["decisions"], self.TEACHER_COMMANDS // 2, summary)
        first = [v for r in results for _, _, v in r["rewards"][:10]]
        last = [v for r in results for _, _, v in r["rewards"][-10:]]
        self.assertGreater(last.count(1), 0.7 * len(last), "obedience at the end of teaching")
        self.assertGreater(last.count(1), first.count(1) + 20, "obedience grows while taught")
        reached = [r for r in results if r["reachedAfterS"] is not None and r["reachedAfterS"] <= self.APPROACH_LIMIT_S]
        print("\nMDB end to end: obedience %d/%d in the first 10 commands, %d/%d in the last 10"
              % (first.count(1), len(first), last.count(1), len(last)), file=sys.stderr)
        print("MDB end to end: %d of 10 episodes reached the object after the teacher left; %s"
              % (len(reached), summary), file=sys.stderr)
        self.assertGreaterEqual(len(reached), 8, summary)

    def test_a_malformed_line_from_the_daemon_is_skipped_and_nothing_else_changes(self):
        with FakeWorld(seed=4, speed=5.0) as world:
            link = ContractLink("127.0.0.1", world.ports, retry_s=0.1).start()
            try:
                self.assertTrue(link.wait_until(lambda: link.samples_seen > 0, 5.0))
                for client in list(world.servers["distance_angle"].clients):
                    client.send_raw(b"{this is not json\n")
                    client.send_raw(b"[1, 2, 3]\n")
                # The client library reports such lines and reads on: no reconnect is needed.
                seen = link.samples_seen
                self.assertTrue(link.wait_until(lambda: link.samples_seen > seen + 5, 5.0))
                self.assertEqual(link.connections, 1)
                seen = link.samples_seen
                self.assertTrue(link.wait_until(lambda: link.samples_seen > seen, 5.0))
                self.assertTrue(link.act("back"))
            finally:
                link.close()

    def test_the_mdb_program_keeps_deciding_across_a_daemon_restart(self):
        world = FakeWorld(seed=5, speed=10.0, teacher_commands=0).start()
        ports = dict(world.ports)
        with tempfile.TemporaryDirectory() as tmp:
            log = os.path.join(tmp, "restart.jsonl")
            proc = subprocess.Popen([sys.executable, os.path.join(HERE, "mdb.py"), "--speed", "10",
                                     "--absent-after-s", "0.3", "--max-seconds", "30", "--log", log]
                                    + ports_args(world))

            def decisions():
                if not os.path.exists(log):
                    return 0
                with open(log) as f:
                    return sum(1 for line in f if '"step"' in line)

            def wait_for(predicate, seconds):
                deadline = time.monotonic() + seconds
                while not predicate() and time.monotonic() < deadline:
                    time.sleep(0.05)
                return predicate()

            try:
                self.assertTrue(wait_for(lambda: decisions() >= 3, 15))
                world.stop()
                time.sleep(0.5)
                before = decisions()
                world = FakeWorld(seed=6, speed=10.0, teacher_commands=0, ports=ports).start()
                self.assertTrue(wait_for(lambda: decisions() >= before + 3, 15), "no decisions after the restart")
                self.assertIsNone(proc.poll())
                self.assertGreater(world.results()["actions"], 0)
            finally:
                proc.terminate()
                proc.wait(timeout=10)
                world.stop()
            with open(log) as f:
                events = [json.loads(line).get("event") for line in f]
            self.assertEqual(2, events.count("connected"), events)
            self.assertEqual("stopped", events[-1])

    def test_the_link_reconnects_when_the_daemon_restarts(self):
        world = FakeWorld(seed=2, speed=5.0).start()
        ports = {"command": world.ports["command"], "distance_angle": world.ports["distance_angle"],
                 "reward": world.ports["reward"], "action": world.ports["action"]}
        events = []
        link = ContractLink("127.0.0.1", ports, retry_s=0.1, on_event=lambda k, d: events.append(k)).start()
        try:
            self.assertTrue(link.wait_connected(5.0))
            self.assertTrue(link.wait_until(lambda: link.samples_seen > 0, 5.0))
            world.stop()
            self.assertTrue(link.wait_until(lambda: not link._connected, 5.0))
            self.assertFalse(link.act("forward"))
            world = FakeWorld(seed=3, speed=5.0, ports=ports).start()
            self.assertTrue(link.wait_until(lambda: link.connections == 2, 10.0), events)
            seen = link.samples_seen
            self.assertTrue(link.wait_until(lambda: link.samples_seen > seen, 5.0))
            self.assertTrue(link.act("left"))
            deadline = time.monotonic() + 5
            while world.results()["actions"] < 1 and time.monotonic() < deadline:
                time.sleep(0.01)
            self.assertEqual(1, world.results()["actions"])
        finally:
            link.close()
            world.stop()


if __name__ == "__main__":
    unittest.main()
