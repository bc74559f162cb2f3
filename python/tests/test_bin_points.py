"""metricmap.bin_points against Active Neural SLAM's numpy bin_points, written here from its
published definition (env/utils/depth_utils.py; the (counts, isvalids) return of the
cognitive-mapping code it derives from), on the bundled Kinect and TUM frames."""

import numpy as np
import pytest

import metricmap as mm


def ans_bin_points(XYZ_cms, map_size, z_bins, xy_resolution):
    sh = XYZ_cms.shape
    XYZ_cms = XYZ_cms.reshape([-1, sh[-3], sh[-2], sh[-1]])
    n_z_bins = len(z_bins) + 1
    counts = []
    isvalids = []
    for XYZ_cm in XYZ_cms:
        isnotnan = np.logical_not(np.isnan(XYZ_cm[:, :, 0]))
        with np.errstate(invalid="ignore"):
            X_bin = np.round(XYZ_cm[:, :, 0] / xy_resolution).astype(np.int32)
            Y_bin = np.round(XYZ_cm[:, :, 1] / xy_resolution).astype(np.int32)
        Z_bin = np.digitize(XYZ_cm[:, :, 2], bins=z_bins).astype(np.int32)
        isvalid = np.array(
            [X_bin >= 0, X_bin < map_size, Y_bin >= 0, Y_bin < map_size, Z_bin >= 0, Z_bin < n_z_bins, isnotnan]
        )
        isvalid = np.all(isvalid, axis=0)
        ind = (Y_bin * map_size + X_bin) * n_z_bins + Z_bin
        ind[np.logical_not(isvalid)] = 0
        count = np.bincount(ind.ravel(), isvalid.ravel().astype(np.int32), minlength=map_size * map_size * n_z_bins)
        counts.append(np.reshape(count, [map_size, map_size, n_z_bins]))
        isvalids.append(isvalid)
    counts = np.array(counts).reshape(list(sh[:-3]) + [map_size, map_size, n_z_bins])
    isvalids = np.array(isvalids).reshape(list(sh[:-3]) + [sh[-3], sh[-2], 1])
    return counts, isvalids


def frame_cm(data, depth, camera, scale):
    """A depth frame as ANS's geocentric centimetres: x right, y forward, z up (camera 88 cm up)."""
    d = mm.read_depth_image(str(data / depth))
    k = mm.read_camera(str(data / camera))
    xyz = mm.depth_to_cloud(d, k["fx"], k["fy"], k["cx"], k["cy"], scale).astype(np.float64)
    return np.stack([xyz[..., 0] * 100 + 600, xyz[..., 2] * 100, 88 - xyz[..., 1] * 100], axis=-1)


KINECT = [
    ("pcl_grabber_kinect_depth/tiff/frame_20121214T142255.814212_depth.tiff", "pcl_grabber_kinect_depth/xml/frame_20121214T142255.814212.xml"),
    ("pcl_grabber_kinect_depth/tiff/frame_20121214T142256.068683_depth.tiff", "pcl_grabber_kinect_depth/xml/frame_20121214T142256.068683.xml"),
]


@pytest.fixture(scope="module")
def kinect(data):
    return np.stack([frame_cm(data, d, c, 0.001) for d, c in KINECT])


@pytest.fixture(scope="module")
def tum(data):
    return frame_cm(data, "open3d_tum_depth/TUM_depth.png", "open3d_tum_depth/camera_primesense.json", 0.0002)


def check(xyz, map_size, z_bins, res):
    counts, valid = mm.bin_points(xyz, map_size, z_bins, res)
    ref_counts, ref_valid = ans_bin_points(xyz, map_size, z_bins, res)
    assert counts.dtype == ref_counts.dtype and counts.shape == ref_counts.shape
    assert valid.dtype == ref_valid.dtype and valid.shape == ref_valid.shape
    np.testing.assert_array_equal(counts, ref_counts)
    np.testing.assert_array_equal(valid, ref_valid)
    return counts, valid


@pytest.mark.parametrize("dtype", [np.float32, np.float64])
@pytest.mark.parametrize("res", [5, 2.5, 0.7])
def test_kinect_batch(kinect, dtype, res):
    xyz = kinect.copy()
    xyz[..., 0] += 120 * res - 600  # the map (240 cells) centred on the camera
    xyz = xyz.astype(dtype)
    counts, valid = check(xyz, 240, [25, 150], res)
    assert np.isnan(xyz[..., 0]).any()  # the frames have holes: the NaN mask is exercised
    assert 0 < valid.sum() < valid.size and counts.sum() == valid.sum()


@pytest.mark.parametrize("dtype", [np.float32, np.float64])
def test_tum_single_frame(tum, dtype):
    check(tum.astype(dtype), 480, [5.0, 60.0, 120.0], 5.0)


def test_leading_batch_dims_and_channels(kinect):
    xyz = np.concatenate([kinect, np.ones(kinect.shape[:-1] + (1,))], axis=-1)  # C = 4
    check(xyz.reshape((1, 2) + xyz.shape[1:]).astype(np.float32), 100, [0.0, 100.0], 10.0)


def test_edges_and_ties():
    # x / res at .5 ties (half to even), negative zero, NaN z (top bin), NaN y, infinities,
    # values beyond int32, decreasing and empty z_bins.
    vals = [12.5, 17.5, 22.5, -2.4, -0.0, 4.99, 5.0, np.nan, np.inf, -np.inf, 3e10, 1e30]
    rng = np.random.default_rng(1)
    xyz = rng.choice(vals, size=(2, 9, 11, 3))
    xyz[0, :, :, 2] = rng.uniform(-10, 40, size=(9, 11))
    for dtype in (np.float32, np.float64):
        a = xyz.astype(dtype)
        check(a, 8, [0.0, 10.0, 20.0], 5.0)
        check(a, 8, [20.0, 10.0, 0.0], 5.0)
        check(a, 8, [10.0, 10.0], 5.0)
        check(a, 8, [], 5.0)
        check(a, 8, [1.0], -2.5)
    c, v = mm.bin_points(np.array([[[12.5, 17.5, 0.0]]], np.float32), 10, [1.0], 5.0)
    assert c[4, 2, 0] == 1  # round(2.5) = 2, round(3.5) = 4


def test_integer_input_is_divided_in_float64():
    xyz = np.arange(2 * 3 * 4 * 3).reshape(2, 3, 4, 3)
    check(xyz, 20, [5, 30], 3)


@pytest.mark.parametrize(
    "args,exc",
    [
        ((np.zeros((4, 3)), 10, [1.0], 1.0), ValueError),  # no (H, W, C)
        ((np.zeros((2, 2, 2)), 10, [1.0], 1.0), ValueError),  # C < 3
        ((np.zeros((2, 2, 3)), 0, [1.0], 1.0), ValueError),
        ((np.zeros((2, 2, 3)), -5, [1.0], 1.0), ValueError),
        ((np.zeros((2, 2, 3)), 10, [1.0, 0.5, 2.0], 1.0), ValueError),  # not monotonic
        ((np.zeros((2, 2, 3)), 10, [np.nan], 1.0), ValueError),
        ((np.zeros((2, 2, 3)), 10, [1.0], 0.0), ValueError),
        ((np.zeros((2, 2, 3)), 10, [1.0], np.nan), ValueError),
        ((np.zeros((2, 2, 3)), 10**6, [1.0], 1.0), ValueError),  # 2**31 bins or more
        ((np.zeros((0, 2, 3)), 10, [1.0], 1.0), ValueError),
        ((np.zeros((2, 2, 3), complex), 10, [1.0], 1.0), TypeError),
        ((np.array([[["a", "b", "c"]]]), 10, [1.0], 1.0), TypeError),
    ],
)
def test_bad_arguments(args, exc):
    with pytest.raises(exc):
        mm.bin_points(*args)
