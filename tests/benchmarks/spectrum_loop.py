"""The Python peer of benchmarks/spectrum_loop: `count` spectra of new Anderson chains of N beads,
timed `repeats` times; prints the median [s]. usage: spectrum_loop.py N COUNT REPEATS"""
import sys
import time

import granular as gr

n, count, repeats = map(int, sys.argv[1:])
seconds = []
for _ in range(repeats):
    start = time.perf_counter()
    for i in range(count):
        gr.spectrum(gr.anderson(N=n, realization=i))
    seconds.append(time.perf_counter() - start)
print(sorted(seconds)[len(seconds) // 2])
