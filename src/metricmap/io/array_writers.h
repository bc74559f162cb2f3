#pragma once
/// \file array_writers.h
/// \brief Images (PNG through VTK) and NumPy .npy files, written atomically.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace metricmap {

/// \brief Write an 8-bit image with 1 (grey) or 3 (RGB) channels, row 0 at the top, as PNG.
/// \throws std::runtime_error naming the file
void writePng(const std::string& path, int width, int height, int channels,
              const std::vector<std::uint8_t>& pixels);

/// \brief Write an 8-bit grey image as binary PGM (P5) through VTK's PNM writer.
/// \throws std::runtime_error naming the file
void writePgm(const std::string& path, int width, int height,
              const std::vector<std::uint8_t>& grey);

/// \brief Write a C-order little-endian uint32 array as .npy (format 1.0). No Debian package
/// writes .npy from C++ (Boost.NumPy needs a Python runtime); the format is a short header.
/// \throws std::runtime_error naming the file
void writeNpyUint32(const std::string& path, const std::vector<std::size_t>& shape,
                    const std::vector<std::uint32_t>& data);

/// \brief Write a C-order little-endian float32 array as .npy (format 1.0).
/// \throws std::runtime_error naming the file
void writeNpyFloat32(const std::string& path, const std::vector<std::size_t>& shape,
                     const std::vector<float>& data);

}  // namespace metricmap
