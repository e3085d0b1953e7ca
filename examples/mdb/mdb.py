"""A control architecture in the manner of the Multilevel Darwinist Brain, over HABLA's control contract.

It knows four sockets and nothing of the robot behind them: the teacher's `command` labels, the
`distance_angle` to a target object, the teacher's `reward` and the `action` it writes. Everything it
knows about what those mean it learns:

* a short-term memory of experiences: perception before, action, perception after, reward;
* a world model that predicts, for each action, the next perception: how distance and angle change,
  and the *relevance* of the action to the command heard (the reward the teacher is expected to give);
* a satisfaction model that predicts the reward from perceptions: while a command is heard,
  satisfaction is the reward, so the predicted relevance gives it; the induced model gives it from the
  non-command sensors (the change of distance and of |angle|, and the |angle| after);
* an evolutionary search per model (a population of parameter vectors, crossover, self-adaptive
  Gaussian mutation, selection on the error over the memory), run after each experience;
* action selection: for every candidate action, predict with the world model, score with the
  satisfaction model, take the best, with an exploration rate that decays.

While a teacher is present (commands keep coming) the robot acts once per command and the relevance
drives it; the induced model learns on the side that the rewards came with getting closer and facing
the target. When no command has come for `--absent-after-s`, the induced model drives the robot, which
keeps approaching the object on its own.

    python3 mdb.py --host 127.0.0.1 --seed 7 --log decisions.jsonl --max-seconds 600

One JSON line per decision goes to `--log` (stderr by default).
"""

import argparse
import collections
import json
import math
import random
import signal
import sys
import time

from habla_contract import ContractLink

ACTIONS = ("forward", "left", "right", "back")
COMMANDS = ("forward", "left", "right", "back")  # labels the teacher may use; their meaning is learned
MIRROR = {"forward": "forward", "left": "right", "right": "left", "back": "back"}  # each move seen in a mirror


JUMP = 4.0  # a distance change beyond JUMP * distance scale is not the robot's doing
OUTLIER = 4.0  # cap on one experience's squared error (in scale units): a target moved, a wheel slipped


def wrap(angle):
    """The angle in (-pi, pi]."""
    return math.atan2(math.sin(angle), math.cos(angle))


def clamp(x, lo, hi):
    return lo if x < lo else hi if x > hi else x


class Perception(collections.namedtuple("Perception", "distance_m angle_rad seen command")):
    """What the robot senses at one instant: target distance (m) and angle (rad, + left), whether the
    target is perceived now, and the command just heard (a label, or None)."""


def settled(samples, command=None):
    """One perception from a few consecutive distance_angle samples: the median distance and the median
    angle (taken round the latest, so that +-pi is no seam), seen if most of them saw the target. A
    sonar's angle jumps between neighbouring transducers' directions from one scan to the next; the
    median of three keeps one odd scan from steering the robot."""
    latest = samples[-1]
    distances = sorted(s.distance_m for s in samples)
    offsets = sorted(wrap(s.angle_rad - latest.angle_rad) for s in samples)
    mid = len(samples) // 2
    if len(samples) % 2:
        d, o = distances[mid], offsets[mid]
    else:
        d, o = (distances[mid - 1] + distances[mid]) / 2, (offsets[mid - 1] + offsets[mid]) / 2
    seen = 2 * sum(1 for s in samples if s.seen) > len(samples)
    return Perception(d, wrap(latest.angle_rad + o), seen, command)


class Experience(collections.namedtuple("Experience", "before action after reward")):
    """One step: the perception before, the action taken, the perception after, and the reward heard
    for it (None when no reward came)."""

    @property
    def delta_distance(self):
        return self.after.distance_m - self.before.distance_m

    @property
    def delta_angle(self):
        return wrap(self.after.angle_rad - self.before.angle_rad)

    @property
    def delta_abs_angle(self):
        return abs(self.after.angle_rad) - abs(self.before.angle_rad)

    @property
    def sighted(self):
        return self.before.seen and self.after.seen


def mirrored(experience):
    """The same step seen in a mirror: the target on the other side, the mirror image of the move (MIRROR). The
    body is the same on both sides, so a left turn with the target 0.4 rad to the left tells what a right turn
    does with it 0.4 rad to the right. The teacher's judgement is left out: what a command means is learned, not
    mirrored."""
    b, a = experience.before, experience.after
    return Experience(Perception(b.distance_m, -b.angle_rad, b.seen, None), MIRROR[experience.action],
                      Perception(a.distance_m, -a.angle_rad, a.seen, None), None)


def usable(experience, distance_scale_m):
    """Whether an experience can teach the models: the target was seen before and after, and the distance
    did not jump by more than JUMP steps' worth (the target was moved, or another object taken for it)."""
    return experience.sighted and abs(experience.delta_distance) <= JUMP * distance_scale_m


class ShortTermMemory:
    """The last experiences, bounded. When full it forgets the oldest experience of the most crowded
    kind (action and sign of the reward), so rare lessons such as a punishment outlive routine ones."""

    def __init__(self, capacity=80):
        if capacity < 4:
            raise ValueError("memory capacity must be at least 4, got %r" % capacity)
        self.capacity = capacity
        self._items = []

    def __len__(self):
        return len(self._items)

    @staticmethod
    def _kind(e):
        sign = None if e.reward is None else (e.reward > 0) - (e.reward < 0)
        return e.action, sign

    def add(self, experience):
        self._items.append(experience)
        if len(self._items) > self.capacity:
            counts = collections.Counter(self._kind(e) for e in self._items)
            crowded = max(counts.values())
            for i, e in enumerate(self._items):
                if counts[self._kind(e)] == crowded:
                    del self._items[i]
                    break

    def experiences(self):
        return list(self._items)

    def judged(self):
        """Experiences the teacher judged: a command was heard before the action and a reward came for it. A
        reward that came when no command had been heard judges a command the robot missed; it teaches nothing."""
        return [e for e in self._items if e.reward is not None and e.before.command in COMMANDS]


class Evolution:
    """A population of parameter vectors improved against an error function (lower is better).

    Each generation keeps the `elite` best, and breeds the rest from the better half: uniform crossover
    of two tournament winners, then Gaussian mutation whose step size each individual carries and
    mutates itself (log-normal), never below `MIN_SIGMA`. The whole population is re-scored at every run,
    because the memory it is scored on has changed since the last.

    The floor keeps a model able to move: a step size left to shrink while nothing changes (it fell to about
    0.001 within a hundred runs) leaves a model that can no longer follow what changes later; a relevance
    entry that one early mistake had set high stayed there through a dozen punishments."""

    MIN_SIGMA = 0.03

    def __init__(self, dim, rng, size=16, elite=4, init_scale=0.1, sigma=0.3):
        if dim < 1 or size < 4 or not 1 <= elite < size:
            raise ValueError("need dim >= 1, size >= 4 and 1 <= elite < size")
        self.dim, self.size, self.elite, self._rng = dim, size, elite, rng
        self._tau = 1.0 / math.sqrt(2.0 * dim)
        self._gene_rate = min(1.0, 3.0 / dim)
        self.population = [([rng.gauss(0.0, init_scale) for _ in range(dim)], sigma) for _ in range(size)]
        self.best = list(self.population[0][0])
        self.best_error = None
        self.generations = 0

    def _tournament(self, scored):
        a, b = self._rng.choice(scored), self._rng.choice(scored)
        return a if a[0] <= b[0] else b

    def _child(self, parents):
        rng = self._rng
        _, pa, sa = self._tournament(parents)
        _, pb, sb = self._tournament(parents)
        genes = [x if rng.random() < 0.5 else y for x, y in zip(pa, pb)]
        sigma = clamp(math.sqrt(sa * sb) * math.exp(self._tau * rng.gauss(0.0, 1.0)), self.MIN_SIGMA, 2.0)
        forced = rng.randrange(self.dim)
        return [g + sigma * rng.gauss(0.0, 1.0) if i == forced or rng.random() < self._gene_rate else g
                for i, g in enumerate(genes)], sigma

    def run(self, error, generations=1):
        """Runs some generations against `error(params) -> float`; returns the best error."""
        scored = sorted(((error(p), p, s) for p, s in self.population), key=lambda t: t[0])
        for _ in range(generations):
            parents = scored[:max(self.elite, self.size // 2)]
            children = []
            for _ in range(self.size - self.elite):
                params, sigma = self._child(parents)
                children.append((error(params), params, sigma))
            scored = sorted(scored[:self.elite] + children, key=lambda t: t[0])
            self.generations += 1
        self.population = [(p, s) for _, p, s in scored]
        self.best_error, self.best = scored[0][0], list(scored[0][1])
        return self.best_error


def motion_features(distance_m, angle_rad):
    """The inputs of a motion model: what a move does to distance and angle depends on where the target is."""
    return (1.0, math.cos(angle_rad), math.sin(angle_rad), math.sin(angle_rad) / max(distance_m, 0.25))


class Prediction(collections.namedtuple("Prediction", "distance_m angle_rad relevance")):
    """The world model's next perception for one action: distance, angle and command relevance."""


class WorldModel:
    """Predicts the next perception from the current one and an action.

    Per action a motion model (8 parameters): the change of distance and of angle are each a linear
    function of `motion_features`, in units of `distance_scale_m` and `angle_scale_rad`. One relevance
    table (actions x commands): the reward the teacher is expected to give for an action after a command.
    Each part is its own evolving population, scored on the experiences it can explain. A motion model learns
    from its action's steps and from its mirror image's steps seen in a mirror (`mirrored`)."""

    MOTION_DIM = 8
    RELEVANCE_DECAY = 0.05  # pulls untried entries of the table towards 0: neither good nor bad
    RELEVANCE_GENERATIONS = 3  # the table gets this many times the generations: commands are few and precious
    RELEVANCE_HALF_LIFE = 3.0  # later judgements of the same action and command after which one counts half

    def __init__(self, rng, distance_scale_m=0.2, angle_scale_rad=0.5, population=16):
        self.ds, self.as_ = distance_scale_m, angle_scale_rad
        self.motion = {a: Evolution(self.MOTION_DIM, rng, size=population) for a in ACTIONS}
        self.relevance = Evolution(len(ACTIONS) * len(COMMANDS), rng, size=population, init_scale=0.05)

    def _motion(self, params, distance_m, angle_rad):
        f = motion_features(distance_m, angle_rad)
        dd = self.ds * sum(w * x for w, x in zip(params[:4], f))
        da = self.as_ * sum(w * x for w, x in zip(params[4:], f))
        return dd, da

    @staticmethod
    def _relevance(params, action, command):
        if command not in COMMANDS:
            return 0.0
        return clamp(params[ACTIONS.index(action) * len(COMMANDS) + COMMANDS.index(command)], -1.0, 1.0)

    def predict(self, perception, action):
        dd, da = self._motion(self.motion[action].best, perception.distance_m, perception.angle_rad)
        return Prediction(max(0.0, perception.distance_m + dd), wrap(perception.angle_rad + da),
                          self._relevance(self.relevance.best, action, perception.command))

    def relevance_of(self, action, command):
        return self._relevance(self.relevance.best, action, command)

    def motion_error(self, params, experiences):
        total = 0.0
        for e in experiences:
            dd, da = self._motion(params, e.before.distance_m, e.before.angle_rad)
            total += min(OUTLIER, ((dd - e.delta_distance) / self.ds) ** 2 + (wrap(da - e.delta_angle) / self.as_) ** 2)
        return total / len(experiences)

    def relevance_error(self, params, weighted):
        """Weighted mean squared error over (experience, weight) pairs, plus a little decay."""
        total = sum(w * (e.reward - self._relevance(params, e.action, e.before.command)) ** 2 for e, w in weighted)
        return total / sum(w for _, w in weighted) + self.RELEVANCE_DECAY * sum(p * p for p in params) / len(params)

    def recency_weighted(self, judged):
        """Each judged experience with its weight: halved for every RELEVANCE_HALF_LIFE later judgements of the
        same action after the same command. An entry of the table is then a mean that follows the teacher's
        latest judgements of it, so a few punishments outweigh an early reward that was a mistake (a command
        misheard, a reward that judged the step before)."""
        later = collections.Counter()
        out = []
        for e in reversed(judged):
            pair = (e.action, e.before.command)
            out.append((e, 0.5 ** (later[pair] / self.RELEVANCE_HALF_LIFE)))
            later[pair] += 1
        out.reverse()
        return out

    def learn(self, memory, generations):
        """Evolves every part that has experiences to learn from; returns the errors by part."""
        errors = {}
        sighted = [e for e in memory.experiences() if usable(e, self.ds)]
        for action, population in self.motion.items():
            # Every move learns from its mirror image's steps too: with a teacher who only ever said "left" (the
            # ball always started on the robot's left), the right turn had two or three steps behind it; alone,
            # with the ball 0.36 rad to its right at 0.28 m, the Aibo turned left, away, on the left turn's model
            # (the right one was barely trusted), lost the ball and searched for it until its time ran out.
            mine = [e for e in sighted if e.action == action] + [mirrored(e) for e in sighted if MIRROR[e.action] == action]
            if mine:
                errors["motion." + action] = population.run(lambda p: self.motion_error(p, mine), generations)
        errors.update(self.learn_relevance(memory, generations))
        return errors

    def learn_relevance(self, memory, generations):
        """Evolves the relevance table alone (a few milliseconds); returns its error by part."""
        judged = self.recency_weighted(memory.judged())
        if not judged:
            return {}
        return {"relevance": self.relevance.run(lambda p: self.relevance_error(p, judged),
                                                generations * self.RELEVANCE_GENERATIONS)}


class SatisfactionModel:
    """Predicts satisfaction (the reward to come) from a perception and its predicted successor.

    While a command is heard, satisfaction is the reward, so the predicted satisfaction is the command
    relevance the world model predicts. Without one, the induced model — fitted to the same rewards but
    over the other sensors only — gives it, linear in the change of distance and the change of |angle| (each
    in scale units, clipped to +-2), and clipped to [-1, 1] when fitted. It is
    what remains useful once the teacher has gone."""

    # Changes only: with a term for the |angle| after, a teacher who rewarded and rarely punished (+7 -0) gave it
    # a positive weight — every rewarded step ends at some |angle| > 0, and the decay spreads the weight over every
    # input that is positive whenever the reward is — so alone, close to the ball, the Aibo found more satisfaction
    # the further the ball was off to the side, turned it out of view and searched until its time ran out. The
    # rewarded steps all came closer or faced the target better, so the changes get the right signs either way.
    DIM = 3
    # Fitted through a clip to [-1, 1], the model is free above +1 and below -1: without a real decay its weights
    # drift to any size that keeps the rewarded steps above +1, and the unclipped values a plan is ranked by say
    # more of that drift than of the rewards (the Pioneer, alone, backed away from the object because a bearing
    # that grew as it closed in cost more than the distance gained). The decay keeps the smallest weights that
    # explain the rewards.
    DECAY = 0.05

    def __init__(self, rng, distance_scale_m=0.2, angle_scale_rad=0.5, population=16):
        self.ds, self.as_ = distance_scale_m, angle_scale_rad
        self.induced = Evolution(self.DIM, rng, size=population)

    def sensed(self, before, after_distance_m, after_angle_rad):
        """The induced model's inputs for a move from `before` to the given distance and angle."""
        return (clamp((after_distance_m - before.distance_m) / self.ds, -2.0, 2.0),
                clamp((abs(after_angle_rad) - abs(before.angle_rad)) / self.as_, -2.0, 2.0))

    @staticmethod
    def _induced(params, x):
        return params[0] + params[1] * x[0] + params[2] * x[1]

    @staticmethod
    def of_command(relevance):
        return relevance

    def induced_of(self, before, after_distance_m, after_angle_rad):
        """The induced satisfaction of going from `before` to the given distance and angle (unclipped, so
        that it still ranks actions where the clipped value would be a tie)."""
        return self._induced(self.induced.best, self.sensed(before, after_distance_m, after_angle_rad))

    def induced_error(self, params, examples):
        """Mean squared error over (inputs, reward) pairs, plus a little weight decay."""
        return (sum((r - clamp(self._induced(params, x), -1.0, 1.0)) ** 2 for x, r in examples) / len(examples)
                + self.DECAY * sum(p * p for p in params))

    def learn(self, memory, generations):
        examples = [(self.sensed(e.before, e.after.distance_m, e.after.angle_rad), e.reward)
                    for e in memory.judged() if usable(e, self.ds)]
        if not examples:
            return {}
        return {"satisfaction.induced": self.induced.run(lambda p: self.induced_error(p, examples), generations)}


class Brain:
    """Memory, models and action selection; the part of the architecture that knows no sockets."""

    TRUSTED_AFTER = 8  # experiences of an action after which its world model is fully trusted
    SECOND_STEP = 0.5  # what the second step of a plan counts for: it is predicted from a prediction
    APPROVED = 0.5  # relevance above which a move counts as one the teacher has rewarded
    LOST_AFTER = 3  # decisions without seeing the target after which, uncommanded, the robot tries moves at random
    STUCK_AFTER = 6  # uncommanded decisions in sight without coming closer or facing the target better: stuck
    STUCK_GAIN_M = 0.05  # what counts as having come closer, above the noise of a sighting
    STUCK_GAIN_RAD = 0.2  # what counts as facing the target better

    def __init__(self, seed=0, memory=80, population=16, generations=3, epsilon=0.2, epsilon_decay=0.97,
                 epsilon_min=0.02, distance_scale_m=0.2, angle_scale_rad=0.5, horizon=2):
        self.rng = random.Random(seed)
        self.memory = ShortTermMemory(memory)
        self.world = WorldModel(self.rng, distance_scale_m, angle_scale_rad, population)
        self.satisfaction = SatisfactionModel(self.rng, distance_scale_m, angle_scale_rad, population)
        self.generations = generations
        self.horizon = horizon
        self.epsilon0, self.epsilon_decay, self.epsilon_min = epsilon, epsilon_decay, epsilon_min
        self.decisions = 0
        self.errors = {}
        self.predictions = {}
        self.unseen = 0  # decisions in a row taken while the target was not seen
        self.alone = collections.deque(maxlen=self.STUCK_AFTER + 1)  # (distance, |angle|) of the last uncommanded decisions in sight
        self.proven = set()  # moves not approved by the teacher that, tried when stuck, brought the robot closer
        self.trying = None  # the move not approved that the robot, stuck, is making now
        self.failed = set()  # moves not approved that, tried since the robot got stuck, brought it no closer

    def confidence(self, action):
        """How far the world model of `action` can be trusted, 0..1: n / TRUSTED_AFTER, n being the
        experiences of that action and of its mirror image it has learned from, at most 1. An action tried a few times has a model
        fitted to a few points, whose guesses away from them are anybody's."""
        n = sum(1 for e in self.memory.experiences() if e.action in (action, MIRROR[action]) and usable(e, self.world.ds))
        return min(1.0, n / self.TRUSTED_AFTER)

    @property
    def epsilon(self):
        return max(self.epsilon_min, self.epsilon0 * self.epsilon_decay ** self.decisions)

    def score(self, perception, action):
        """The satisfaction predicted for taking `action` now."""
        predicted = self.world.predict(perception, action)
        if perception.command in COMMANDS:
            return self.satisfaction.of_command(predicted.relevance)
        return self.satisfaction.induced_of(perception, predicted.distance_m, predicted.angle_rad)

    def decide(self, perception):
        """Chooses an action; returns (action, explored, scores by action).

        With a command, an action's score is the relevance the world model predicts for it. Without one,
        the induced satisfaction model scores a short plan step by step: for `horizon` 2, every action
        followed by every action, a plan worth the satisfaction of its first step plus SECOND_STEP times
        that of its second, each first action scored by its best plan. One step alone rewards moves that
        only seem to gain — near the object, a turn that flips a sonar's bearing from one side to the other
        looks like facing it better, and the turn back looks the same; over two steps a turn and its undoing
        pay for the worse bearing they pass through, while closing in twice gains twice.

        A plan is only as good as the experience behind it: its satisfaction is pulled towards that of
        staying where the robot is — what an unknown move is worth, neither gain nor loss — in proportion
        to how little the world models of its actions have seen (the least `confidence` of them), so a
        rarely tried action is not taken on a badly trained model's word, yet is not ruled out either when
        everything known makes matters worse. The relevance table needs no such care: its untried entries
        sit at 0, below rewarded ones."""
        self.unseen = 0 if perception.seen else self.unseen + 1
        if perception.command in COMMANDS or not perception.seen:
            self.alone.clear()
        else:
            self.alone.append((perception.distance_m, abs(perception.angle_rad)))
        self.predictions = {a: self.world.predict(perception, a) for a in ACTIONS}
        if perception.command in COMMANDS:
            scores = {a: self.score(perception, a) for a in ACTIONS}
        else:
            scores = self._plan_scores(perception)
        # Lost: a target not seen for a while is where it was last seen only in the perception, which the robot's
        # moves no longer change. Deciding on that frozen sighting, the Aibo walked into a wall for half a minute with
        # the ball it had lost 0.74 m "ahead"; when its moves change nothing it sees, it tries moves at random.
        lost = perception.command not in COMMANDS and self.unseen > self.LOST_AFTER
        explored = lost or self.rng.random() < self.epsilon
        candidates = ACTIONS if perception.command in COMMANDS else self.approved()
        untried = self._untried(perception, candidates)
        if explored:
            action = self.rng.choice(ACTIONS)
        else:
            pool = untried or candidates
            top = max(scores[a] for a in pool)
            action = self.rng.choice([a for a in pool if scores[a] >= top - 1e-9])
        self.trying = action if action in untried else None
        self.decisions += 1
        return action, explored, scores

    def stuck(self):
        """Whether the robot, alone and in sight of the target, has made STUCK_AFTER decisions without coming
        STUCK_GAIN_M closer or turning STUCK_GAIN_RAD more towards the target than it was before them. Under load
        the Aibo heard its teacher late and was never rewarded for `forward`; alone, with the ball ahead, it turned
        left and right for half a minute, the only moves approved, while its satisfaction model ranked `forward`
        first. Stuck, it tries the moves not approved, one at a time, the best scored first: one that brings it
        closer is approved from then on (`proven`), one that does not is left until the robot is no longer stuck.
        Moves that only happened to bring it closer while exploring are not: exploration is where the models that
        misled it came from."""
        if len(self.alone) <= self.STUCK_AFTER:
            return False
        (d0, a0), since = self.alone[0], list(self.alone)[1:]
        return min(d for d, _ in since) > d0 - self.STUCK_GAIN_M and min(a for _, a in since) > a0 - self.STUCK_GAIN_RAD

    def _untried(self, perception, approved):
        """Stuck (uncommanded), the moves not approved that it has not yet tried since it got stuck, best first."""
        if perception.command in COMMANDS or not self.stuck():
            self.failed.clear()
            return []
        return [a for a in ACTIONS if a not in approved and a not in self.failed]

    def approved(self):
        """The moves the robot makes when no command is heard: those the teacher has rewarded after some command
        (relevance above APPROVED) and their mirror images (MIRROR: the body is the same on both sides, so a turn
        rewarded one way is a move it knows the other way too), those that brought it closer when it tried them
        stuck (`proven`, see `stuck`), or every move while it has rewarded none. A move the
        teacher never asked for is known to the satisfaction model only from the few times exploration or a mistake
        made it; alone, the Pioneer trusted such a model of `back` and backed away from an object straight ahead. A
        teacher who never needed to say "right" leaves only its mirror rewarded: without the mirror, the robots drove
        on with the object passing behind them on that side."""
        rewarded = {a for a in ACTIONS if max(self.world.relevance_of(a, c) for c in COMMANDS) > self.APPROVED}
        if not rewarded:
            return list(ACTIONS)
        return [a for a in ACTIONS if a in rewarded or MIRROR[a] in rewarded or a in self.proven]

    def _plan_scores(self, perception):
        trust = {a: self.confidence(a) for a in ACTIONS}
        induced = self.satisfaction.induced_of
        plans = {}  # first action -> [(satisfaction, confidence)] of its plans
        for first, p in self.predictions.items():
            now = induced(perception, p.distance_m, p.angle_rad)
            if self.horizon < 2:
                plans[first] = [(now, trust[first])]
                continue
            middle = Perception(p.distance_m, p.angle_rad, True, None)
            plans[first] = [(now + self.SECOND_STEP * induced(middle, e.distance_m, e.angle_rad), min(trust[first], trust[a]))
                            for a, e in ((a, self.world.predict(middle, a)) for a in ACTIONS)]
        stay = (1 + (self.SECOND_STEP if self.horizon >= 2 else 0)) * induced(perception, perception.distance_m,
                                                                            perception.angle_rad)
        return {a: max(stay + c * (v - stay) for v, c in ends) for a, ends in plans.items()}

    def remember(self, experience):
        self.memory.add(experience)
        e = experience
        if e.action == self.trying and e.sighted:
            (self.proven if e.delta_distance < -self.STUCK_GAIN_M else self.failed).add(e.action)

    def learn_judgement(self):
        """What a judgement teaches at once: the relevance table, so that the next command is obeyed in its light
        (the world and satisfaction models learn from it while the next action takes effect)."""
        errors = self.world.learn_relevance(self.memory, self.generations)
        self.errors.update(errors)
        return errors

    def learn(self, generations=None):
        """One round of evolution of every model on the memory; returns the errors by model."""
        g = self.generations if generations is None else generations
        errors = self.world.learn(self.memory, g)
        errors.update(self.satisfaction.learn(self.memory, g))
        self.errors.update(errors)
        return errors


class Runner:
    """The decision loop over a `ContractLink`: wait for a fresh perception (or a command), decide, write
    the action, learn while it takes effect, then record the experience with the reward it earned."""

    def __init__(self, link, brain, step_s=1.2, reward_wait_s=2.0, absent_after_s=8.0, log=None, clock=time.monotonic,
                 smooth=3):
        self.link, self.brain = link, brain
        self.smooth = max(1, smooth)
        self.step_s, self.reward_wait_s, self.absent_after_s = step_s, reward_wait_s, absent_after_s
        self.log = log or (lambda record: None)
        self.clock = clock
        self.steps = 0

    def run(self, max_seconds=None):
        link, start = self.link, self.clock()
        deadline = None if max_seconds is None else start + max_seconds
        heard_command = 0
        used_sample = 0
        last_command_at = start  # wait for a teacher a while before acting alone
        while deadline is None or self.clock() < deadline:
            if not link.wait_connected(0.5):
                continue
            present = self.clock() - last_command_at < self.absent_after_s
            if present:
                link.wait_until(lambda: link.commands_heard > heard_command, 0.25)
            else:
                link.wait_until(lambda: link.commands_heard > heard_command or (
                    link.distance_angle is not None and link.distance_angle.number > used_sample), 0.5)
            fresh = link.commands_after(heard_command)
            command = None
            if fresh:
                heard_command = fresh[-1].number
                last_command_at = fresh[-1].arrived
                command = fresh[-1].value if fresh[-1].value in COMMANDS else None
                if command is None:
                    self.log({"event": "unknown_command", "label": fresh[-1].value})
            if command is None and present:
                continue  # a teacher is around: act when told
            da = link.distance_angle
            if da is None or (command is None and da.number <= used_sample):
                continue
            if da.stale:  # the daemon says the robot's link is down: this is old news, wait for fresh
                used_sample = da.number
                continue
            used_sample = da.number
            self._step(self._perceive(da, command), da.number, start)

    def _perceive(self, latest, command):
        """The perception from the last `smooth` fresh samples up to `latest` (fewer if the link has only
        those)."""
        recent = [s for s in self.link.samples_after(latest.number - self.smooth)
                  if s.number <= latest.number and not s.stale]
        return settled(recent or [latest], command)

    def _step(self, before, sample_number, start):
        link, brain = self.link, self.brain
        action, explored, scores = brain.decide(before)
        decided_wall = time.time()
        rewards_mark, commands_mark = link.rewards_heard, link.commands_heard
        if not link.act(action):
            self.log({"event": "not_written", "action": action})
            return
        written_at = self.clock()
        errors = brain.learn()
        link.wait_until(lambda: False, written_at + self.step_s - self.clock())
        # the move is over: wait for `smooth` samples taken since, so that the perception after is one at rest
        mark = max(sample_number, link.distance_angle.number if link.distance_angle is not None else 0)
        link.wait_until(lambda: link.distance_angle is not None and link.distance_angle.number >= mark + self.smooth,
                        0.5)
        if link.distance_angle is not None and link.distance_angle.number <= sample_number:
            link.wait_until(lambda: link.distance_angle.number > sample_number, 0.5)
        if before.command is not None:
            # a teacher judges a while after the command (a spoken one is heard late), and a touch takes
            # time too: wait for the reward, but not past the next command — that one is the next step's
            link.wait_until(lambda: link.rewards_heard > rewards_mark or link.commands_heard > commands_mark,
                            written_at + self.step_s + self.reward_wait_s - self.clock())
        rewards = link.rewards_after(rewards_mark)
        reward = rewards[-1].value if rewards and before.command is not None else None
        if rewards and before.command is None:
            # the teacher judged a command this robot never heard (not yet listening, or missed): not this step's
            self.log({"event": "reward_without_command", "reward": rewards[-1].value, "action": action})
        da = link.distance_angle
        if da.number <= sample_number or da.stale:
            self.log({"event": "no_fresh_perception", "action": action})  # the daemon went away meanwhile
            return
        after = self._perceive(da, None)
        brain.remember(Experience(before, action, after, reward))
        if reward is not None:
            # A judgement is learned from before the next decision, not a step late: learning only while the next
            # action took effect, the robot told "left" and punished for going forward went forward again.
            errors.update(brain.learn_judgement())
        self.steps += 1
        self.log({"t": round(self.clock() - start, 3), "wall": round(decided_wall, 3), "step": self.steps, "command": before.command,
                  "distanceM": round(before.distance_m, 4), "angleRad": round(before.angle_rad, 4),
                  "seen": before.seen, "action": action, "explored": explored,
                  "epsilon": round(brain.epsilon, 4), "scores": {a: round(s, 4) for a, s in scores.items()},
                  "after": {"distanceM": round(after.distance_m, 4), "angleRad": round(after.angle_rad, 4)},
                  "reward": reward,
                  "predicted": {a: [round(p.distance_m, 4), round(p.angle_rad, 4)] for a, p in brain.predictions.items()},
                  "errors": {k: round(v, 5) for k, v in errors.items()}})


def parse_args(argv):
    p = argparse.ArgumentParser(description="Multilevel-Darwinist-Brain-style control over HABLA's control contract.")
    p.add_argument("--host", default="127.0.0.1")
    p.add_argument("--command-port", type=int, default=7001)
    p.add_argument("--distance-angle-port", type=int, default=7002)
    p.add_argument("--reward-port", type=int, default=7003)
    p.add_argument("--action-port", type=int, default=7004)
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--log", help="file for the JSON decision lines (default: stderr)")
    p.add_argument("--max-seconds", type=float, help="stop after this long (default: run until killed)")
    p.add_argument("--speed", type=float, default=1.0,
                   help="divides the default times below, for a world that runs S times faster")
    p.add_argument("--step-s", type=float, help="how long an action is given to take effect (default 1.2)")
    p.add_argument("--reward-wait-s", type=float, help="extra wait for the reward after a command, ended by the next command (default 2.0)")
    p.add_argument("--absent-after-s", type=float, help="no command for this long: the teacher has gone (default 8)")
    p.add_argument("--smooth", type=int, default=3, help="distance_angle samples a perception is the median of")
    p.add_argument("--horizon", type=int, default=2, choices=(1, 2),
                   help="steps a plan looks ahead when no command is heard")
    p.add_argument("--memory", type=int, default=80, help="experiences kept in short-term memory")
    p.add_argument("--population", type=int, default=16, help="individuals per evolving model")
    p.add_argument("--generations", type=int, default=3, help="generations per model after each experience")
    p.add_argument("--epsilon", type=float, default=0.2, help="initial exploration rate")
    p.add_argument("--epsilon-decay", type=float, default=0.97, help="exploration rate factor per decision")
    p.add_argument("--epsilon-min", type=float, default=0.02)
    args = p.parse_args(argv)
    if args.speed < 1.0:
        p.error("--speed must be at least 1")
    for name, default in (("step_s", 1.2), ("reward_wait_s", 2.0), ("absent_after_s", 8.0)):
        if getattr(args, name) is None:
            setattr(args, name, default / args.speed)
    return args


def _interrupt(signum, frame):
    raise KeyboardInterrupt()


def main(argv=None):
    args = parse_args(sys.argv[1:] if argv is None else argv)
    out = open(args.log, "a", buffering=1) if args.log else sys.stderr

    def log(record):
        out.write(json.dumps(record) + "\n")
        out.flush()

    ports = {"command": args.command_port, "distance_angle": args.distance_angle_port,
             "reward": args.reward_port, "action": args.action_port}
    link = ContractLink(args.host, ports, on_event=lambda kind, detail: log({"event": kind, "detail": detail}))
    brain = Brain(seed=args.seed, memory=args.memory, population=args.population, generations=args.generations,
                  epsilon=args.epsilon, epsilon_decay=args.epsilon_decay, epsilon_min=args.epsilon_min, horizon=args.horizon)
    runner = Runner(link, brain, args.step_s, args.reward_wait_s, args.absent_after_s, log, smooth=args.smooth)
    signal.signal(signal.SIGTERM, _interrupt)
    link.start()
    try:
        runner.run(args.max_seconds)
    except KeyboardInterrupt:
        pass
    finally:
        link.act("stop")
        link.close()
        log({"event": "stopped", "steps": runner.steps})
        if out is not sys.stderr:
            out.close()
    return 0


if __name__ == "__main__":
    sys.exit(main())
