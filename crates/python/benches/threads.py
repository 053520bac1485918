"""Four runs in four Python threads against four in sequence (the GIL is released during a run): the wall-time
ratio, with the machine's core count. Run after `pip install ./crates/python`:

    python crates/python/benches/threads.py [REPEATS]
"""

import os
import statistics
import sys
import threading
import time

import frictrack

CASES = [dict(speed=v, distributed_friction=2000.0) for v in (100.0, 150.0, 200.0, 250.0)]


def sequence():
    for case in CASES:
        frictrack.run(**case)


def threads():
    workers = [threading.Thread(target=frictrack.run, kwargs=case) for case in CASES]
    for w in workers:
        w.start()
    for w in workers:
        w.join()


def timed(f, repeats):
    times = []
    for _ in range(repeats):
        started = time.perf_counter()
        f()
        times.append(time.perf_counter() - started)
    return statistics.median(times), min(times), max(times)


if __name__ == "__main__":
    repeats = int(sys.argv[1]) if len(sys.argv) > 1 else 5
    frictrack.run(elements=20)  # load the library
    s = timed(sequence, repeats)
    t = timed(threads, repeats)
    print(f"cores: {os.cpu_count()}; median of {repeats} (min–max)")
    print(f"4 runs in sequence:  {s[0]:.3f} s ({s[1]:.3f}–{s[2]:.3f})")
    print(f"4 runs in 4 threads: {t[0]:.3f} s ({t[1]:.3f}–{t[2]:.3f})")
    print(f"ratio threads/sequence: {t[0] / s[0]:.3f}")
