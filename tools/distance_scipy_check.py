# The KITTI field (.npy of `metricmap distance`) against scipy's exact EDT over the occupied voxels.
import sys, json, numpy as np, metricmap as mm
from scipy.ndimage import distance_transform_edt
bt, npy, rep = sys.argv[1:4]
r = json.load(open(rep)); f = np.load(npy)
m = mm.LogOddsMap.read(bt)
keys, lo = m.voxels()
res = r["resolution"]; origin = np.array(r["origin"])
k0 = np.round((origin / res) - 0.5).astype(np.int64)
occ = np.zeros(f.shape, bool)
sel = lo >= 0  # log-odds >= 0: occupied (threshold 0.5)
idx = keys[sel] - k0
occ[idx[:, 0], idx[:, 1], idx[:, 2]] = True
ref = np.minimum(distance_transform_edt(~occ) * res, r["max_distance"])
print("voxels", f.size, "occupied", occ.sum(), "max |npy - scipy| =", float(np.abs(f - ref).max()))
