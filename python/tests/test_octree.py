"""metricmap.octree against the study's table, a plain recursive reference and the CLI."""

import csv
import subprocess

import numpy as np
import pytest

import metricmap as mm

# README's study table (max 100 points, min cell 1.0): nodes, leaves, internal, occupied, empty, mean.
STUDY_OCTREE = {
    "ciencias000": (2521, 2206, 315, 1223, 983, 48.10),
    "museo000": (2793, 2444, 349, 1212, 1232, 65.30),
    "poli000": (2777, 2430, 347, 1437, 993, 43.72),
    "poli001": (2473, 2164, 309, 1373, 791, 44.74),
}


@pytest.mark.parametrize("name", sorted(STUDY_OCTREE))
def test_study_table(data, name):
    points = mm.read_points(str(data / "ua_mapas_metricos_pcd" / f"{name}.pcd"))
    s = mm.octree(points, max_points=100, min_cell_size=1.0).statistics
    got = (s["total_nodes"], s["leaf_nodes"], s["internal_nodes"], s["occupied_leaves"], s["empty_leaves"])
    assert got == STUDY_OCTREE[name][:5]
    assert round(s["mean_points_per_occupied_leaf"], 2) == STUDY_OCTREE[name][5]


def reference_leaves(p, max_points, min_cell):
    """The definition, recursively: split in 8 at the midpoint while count > max_points and the
    largest edge > min_cell (depth < 21); a point goes up on an axis iff coord >= mid."""
    leaves = []
    nodes = [0]

    def build(idx, lo, hi, depth):
        if len(idx) > max_points and (hi - lo).max() > min_cell and depth < 21:
            mid = (lo + hi) / 2
            up = p[idx] >= mid
            code = up[:, 0] * 1 + up[:, 1] * 2 + up[:, 2] * 4
            for octant in range(8):
                bits = np.array([(octant >> k) & 1 for k in range(3)], bool)
                clo = np.where(bits, mid, lo)
                chi = np.where(bits, hi, mid)
                nodes[0] += 1
                build(idx[code == octant], clo, chi, depth + 1)
        else:
            mean = p[idx].mean(axis=0) if len(idx) else np.zeros(3)
            leaves.append((*lo, *hi, len(idx), *mean))

    build(np.arange(len(p)), p.min(axis=0), p.max(axis=0), 0)
    return np.array(leaves), nodes[0] + 1


@pytest.mark.parametrize("max_points,min_cell", [(100, 1.0), (20, 0.25), (1000, 0.0)])
def test_leaves_equal_a_recursive_reference(data, max_points, min_cell):
    points = mm.read_points(str(data / "ua_mapas_metricos_pcd/museo000.pcd"))
    p = points[:, :3].astype(np.float64)
    ref, nodes = reference_leaves(p, max_points, min_cell)
    o = mm.octree(points, max_points=max_points, min_cell_size=min_cell)
    assert len(o) == nodes
    leaf = o.leaves
    mine = np.column_stack([o.mins[leaf], o.maxs[leaf], o.counts[leaf], o.means[leaf]])
    a = mine[np.lexsort(mine[:, :3].T)]
    b = ref[np.lexsort(ref[:, :3].T)]
    np.testing.assert_array_equal(a[:, :6], b[:, :6])  # bounds bit for bit
    np.testing.assert_array_equal(a[:, 6], b[:, 6])  # counts
    np.testing.assert_allclose(a[:, 7:], b[:, 7:], rtol=0, atol=1e-9)
    # point_order groups each node's rows
    for k in np.flatnonzero(leaf & (o.counts > 0))[:50]:
        rows = o.point_order[o.first_points[k] : o.first_points[k] + o.counts[k]]
        np.testing.assert_allclose(p[rows].mean(axis=0), o.means[k], atol=1e-9)


def test_leaves_equal_the_cli(cli, data, tmp_path):
    src = data / "ua_mapas_metricos_pcd/poli001.pcd"
    out = tmp_path / "leaves.csv"
    subprocess.run(
        [cli, "octree", str(src), "--max-points", "50", "--min-cell-size", "0.5", "--leaves", str(out)],
        check=True,
        capture_output=True,
    )
    with open(out) as f:
        rows = list(csv.DictReader(f))
    o = mm.octree(mm.read_points(str(src)), max_points=50, min_cell_size=0.5)
    assert len(rows) == int(o.leaves.sum())
    node = np.array([int(r["node"]) for r in rows])
    assert o.leaves[node].all()  # the CLI's node ids are the module's
    np.testing.assert_array_equal(np.array([int(r["depth"]) for r in rows]), o.depths[node])
    np.testing.assert_array_equal(np.array([int(r["count"]) for r in rows]), o.counts[node])

    def col(*names):
        return np.array([[float(r[n]) for n in names] for r in rows])

    np.testing.assert_allclose(col("min_x", "min_y", "min_z"), o.mins[node], rtol=1e-8, atol=1e-12)
    np.testing.assert_allclose(col("max_x", "max_y", "max_z"), o.maxs[node], rtol=1e-8, atol=1e-12)
    np.testing.assert_allclose(col("mean_x", "mean_y", "mean_z"), o.means[node], rtol=1e-8, atol=1e-12)
