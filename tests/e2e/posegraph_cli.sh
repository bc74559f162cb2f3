#!/usr/bin/env bash
# metricmap posegraph: a real 2D graph (MIT) and a 3D one (sphere2500) optimised; the chi² the
# command reports equals numpy's chi² of the graph it wrote (g2o's error: z^-1 x_i^-1 x_j);
# bad input and bad options refused with nothing written.
MM=$1
SHARED=$3
source "$(dirname "$0")/lib.sh"
g=$SHARED/posegraph_g2o
need_shared_data "$g/MIT.g2o"
chi2_2d() {  # chi2_2d FILE: g2o's chi² of an SE(2) graph, in numpy
  /usr/bin/python3 -c "
import numpy as np, sys
V, E = {}, []
for line in open('$1'):
    f = line.split()
    if not f: continue
    if f[0] == 'VERTEX_SE2': V[int(f[1])] = np.array(list(map(float, f[2:5])))
    if f[0] == 'EDGE_SE2': E.append((int(f[1]), int(f[2]), np.array(list(map(float, f[3:6]))), list(map(float, f[6:12]))))
def T(p):
    c, s = np.cos(p[2]), np.sin(p[2])
    return np.array([[c, -s, p[0]], [s, c, p[1]], [0, 0, 1]])
chi2 = 0.0
for i, j, z, u in E:
    D = np.linalg.inv(T(z)) @ np.linalg.inv(T(V[i])) @ T(V[j])
    e = np.array([D[0, 2], D[1, 2], np.arctan2(D[1, 0], D[0, 0])])
    O = np.array([[u[0], u[1], u[2]], [u[1], u[3], u[4]], [u[2], u[4], u[5]]])
    chi2 += e @ O @ e
print(repr(chi2))"
}
"$MM" posegraph "$g/MIT.g2o" --out "$tmp/mit.g2o" --format json >"$tmp/mit.json"
check "MIT optimised and written" test -s "$tmp/mit.g2o"
check "MIT: chi² drops by orders of magnitude" /usr/bin/python3 -c "
import json; j = json.load(open('$tmp/mit.json'))
assert j['termination'] == 'converged' and j['final_chi2'] < 1e-5 * j['initial_chi2'], j"
check "MIT: the reported initial chi² is numpy's of the input" /usr/bin/python3 -c "
import json; j = json.load(open('$tmp/mit.json')); n = $(chi2_2d "$g/MIT.g2o")
assert abs(j['initial_chi2'] - n) <= 1e-9 * n, (j['initial_chi2'], n)"
check "MIT: the reported final chi² is numpy's of the graph written" /usr/bin/python3 -c "
import json; j = json.load(open('$tmp/mit.json')); n = $(chi2_2d "$tmp/mit.g2o")
assert abs(j['final_chi2'] - n) <= 1e-9 * n, (j['final_chi2'], n)"
"$MM" posegraph "$tmp/mit.g2o" --format json >"$tmp/again.json"
check "the written graph reads back at its optimum" /usr/bin/python3 -c "
import json; a = json.load(open('$tmp/mit.json')); b = json.load(open('$tmp/again.json'))
assert abs(b['initial_chi2'] - a['final_chi2']) <= 1e-9 * a['final_chi2'], (a, b)
assert b['final_chi2'] <= b['initial_chi2'] * (1 + 1e-9), b"
"$MM" posegraph "$g/manhattan.g2o" --format json >"$tmp/man.json"
check "manhattan (edges only): chained guess, then optimised" /usr/bin/python3 -c "
import json; j = json.load(open('$tmp/man.json'))
assert j['initial_guess'] == 'chained odometry' and j['vertices'] == 3500, j
assert j['final_chi2'] < 1e-5 * j['initial_chi2'], j"
"$MM" posegraph "$g/smallGrid3D.g2o" --out "$tmp/grid3d.g2o" >"$tmp/grid3d.txt"
check "3D graph optimised" grep -q "3D, 125 vertices" "$tmp/grid3d.txt"
printf 'VERTEX_SE2 0 0 0 0\nVERTEX_SE2 1 1 0 0\nEDGE_SE2 0 7 1 0 0 1 0 0 1 0 1\n' >"$tmp/bad.g2o"
expect 1 "line 3" -- "$MM" posegraph "$tmp/bad.g2o" --out "$tmp/x.g2o"
expect 1 "missing.g2o" -- "$MM" posegraph "$tmp/missing.g2o" --out "$tmp/x.g2o"
expect 2 "--out" -- "$MM" posegraph "$tmp/mit.g2o" --out "$tmp/./mit.g2o"
expect 2 "--out" -- "$MM" posegraph "$tmp/mit.g2o" --out "$tmp/x.txt"
expect 2 "--loss-scale" -- "$MM" posegraph "$tmp/mit.g2o" --loop-loss none --loss-scale 3
expect 2 "--max-iterations" -- "$MM" posegraph "$tmp/mit.g2o" --max-iterations 0
check "nothing written after a refusal" test ! -e "$tmp/x.g2o" -a ! -e "$tmp/x.txt"
finish
