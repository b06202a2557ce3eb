#!/usr/bin/env python3
"""Compare two runs of one case: postProcessing/history.dat row by row and
the numeric entries of postProcessing/summary (wall times excepted).

    compareRuns.py <reference case> <case>

Prints "<max difference> <values compared>"; the difference of a value is
|a - b| / max(|b|, column scale), the column scale being the largest
magnitude of that column in the reference (so that values crossing zero are
compared at the column's level). A missing file, a different header or row
count prints "missing <what>" and exits 1: the caller's check then fails.
"""
import re
import sys


def history(case):
    with open(case + "/postProcessing/history.dat") as f:
        lines = [l.split() for l in f if l.strip()]
    return lines[0], [[float(v) for v in l] for l in lines[1:]]


def summary(case):
    values = {}
    with open(case + "/postProcessing/summary") as f:
        for line in f:
            m = re.match(r"^(\w+)\s+([-+0-9.eE]+);", line)
            if m and not m.group(1).endswith("WallTime") \
                    and m.group(1) != "wallTime":
                values[m.group(1)] = float(m.group(2))
    return values


def main():
    ref, case = sys.argv[1], sys.argv[2]
    try:
        h0, rows0 = history(ref)
        h1, rows1 = history(case)
        s0, s1 = summary(ref), summary(case)
    except (OSError, ValueError, IndexError) as e:
        print("missing", e)
        return 1
    if h0 != h1 or len(rows0) != len(rows1):
        print("missing same history: %d vs %d rows" % (len(rows1), len(rows0)))
        return 1
    if set(s0) != set(s1) or not s0:
        print("missing same summary entries")
        return 1
    worst, n = 0.0, 0
    scale = [max(abs(r[k]) for r in rows0) for k in range(len(h0) - 1)]
    for a, b in zip(rows1, rows0):
        for k, (x, y) in enumerate(zip(a, b)):
            d = abs(x - y) / max(abs(y), scale[k], 1e-300)
            worst, n = max(worst, d), n + 1
    for k, y in s0.items():
        d = abs(s1[k] - y) / max(abs(y), 1e-300) if y != 0 else abs(s1[k])
        worst, n = max(worst, d), n + 1
    print("%.3g %d" % (worst, n))
    return 0


if __name__ == "__main__":
    sys.exit(main())
