"""Do two Python threads compute at once? Two IPR maps (one worker thread each) on two Python threads
against the same two calls one after the other, in-process wall time, median of `repeats`; prints the
ratio (threads / serial: ~0.5 on two idle cores, 1 if a call held the GIL).
usage: two_threads.py REPEATS"""
import sys
import threading
import time

import granular as gr

work = dict(xi="0.1:0.6", q=0.5, N=100, realizations=40, threads=1)


def one():
    gr.ipr_map(**work)


def timed(run):
    start = time.perf_counter()
    run()
    return time.perf_counter() - start


def together():
    calls = [threading.Thread(target=one) for _ in range(2)]
    for call in calls:
        call.start()
    for call in calls:
        call.join()


ratios = sorted(timed(together) / timed(lambda: (one(), one())) for _ in range(int(sys.argv[1])))
print(ratios[len(ratios) // 2])
