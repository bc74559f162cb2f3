"""metricmap: metric maps from range data — occupancy grids, adaptive octrees, Split & Merge
lines, depth images to height-binned maps, 3D log-odds maps and LiDAR odometry — over numpy.

Every function takes points as (N, 3) or (N, 4) arrays (float32 read in place when
C-contiguous, anything else converted once) and returns numpy arrays; see docs/PYTHON.md.
"""

from ._metricmap import (  # noqa: F401
    FREE,
    OCCUPIED,
    UNKNOWN,
    CapacityError,
    Grid,
    HeightMap,
    InputError,
    LidarOdometry,
    LogOddsMap,
    Octree,
    __version__,
    bin_points,
    camera_to_map,
    cloud_info,
    depth_to_cloud,
    fit_floor,
    grid,
    octree,
    read_camera,
    read_cloud,
    read_depth_image,
    read_points,
    read_scan_log,
    sensor_profile,
    split_and_merge,
    write_pcd,
)
from ._study import STUDY_CONFIGS, compare  # noqa: F401

__all__ = [
    "FREE",
    "OCCUPIED",
    "UNKNOWN",
    "CapacityError",
    "Grid",
    "HeightMap",
    "InputError",
    "LidarOdometry",
    "LogOddsMap",
    "Octree",
    "STUDY_CONFIGS",
    "__version__",
    "bin_points",
    "camera_to_map",
    "cloud_info",
    "compare",
    "depth_to_cloud",
    "fit_floor",
    "grid",
    "octree",
    "read_camera",
    "read_cloud",
    "read_depth_image",
    "read_points",
    "read_scan_log",
    "sensor_profile",
    "split_and_merge",
    "write_pcd",
]
