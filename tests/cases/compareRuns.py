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
import math
import re
import sys


def differs(x, y, scale):
    """Relative difference; nan equals only nan (an entry not yet set)."""
    if math.isnan(x) or math.isnan(y):
        return 0.0 if math.isnan(x) and math.isnan(y) else math.inf
    return abs(x - y) / max(abs(y), scale, 1e-300)


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
    scale = [max((abs(r[k]) for r in rows0 if not math.isnan(r[k])),
                 default=0.0) for k in range(len(rows0[0]) if rows0 else 0)]
    for a, b in zip(rows1, rows0):
        if len(a) != len(b):
            print("missing same row length at time", b[0])
            return 1
        for k, (x, y) in enumerate(zip(a, b)):
            worst, n = max(worst, differs(x, y, scale[k])), n + 1
    for k, y in s0.items():
        worst, n = max(worst, differs(s1[k], y, 0.0 if y else 1.0)), n + 1
    print("%.3g %d" % (worst, n))
    return 0


if __name__ == "__main__":
    sys.exit(main())
