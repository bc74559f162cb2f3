// libtiff with its own error handler: every codec error becomes an InputError naming the file.
#include <tiffio.h>

#include <sys/stat.h>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <memory>
#include <mutex>
#include <string>

#include "metricmap/common/memory_budget.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/image_decoders.h"

namespace metricmap {
namespace detail {
namespace {

thread_local char tiff_message[256];

extern "C" void tiffOnError(const char* module, const char* format, va_list args) {
  if (tiff_message[0] != '\0') return;  // keep the first error: it names the cause
  char text[200];
  std::vsnprintf(text, sizeof text, format, args);
  std::snprintf(tiff_message, sizeof tiff_message, "%s%s%s", module != nullptr ? module : "",
                module != nullptr ? ": " : "", text);
}

extern "C" void tiffOnWarning(const char*, const char*, va_list) {}

void installHandlers() {
  static std::once_flag once;
  std::call_once(once, [] {
    TIFFSetErrorHandler(tiffOnError);
    TIFFSetWarningHandler(tiffOnWarning);
  });
}

struct TiffCloser {
  void operator()(TIFF* t) const { TIFFClose(t); }
};

[[noreturn]] void damaged(const std::string& path, const char* what) {
  std::string m = path + ": " + what;
  if (tiff_message[0] != '\0') m += std::string(" (") + tiff_message + ")";
  throw InputError(m);
}

}  // namespace

DecodedImage decodeTiff(const std::string& path, ImageWant want) {
  installHandlers();
  tiff_message[0] = '\0';
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode))
    throw InputError(path + ": cannot open (not a regular file)");
  std::unique_ptr<TIFF, TiffCloser> tif(TIFFOpen(path.c_str(), "rm"));
  if (!tif) damaged(path, "not a readable TIFF image");

  std::uint32_t width = 0, height = 0;
  std::uint16_t bits = 0, samples = 1, format = SAMPLEFORMAT_UINT, planar = PLANARCONFIG_CONTIG;
  std::uint16_t photometric = 0;
  TIFFGetField(tif.get(), TIFFTAG_IMAGEWIDTH, &width);
  TIFFGetField(tif.get(), TIFFTAG_IMAGELENGTH, &height);
  TIFFGetFieldDefaulted(tif.get(), TIFFTAG_BITSPERSAMPLE, &bits);
  TIFFGetFieldDefaulted(tif.get(), TIFFTAG_SAMPLESPERPIXEL, &samples);
  TIFFGetFieldDefaulted(tif.get(), TIFFTAG_SAMPLEFORMAT, &format);
  TIFFGetFieldDefaulted(tif.get(), TIFFTAG_PLANARCONFIG, &planar);
  TIFFGetFieldDefaulted(tif.get(), TIFFTAG_PHOTOMETRIC, &photometric);
  if (width == 0 || height == 0 || width > (1u << 20) || height > (1u << 20))
    throw InputError(path + ": image size " + std::to_string(width) + " x " +
                     std::to_string(height) + " is empty or larger than 1048576 pixels a side");
  if (want == ImageWant::Depth16) {
    if (bits != 16 || samples != 1 || (format != SAMPLEFORMAT_UINT && format != SAMPLEFORMAT_INT)) {
      throw InputError(
          path + ": a depth image must be 16-bit integer with one channel, this one is " +
          std::to_string(bits) + "-bit with " + std::to_string(samples) + " channel(s)");
    }
  } else if (bits != 8 || samples < 3 || samples > 4 || photometric != PHOTOMETRIC_RGB) {
    throw InputError(path + ": an RGB image must be 8-bit RGB with 3 or 4 channels");
  }
  if (TIFFIsTiled(tif.get()) != 0 || planar != PLANARCONFIG_CONTIG)
    throw InputError(path + ": tiled or planar TIFF layouts are not supported (strips only)");
  // Every strip must lie inside the file: a longer declared strip means a damaged file.
  const std::uint32_t strips = TIFFNumberOfStrips(tif.get());
  for (std::uint32_t k = 0; k < strips; ++k) {
    int err = 0;
    const std::uint64_t offset = TIFFGetStrileOffsetWithErr(tif.get(), k, &err);
    const std::uint64_t bytes = TIFFGetStrileByteCountWithErr(tif.get(), k, &err);
    const auto file_size = static_cast<std::uint64_t>(st.st_size);
    if (err != 0 || offset > file_size || bytes > file_size - offset) {
      throw InputError(path + ": strip " + std::to_string(k) + " (" + std::to_string(bytes) +
                       " bytes at offset " + std::to_string(offset) +
                       ") runs past the end of the " + std::to_string(file_size) + "-byte file");
    }
  }
  const std::string dims = std::to_string(width) + " x " + std::to_string(height);
  const std::uint64_t row_bytes = static_cast<std::uint64_t>(width) * samples * (bits / 8);
  if (static_cast<std::uint64_t>(TIFFScanlineSize64(tif.get())) != row_bytes)
    damaged(path, "inconsistent scanline size");
  checkMemory(height, row_bytes * (want == ImageWant::Rgb8 ? 2 : 1),
              path + " (" + dims + " pixels)");

  DecodedImage out;
  out.width = static_cast<int>(width);
  out.height = static_cast<int>(height);
  const std::size_t n = static_cast<std::size_t>(width) * height;
  std::vector<std::uint8_t> line(row_bytes);
  if (want == ImageWant::Depth16)
    out.depth.resize(n);
  else
    out.rgb.resize(3 * n);
  for (std::uint32_t v = 0; v < height; ++v) {
    if (TIFFReadScanline(tif.get(), line.data(), v, 0) < 0) damaged(path, "damaged TIFF");
    if (want == ImageWant::Depth16) {
      std::uint16_t* row = out.depth.data() + static_cast<std::size_t>(v) * width;
      for (std::uint32_t u = 0; u < width; ++u) {
        std::uint16_t value;
        std::memcpy(&value, line.data() + 2 * u, 2);
        if (format == SAMPLEFORMAT_INT && (value & 0x8000u) != 0) {
          throw InputError(path + ": pixel (" + std::to_string(u) + ", " + std::to_string(v) +
                           ") holds " + std::to_string(static_cast<int>(value) - 65536) +
                           ", a depth must not be negative");
        }
        row[u] = value;
      }
    } else {
      std::uint8_t* row = out.rgb.data() + 3 * static_cast<std::size_t>(v) * width;
      for (std::uint32_t u = 0; u < width; ++u)
        for (std::uint32_t k = 0; k < 3; ++k) row[3 * u + k] = line[samples * u + k];
    }
  }
  if (tiff_message[0] != '\0') damaged(path, "damaged TIFF");
  return out;
}

}  // namespace detail
}  // namespace metricmap
