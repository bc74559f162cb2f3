#include "metricmap/io/array_writers.h"

#include <atomic>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <type_traits>

#include <unistd.h>
#include <vtkErrorCode.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkObject.h>
#include <vtkPNGWriter.h>
#include <vtkPNMWriter.h>

#include "metricmap/io/atomic_file.h"
#include "metricmap/io/checked_file.h"
#include "metricmap/io/cloud_writer.h"
#include "metricmap/io/output_set.h"

namespace metricmap {

namespace {

/// Bytes of a PNM header ("P5", whitespace or comments, width, height, maxval, one whitespace)
/// at the start of `f`, or -1.
long pnmHeaderBytes(std::FILE* f) {
  char head[512] = {0};
  const std::size_t n = std::fread(head, 1, sizeof head, f);
  if (n < 2 || head[0] != 'P') return -1;
  std::size_t i = 2;
  for (int field = 0; field < 3; ++field) {
    while (i < n && (std::isspace(static_cast<unsigned char>(head[i])) || head[i] == '#')) {
      if (head[i] == '#') {
        while (i < n && head[i] != '\n') ++i;
      } else {
        ++i;
      }
    }
    if (i >= n || !std::isdigit(static_cast<unsigned char>(head[i]))) return -1;
    while (i < n && std::isdigit(static_cast<unsigned char>(head[i]))) ++i;
  }
  return i < n ? static_cast<long>(i + 1) : -1;
}

/// VTK's writers do not report a short write everywhere (a full disk): the file must hold the
/// whole image (PNG: ends with the IEND chunk; PNM: exactly its header and every pixel byte).
bool wholeFileWritten(const std::string& tmp, bool png, std::size_t pixel_bytes) {
  std::FILE* f = std::fopen(tmp.c_str(), "rb");
  if (f == nullptr) return false;
  bool ok = std::fseek(f, 0, SEEK_END) == 0 && std::ftell(f) > 0;
  if (ok && !png) {
    const long size = std::ftell(f);
    std::rewind(f);
    const long header = pnmHeaderBytes(f);
    std::fclose(f);
    return header > 0 &&
           static_cast<std::size_t>(size) == static_cast<std::size_t>(header) + pixel_bytes;
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
  const std::string tmp = temporaryPathFor(path);
  vtkNew<Writer> writer;
  writer->SetFileName(tmp.c_str());
  writer->SetInputData(image);
  writer->Write();
  const unsigned long vtk_error = writer->GetErrorCode();
  const bool whole =
      vtk_error == 0 &&
      wholeFileWritten(tmp, std::is_same<Writer, vtkPNGWriter>::value, pixels.size());
  if (!whole) {
    discardTemporary(tmp);
    const std::string why = vtk_error == vtkErrorCode::OutOfDiskSpaceError || vtk_error == 0
                                ? "incomplete image: no space left on device?"
                                : vtkErrorCode::GetStringFromErrorCode(vtk_error);
    throw std::runtime_error(outputDisplayName(path) + ": cannot write image (" + why + ")");
  }
  commitTemporary(tmp, path);
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

namespace {

/// One .npy (format 1.0) of a C-order little-endian array: `descr` its numpy type string.
void writeNpy(const std::string& path, const std::vector<std::size_t>& shape, const char* descr,
              const void* data, std::size_t count, std::size_t item_bytes) {
  std::string dims;
  std::size_t n = 1;
  for (std::size_t s : shape) {
    dims += std::to_string(s) + ", ";
    n *= s;
  }
  if (shape.size() > 1) dims.erase(dims.size() - 2);  // (a, b, c) but (a,) for one axis
  if (n != count) throw std::invalid_argument(path + ": shape does not match the data");
  std::string header =
      std::string("{'descr': '") + descr + "', 'fortran_order': False, 'shape': (" + dims + "), }";
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
  out.append(reinterpret_cast<const char*>(data), count * item_bytes);
  writeTextAtomic(path, out);
}

}  // namespace

void writeNpyUint32(const std::string& path, const std::vector<std::size_t>& shape,
                    const std::vector<std::uint32_t>& data) {
  writeNpy(path, shape, "<u4", data.data(), data.size(), sizeof(std::uint32_t));
}

void writeNpyFloat32(const std::string& path, const std::vector<std::size_t>& shape,
                     const std::vector<float>& data) {
  writeNpy(path, shape, "<f4", data.data(), data.size(), sizeof(float));
}

}  // namespace metricmap
