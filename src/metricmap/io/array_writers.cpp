#include "metricmap/io/array_writers.h"

#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <type_traits>

#include <unistd.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkObject.h>
#include <vtkPNGWriter.h>
#include <vtkPNMWriter.h>

#include "metricmap/io/cloud_writer.h"
#include "metricmap/io/output_set.h"

namespace metricmap {

namespace {

/// VTK's writers do not report a short write everywhere: the file must exist and end with
/// a complete image (PNG: the IEND chunk; PNM: non-empty).
bool wholeFileWritten(const std::string& tmp, bool png) {
  std::FILE* f = std::fopen(tmp.c_str(), "rb");
  if (f == nullptr) return false;
  bool ok = std::fseek(f, 0, SEEK_END) == 0 && std::ftell(f) > 0;
  if (ok && !png) {
    std::fclose(f);
    return true;
  }
  char tail[8] = {0};
  ok = ok && std::fseek(f, -8, SEEK_END) == 0 && std::fread(tail, 1, 8, f) == 8 &&
       std::memcmp(tail, "IEND", 4) == 0;
  std::fclose(f);
  return ok;
}

template <typename Writer>
void writeImage(const std::string& path, int width, int height, int channels,
                const std::vector<std::uint8_t>& pixels) {
  if (pixels.size() != static_cast<std::size_t>(width) * height * channels) {
    throw std::invalid_argument(path + ": pixel buffer does not match the image size");
  }
  vtkObject::GlobalWarningDisplayOff();  // failures are reported by the exception below
  vtkNew<vtkImageData> image;
  image->SetDimensions(width, height, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, channels);
  auto* dst = static_cast<std::uint8_t*>(image->GetScalarPointer());
  const std::size_t row_bytes = static_cast<std::size_t>(width) * channels;
  for (int v = 0; v < height; ++v) {  // VTK's row 0 is the bottom
    std::memcpy(dst + static_cast<std::size_t>(height - 1 - v) * row_bytes,
                pixels.data() + static_cast<std::size_t>(v) * row_bytes, row_bytes);
  }
  checkOutputPath(path);
  const std::string tmp = path + ".tmp-" + std::to_string(::getpid());
  vtkNew<Writer> writer;
  writer->SetFileName(tmp.c_str());
  writer->SetInputData(image);
  writer->Write();
  if (writer->GetErrorCode() != 0 ||
      !wholeFileWritten(tmp, std::is_same<Writer, vtkPNGWriter>::value) ||
      std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw std::runtime_error(path + ": cannot write image");
  }
}

}  // namespace

void writePng(const std::string& path, int width, int height, int channels,
              const std::vector<std::uint8_t>& pixels) {
  writeImage<vtkPNGWriter>(path, width, height, channels, pixels);
}

void writePgm(const std::string& path, int width, int height,
              const std::vector<std::uint8_t>& grey) {
  writeImage<vtkPNMWriter>(path, width, height, 1, grey);
}

void writeNpyUint32(const std::string& path, const std::vector<std::size_t>& shape,
                    const std::vector<std::uint32_t>& data) {
  std::string dims;
  std::size_t n = 1;
  for (std::size_t s : shape) {
    dims += std::to_string(s) + ", ";
    n *= s;
  }
  if (shape.size() > 1) dims.erase(dims.size() - 2);  // (a, b, c) but (a,) for one axis
  if (n != data.size()) throw std::invalid_argument(path + ": shape does not match the data");
  std::string header = "{'descr': '<u4', 'fortran_order': False, 'shape': (" + dims + "), }";
  // Magic (6) + version (2) + header length (2) + header, padded with spaces to 64 bytes, '\n'.
  const std::size_t total = 10 + header.size() + 1;
  header.append((64 - total % 64) % 64, ' ');
  header += '\n';
  std::string out = "\x93NUMPY";
  out += '\x01';
  out += '\x00';
  out += static_cast<char>(header.size() & 0xFF);
  out += static_cast<char>((header.size() >> 8) & 0xFF);
  out += header;
  out.append(reinterpret_cast<const char*>(data.data()), data.size() * sizeof(std::uint32_t));
  writeTextAtomic(path, out);
}

}  // namespace metricmap
