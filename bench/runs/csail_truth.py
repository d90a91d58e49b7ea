#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Reference poses for the raw MIT CSAIL log: the Radish corrected log keeps 406 of the raw
# log's 1988 FLASER scans, with corrected poses but truncated time stamps, so each corrected
# scan is paired with the raw scan of the same ranges (printed to 2 decimals; the two logs
# print 4.1 and 4.10 alike). Every corrected scan pairs with exactly one raw scan.
# usage: csail_truth.py RAW.log CORRECTED.log > TRUTH.txt   (lines: raw_scan_index x y theta)
import sys

def flaser(path):
    return [l.split() for l in open(path) if l.startswith('FLASER')]

def ranges(f):
    return ' '.join(f"{float(v):.2f}" for v in f[2:2 + int(f[1])])

raw, corrected = flaser(sys.argv[1]), flaser(sys.argv[2])
index = {}
for i, f in enumerate(raw):
    index.setdefault(ranges(f), []).append(i)
paired = 0
for f in corrected:
    hits = index.get(ranges(f), [])
    if len(hits) != 1:
        continue
    n = int(f[1])
    x, y, theta = map(float, f[2 + n:5 + n])
    print(hits[0], x, y, theta)
    paired += 1
print(f"{sys.argv[2]}: {paired} of {len(corrected)} scans paired with {sys.argv[1]} ({len(raw)} scans)", file=sys.stderr)
if paired < len(corrected):
    sys.exit(f"{len(corrected) - paired} corrected scans without exactly one raw scan of the same ranges")
