#!/usr/bin/env python3
"""What a thread waited behind each time it was woken and did not get a core at once (docs/performance.md (k)).

    bench/sched/wait-behind.py TIMEHIST THREAD MIN_MS

TIMEHIST is the output of `perf sched timehist` (bench/sched/record.sh); THREAD a part of the thread's name. For
every wake-up of THREAD whose scheduling delay exceeded MIN_MS, adds up what ran on its CPU while it waited, by
thread name and process id. Time on <idle> means the CPU had nothing to run and still did not run the woken
thread: in a virtual machine, a halted virtual CPU waiting for its host.
"""
import collections
import re
import sys

LINE = re.compile(r'\s*([\d.]+)\s+\[(\d+)\]\s+(.+?)\s+([\d.]+)\s+([\d.]+)\s+([\d.]+)\s*$')


def main():
    path, thread, least = sys.argv[1], sys.argv[2], float(sys.argv[3])
    by_cpu = collections.defaultdict(list)
    waits = []
    with open(path) as f:
        for line in f:
            m = LINE.match(line)
            if not m:
                continue
            # end of the run (s), cpu, task, wait (ms), scheduling delay (ms), run time (ms)
            end, cpu, task, delay, run = float(m[1]), int(m[2]), m[3], float(m[5]), float(m[6])
            start = end - run / 1000
            by_cpu[cpu].append((start, end, task))
            if thread in task and delay > least:
                waits.append((cpu, start - delay / 1000, start))
    behind = collections.Counter()
    for cpu, since, until in waits:
        for start, end, task in by_cpu[cpu]:
            overlap = min(end, until) - max(start, since)
            if overlap > 0:
                ids = re.search(r'\[(\d+)(?:/(\d+))?\]', task)
                name = re.sub(r'\[.*', '', task).strip()
                pid = (ids.group(2) or ids.group(1)) if ids else '-'
                behind[(name, pid)] += overlap * 1000
    total = sum(until - since for _, since, until in waits) * 1000
    print(f'{len(waits)} wake-ups of {thread} waited more than {least} ms, {total:.1f} ms in all; '
          f'on their CPU meanwhile (ms, thread, process):')
    for (name, pid), ms in behind.most_common(15):
        print(f'  {ms:8.2f}  {name:16s} {pid}')


if __name__ == '__main__':
    main()
