#!/usr/bin/env python3
"""Relation-based self-check of a slam2d trajectory on a raw CARMEN log with a corrected log.

Revisit pairs: two corrected scans at least MIN_GAP s apart whose corrected positions are
within NEAR m; each gives a relation (the corrected log's relative pose, at the raw log's
stamps: scans matched by their ranges). A doubled place shows up as the worst relations, with
the stamps of both visits. The file is scored with `metricmap evaluate --relations --format
json`; the report is mean ± std and the five worst relations (log time from the first scan).

usage: slam2d_selfcheck.py METRICMAP RAW.clf[.bz2] CORRECTED.log[.gz] ESTIMATE.tum OUTDIR
"""
import bz2
import gzip
import json
import math
import subprocess
import sys

import numpy as np

MIN_GAP, NEAR = 120.0, 1.5


def lines(path):
    if path.endswith('.bz2'):
        return bz2.open(path, 'rt')
    if path.endswith('.gz'):
        return gzip.open(path, 'rt')
    return open(path)


def flaser(path):
    for l in lines(path):
        if l.startswith('FLASER'):
            t = l.split()
            n = int(t[1])
            yield t, n


def relative(a, b):
    c, s = math.cos(a[2]), math.sin(a[2])
    dx, dy = b[0] - a[0], b[1] - a[1]
    return c * dx + s * dy, -s * dx + c * dy, math.remainder(b[2] - a[2], 2 * math.pi)


def main():
    mm, raw_path, cor_path, est, out = sys.argv[1:6]
    raw = {}
    for t, n in flaser(raw_path):
        key = tuple(round(float(x) * 100) for x in t[2:2 + n])
        raw.setdefault(key, (float(t[-3]), [float(x) for x in t[2:2 + n]]))
    scans = []  # (raw stamp, ranges, corrected pose)
    for t, n in flaser(cor_path):
        key = tuple(round(float(x) * 100) for x in t[2:2 + n])
        if key in raw:
            scans.append((raw[key][0], raw[key][1], [float(v) for v in t[2 + n:5 + n]]))
    pos = np.array([s[2][:2] for s in scans])
    stamps = np.array([s[0] for s in scans])
    pairs = []
    for j in range(len(scans)):
        d = np.linalg.norm(pos[:j] - pos[j], axis=1)
        for i in np.where((d < NEAR) & (stamps[:j] < stamps[j] - MIN_GAP))[0]:
            pairs.append((int(i), j))
    files = {'corrected': []}
    for i, j in pairs:
        (si, _, pi), (sj, _, pj) = scans[i], scans[j]
        files['corrected'].append((si, sj) + relative(pi, pj))
    for name, rows in files.items():
        path = '%s/rel_%s.txt' % (out, name)
        with open(path, 'w') as f:
            for si, sj, x, y, th in rows:
                f.write('%.6f %.6f %.6f %.6f 0 0 0 %.9f\n' % (si, sj, x, y, th))
        j = json.loads(subprocess.run([mm, 'evaluate', est, '--relations', path, '--max-time-diff',
                                       '0.0001', '--format', 'json'], check=True,
                                      capture_output=True, text=True).stdout)
        print('%s: %d revisit relations (%d used): %.4f ± %.4f m, %.3f ± %.3f deg' % (
            name, len(rows), j['relations']['used'], j['abs_translation_m']['mean'],
            j['abs_translation_m']['std'], j['abs_rotation_deg']['mean'],
            j['abs_rotation_deg']['std']))
        t0 = min(stamps)
        for w in j['worst']['by_translation'][:5]:
            print('  worst: t %.1f s -> %.1f s (log time), %.3f m, %.2f deg' % (
                w['stamp1'] - t0, w['stamp2'] - t0, w['translation_m'], w['rotation_deg']))


if __name__ == '__main__':
    main()
