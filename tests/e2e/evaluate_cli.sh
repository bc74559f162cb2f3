#!/usr/bin/env bash
# metricmap evaluate on real trajectory pairs, every printed figure checked against an independent
# numpy computation (evo's APE/RPE, the KITTI devkit's drift, the relation metric of Kümmerle et
# al. 2009), and its bad-input and usage errors.
# Pairs: BALM's hand-carried trajectory (40 poses, ../shared/data/balm_realworld_dev) against a
# deterministically perturbed similarity copy (KITTI form by index; TUM form by time stamps with
# two poses dropped); KITTI 00's ground truth (4541 poses, 3.7 km) against an estimate that drifts.
MM=$1
DATA=$2
SHARED=${3:-$DATA/../../shared/data}
source "$(dirname "$0")/lib.sh"
PY=/usr/bin/python3
if ! "$PY" -c "import numpy" 2>/dev/null; then
  echo "FAIL: $PY has no numpy (apt-get install python3-numpy)"
  exit 1
fi
balm=$SHARED/balm_realworld_dev
kitti=$DATA/kitti_odometry_00/poses/00.txt
for f in "$balm/poses.txt" "$balm/times.txt" "$kitti"; do
  [ -f "$f" ] || { echo "FAIL: $f missing"; exit 1; }
done

cat >"$tmp/oracle.py" <<'EOF'
import json, math, re, sys
import numpy as np

LENGTHS = [100.0, 200.0, 300.0, 400.0, 500.0, 600.0, 700.0, 800.0]


def read_traj(path):
    stamps, poses = [], []
    for line in open(path):
        tok = line.split()
        if not tok or tok[0].startswith('#'):
            continue
        v = [float(x) for x in tok]
        T = np.eye(4)
        if len(v) == 12:
            T[:3, :] = np.array(v).reshape(3, 4)
        else:
            x, y, z, w = np.array(v[4:8]) / np.linalg.norm(v[4:8])
            T[:3, :3] = [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                         [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                         [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]]
            T[:3, 3] = v[1:4]
            stamps.append(v[0])
        poses.append(T)
    return (stamps or None), poses


def inv_se3(T):  # evo's lie.se3_inverse
    I = np.eye(4)
    I[:3, :3] = T[:3, :3].T
    I[:3, 3] = -T[:3, :3].T @ T[:3, 3]
    return I


def angle(R):  # the rotation angle; acos((tr - 1) / 2) for a rotation, exact for small angles
    v = np.array([R[2, 1] - R[1, 2], R[0, 2] - R[2, 0], R[1, 0] - R[0, 1]])
    return math.atan2(0.5 * np.linalg.norm(v), 0.5 * (np.trace(R) - 1.0))


def stats(values):  # evo's statistics (numpy's population std and median)
    a = np.asarray(values, dtype=float)
    return dict(count=len(a), rmse=math.sqrt(np.mean(a * a)), mean=np.mean(a),
                median=np.median(a), std=np.std(a), min=np.min(a), max=np.max(a))


def pair(est_stamps, ref_stamps, n_est, n_ref, max_diff):  # evo's associate_trajectories
    if est_stamps is None or ref_stamps is None:
        return 'index', list(range(n_est)), list(range(n_ref))
    est_short = n_est <= n_ref
    short, long_ = (est_stamps, ref_stamps) if est_short else (ref_stamps, est_stamps)
    long_ = np.array(long_)
    pe, pr = [], []
    for i, s in enumerate(short):
        d = np.abs(long_ - s)
        j = int(np.argmin(d))
        if d[j] <= max_diff:
            pe.append(i if est_short else j)
            pr.append(j if est_short else i)
    return 'stamps', pe, pr


def umeyama(x, y, with_scale):  # evo's geometry.umeyama_alignment: y ~ c R x + t
    n = x.shape[1]
    mx, my = x.mean(axis=1), y.mean(axis=1)
    sigma_x = np.sum((x - mx[:, None]) ** 2) / n
    cov = (y - my[:, None]) @ (x - mx[:, None]).T / n
    u, d, vt = np.linalg.svd(cov)
    s = np.eye(3)
    if np.linalg.det(u) * np.linalg.det(vt) < 0:
        s[2, 2] = -1
    r = u @ s @ vt
    c = np.trace(np.diag(d) @ s) / sigma_x if with_scale else 1.0
    return r, my - c * r @ mx, c


def drift(est, ref):  # the KITTI devkit's calcSequenceErrors, step 10, then the averages
    dist = [0.0]
    for i in range(1, len(ref)):
        dist.append(dist[-1] + float(np.linalg.norm(ref[i][:3, 3] - ref[i - 1][:3, 3])))
    per = {L: [] for L in LENGTHS}
    for first in range(0, len(ref), 10):
        for L in LENGTHS:
            last = next((i for i in range(first, len(ref)) if dist[i] > dist[first] + L), -1)
            if last == -1:
                continue
            gt = np.linalg.inv(ref[first]) @ ref[last]
            es = np.linalg.inv(est[first]) @ est[last]
            err = np.linalg.inv(es) @ gt
            r = math.acos(max(min(0.5 * (np.trace(err[:3, :3]) - 1.0), 1.0), -1.0))
            per[L].append((np.linalg.norm(err[:3, 3]) / L, r / L))
    every = [e for L in LENGTHS for e in per[L]]
    avg = lambda es: (100 * np.mean([e[0] for e in es]), math.degrees(np.mean([e[1] for e in es]))) if es else (None, None)
    return dist[-1], every, avg(every), {L: (len(per[L]),) + avg(per[L]) for L in LENGTHS}


checked, fails = [0], []


def close(name, got, want, rel, absolute=1e-12):
    checked[0] += 1
    if got is None or want is None:
        ok = got is None and want is None
    else:
        ok = abs(float(got) - float(want)) <= absolute + rel * abs(float(want))
    if not ok:
        fails.append('%s: printed %r, numpy %r' % (name, got, want))


def finish(what):
    if fails:
        print('\n'.join(fails[:20]))
        print('%d of %d figures differ (%s)' % (len(fails), checked[0], what))
        sys.exit(1)
    print('%d figures agree with numpy (%s)' % (checked[0], what))


def check_reference(est_path, ref_path, align, max_diff, json_path, table_path):
    es, ep = read_traj(est_path)
    rs, rp = read_traj(ref_path)
    mode, pe, pr = pair(es, rs, len(ep), len(rp), max_diff)
    est = [ep[i] for i in pe]
    ref = [rp[i] for i in pr]
    r, t, c = np.eye(3), np.zeros(3), 1.0
    if align != 'none':
        r, t, c = umeyama(np.array([p[:3, 3] for p in est]).T, np.array([p[:3, 3] for p in ref]).T,
                          align == 'sim')
    aligned = []
    for p in est:
        a = np.eye(4)
        a[:3, :3] = r @ p[:3, :3]
        a[:3, 3] = c * r @ p[:3, 3] + t
        aligned.append(a)
    ate_t = [np.linalg.norm(a[:3, 3] - q[:3, 3]) for a, q in zip(aligned, ref)]
    ate_r = [math.degrees(angle(q[:3, :3].T @ a[:3, :3])) for a, q in zip(aligned, ref)]
    rpe_t, rpe_r = [], []
    for i in range(len(ref) - 1):
        E = inv_se3(inv_se3(ref[i]) @ ref[i + 1]) @ (inv_se3(aligned[i]) @ aligned[i + 1])
        rpe_t.append(np.linalg.norm(E[:3, 3]))
        rpe_r.append(math.degrees(angle(E[:3, :3])))
    path, segs, (dt, dr), per = drift(est, ref)
    want = {'ate_translation_m': stats(ate_t), 'ate_rotation_deg': stats(ate_r),
            'rpe_translation_m': stats(rpe_t), 'rpe_rotation_deg': stats(rpe_r)}

    j = json.load(open(json_path))
    assert j['pairing']['mode'] == mode and j['pairing']['pairs'] == len(pe), j['pairing']
    assert j['alignment']['mode'] == align
    assert j['estimate']['poses'] == len(ep) and j['reference']['poses'] == len(rp)
    close('alignment scale', j['alignment']['scale'], c, 1e-9)
    for k in range(9):
        close('alignment rotation', j['alignment']['rotation'][k // 3][k % 3], r[k // 3, k % 3], 1e-9, 1e-9)
    close('alignment rotation_deg', j['alignment']['rotation_deg'], math.degrees(angle(r)), 1e-9, 1e-9)
    for k in range(3):
        close('alignment translation', j['alignment']['translation_m'][k], t[k], 1e-9, 1e-9)
    for key, s in want.items():
        metric, part = key[:3], key[4:]
        for f, v in s.items():
            close(key + ' ' + f, j[metric][part][f], v, 1e-9)
    for k in range(len(rpe_t)):
        close('rpe frame %d m' % k, j['rpe']['per_frame']['translation_m'][k], rpe_t[k], 1e-9)
        close('rpe frame %d deg' % k, j['rpe']['per_frame']['rotation_deg'][k], rpe_r[k], 1e-9, 1e-9)
    d = j['kitti_drift']
    close('drift path', d['path_length_m'], path, 1e-12)
    close('drift segments', d['segments'], len(segs), 0)
    close('drift translation %', d['translation_percent'], dt, 1e-9)
    close('drift rotation deg/m', d['rotation_deg_per_m'], dr, 1e-9, 1e-12)
    for entry in d['lengths']:
        n, pt, prr = per[entry['length_m']]
        close('drift %g segments' % entry['length_m'], entry['segments'], n, 0)
        close('drift %g %%' % entry['length_m'], entry['translation_percent'], pt, 1e-9)
        close('drift %g deg/m' % entry['length_m'], entry['rotation_deg_per_m'], prr, 1e-9, 1e-12)

    # The table: the same figures to the 6 significant digits it prints.
    text = open(table_path).read()
    m = re.search(r'pairing: +(by index|by time stamps)[^,]*\), (\d+) pairs|pairing: +by index, (\d+) pairs', text)
    assert m and int(m.group(2) or m.group(3)) == len(pe), 'pairing line'
    m = re.search(r'scale (\S+), rotation (\S+) deg, translation (\S+) (\S+) (\S+) m', text)
    assert m, 'alignment line'
    for name, got, w in zip(['scale', 'rotation', 'tx', 'ty', 'tz'], m.groups(),
                            [c, math.degrees(angle(r))] + list(t)):
        close('table alignment ' + name, float(got), w, 1e-5, 1e-9)
    rows = {l.split()[0]: l.split()[1:] for l in text.splitlines() if l.split() and l.split()[0] in want}
    assert len(rows) == 4, 'four metric rows'
    for key, s in want.items():
        for f, v in zip(['count', 'rmse', 'mean', 'median', 'std', 'min', 'max'], rows[key]):
            close('table %s %s' % (key, f), float(v), s[f], 1e-5)
    m = re.search(r'reference path (\S+) m', text)
    close('table drift path', float(m.group(1)), path, 1e-5)
    if not segs:
        assert 'no segment fits' in text, 'no-segment line'
    else:
        drows = {l.split()[0]: l.split()[1:] for l in text.splitlines()
                 if l.split() and re.fullmatch(r'\d+|all', l.split()[0])}
        for L in LENGTHS:
            n, pt, prr = per[L]
            got = drows['%g' % L]
            close('table drift %g segments' % L, float(got[0]), n, 0)
            if n:
                close('table drift %g %%' % L, float(got[1]), pt, 1e-5)
                close('table drift %g deg/m' % L, float(got[2]), prr, 1e-5)
        close('table drift all %', float(drows['all'][1]), dt, 1e-5)
        close('table drift all deg/m', float(drows['all'][2]), dr, 1e-5)
    finish('%s vs %s, align %s, %s pairing' % (est_path.split('/')[-1], ref_path.split('/')[-1], align, mode))


def rpy_matrix(roll, pitch, yaw):
    cr, sr, cp, sp, cy, sy = math.cos(roll), math.sin(roll), math.cos(pitch), math.sin(pitch), math.cos(yaw), math.sin(yaw)
    Rx = np.array([[1, 0, 0], [0, cr, -sr], [0, sr, cr]])
    Ry = np.array([[cp, 0, sp], [0, 1, 0], [-sp, 0, cp]])
    Rz = np.array([[cy, -sy, 0], [sy, cy, 0], [0, 0, 1]])
    return Rz @ Ry @ Rx


def check_relations(est_path, rel_path, max_diff, json_path, table_path):
    es, ep = read_traj(est_path)
    es = np.array(es)
    t_err, r_err, used, skipped = [], [], [], 0
    rels = [list(map(float, l.split())) for l in open(rel_path) if l.split() and not l.startswith('#')]
    for k, (t1, t2, x, y, z, roll, pitch, yaw) in enumerate(rels):
        i, j = int(np.argmin(np.abs(es - t1))), int(np.argmin(np.abs(es - t2)))
        if abs(es[i] - t1) > max_diff or abs(es[j] - t2) > max_diff:
            skipped += 1
            continue
        used.append(k)
        G = np.eye(4)
        G[:3, :3] = rpy_matrix(roll, pitch, yaw)
        G[:3, 3] = [x, y, z]
        E = inv_se3(G) @ (inv_se3(ep[i]) @ ep[j])
        t_err.append(np.linalg.norm(E[:3, 3]))
        r_err.append(math.degrees(angle(E[:3, :3])))
    t_err, r_err = np.array(t_err), np.array(r_err)
    want = {'abs_translation_m': t_err, 'sqr_translation_m2': t_err ** 2,
            'abs_rotation_deg': r_err, 'sqr_rotation_deg2': r_err ** 2}
    j = json.load(open(json_path))
    assert j['relations']['count'] == len(rels)
    close('relations used', j['relations']['used'], len(t_err), 0)
    close('relations skipped', j['relations']['skipped'], skipped, 0)
    text = open(table_path).read()
    m = re.search(r'\((\d+) relations: (\d+) used, (\d+) skipped', text)
    assert m and [int(g) for g in m.groups()] == [len(rels), len(t_err), skipped], 'relations line'
    rows = {l.split()[0]: l.split()[1:] for l in text.splitlines() if l.split() and l.split()[0] in want}
    for key, v in want.items():
        close(key + ' mean', j[key]['mean'], np.mean(v), 1e-9)
        close(key + ' std', j[key]['std'], np.std(v, ddof=1), 1e-9)
        close('table ' + key + ' mean', float(rows[key][0]), np.mean(v), 1e-5)
        close('table ' + key + ' std', float(rows[key][1]), np.std(v, ddof=1), 1e-5)
    # Every used relation with its stamps and errors, in input order; the ten worst of each.
    per = j['per_relation']
    close('per_relation rows', len(per), len(used), 0)
    for row, k, te, re_ in zip(per, used, t_err, r_err):
        close('per_relation index', row['index'], k, 0)
        close('per_relation stamp1', row['stamp1'], rels[k][0], 1e-12)
        close('per_relation stamp2', row['stamp2'], rels[k][1], 1e-12)
        close('per_relation %d translation' % k, row['translation_m'], te, 1e-9, 1e-12)
        close('per_relation %d rotation' % k, row['rotation_deg'], re_, 1e-9, 1e-9)
    for key, v in (('by_translation', t_err), ('by_rotation', r_err)):
        want_order = [used[u] for u in sorted(range(len(v)), key=lambda u: -v[u])[:10]]
        got = [row['index'] for row in j['worst'][key]]
        assert got == want_order, 'worst %s: %s, numpy %s' % (key, got, want_order)
    worst_rows = [l.split() for l in text.split('worst relations')[1].splitlines()[2:] if l.split()]
    assert [int(r[0]) for r in worst_rows] == [row['index'] for row in j['worst']['by_translation']], 'worst table'
    finish('relations %s on %s, %d used, %d skipped' % (rel_path.split('/')[-1], est_path.split('/')[-1], len(t_err), skipped))


def rot(axis, a):
    k = np.asarray(axis, dtype=float) / np.linalg.norm(axis)
    K = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + math.sin(a) * K + (1 - math.cos(a)) * K @ K


def quaternion(R):  # x y z w of a rotation matrix
    w = math.sqrt(max(0.0, 1 + np.trace(R))) / 2
    x = math.copysign(math.sqrt(max(0.0, 1 + R[0, 0] - R[1, 1] - R[2, 2])) / 2, R[2, 1] - R[1, 2])
    y = math.copysign(math.sqrt(max(0.0, 1 - R[0, 0] + R[1, 1] - R[2, 2])) / 2, R[0, 2] - R[2, 0])
    z = math.copysign(math.sqrt(max(0.0, 1 - R[0, 0] - R[1, 1] + R[2, 2])) / 2, R[1, 0] - R[0, 1])
    return x, y, z, w


def kitti_line(T):
    return ' '.join('%.9e' % v for v in T[:3, :].reshape(-1)) + '\n'


def tum_line(stamp, T):
    return '%.6f ' % stamp + ' '.join('%.9e' % v for v in list(T[:3, 3]) + list(quaternion(T[:3, :3]))) + '\n'


def generate(balm, kitti, out):
    _, ref = read_traj(balm + '/poses.txt')
    times = [float(l) for l in open(balm + '/times.txt') if l.strip()]
    Ra, ta, s = rot([0.3, -0.5, 0.8], math.radians(25)), np.array([2.0, -1.0, 0.5]), 1.05
    est = []
    for i, T in enumerate(ref):  # a similarity copy with deterministic noise
        dR = rot([math.sin(1.3 * i), math.cos(0.7 * i), 0.5], math.radians(0.4 * math.sin(2.1 * i + 0.3)))
        dt = 0.02 * np.array([math.sin(0.9 * i), math.cos(1.1 * i), math.sin(0.5 * i + 1)])
        E = np.eye(4)
        E[:3, :3] = Ra @ T[:3, :3] @ dR
        E[:3, 3] = s * Ra @ (T[:3, 3] + dt) + ta
        est.append(E)
    open(out + '/balm_est.txt', 'w').write(''.join(kitti_line(T) for T in est))
    open(out + '/balm_est39.txt', 'w').write(''.join(kitti_line(T) for T in est[:39]))
    open(out + '/balm_ref_tum.txt', 'w').write('# stamp tx ty tz qx qy qz qw\n' + ''.join(
        tum_line(times[i], T) for i, T in enumerate(ref)))
    open(out + '/balm_est_tum.txt', 'w').write(''.join(
        tum_line(times[i] + 0.002, T) for i, T in enumerate(est) if i not in (10, 25)))
    rel = []
    pairs = [(i, i + 1) for i in range(39)] + [(i, i + 5) for i in range(0, 35, 5)] + [(3, 30)]
    for i, k in pairs:
        D = inv_se3(ref[i]) @ ref[k]
        R = D[:3, :3]
        yaw, pitch, roll = math.atan2(R[1, 0], R[0, 0]), math.asin(max(-1, min(1, -R[2, 0]))), math.atan2(R[2, 1], R[2, 2])
        rel.append('%.6f %.6f %.12e %.12e %.12e %.12e %.12e %.12e\n' % ((times[i], times[k]) + tuple(D[:3, 3]) + (roll, pitch, yaw)))
    rel.append('%.6f %.6f 1 0 0 0 0 0\n' % (times[0] - 100, times[0] - 99))  # not in the estimate
    open(out + '/balm_rel.txt', 'w').write('# t1 t2 x y z roll pitch yaw\n' + ''.join(rel))
    _, gt = read_traj(kitti)
    est = [gt[0].copy()]
    for i in range(len(gt) - 1):  # 1 % longer steps, a yaw bias and noise: the estimate drifts
        D = np.linalg.inv(gt[i]) @ gt[i + 1]
        D[:3, 3] = 1.01 * D[:3, 3] + 0.005 * np.array([math.sin(i), math.cos(1.3 * i), math.sin(0.7 * i)])
        D[:3, :3] = rot([0, 1, 0], 2e-5) @ D[:3, :3]
        T = est[-1] @ D
        u, _, vt = np.linalg.svd(T[:3, :3])
        T[:3, :3] = u @ vt
        est.append(T)
    open(out + '/kitti_est.txt', 'w').write(''.join(kitti_line(T) for T in est))


if __name__ == '__main__':
    a = sys.argv
    if a[1] == 'generate':
        generate(a[2], a[3], a[4])
    elif a[1] == 'reference':
        check_reference(a[2], a[3], a[4], float(a[5]), a[6], a[7])
    else:
        check_relations(a[2], a[3], float(a[4]), a[5], a[6])
EOF

check "perturbed estimates generated" "$PY" "$tmp/oracle.py" generate "$balm" "$kitti" "$tmp"

# evaluate EST REF ALIGN [options]: table and JSON runs, then numpy on both.
evaluate() {
  local est=$1 ref=$2 align=$3
  shift 3
  if "$MM" evaluate "$est" --reference "$ref" --align "$align" "$@" >"$tmp/table.txt" 2>"$tmp/err" &&
    "$MM" evaluate "$est" --reference "$ref" --align "$align" --format json "$@" >"$tmp/run.json" 2>>"$tmp/err"; then
    [ "$(basename "$est")" = balm_est.txt ] && [ "$align" = sim ] && cat "$tmp/table.txt"
    check "evaluate $(basename "$est") vs $(basename "$ref") --align $align: every figure" \
      "$PY" "$tmp/oracle.py" reference "$est" "$ref" "$align" 0.01 "$tmp/run.json" "$tmp/table.txt"
  else
    echo "FAIL: evaluate $est $ref $align: $(head -c 300 "$tmp/err")"
    fails=$((fails + 1))
  fi
}
for align in none rigid sim; do evaluate "$tmp/balm_est.txt" "$balm/poses.txt" "$align"; done
evaluate "$tmp/balm_est_tum.txt" "$tmp/balm_ref_tum.txt" sim     # by stamps, 38 pairs
evaluate "$tmp/balm_est_tum.txt" "$tmp/balm_ref_tum.txt" rigid --est-format tum --ref-format tum
evaluate "$tmp/kitti_est.txt" "$kitti" rigid                      # drift over 3.7 km
check "the KITTI pair has drift segments" "$PY" -c "
import json; assert json.load(open('$tmp/run.json'))['kitti_drift']['segments'] > 3000"

if "$MM" evaluate "$tmp/balm_est_tum.txt" --relations "$tmp/balm_rel.txt" >"$tmp/table.txt" 2>"$tmp/err" &&
  "$MM" evaluate "$tmp/balm_est_tum.txt" --relations "$tmp/balm_rel.txt" --format json >"$tmp/run.json" 2>>"$tmp/err"; then
  cat "$tmp/table.txt"
  check "relation metric: every figure" "$PY" "$tmp/oracle.py" relations "$tmp/balm_est_tum.txt" \
    "$tmp/balm_rel.txt" 0.01 "$tmp/run.json" "$tmp/table.txt"
else
  echo "FAIL: evaluate --relations: $(head -c 300 "$tmp/err")"
  fails=$((fails + 1))
fi

# Bad input: exit 1, one line naming the file.
ref=$balm/poses.txt
est=$tmp/balm_est.txt
expect 1 "nothere.txt" -- "$MM" evaluate "$tmp/nothere.txt" --reference "$ref"
expect 1 "nothere.txt" -- "$MM" evaluate "$est" --reference "$tmp/nothere.txt"
expect 1 "nothere.txt" -- "$MM" evaluate "$tmp/balm_est_tum.txt" --relations "$tmp/nothere.txt"
head -1 "$est" >"$tmp/cols.txt"
echo "1 0 0 0 0 1 0 0 0 0 1" >>"$tmp/cols.txt"
expect 1 "cols.txt: line 2" -- "$MM" evaluate "$tmp/cols.txt" --reference "$ref"
sed '3s/^[^ ]*/nan/' "$est" >"$tmp/nan.txt"
expect 1 "nan.txt: line 3" -- "$MM" evaluate "$tmp/nan.txt" --reference "$ref"
sed '5s/^[^ ]*/2.0/' "$est" >"$tmp/notrot.txt"
expect 1 "notrot.txt: line 5" -- "$MM" evaluate "$tmp/notrot.txt" --reference "$ref"
awk 'NR == 4 { $1 = 0 } { print }' "$tmp/balm_est_tum.txt" >"$tmp/nonmono.txt"
expect 1 "nonmono.txt: line 4" -- "$MM" evaluate "$tmp/nonmono.txt" --reference "$tmp/balm_ref_tum.txt"
awk 'NR == 2 { $5 = 0; $6 = 0; $7 = 0; $8 = 0 } { print }' "$tmp/balm_est_tum.txt" >"$tmp/zeroq.txt"
expect 1 "zeroq.txt: line 2" -- "$MM" evaluate "$tmp/zeroq.txt" --reference "$tmp/balm_ref_tum.txt"
expect 1 "balm_est39.txt" -- "$MM" evaluate "$tmp/balm_est39.txt" --reference "$ref"
expect 1 "balm_est_tum.txt" -- "$MM" evaluate "$tmp/balm_est_tum.txt" --reference "$ref"
expect 1 "balm_est.txt" -- "$MM" evaluate "$est" --relations "$tmp/balm_rel.txt"
expect 1 "line 1" -- "$MM" evaluate "$est" --reference "$ref" --est-format tum
: >"$tmp/empty.txt"
expect 1 "empty.txt" -- "$MM" evaluate "$tmp/empty.txt" --reference "$ref"
expect 1 "balm_rel.txt" -- "$MM" evaluate "$tmp/balm_est_tum.txt" --relations "$tmp/balm_rel.txt" --max-time-diff 0.001
echo "1 2 3" >"$tmp/rel_bad.txt"
expect 1 "rel_bad.txt: line 1" -- "$MM" evaluate "$tmp/balm_est_tum.txt" --relations "$tmp/rel_bad.txt"
expect 1 "$tmp" -- "$MM" evaluate "$tmp" --reference "$ref"

# Usage: exit 2.
expect 2 "--align" -- "$MM" evaluate "$est" --reference "$ref" --align affine
expect 2 "--format" -- "$MM" evaluate "$est" --reference "$ref" --format xml
expect 2 "--est-format" -- "$MM" evaluate "$est" --reference "$ref" --est-format csv
expect 2 "--ref-format" -- "$MM" evaluate "$est" --reference "$ref" --ref-format ""
for v in nan -1 inf 1e999 x; do
  expect 2 "--max-time-diff" -- "$MM" evaluate "$est" --reference "$ref" --max-time-diff "$v"
done
expect 2 "--reference" -- "$MM" evaluate "$est"
expect 2 "--relations" -- "$MM" evaluate "$est" --reference "$ref" --relations "$tmp/balm_rel.txt"
expect 2 "--align" -- "$MM" evaluate "$tmp/balm_est_tum.txt" --relations "$tmp/balm_rel.txt" --align sim
expect 2 "estimate" -- "$MM" evaluate --reference "$ref"
finish
