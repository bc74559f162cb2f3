// libtiff with its own error handler: every codec error becomes an InputError naming the file.
#include <tiffio.h>

#include <sys/stat.h>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

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

/// The layout fields of the image, with libtiff's defaults.
struct TiffLayout {
  std::uint32_t width = 0, height = 0;
  std::uint16_t bits = 0, samples = 1, format = SAMPLEFORMAT_UINT, planar = PLANARCONFIG_CONTIG;
  std::uint16_t photometric = 0;
};

/// The layout, checked against what `want` needs (sizes, depth, channels, strips only).
TiffLayout checkedLayout(TIFF* tif, const std::string& path, ImageWant want) {
  TiffLayout t;
  TIFFGetField(tif, TIFFTAG_IMAGEWIDTH, &t.width);
  TIFFGetField(tif, TIFFTAG_IMAGELENGTH, &t.height);
  TIFFGetFieldDefaulted(tif, TIFFTAG_BITSPERSAMPLE, &t.bits);
  TIFFGetFieldDefaulted(tif, TIFFTAG_SAMPLESPERPIXEL, &t.samples);
  TIFFGetFieldDefaulted(tif, TIFFTAG_SAMPLEFORMAT, &t.format);
  TIFFGetFieldDefaulted(tif, TIFFTAG_PLANARCONFIG, &t.planar);
  TIFFGetFieldDefaulted(tif, TIFFTAG_PHOTOMETRIC, &t.photometric);
  if (t.width == 0 || t.height == 0 || t.width > (1u << 20) || t.height > (1u << 20))
    throw InputError(path + ": image size " + std::to_string(t.width) + " x " +
                     std::to_string(t.height) + " is empty or larger than 1048576 pixels a side");
  if (want == ImageWant::Depth16) {
    if (t.bits != 16 || t.samples != 1 ||
        (t.format != SAMPLEFORMAT_UINT && t.format != SAMPLEFORMAT_INT)) {
      throw InputError(
          path + ": a depth image must be 16-bit integer with one channel, this one is " +
          std::to_string(t.bits) + "-bit with " + std::to_string(t.samples) + " channel(s)");
    }
  } else if (t.bits != 8 || t.samples < 3 || t.samples > 4 || t.photometric != PHOTOMETRIC_RGB) {
    throw InputError(path + ": an RGB image must be 8-bit RGB with 3 or 4 channels");
  }
  if (TIFFIsTiled(tif) != 0 || t.planar != PLANARCONFIG_CONTIG)
    throw InputError(path + ": tiled or planar TIFF layouts are not supported (strips only)");
  return t;
}

/// Every strip must lie inside the file: a longer declared strip means a damaged file.
void checkStrips(TIFF* tif, const std::string& path, std::uint64_t file_size) {
  const std::uint32_t strips = TIFFNumberOfStrips(tif);
  for (std::uint32_t k = 0; k < strips; ++k) {
    int err = 0;
    const std::uint64_t offset = TIFFGetStrileOffsetWithErr(tif, k, &err);
    const std::uint64_t bytes = TIFFGetStrileByteCountWithErr(tif, k, &err);
    if (err != 0 || offset > file_size || bytes > file_size - offset) {
      throw InputError(path + ": strip " + std::to_string(k) + " (" + std::to_string(bytes) +
                       " bytes at offset " + std::to_string(offset) +
                       ") runs past the end of the " + std::to_string(file_size) + "-byte file");
    }
  }
}

/// One scanline into row v of the output.
void copyRow(const std::vector<std::uint8_t>& line, const TiffLayout& t, std::uint32_t v,
             ImageWant want, const std::string& path, DecodedImage& out) {
  if (want == ImageWant::Depth16) {
    std::uint16_t* row = out.depth.data() + static_cast<std::size_t>(v) * t.width;
    for (std::uint32_t u = 0; u < t.width; ++u) {
      std::uint16_t value;
      std::memcpy(&value, line.data() + 2 * u, 2);
      if (t.format == SAMPLEFORMAT_INT && (value & 0x8000u) != 0) {
        throw InputError(path + ": pixel (" + std::to_string(u) + ", " + std::to_string(v) +
                         ") holds " + std::to_string(static_cast<int>(value) - 65536) +
                         ", a depth must not be negative");
      }
      row[u] = value;
    }
  } else {
    std::uint8_t* row = out.rgb.data() + 3 * static_cast<std::size_t>(v) * t.width;
    for (std::uint32_t u = 0; u < t.width; ++u)
      for (std::uint32_t k = 0; k < 3; ++k) row[3 * u + k] = line[t.samples * u + k];
  }
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
  const TiffLayout t = checkedLayout(tif.get(), path, want);
  checkStrips(tif.get(), path, static_cast<std::uint64_t>(st.st_size));
  const std::string dims = std::to_string(t.width) + " x " + std::to_string(t.height);
  const std::uint64_t row_bytes = static_cast<std::uint64_t>(t.width) * t.samples * (t.bits / 8);
  if (static_cast<std::uint64_t>(TIFFScanlineSize64(tif.get())) != row_bytes)
    damaged(path, "inconsistent scanline size");
  checkMemory(t.height, row_bytes * (want == ImageWant::Rgb8 ? 2 : 1),
              path + " (" + dims + " pixels)");

  DecodedImage out;
  out.width = static_cast<int>(t.width);
  out.height = static_cast<int>(t.height);
  const std::size_t n = static_cast<std::size_t>(t.width) * t.height;
  std::vector<std::uint8_t> line(row_bytes);
  if (want == ImageWant::Depth16)
    out.depth.resize(n);
  else
    out.rgb.resize(3 * n);
  for (std::uint32_t v = 0; v < t.height; ++v) {
    if (TIFFReadScanline(tif.get(), line.data(), v, 0) < 0) damaged(path, "damaged TIFF");
    copyRow(line, t, v, want, path, out);
  }
  if (tiff_message[0] != '\0') damaged(path, "damaged TIFF");
  return out;
}

}  // namespace detail
}  // namespace metricmap
