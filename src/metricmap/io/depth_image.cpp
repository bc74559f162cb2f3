#include "metricmap/io/depth_image.h"

#include <algorithm>
#include <cctype>
#include <fstream>

#include <vtkImageData.h>
#include <vtkImageReader2.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkSmartPointer.h>
#include <vtkTIFFReader.h>

#include "metricmap/exceptions.h"

namespace metricmap {
namespace {

vtkSmartPointer<vtkImageData> readImage(const std::string& path, std::string& kind) {
  if (!std::ifstream(path).good()) throw InputError(path + ": cannot open");
  std::string ext = path.substr(path.find_last_of('.') + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  vtkSmartPointer<vtkImageReader2> reader;
  if (ext == "png") {
    reader = vtkSmartPointer<vtkPNGReader>::New();
    kind = "png";
  } else if (ext == "tif" || ext == "tiff") {
    reader = vtkSmartPointer<vtkTIFFReader>::New();
    kind = "tiff";
  } else {
    throw InputError(path + ": unknown image extension (expected .png, .tif or .tiff)");
  }
  if (!reader->CanReadFile(path.c_str()))
    throw InputError(path + ": not a readable " + kind + " image");
  reader->SetFileName(path.c_str());
  reader->GlobalWarningDisplayOff();
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  int dims[3] = {0, 0, 0};
  if (image == nullptr || reader->GetErrorCode() != 0) throw InputError(path + ": cannot decode");
  image->GetDimensions(dims);
  if (dims[0] <= 0 || dims[1] <= 0 || dims[2] != 1 || image->GetPointData() == nullptr ||
      image->GetScalarPointer() == nullptr) {
    throw InputError(path + ": not a 2D image");
  }
  return image;
}

/// VTK's image origin is the lower-left pixel (the PNG reader flips to it); row 0 here is the top
/// row of the picture. `flip` says whether VTK's rows run bottom-up for this reader.
template <typename T, typename Out>
void copyRows(vtkImageData* image, int comps_out, bool flip, std::vector<Out>& out) {
  int dims[3];
  image->GetDimensions(dims);
  const int comps = image->GetNumberOfScalarComponents();
  const T* src = static_cast<const T*>(image->GetScalarPointer());
  out.resize(static_cast<std::size_t>(dims[0]) * dims[1] * comps_out);
  for (int v = 0; v < dims[1]; ++v) {
    const T* row = src + static_cast<std::size_t>(flip ? dims[1] - 1 - v : v) * dims[0] * comps;
    for (int u = 0; u < dims[0]; ++u) {
      for (int c = 0; c < comps_out; ++c) {
        out[(static_cast<std::size_t>(v) * dims[0] + u) * comps_out + c] =
            static_cast<Out>(row[u * comps + c]);
      }
    }
  }
}

}  // namespace

DepthImage readDepthImage(const std::string& path) {
  DepthImage d;
  vtkSmartPointer<vtkImageData> image = readImage(path, d.kind);
  if (image->GetScalarType() != VTK_UNSIGNED_SHORT && image->GetScalarType() != VTK_SHORT) {
    throw InputError(path + ": a depth image must be 16-bit, this one is " +
                     std::string(image->GetScalarTypeAsString()));
  }
  if (image->GetNumberOfScalarComponents() != 1) {
    throw InputError(path + ": a depth image must have one channel, this one has " +
                     std::to_string(image->GetNumberOfScalarComponents()));
  }
  int dims[3];
  image->GetDimensions(dims);
  d.width = dims[0];
  d.height = dims[1];
  copyRows<std::uint16_t>(image, 1, d.kind == "png", d.values);
  return d;
}

RgbImage readRgbImage(const std::string& path) {
  std::string kind;
  vtkSmartPointer<vtkImageData> image = readImage(path, kind);
  if (image->GetScalarType() != VTK_UNSIGNED_CHAR || image->GetNumberOfScalarComponents() < 3) {
    throw InputError(path + ": an RGB image must be 8-bit with 3 or 4 channels");
  }
  RgbImage rgb;
  int dims[3];
  image->GetDimensions(dims);
  rgb.width = dims[0];
  rgb.height = dims[1];
  copyRows<std::uint8_t>(image, 3, kind == "png", rgb.rgb);
  return rgb;
}

}  // namespace metricmap
