"""LiDAR odometry over a scan source, its error against the source's reference poses, and the
map built from the estimated trajectory.
Usage: python3 sequence_odometry.py [SOURCE] [map.pgm]   (default: the bundled KITTI frames)"""

import pathlib
import sys

import metricmap as mm

repo = pathlib.Path(__file__).resolve().parents[2]
path = sys.argv[1] if len(sys.argv) > 1 else repo / "data/kitti_odometry_00"
out = pathlib.Path(sys.argv[2]) if len(sys.argv) > 2 else pathlib.Path("odometry_map.pgm")

source = mm.open_scan_source(path)  # KITTI root, folder of scans, .txt list or CARMEN log
print(f"{source.info['kind']} source: {len(source)} scans, first has {len(source[0].points)} points")

run = mm.run_odometry(source)  # what `metricmap odometry` computes
print(f"odometry: {len(run['poses'])} poses ({run['convention']}), "
      f"range window {run['config']['min_range']:.1f}-{run['config']['max_range']:.1f} m")
if run["reference_poses"] is not None:
    # both start at the first frame: no alignment (6 collinear frames do not fix a rotation)
    ev = mm.evaluate_trajectory(run["poses"], run["reference_poses"], align="none")
    print(f"ATE rmse {ev['ate']['translation_stats']['rmse']:.3f} m, "
          f"RPE rmse {ev['rpe']['translation_stats']['rmse']:.3f} m per frame")

mapper = mm.SequenceMapper(source, map_resolution=0.2)
mapper.build(run["sensor_poses"])  # the scans again, at the estimated poses
mapper.write_map(out)
print(f"map: {mapper.occupied_cells()} occupied cells -> {out}")
