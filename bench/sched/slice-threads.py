#!/usr/bin/env python3
"""Gives chosen threads of running processes a short time slice, as they appear (docs/performance.md (k)).

    bench/sched/slice-threads.py NS SECONDS CMDPART:PREFIX[,PREFIX...] ...

Every 0.3 s for SECONDS, each thread whose name starts with a PREFIX, in a process whose command line contains
CMDPART, is set once to normal scheduling (SCHED_OTHER) with a slice of NS nanoseconds (sched_attr.sched_runtime;
Linux 6.12 and later clamp it to 0.1-100 ms and let any user ask it for their own threads). Each thread set is
logged to /tmp/slice-threads.log. Example, the isolation benchmark's robot and client threads at 0.1 ms:

    bench/sched/slice-threads.py 100000 1500 org.habla.bench:bench-client,bench-robot &
    bench/run isolation --rounds 3
"""
import ctypes
import os
import platform
import struct
import sys
import time

SCHED_SETATTR = {'x86_64': 314, 'aarch64': 274}[platform.machine()]
libc = ctypes.CDLL(None, use_errno=True)


def set_slice(tid, ns):
    # struct sched_attr: size, policy, flags, nice, priority, runtime, deadline, period
    attr = ctypes.create_string_buffer(struct.pack('IIQiIQQQ', 48, 0, 0, 0, 0, ns, 0, 0), 48)
    if libc.syscall(SCHED_SETATTR, tid, attr, 0) == 0:
        return 'ok'
    return os.strerror(ctypes.get_errno())


def main():
    ns, seconds = int(sys.argv[1]), float(sys.argv[2])
    rules = [(rule.split(':', 1)[0], rule.split(':', 1)[1].split(',')) for rule in sys.argv[3:]]
    done = set()
    end = time.time() + seconds
    with open('/tmp/slice-threads.log', 'a') as log:
        while time.time() < end:
            for pid in filter(str.isdigit, os.listdir('/proc')):
                if int(pid) == os.getpid():
                    continue
                try:
                    with open(f'/proc/{pid}/cmdline', 'rb') as f:
                        cmd = f.read().replace(b'\0', b' ').decode(errors='replace')
                    tids = os.listdir(f'/proc/{pid}/task')
                except OSError:
                    continue
                for part, prefixes in rules:
                    if part not in cmd:
                        continue
                    for tid in tids:
                        if (pid, tid) in done:
                            continue
                        try:
                            with open(f'/proc/{pid}/task/{tid}/comm') as f:
                                name = f.read().strip()
                        except OSError:
                            continue
                        if name.startswith(tuple(prefixes)):
                            done.add((pid, tid))
                            log.write(f'{time.strftime("%T")} {pid} {tid} {name} {set_slice(int(tid), ns)}\n')
                            log.flush()
            time.sleep(0.3)


if __name__ == '__main__':
    main()
