#!/bin/bash
# Records the scheduler's switches and wake-ups on every CPU for a while (perf, as root), once a process whose
# command line matches a pattern has run for some seconds, e.g. during the isolation benchmark's measured window
# beside the simulated Aibo (docs/performance.md (k)):
#
#   bench/sched/record.sh 'aibo-aren[a]' 25 8 /tmp/beside.data & bench/run isolation --rounds 1
#   perf sched timehist -i /tmp/beside.data > /tmp/beside.txt
#   bench/sched/wait-behind.py /tmp/beside.txt bench-client 0.3
#
# The pattern is a pgrep regular expression; bracket one letter so that it does not match this command's own shell.
set -u
pattern=$1; delay=$2; seconds=$3; out=$4
for _ in $(seq 1 3000); do pgrep -f -- "$pattern" >/dev/null && break; sleep 0.2; done
sleep "$delay"
perf record -q -m 16M -e sched:sched_switch -e sched:sched_wakeup -e sched:sched_waking -a -o "$out" \
    -- sleep "$seconds" >/dev/null 2>&1
echo "recorded $out"
