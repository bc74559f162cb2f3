// libpng's own API: errors come back through setjmp/longjmp, never through a crash.
#include <png.h>

#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>

#include "metricmap/common/memory_budget.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/image_decoders.h"
#include "metricmap/io/input_file.h"

namespace metricmap {
namespace detail {
namespace {

/// \brief Error state shared with libpng's callbacks; plain data only (longjmp skips frames).
struct PngError {
  std::jmp_buf jump;
  char message[256] = {0};
};

extern "C" void pngOnError(png_structp png, png_const_charp message) {
  auto* e = static_cast<PngError*>(png_get_error_ptr(png));
  std::snprintf(e->message, sizeof e->message, "%s", message != nullptr ? message : "error");
  std::longjmp(e->jump, 1);
}

extern "C" void pngOnWarning(png_structp, png_const_charp) {}

/// \brief Owns the read and info structs and the file.
struct PngReader {
  std::FILE* file = nullptr;
  png_structp png = nullptr;
  png_infop info = nullptr;
  PngError error;
  ~PngReader() {
    if (png != nullptr) png_destroy_read_struct(&png, info != nullptr ? &info : nullptr, nullptr);
    if (file != nullptr) std::fclose(file);
  }
};

struct PngHeader {
  png_uint_32 width = 0, height = 0;
  int bit_depth = 0, color_type = 0, channels = 0;
  std::size_t row_bytes = 0;
};

/// \brief Reads the header and sets the transforms. Only plain data lives in this frame.
bool readHeader(PngReader& r, ImageWant want, PngHeader& h) {
  if (setjmp(r.error.jump) != 0) return false;
  png_init_io(r.png, r.file);
  png_set_sig_bytes(r.png, 8);
  png_set_user_limits(r.png, 1u << 20, 1u << 20);
  png_set_chunk_malloc_max(r.png, 64u << 20);
  png_read_info(r.png, r.info);
  h.width = png_get_image_width(r.png, r.info);
  h.height = png_get_image_height(r.png, r.info);
  h.bit_depth = png_get_bit_depth(r.png, r.info);
  h.color_type = png_get_color_type(r.png, r.info);
  if (want == ImageWant::Depth16) {
    if (h.bit_depth == 16 && h.color_type == PNG_COLOR_TYPE_GRAY) png_set_swap(r.png);
  } else if (h.bit_depth <= 8) {
    if (h.color_type == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(r.png);
    if (png_get_valid(r.png, r.info, PNG_INFO_tRNS) != 0) png_set_tRNS_to_alpha(r.png);
    if (h.bit_depth < 8 && h.color_type == PNG_COLOR_TYPE_PALETTE) png_set_packing(r.png);
  }
  png_set_interlace_handling(r.png);
  png_read_update_info(r.png, r.info);
  h.channels = png_get_channels(r.png, r.info);
  h.row_bytes = png_get_rowbytes(r.png, r.info);
  h.bit_depth = png_get_bit_depth(r.png, r.info);
  h.color_type = png_get_color_type(r.png, r.info);
  return true;
}

bool readRows(PngReader& r, png_bytepp rows) {
  if (setjmp(r.error.jump) != 0) return false;
  png_read_image(r.png, rows);
  png_read_end(r.png, nullptr);
  return true;
}

}  // namespace

DecodedImage decodePng(const std::string& path, ImageWant want) {
  requireRegularFile(path);
  PngReader r;
  r.file = std::fopen(path.c_str(), "rb");
  if (r.file == nullptr) throw InputError(path + ": cannot open");
  unsigned char signature[8];
  if (std::fread(signature, 1, 8, r.file) != 8 || png_sig_cmp(signature, 0, 8) != 0)
    throw InputError(path + ": not a PNG file");
  std::fseek(r.file, 0, SEEK_END);
  const long file_size = std::ftell(r.file);
  std::fseek(r.file, 8, SEEK_SET);
  r.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &r.error, pngOnError, pngOnWarning);
  if (r.png == nullptr) throw InputError(path + ": cannot start the PNG decoder");
  r.info = png_create_info_struct(r.png);
  if (r.info == nullptr) throw InputError(path + ": cannot start the PNG decoder");

  PngHeader h;
  if (!readHeader(r, want, h)) throw InputError(path + ": damaged PNG (" + r.error.message + ")");
  const std::string dims = std::to_string(h.width) + " x " + std::to_string(h.height);
  if (want == ImageWant::Depth16 && (h.bit_depth != 16 || h.channels != 1)) {
    throw InputError(path + ": a depth image must be 16-bit with one channel, this one is " +
                     std::to_string(h.bit_depth) + "-bit with " + std::to_string(h.channels) +
                     " channel(s)");
  }
  if (want == ImageWant::Rgb8 && (h.bit_depth != 8 || h.channels < 3)) {
    throw InputError(path + ": an RGB image must be 8-bit with 3 or 4 channels");
  }
  // Deflate cannot expand more than 1032:1; a header declaring more pixels than that is damaged.
  const double raw = (static_cast<double>(h.row_bytes) + 1.0) * h.height;
  if (raw > 1032.0 * static_cast<double>(file_size) + 4096.0) {
    throw InputError(path + ": declares " + dims + " pixels, more than its " +
                     std::to_string(file_size) + " bytes can hold");
  }
  // the decoded rows, then the copy handed out
  checkMemory(static_cast<std::uint64_t>(h.height), 2 * h.row_bytes + sizeof(png_bytep),
              path + " (" + dims + " pixels)");

  std::vector<png_byte> pixels(h.row_bytes * h.height);
  std::vector<png_bytep> rows(h.height);
  for (png_uint_32 v = 0; v < h.height; ++v) rows[v] = pixels.data() + h.row_bytes * v;
  if (!readRows(r, rows.data())) throw InputError(path + ": damaged PNG (" + r.error.message + ")");

  DecodedImage out;
  out.width = static_cast<int>(h.width);
  out.height = static_cast<int>(h.height);
  const std::size_t n = static_cast<std::size_t>(h.width) * h.height;
  if (want == ImageWant::Depth16) {
    out.depth.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      std::uint16_t value;
      std::memcpy(&value, pixels.data() + 2 * i, 2);
      out.depth[i] = value;
    }
  } else {
    out.rgb.resize(3 * n);
    const std::size_t c = static_cast<std::size_t>(h.channels);
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t k = 0; k < 3; ++k) out.rgb[3 * i + k] = pixels[c * i + k];
  }
  return out;
}

}  // namespace detail
}  // namespace metricmap
