"""Open3D out: `to_open3d()` on clouds and maps. Open3D is imported on the first call, and is
not needed by anything else in metricmap."""

import numpy as np

_MISSING = (
    "to_open3d needs Open3D, which is not installed for this interpreter "
    "(pip install open3d, or Debian's python3-open3d); the rest of metricmap does not need it"
)


def _o3d():
    try:
        import open3d
    except ImportError as e:
        raise ImportError(_MISSING) from e
    return open3d


def _cloud(xyz):
    o3d = _o3d()
    xyz = np.ascontiguousarray(np.asarray(xyz)[:, :3], dtype=np.float64)
    return o3d.geometry.PointCloud(o3d.utility.Vector3dVector(xyz))


def to_open3d(points):
    """An `open3d.geometry.PointCloud` of points: an (N, 3) or (N, 4) array (as `read_points`
    returns; the fourth column is dropped), anything with a `to_open3d()` (a `Grid`, a
    `LogOddsMap`, a `Scan`) or with `.points`. Coordinates become float64, Open3D's type."""
    if hasattr(points, "to_open3d"):
        return points.to_open3d()
    if hasattr(points, "points") and not isinstance(points, np.ndarray):
        points = points.points
    a = np.asarray(points)
    if a.dtype.kind not in "iuf" or a.ndim != 2 or a.shape[1] not in (3, 4):
        raise ValueError(
            f"to_open3d: points must be an (N, 3) or (N, 4) array of real numbers, "
            f"got shape {a.shape} dtype {a.dtype}"
        )
    return _cloud(a)


def _grid_to_open3d(self):
    """An `open3d.geometry.PointCloud` of the occupied cells' means (centroids), in the cells'
    order: with `origin='open3d'` the points of Open3D's `voxel_down_sample`."""
    return _cloud(self.means)


def _log_odds_to_open3d(self, free=False):
    """An `open3d.geometry.PointCloud` of the occupied voxels' centres (`free=True`: the free
    ones'), as `extract_point_cloud` gives them."""
    occupied, free_centres = self.extract_point_cloud()
    return _cloud(free_centres if free else occupied)


def _scan_to_open3d(self):
    """An `open3d.geometry.PointCloud` of the scan's points (sensor frame)."""
    return _cloud(self.points)


def install(module):
    module.Grid.to_open3d = _grid_to_open3d
    module.LogOddsMap.to_open3d = _log_odds_to_open3d
    module.Scan.to_open3d = _scan_to_open3d
