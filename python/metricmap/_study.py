"""The study's table (`metricmap compare`) as a list of dicts: grid and octree statistics of
each file under each configuration. Wiring only: read_points, grid and octree do the work."""

import os
from typing import Any, Dict, Iterable, List, Mapping, Optional, Union

from ._metricmap import grid, octree, read_points

#: The study's three configurations (J. Blasco Lozano, "Práctica 2: Mapas métricos").
STUDY_CONFIGS = (
    {"cell_size": 1.0, "min_cell_size": 1.0, "max_points": 100},
    {"cell_size": 0.5, "min_cell_size": 0.5, "max_points": 100},
    {"cell_size": 2.0, "min_cell_size": 1.0, "max_points": 200},
)

_GRID_KEYS = ("total_cells", "occupied_cells", "empty_cells", "mean_points_per_occupied_cell", "points")
_OCTREE_KEYS = (
    "total_nodes",
    "leaf_nodes",
    "internal_nodes",
    "occupied_leaves",
    "empty_leaves",
    "mean_points_per_occupied_leaf",
    "points",
    "max_depth",
)


def compare(
    paths: Iterable[Union[str, "os.PathLike[str]"]],
    configs: Optional[Iterable[Mapping[str, float]]] = None,
) -> List[Dict[str, Any]]:
    """Grid vs octree statistics over files x configurations, as ``metricmap compare``.

    Parameters
    ----------
    paths : iterable of str or os.PathLike
        Point cloud files (.pcd, .ply, KITTI .bin).
    configs : iterable of dict, optional
        Each with ``cell_size`` (grid, metres), ``min_cell_size`` (octree, metres) and
        ``max_points`` (octree); default: the study's three (:data:`STUDY_CONFIGS`).

    An empty ``paths`` or ``configs`` is a ValueError (``metricmap compare`` refuses an empty
    selection too).

    Returns
    -------
    list of dict
        One per (file, configuration), files outermost: ``file``, ``config``, ``points``,
        ``grid`` (total_cells, occupied_cells, empty_cells, mean_points_per_occupied_cell,
        points) and ``octree`` (total_nodes, leaf_nodes, internal_nodes, occupied_leaves,
        empty_leaves, mean_points_per_occupied_leaf, points, max_depth).
    """
    if isinstance(paths, (str, bytes, os.PathLike)):
        raise TypeError(f"paths must be an iterable of paths, got the single path {paths!r}: "
                        "give [path]")
    keys = {"cell_size", "min_cell_size", "max_points"}
    paths = list(paths)
    if not paths:
        raise ValueError("paths is empty: give at least one point cloud file")
    configs = [dict(c) for c in (STUDY_CONFIGS if configs is None else configs)]
    if not configs:
        raise ValueError("configs is empty: give at least one configuration, or None for the study's three")
    for c in configs:
        missing, unknown = keys - set(c), set(c) - keys
        if missing:
            raise ValueError(f"config {c} lacks {sorted(missing)}")
        if unknown:
            raise ValueError(f"config {c}: unknown key(s) {sorted(unknown)}; the keys are "
                             f"{sorted(keys)}")
        m = c["max_points"]
        if isinstance(m, bool) or not float(m).is_integer():
            raise ValueError(f"config {c}: max_points must be a whole number, got {m!r}")
    rows = []
    for path in paths:
        points = read_points(path)
        for c in configs:
            g = grid(points, cell_size=c["cell_size"]).statistics
            o = octree(points, max_points=int(c["max_points"]), min_cell_size=c["min_cell_size"]).statistics
            rows.append(
                {
                    "file": os.fspath(path),
                    "config": {k: c[k] for k in ("cell_size", "min_cell_size", "max_points")},
                    "points": len(points),
                    "grid": {k: g[k] for k in _GRID_KEYS},
                    "octree": {k: o[k] for k in _OCTREE_KEYS},
                }
            )
    return rows
