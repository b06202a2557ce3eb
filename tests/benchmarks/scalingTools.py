"""Shared by the scaling benchmarks (cooksScaling, hexScaling): running a
case with its peak memory, reading formFoam's time-per-phase report, the
growth-exponent fit, and the machine's DGEMM rate measured with the BLAS
that CHOLMOD and UMFPACK call (libblas.so.3: OpenBLAS on Debian), so that
a factorisation's GFLOP/s can be read against what the machine's dense
kernels reach in the same run, with the same threads."""
import array
import ctypes
import ctypes.util
import math
import os
import re
import subprocess
import sys
import time


def fit(xs, ys):
    """Exponent b of y ~ x^b, least squares in log-log."""
    lx = [math.log(x) for x in xs]
    ly = [math.log(max(y, 1e-9)) for y in ys]
    n = len(lx)
    mx, my = sum(lx) / n, sum(ly) / n
    sxx = sum((a - mx) ** 2 for a in lx)
    return sum((a - mx) * (b - my) for a, b in zip(lx, ly)) / sxx if sxx else float('nan')


def dgemmRate(n=2000, repeat=3):
    """GFLOP/s of C = A B (n x n, double) with libblas.so.3: the best of
    `repeat` runs."""
    lib = ctypes.CDLL('libblas.so.3')
    dgemm = lib.dgemm_
    a = array.array('d', [1.0 / (1 + (i % 7)) for i in range(n * n)])
    b = array.array('d', [1.0 / (2 + (i % 5)) for i in range(n * n)])
    c = array.array('d', bytes(8 * n * n))
    ptr = lambda x: ctypes.cast(x.buffer_info()[0], ctypes.POINTER(ctypes.c_double))
    N = ctypes.c_int(n)
    one, zero = ctypes.c_double(1.0), ctypes.c_double(0.0)
    tr = ctypes.c_char(b'N')
    best = 0.0
    for _ in range(repeat):
        t0 = time.perf_counter()
        dgemm(ctypes.byref(tr), ctypes.byref(tr), ctypes.byref(N), ctypes.byref(N),
              ctypes.byref(N), ctypes.byref(one), ptr(a), ctypes.byref(N), ptr(b),
              ctypes.byref(N), ctypes.byref(zero), ptr(c), ctypes.byref(N))
        best = max(best, 2.0 * n ** 3 / (time.perf_counter() - t0) / 1e9)
    return best


def runFormFoam(case):
    """Run formFoam in a case; returns the phase times, factor statistics,
    peak memory (MB) and the log text."""
    logPath = os.path.join(case, 'log.formFoam')
    with open(logPath, 'w') as logFile:
        proc = subprocess.Popen(['formFoam', '-case', case], stdout=logFile,
                                stderr=subprocess.STDOUT)
        _, status, usage = os.wait4(proc.pid, 0)
        rc = os.waitstatus_to_exitcode(status)
    log = open(logPath).read()
    if rc != 0:
        sys.exit('formFoam failed in %s:\n%s' % (case, log[-3000:]))
    get = lambda key: float(re.search(r'^\s*%s\s+([0-9.eE+-]+)' % key, log, re.M).group(1))
    return dict(assembly=get('assembly'), factor=get('factorisation'),
                solve=get('solve'), total=get(r'total \(wall\)'),
                factorisations=int(get('factorisations')),
                nonzeros=get('factor nonzeros'), flops=get('factor flops'),
                rssMB=usage.ru_maxrss / 1024.0, log=log)


def summaryValue(case, entry):
    text = open(os.path.join(case, 'postProcessing', 'summary')).read()
    return float(re.search(r'^%s\s+([^;]+);' % entry, text, re.M).group(1))


def cpuLine():
    return 'cpu: %s, %d cores; OPENBLAS_NUM_THREADS=%s' % (
        next((l.split(':')[1].strip() for l in open('/proc/cpuinfo')
              if l.startswith('model name')), '?'), os.cpu_count(),
        os.environ.get('OPENBLAS_NUM_THREADS', '(unset: all cores)'))
