#!/usr/bin/env python3
"""Compares accept/reject rules for Moonshine's best grammar phrase on the scores MoonshineScores wrote.

  moonshine-rules.py TUNE.jsonl [HELD.jsonl]
  moonshine-rules.py --ceiling FILE.jsonl     what each choice of the best phrase gets with every phrase said

Each rule is scored as bench/run speech scores the chain (StreamScore): an in-grammar item is right when exactly
its phrase was said once between its start and the next item's start; an item outside the grammar is right when
nothing was said. For each rule family the threshold is chosen on the first file (the tune voices) alone: the
setting with the best in-grammar accuracy (conditions weighted alike) whose rejection of speech outside the
grammar is at least MIN_REJECTION over all conditions. The second file, if given, is scored once with that setting.
"""
import json
import math
import sys

MIN_REJECTION = 90.0
CONDITIONS = ["clean", "noise20", "noise10", "echo", "babble"]


def load(path):
    rows, streams = None, []
    for line in open(path):
        if not line.endswith("\n"):
            break  # a file still being written: its last line is not whole
        d = json.loads(line)
        if d["kind"] == "rows":
            rows = d
        elif d["kind"] == "stream":
            d["utterances"] = []
            streams.append(d)
        else:
            streams[-1]["utterances"].append(d)
    return rows, streams


def logsumexp(xs):
    m = max(xs)
    return m + math.log(sum(math.exp(x - m) for x in xs))


def features(u, phrases, bonus):
    """The best phrase's index (by log-probability plus {@code bonus} per step) and the measures a rule may threshold."""
    s = u["scores"]
    lp = [r[0] for r in s]
    best = max(range(phrases), key=lambda i: lp[i] + bonus * s[i][2])
    others = sorted(lp[:phrases], reverse=True)
    fillers = lp[phrases:]
    return best, {
        "shortfall": math.exp(-s[best][1] / s[best][2]),
        "margin": lp[best] - others[1],
        "filler": lp[best] - (max(fillers) if fillers else -1e9),
        "posterior": math.exp(lp[best] - logsumexp(lp)),
        "grammarPosterior": math.exp(lp[best] - logsumexp(lp[:phrases])),
        "perToken": lp[best] / s[best][2],
        "logProb": lp[best],
        "worst": s[best][3] if len(s[best]) > 3 else 0.0,
    }


def prepare(path, bonus=0.0, voice_check=True):
    """The streams of a file, each utterance with its best phrase and features; unvoiced ones left out if checked."""
    rows, streams = load(path)
    phrases = rows["phrases"]
    names = rows["rows"]
    for st in streams:
        for u in st["utterances"]:
            if "scores" in u and (u.get("voiced", True) or not voice_check):
                b, f = features(u, phrases, bonus)
                u["phrase"] = names[b]
                u["f"] = f
    return streams


def score(streams, accept):
    """Per condition: (in-grammar right, in-grammar, out-of-grammar silent, out-of-grammar, not-in-grammar said)."""
    out = {c: [0, 0, 0, 0] for c in CONDITIONS}
    for st in streams:
        items = st["items"]
        said = [(u["at"], u["phrase"]) for u in st["utterances"] if "f" in u and accept(u["f"])]
        c = out[st["condition"]]
        for i, it in enumerate(items):
            lo = it["start"]
            hi = items[i + 1]["start"] if i + 1 < len(items) else 1e18
            heard = [p for at, p in said if lo <= at < hi]
            if it["in"]:
                c[1] += 1
                c[0] += heard == [it["text"]]
            else:
                c[3] += 1
                c[2] += not heard
    return out


def summary(out):
    acc = [100.0 * out[c][0] / out[c][1] for c in CONDITIONS if out[c][1]]
    rej = 100.0 * sum(out[c][2] for c in CONDITIONS) / max(1, sum(out[c][3] for c in CONDITIONS))
    return sum(acc) / len(acc), rej


def table(out):
    return "  ".join("%s %.1f/%.1f" % (c, 100.0 * out[c][0] / max(1, out[c][1]), 100.0 * out[c][2] / max(1, out[c][3]))
                     for c in CONDITIONS)


def grid(lo, hi, n):
    return [lo + (hi - lo) * k / n for k in range(n + 1)]


RULES = {
    "shortfall": [(lambda t: (lambda f: f["shortfall"] >= t), (t,)) for t in grid(0, 0.6, 60)],
    "margin": [(lambda t: (lambda f: f["margin"] >= t), (t,)) for t in grid(0, 15, 60)],
    "filler+margin": [(lambda t: (lambda f: f["filler"] > 0 and f["margin"] >= t), (t,)) for t in grid(0, 15, 60)],
    "posterior": [(lambda t: (lambda f: f["posterior"] >= t), (t,)) for t in grid(0, 1, 100)],
    "grammarPosterior": [(lambda t: (lambda f: f["grammarPosterior"] >= t), (t,)) for t in grid(0, 1, 100)],
    "perToken": [(lambda t: (lambda f: f["perToken"] >= t), (t,)) for t in grid(-6, 0, 60)],
    "shortfall|margin": [(lambda a, b: (lambda f: f["shortfall"] >= a or f["margin"] >= b), (a, b))
                         for a in grid(0.1, 0.5, 20) for b in grid(2, 20, 36)],
    "shortfall&margin": [(lambda a, b: (lambda f: f["shortfall"] >= a and f["margin"] >= b), (a, b))
                         for a in grid(0, 0.4, 20) for b in grid(0, 10, 40)],
    "filler&shortfall|margin": [(lambda a, b: (lambda f: f["filler"] > 0 and (f["shortfall"] >= a or f["margin"] >= b)),
                                 (a, b)) for a in grid(0.1, 0.5, 20) for b in grid(2, 20, 36)],
    "perToken+w*log(shortfall)": [(lambda w, t: (lambda f: f["perToken"] + w * math.log(f["shortfall"]) >= t), (w, t))
                                  for w in grid(0, 2, 10) for t in grid(-8, 0, 80)],
    "perToken&shortfall": [(lambda a, b: (lambda f: f["perToken"] >= a and f["shortfall"] >= b), (a, b))
                           for a in grid(-5, -1, 40) for b in grid(0, 0.4, 20)],
    "filler&perToken": [(lambda t: (lambda f: f["filler"] > 0 and f["perToken"] >= t), (t,)) for t in grid(-6, 0, 60)],
    "perToken|margin": [(lambda a, b: (lambda f: f["perToken"] >= a or f["margin"] >= b), (a, b))
                        for a in grid(-4, -1, 30) for b in grid(4, 20, 32)],
    "worst": [(lambda t: (lambda f: f["worst"] >= t), (t,)) for t in grid(-12, 0, 96)],
    "perToken&worst": [(lambda a, b: (lambda f: f["perToken"] >= a and f["worst"] >= b), (a, b))
                       for a in grid(-5, -0.5, 45) for b in grid(-12, -1, 44)],
    "perToken+w*worst": [(lambda w, t: (lambda f: (f["perToken"] + w * f["worst"]) / (1 + w) >= t), (w, t))
                         for w in grid(0, 1, 10) for t in grid(-6, 0, 120)],
    "posterior&margin": [(lambda a, b: (lambda f: f["posterior"] >= a and f["margin"] >= b), (a, b))
                         for a in grid(0, 1, 20) for b in grid(0, 10, 40)],
}


BONUSES = [0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 8.0]


def ceiling(path):
    for bonus in BONUSES:
        for check in (True, False):
            o = score(prepare(path, bonus, check), lambda f: True)
            print("bonus %.1f voice check %-5s every phrase said: %.1f   %s" % (bonus, check, summary(o)[0], table(o)))


def main():
    if sys.argv[1] == "--ceiling":
        ceiling(sys.argv[2])
        return
    files = sys.argv[1:]
    print("rule family: chosen on the tune voices (accuracy mean of conditions / out-of-grammar silent); bonus per step "
          "in the choice of the best phrase; voice check")
    prepared = {}
    for bonus in BONUSES:
        for check in (True, False):
            prepared[(bonus, check)] = [prepare(f, bonus, check) for f in files]
    for name, family in RULES.items():
        best = None
        for key, (tune, *_) in prepared.items():
            for make, args in family:
                acc, rej = summary(score(tune, make(*args)))
                if rej >= MIN_REJECTION and (best is None or acc > best[0]):
                    best = (acc, rej, make, args, key)
        if best is None:
            print("%-24s no setting silences %.0f %% outside the grammar" % (name, MIN_REJECTION))
            continue
        acc, rej, make, args, key = best
        tune = prepared[key][0]
        print("%-24s %-14s bonus %.1f voice %-5s tune %.1f / %.1f   %s" % (name, ",".join("%.3g" % a for a in args),
              key[0], key[1], acc, rej, table(score(tune, make(*args)))))
        if len(files) > 1:
            o = score(prepared[key][1], make(*args))
            h_acc, h_rej = summary(o)
            print("%-24s %-14s %-21s held %.1f / %.1f   %s" % ("", "", "", h_acc, h_rej, table(o)))


if __name__ == "__main__":
    main()
