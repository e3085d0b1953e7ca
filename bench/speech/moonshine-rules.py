#!/usr/bin/env python3
"""Compares accept/reject rules for Moonshine's best grammar phrase on the scores MoonshineScores wrote.

  moonshine-rules.py TUNE.jsonl [HELD.jsonl]

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


def features(u, phrases):
    """The best phrase's index and the measures a rule may threshold."""
    s = u["scores"]
    lp = [r[0] for r in s]
    best = max(range(phrases), key=lambda i: lp[i])
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


def prepare(path):
    rows, streams = load(path)
    phrases = rows["phrases"]
    names = rows["rows"]
    for st in streams:
        for u in st["utterances"]:
            if "scores" in u:
                b, f = features(u, phrases)
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


def main():
    tune = prepare(sys.argv[1])
    held = prepare(sys.argv[2]) if len(sys.argv) > 2 else None
    print("rule family: chosen on the tune voices (accuracy mean of conditions / out-of-grammar silent)")
    for name, family in RULES.items():
        best = None
        for make, args in family:
            acc, rej = summary(score(tune, make(*args)))
            if rej >= MIN_REJECTION and (best is None or acc > best[0]):
                best = (acc, rej, make, args)
        if best is None:
            print("%-24s no setting silences %.0f %% outside the grammar" % (name, MIN_REJECTION))
            continue
        acc, rej, make, args = best
        print("%-24s %-22s tune %.1f / %.1f   %s" % (name, ",".join("%.3g" % a for a in args), acc, rej,
                                                   table(score(tune, make(*args)))))
        if held:
            o = score(held, make(*args))
            h_acc, h_rej = summary(o)
            print("%-24s %-22s held %.1f / %.1f   %s" % ("", "", h_acc, h_rej, table(o)))


if __name__ == "__main__":
    main()
