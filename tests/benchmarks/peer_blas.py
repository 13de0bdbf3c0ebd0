#!/usr/bin/python3
"""Which BLAS the NumPy/SciPy peers run on, as threadpoolctl reports it: library, version,
kernel (OpenBLAS's architecture) and threads, one line per library NumPy and SciPy loaded.

usage: /usr/bin/python3 peer_blas.py   (run-benchmarks.sh puts the line in its report)
"""
import numpy  # noqa: F401  (loads the BLAS NumPy links)
import scipy.linalg  # noqa: F401  (and LAPACK, through SciPy)

try:
    from threadpoolctl import threadpool_info
except ImportError:
    print("unknown (python3-threadpoolctl is not installed)")
else:
    rows = [f"{i.get('internal_api')} {i.get('version') or ''} {i.get('architecture') or ''} "
            f"({i.get('num_threads')} threads, {i.get('filepath')})"
            for i in threadpool_info() if i.get("user_api") == "blas"]
    if not rows:  # threadpoolctl knows optimized BLAS only: name the library the process mapped
        with open("/proc/self/maps") as maps:
            rows = sorted({line.split()[-1] for line in maps if "libblas" in line or "liblapack" in line})
        rows = [f"not an optimized BLAS (threadpoolctl found none); mapped: {', '.join(rows) or 'unknown'}"]
    print("; ".join(" ".join(r.split()) for r in rows))
