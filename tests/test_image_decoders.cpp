// libpng/libtiff decoders against VTK's readers (the previous decoders) on the bundled images,
// and damaged images refused with InputError / CapacityError.
#include <string>

#include <gtest/gtest.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkTIFFReader.h>

#include "metricmap/common/memory_budget.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/depth_image.h"

namespace metricmap {
namespace {

const std::string kData = METRICMAP_DATA_DIR;
const std::string kRegress = std::string(METRICMAP_SOURCE_DIR) + "/tests/fuzz_regressions/";
const std::string kKinect = kData + "/pcl_grabber_kinect_depth/tiff/frame_20121214T142255.814212_";

/// VTK's value at picture row v (row 0 at the top); `flip`: VTK's rows run bottom-up.
template <typename T>
T vtkAt(vtkImageData* image, int u, int v, int c, bool flip) {
  int dims[3];
  image->GetDimensions(dims);
  const int row = flip ? dims[1] - 1 - v : v;
  return static_cast<T*>(image->GetScalarPointer(u, row, 0))[c];
}

}  // namespace

TEST(ImageDecoders, PngDepthAndColourMatchVtk) {
  vtkNew<vtkPNGReader> depth_reader;
  depth_reader->SetFileName((kData + "/open3d_tum_depth/TUM_depth.png").c_str());
  depth_reader->Update();
  const DepthImage d = readDepthImage(kData + "/open3d_tum_depth/TUM_depth.png");
  ASSERT_EQ(d.width, 640);
  ASSERT_EQ(d.height, 480);
  std::size_t nonzero = 0;
  for (int v = 0; v < d.height; ++v)
    for (int u = 0; u < d.width; ++u) {
      ASSERT_EQ(d.at(u, v), (vtkAt<std::uint16_t>(depth_reader->GetOutput(), u, v, 0, true)));
      nonzero += d.at(u, v) != 0;
    }
  EXPECT_GT(nonzero, 200000u);

  vtkNew<vtkPNGReader> rgb_reader;
  rgb_reader->SetFileName((kData + "/open3d_tum_depth/TUM_color.png").c_str());
  rgb_reader->Update();
  const RgbImage rgb = readRgbImage(kData + "/open3d_tum_depth/TUM_color.png");
  ASSERT_EQ(rgb.rgb.size(), 640u * 480u * 3u);
  for (int v = 0; v < rgb.height; v += 7)
    for (int u = 0; u < rgb.width; ++u)
      for (int c = 0; c < 3; ++c)
        ASSERT_EQ(rgb.rgb[(static_cast<std::size_t>(v) * rgb.width + u) * 3 + c],
                  (vtkAt<std::uint8_t>(rgb_reader->GetOutput(), u, v, c, true)));
}

TEST(ImageDecoders, TiffDepthAndColourMatchVtk) {
  vtkNew<vtkTIFFReader> depth_reader;
  depth_reader->SetFileName((kKinect + "depth.tiff").c_str());
  depth_reader->Update();
  const DepthImage d = readDepthImage(kKinect + "depth.tiff");
  ASSERT_EQ(d.width, 640);
  ASSERT_EQ(d.height, 480);
  for (int v = 0; v < d.height; ++v)
    for (int u = 0; u < d.width; ++u)
      ASSERT_EQ(d.at(u, v), (vtkAt<std::uint16_t>(depth_reader->GetOutput(), u, v, 0, false)));

  vtkNew<vtkTIFFReader> rgb_reader;
  rgb_reader->SetFileName((kKinect + "rgb.tiff").c_str());
  rgb_reader->Update();
  const RgbImage rgb = readRgbImage(kKinect + "rgb.tiff");
  for (int v = 0; v < rgb.height; v += 7)
    for (int u = 0; u < rgb.width; ++u)
      for (int c = 0; c < 3; ++c)
        ASSERT_EQ(rgb.rgb[(static_cast<std::size_t>(v) * rgb.width + u) * 3 + c],
                  (vtkAt<std::uint8_t>(rgb_reader->GetOutput(), u, v, c, false)));
}

TEST(ImageDecoders, DamagedImagesAreInputErrors) {
  for (const char* f : {"png_truncated_60000.png", "png_8_bytes.png", "png_zero_size.png",
                        "png_declares_30000x30000.png", "tiff_signed_negative.tiff"}) {
    EXPECT_THROW(readDepthImage(kRegress + f), InputError) << f;
    EXPECT_THROW(readRgbImage(kRegress + f), InputError) << f;
  }
  EXPECT_THROW(readDepthImage(kRegress), InputError);  // a directory
}

TEST(ImageDecoders, OneRowImageAndBudget) {
  const DepthImage d = readDepthImage(kRegress + "depth_one_row.png");
  ASSERT_EQ(d.width, 4);
  ASSERT_EQ(d.height, 1);
  EXPECT_EQ(d.values, (std::vector<std::uint16_t>{1000, 2000, 0, 3000}));
  const std::uint64_t saved = memoryBudget();
  setMemoryBudget(100 * 1024);  // 640 x 480 x 2 bytes do not fit
  EXPECT_THROW(readDepthImage(kData + "/open3d_tum_depth/TUM_depth.png"), CapacityError);
  EXPECT_THROW(readDepthImage(kKinect + "depth.tiff"), CapacityError);
  setMemoryBudget(saved);
  EXPECT_NO_THROW(readDepthImage(kKinect + "depth.tiff"));
}

}  // namespace metricmap
