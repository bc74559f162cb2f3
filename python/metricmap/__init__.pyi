# Type stubs of the metricmap package (checked against the compiled module by
# python/tests/test_stubs.py: every public name here exists there and vice versa, with the
# same parameter names and order).
import enum
import os
from typing import Any, Callable, Dict, Iterable, List, Mapping, Optional, Tuple, Union, overload

import numpy as np
import numpy.typing as npt

_StrPath = Union[str, "os.PathLike[str]"]
_Progress = Callable[[int, int], object]  # progress(done, total)

__version__: str
class CellState(enum.IntEnum):
    UNKNOWN = 0
    FREE = 1
    OCCUPIED = 2

UNKNOWN: CellState
FREE: CellState
OCCUPIED: CellState

STUDY_CONFIGS: Tuple[Dict[str, float], ...]

class InputError(OSError, ValueError): ...
class CapacityError(MemoryError, ValueError): ...

class Grid:
    @property
    def statistics(self) -> Dict[str, Any]: ...
    @property
    def indices(self) -> npt.NDArray[np.int64]: ...
    @property
    def counts(self) -> npt.NDArray[np.uint64]: ...
    @property
    def means(self) -> npt.NDArray[np.float64]: ...
    @property
    def first_points(self) -> npt.NDArray[np.uint64]: ...
    @property
    def min_index(self) -> Tuple[int, int, int]: ...
    @property
    def dims(self) -> Tuple[int, int, int]: ...
    @property
    def origin(self) -> Tuple[float, float, float]: ...
    @property
    def cell_size(self) -> float: ...
    @property
    def point_cells(self) -> Optional[npt.NDArray[np.int64]]: ...
    def to_open3d(self) -> Any: ...
    def __len__(self) -> int: ...

class Octree:
    @property
    def statistics(self) -> Dict[str, Any]: ...
    @property
    def mins(self) -> npt.NDArray[np.float64]: ...
    @property
    def maxs(self) -> npt.NDArray[np.float64]: ...
    @property
    def means(self) -> npt.NDArray[np.float64]: ...
    @property
    def counts(self) -> npt.NDArray[np.uint32]: ...
    @property
    def depths(self) -> npt.NDArray[np.uint32]: ...
    @property
    def first_points(self) -> npt.NDArray[np.uint32]: ...
    @property
    def parents(self) -> npt.NDArray[np.int64]: ...
    @property
    def first_children(self) -> npt.NDArray[np.int64]: ...
    @property
    def leaves(self) -> npt.NDArray[np.bool_]: ...
    @property
    def occupied_leaves(self) -> npt.NDArray[np.uint64]: ...
    @property
    def point_order(self) -> npt.NDArray[np.uint32]: ...
    def __len__(self) -> int: ...

class HeightMap:
    def __init__(
        self,
        resolution: float = 0.05,
        map_size: int = 480,
        z_bins: List[float] = [0.1, 1.0],
        obstacle_threshold: int = 1,
    ) -> None: ...
    def add_frame(self, points: npt.ArrayLike, to_map: npt.ArrayLike) -> None: ...
    @property
    def counts(self) -> npt.NDArray[np.uint32]: ...
    @property
    def obstacles(self) -> npt.NDArray[np.bool_]: ...
    @property
    def explored(self) -> npt.NDArray[np.bool_]: ...
    @property
    def statistics(self) -> Dict[str, Any]: ...

class DistanceField:
    def __init__(
        self,
        source: Union[LogOddsMap, _StrPath, npt.ArrayLike],
        max_distance: float = 2.0,
        resolution: Optional[float] = None,
        unknown: str = "free",
        signed: bool = False,
        incremental: bool = False,
        threads: int = 0,
    ) -> None: ...
    @property
    def field(self) -> npt.NDArray[np.float32]: ...
    @property
    def states(self) -> npt.NDArray[np.uint8]: ...
    @property
    def shape(self) -> Tuple[int, ...]: ...
    @property
    def dimensions(self) -> int: ...
    @property
    def resolution(self) -> float: ...
    @property
    def origin(self) -> List[float]: ...
    @property
    def max_distance(self) -> float: ...
    @property
    def seconds(self) -> float: ...
    def query(
        self, points: npt.ArrayLike
    ) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]: ...
    def is_observed(self, points: npt.ArrayLike) -> npt.NDArray[np.bool_]: ...
    def nearest_obstacle(
        self, points: npt.ArrayLike
    ) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.bool_]]: ...
    def write_vdb(self, path: _StrPath) -> None: ...
    def update(self, map: LogOddsMap) -> Dict[str, Any]: ...
    def costmap(
        self,
        inscribed_radius: float = 0.1,
        inflation_radius: float = 0.55,
        cost_scaling_factor: float = 10.0,
    ) -> npt.NDArray[np.uint8]: ...

class LogOddsMap:
    def to_open3d(self, free: bool = False) -> Any: ...
    def __init__(
        self,
        resolution: float = 0.1,
        prob_hit: float = 0.7,
        prob_miss: float = 0.4,
        clamp_min: float = 0.1192,
        clamp_max: float = 0.971,
        occupancy_threshold: float = 0.5,
    ) -> None: ...
    @staticmethod
    def read(
        path: _StrPath,
        prob_hit: float = 0.7,
        prob_miss: float = 0.4,
        clamp_min: float = 0.1192,
        clamp_max: float = 0.971,
        occupancy_threshold: float = 0.5,
    ) -> LogOddsMap: ...
    def insert_point_cloud(
        self, points: npt.ArrayLike, origin: npt.ArrayLike, max_range: float = -1.0
    ) -> Dict[str, int]: ...
    def probability(self, points: npt.ArrayLike) -> npt.NDArray[np.float64]: ...
    def log_odds(self, points: npt.ArrayLike) -> npt.NDArray[np.float32]: ...
    def states(self, points: npt.ArrayLike) -> npt.NDArray[np.int8]: ...
    def voxels(self) -> Tuple[npt.NDArray[np.int64], npt.NDArray[np.float32]]: ...
    def extract_point_cloud(self) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]: ...
    def write(self, path: _StrPath) -> None: ...
    def project_band(
        self, z_min: float, z_max: float
    ) -> Tuple[npt.NDArray[np.uint8], Dict[str, Any]]: ...
    def merge(self, other: LogOddsMap) -> None: ...
    def clear(self) -> None: ...
    @property
    def resolution(self) -> float: ...
    @property
    def known_voxels(self) -> int: ...
    @property
    def occupied_voxels(self) -> int: ...
    @property
    def free_voxels(self) -> int: ...

class LidarOdometry:
    def __init__(
        self,
        max_range: float = 100.0,
        min_range: float = 3.0,
        voxel_size: float = 1.0,
        max_points_per_voxel: int = 20,
        initial_threshold: float = 2.0,
        min_threshold: float = 0.3,
        fine_threshold: float = 1.0,
        max_iterations: int = 500,
        convergence: float = 1e-4,
        max_threshold: float = 0.0,
        coarse_voxel_size: float = 0.0,
        deskew: bool = False,
        threads: int = 0,
    ) -> None: ...
    def register_frame(
        self, points: npt.ArrayLike, timestamps: Optional[npt.ArrayLike] = None
    ) -> npt.NDArray[np.float64]: ...
    @property
    def last_result(self) -> Dict[str, Any]: ...
    @property
    def poses(self) -> npt.NDArray[np.float64]: ...
    def reset(self) -> None: ...

class Scan:
    @property
    def points(self) -> npt.NDArray[np.float32]: ...
    def to_open3d(self) -> Any: ...
    @property
    def intensity(self) -> npt.NDArray[np.float32]: ...
    @property
    def point_times(self) -> npt.NDArray[np.float64]: ...
    @property
    def stamp(self) -> float: ...
    @property
    def index(self) -> int: ...
    @property
    def name(self) -> str: ...
    @property
    def laser(self) -> Optional[Tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]]: ...
    @property
    def odometry(self) -> Optional[npt.NDArray[np.float64]]: ...

class ScanSource:
    def __len__(self) -> int: ...
    @overload
    def __getitem__(self, index: int) -> Scan: ...
    @overload
    def __getitem__(self, index: slice) -> List[Scan]: ...
    @property
    def info(self) -> Dict[str, Any]: ...
    @property
    def path(self) -> str: ...

class SequenceMapper:
    def __init__(
        self,
        source: Union[ScanSource, _StrPath],
        map_resolution: float = 0.1,
        min_hits: int = 1,
        min_range: float = 0.0,
        max_range: Optional[float] = None,
        voxel: float = 0.0,
        min_height: Optional[float] = None,
        max_height: Optional[float] = None,
        keep_global_cloud: bool = False,
        occupancy_2d_resolution: float = 0.0,
        band_2d: Optional[Tuple[float, float]] = None,
        occupancy_2d_max_range: Optional[float] = None,
    ) -> None: ...
    def build(
        self,
        poses: npt.ArrayLike,
        frames: Optional[Iterable[int]] = None,
        *,
        progress: Optional[_Progress] = None,
    ) -> SequenceMapper: ...
    def hit_map(self) -> Dict[str, Any]: ...
    def occupied_cells(self) -> int: ...
    def write_map(self, path: _StrPath, kind: str = "hits") -> None: ...
    def global_cloud(self) -> npt.NDArray[np.float32]: ...
    def occupancy_2d(self) -> Optional[Dict[str, Any]]: ...
    @property
    def poses(self) -> npt.NDArray[np.float64]: ...

class PoseGraph:
    def __init__(self, dimension: int = 2) -> None: ...
    @property
    def dimension(self) -> int: ...
    @property
    def chained_guess(self) -> bool: ...
    def add_vertex(self, id: int, pose: npt.ArrayLike) -> int: ...
    def add_edge(
        self,
        from_index: int,
        to_index: int,
        measurement: npt.ArrayLike,
        information: npt.ArrayLike,
        loop: bool = False,
    ) -> int: ...
    def __len__(self) -> int: ...
    @property
    def edge_count(self) -> int: ...
    @property
    def poses(self) -> npt.NDArray[np.float64]: ...
    @property
    def ids(self) -> npt.NDArray[np.int64]: ...
    @property
    def fixed(self) -> npt.NDArray[np.bool_]: ...
    def edges(self) -> Dict[str, npt.NDArray[Any]]: ...
    def chi2(self) -> float: ...
    def optimize(
        self,
        max_iterations: int = 100,
        threads: int = 1,
        odometry_loss: str = "none",
        loop_loss: str = "huber",
        loss_scale: float = 0.0,
    ) -> Dict[str, Any]: ...
    def to_g2o(self) -> str: ...
    def write(self, path: _StrPath) -> None: ...

def slam2d_parameters() -> List[Dict[str, Any]]: ...

class Slam2DConfig:
    def __init__(self, **kwargs: Any) -> None: ...
    min_range: float
    max_range: float
    voxel_filter: float
    resolution: float
    scans_per_submap: int
    prob_hit: float
    prob_miss: float
    node_min_distance: float
    node_min_angle_deg: float
    node_max_time: float
    local_linear_window: float
    local_angular_window_deg: float
    local_angular_window_per_turn: float
    weak_direction_min_gain: float
    weak_direction_information: float
    weak_direction_weight: float
    translation_weight: float
    rotation_weight: float
    refine_iterations: int
    bicubic: bool
    loop_linear_window: float
    loop_angular_window_deg: float
    loop_min_score: float
    loop_max_distance: float
    wide_min_node_gap: int
    wide_every_n_nodes: int
    wide_idle_nodes: int
    wide_linear_window: float
    wide_angular_window_deg: float
    loop_every_n_nodes: int
    loop_min_node_gap: int
    loop_min_overlap: float
    loop_max_chi2: float
    loop_max_submaps: int
    loop_search_points: int
    branch_and_bound_depth: int
    edge_translation_sigma: float
    edge_rotation_sigma_deg: float
    loop_translation_sigma: float
    loop_rotation_sigma_deg: float
    optimize_every_n_nodes: int
    optimize_iterations: int
    final_iterations: int
    map_resolution: float
    map_prob_hit: float
    map_prob_miss: float
    map_clamp_min: float
    map_clamp_max: float
    map_occupancy_threshold: float
    map_max_range: float
    def validate(self) -> None: ...

class Slam2D:
    def __init__(
        self,
        config: Optional[Slam2DConfig] = None,
        sensor_to_base: npt.ArrayLike = (0.0, 0.0, 0.0),
    ) -> None: ...
    def add_scan(
        self,
        angles: npt.ArrayLike,
        ranges: npt.ArrayLike,
        *,
        odometry: Optional[npt.ArrayLike] = None,
        stamp: Optional[float] = None,
    ) -> None: ...
    def finish(self) -> None: ...
    @property
    def trajectory(self) -> npt.NDArray[np.float64]: ...
    @property
    def stamps(self) -> npt.NDArray[np.float64]: ...
    @property
    def node_scans(self) -> npt.NDArray[np.int64]: ...
    @property
    def loops(self) -> List[Dict[str, Any]]: ...
    @property
    def graph(self) -> PoseGraph: ...
    @property
    def stats(self) -> Dict[str, Any]: ...
    @property
    def config(self) -> Slam2DConfig: ...
    def map(self) -> Dict[str, Any]: ...
    def map_image(self, kind: str = "trinary") -> Dict[str, Any]: ...
    def write_map(self, path: _StrPath, kind: str = "trinary") -> None: ...

class Map2D:
    @property
    def cells(self) -> npt.NDArray[np.int8]: ...
    @property
    def resolution(self) -> float: ...
    @property
    def origin(self) -> Tuple[float, float, float]: ...
    @property
    def width(self) -> int: ...
    @property
    def height(self) -> int: ...

def read_map(path: _StrPath) -> Map2D: ...
def localize2d_parameters() -> List[Dict[str, Any]]: ...

class Localization2D:
    @property
    def status(self) -> str: ...
    @property
    def localised(self) -> bool: ...
    @property
    def pose(self) -> Optional[npt.NDArray[np.float64]]: ...
    @property
    def score(self) -> float: ...
    @property
    def margin(self) -> float: ...

class Localizer2D:
    def __init__(
        self,
        map: Union[Map2D, _StrPath],
        parameters: Optional[Dict[str, float]] = None,
        sensor_to_base: npt.ArrayLike = (0.0, 0.0, 0.0),
    ) -> None: ...
    def set_initial_pose(self, pose: npt.ArrayLike) -> None: ...
    def localize(
        self,
        angles: npt.ArrayLike,
        ranges: npt.ArrayLike,
        *,
        odometry: Optional[npt.ArrayLike] = None,
    ) -> Localization2D: ...
    @property
    def status(self) -> str: ...
    @property
    def stats(self) -> Dict[str, Any]: ...

class LocalizationRun:
    @property
    def poses(self) -> npt.NDArray[np.float64]: ...
    @property
    def localised(self) -> npt.NDArray[np.bool_]: ...
    @property
    def status(self) -> List[str]: ...
    @property
    def scores(self) -> npt.NDArray[np.float64]: ...
    @property
    def stamps(self) -> npt.NDArray[np.float64]: ...
    @property
    def frames(self) -> npt.NDArray[np.int64]: ...
    @property
    def stats(self) -> Dict[str, Any]: ...

def run_localize2d(
    source: Union[ScanSource, _StrPath],
    map: Union[Map2D, _StrPath],
    frames: Optional[Iterable[int]] = None,
    *,
    initial_pose: Optional[npt.ArrayLike] = None,
    parameters: Optional[Dict[str, float]] = None,
    progress: Optional[_Progress] = None,
) -> LocalizationRun: ...
def read_points(path: _StrPath) -> npt.NDArray[np.float32]: ...
def read_cloud(path: _StrPath) -> Dict[str, npt.NDArray[Any]]: ...
def cloud_info(path: _StrPath) -> Dict[str, Any]: ...
def write_pcd(path: _StrPath, points: npt.ArrayLike, format: str = "binary") -> None: ...
def grid(
    points: npt.ArrayLike,
    cell_size: float = 1.0,
    origin: Union[str, Tuple[float, float, float]] = "cloud-min",
    threads: int = 0,
    *,
    point_cells: bool = False,
) -> Grid: ...
def to_open3d(points: Any) -> Any: ...
def se2_to_se3(poses: npt.ArrayLike) -> npt.NDArray[np.float64]: ...
def se3_to_se2(poses: npt.ArrayLike) -> npt.NDArray[np.float64]: ...
def octree(
    points: npt.ArrayLike,
    max_points: int = 100,
    min_cell_size: float = 1.0,
    cubic: bool = False,
    root_box: Optional[Tuple[npt.ArrayLike, npt.ArrayLike]] = None,
    threads: int = 0,
) -> Octree: ...
def bin_points(
    XYZ: npt.ArrayLike, map_size: int, z_bins: npt.ArrayLike, xy_resolution: float
) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.bool_]]: ...
def camera_to_map(height: float, pitch: float, yaw: float = 0.0) -> npt.NDArray[np.float64]: ...
def fit_floor(
    points: npt.ArrayLike, distance_threshold: float = 0.02, stride: int = 4
) -> Tuple[npt.NDArray[np.float64], Tuple[float, float, float, float], int]: ...
def read_depth_image(path: _StrPath) -> npt.NDArray[np.uint16]: ...
def read_camera(path: _StrPath) -> Dict[str, float]: ...
def depth_to_cloud(
    depth: npt.NDArray[np.uint16], fx: float, fy: float, cx: float, cy: float, depth_scale: float
) -> npt.NDArray[np.float32]: ...
def read_scan_log(
    path: _StrPath, preset: Optional[str] = None
) -> List[Tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]]: ...
def split_and_merge(
    angles: npt.ArrayLike,
    ranges: npt.ArrayLike,
    *,
    distance_threshold: float = 0.05,
    angle_threshold: float = 0.08726646259971647,
    min_points: int = 5,
    min_length: float = 0.1,
    max_gap: float = 0.0,
    purge: Optional[str] = None,
    chi2: Optional[float] = None,
    range_sigma: float = 0.01,
    bearing_sigma: float = 0.0017453292519943296,
) -> Dict[str, Any]: ...
def sensor_profile(points: npt.ArrayLike, *, statistics: bool = False) -> Dict[str, float]: ...
def set_memory_budget(size: Union[int, str]) -> None: ...
def memory_budget() -> int: ...
def open_scan_source(
    path: _StrPath,
    format: str = "auto",
    sequence: Optional[str] = None,
    reference_poses: Optional[_StrPath] = None,
    times: Optional[_StrPath] = None,
    topic: Optional[str] = None,
) -> ScanSource: ...
def run_odometry(
    source: Union[ScanSource, _StrPath],
    frames: Optional[Iterable[int]] = None,
    profile: Optional[str] = None,
    max_range: Optional[float] = None,
    min_range: Optional[float] = None,
    voxel_size: Optional[float] = None,
    deskew: str = "auto",
    threads: int = 0,
    *,
    progress: Optional[_Progress] = None,
) -> Dict[str, Any]: ...
def reference_sensor_poses(
    source: Union[ScanSource, _StrPath], frames: Optional[Iterable[int]] = None
) -> npt.NDArray[np.float64]: ...
def run_slam2d(
    source: Union[ScanSource, _StrPath],
    frames: Optional[Iterable[int]] = None,
    config: Optional[Slam2DConfig] = None,
    loop_closure: bool = True,
    *,
    progress: Optional[_Progress] = None,
) -> Slam2D: ...
class Slam3DConfig:
    def __init__(self, **kwargs: Any) -> None: ...
    min_range: float
    max_range: float
    voxel: float
    local_window: int
    local_voxel: float
    sc_rings: int
    sc_sectors: int
    sc_max_radius: float
    sc_height_offset: float
    sc_candidates: int
    sc_max_distance: float
    loop_min_travel: float
    loop_radius: float
    loop_every: int
    loop_cooldown: int
    verify_coarse_threshold: float
    verify_fine_threshold: float
    verify_overlap_distance: float
    verify_min_overlap: float
    verify_min_structure_overlap: float
    verify_max_correction: float
    odometry_sigma_m: float
    odometry_sigma_deg: float
    loop_sigma_m: float
    loop_sigma_deg: float
    optimize_every: int
    max_iterations: int

class Slam3D:
    def __init__(self, config: Optional[Slam3DConfig] = None) -> None: ...
    def add_scan(self, points: npt.ArrayLike, odometry_pose: npt.ArrayLike) -> Dict[str, Any]: ...
    def finish(self) -> Dict[str, Any]: ...
    @property
    def poses(self) -> npt.NDArray[np.float64]: ...
    @property
    def odometry_poses(self) -> npt.NDArray[np.float64]: ...
    @property
    def loops(self) -> List[Dict[str, Any]]: ...
    @property
    def verified_loops(self) -> int: ...
    @property
    def timing(self) -> Dict[str, Any]: ...
    @property
    def bytes(self) -> int: ...
    def __len__(self) -> int: ...
    def local_map(self, node: int) -> npt.NDArray[np.float32]: ...

def slam3d_parameters() -> List[Dict[str, Any]]: ...
def run_slam3d(
    source: Union[ScanSource, _StrPath],
    frames: Optional[Iterable[int]] = None,
    config: Optional[Slam3DConfig] = None,
    *,
    progress: Optional[_Progress] = None,
) -> Dict[str, Any]: ...
def read_g2o(path: _StrPath) -> PoseGraph: ...
def read_trajectory(
    path: _StrPath, format: str = "auto"
) -> Tuple[npt.NDArray[np.float64], Optional[npt.NDArray[np.float64]]]: ...
def write_trajectory(
    path: _StrPath,
    poses: npt.ArrayLike,
    stamps: Optional[npt.ArrayLike] = None,
    format: str = "kitti",
) -> None: ...
def evaluate_trajectory(
    estimate: npt.ArrayLike,
    reference: npt.ArrayLike,
    estimate_stamps: Optional[npt.ArrayLike] = None,
    reference_stamps: Optional[npt.ArrayLike] = None,
    align: str = "rigid",
    max_time_diff: Optional[float] = None,
) -> Dict[str, Any]: ...
def read_relations(
    path: _StrPath,
) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]: ...
def relation_error(
    poses: npt.ArrayLike,
    stamps: npt.ArrayLike,
    relations: Union[_StrPath, npt.ArrayLike],
    relation_stamps: Optional[npt.ArrayLike] = None,
    max_time_diff: float = 0.01,
    odometry_poses: Optional[npt.ArrayLike] = None,
    odometry_stamps: Optional[npt.ArrayLike] = None,
) -> Dict[str, Any]: ...
def compare(
    paths: Iterable[_StrPath], configs: Optional[Iterable[Mapping[str, float]]] = None
) -> List[Dict[str, Any]]: ...
