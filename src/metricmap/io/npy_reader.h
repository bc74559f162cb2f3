#pragma once
/// \file npy_reader.h
/// \brief NumPy .npy point arrays: (N, C) with C >= 3 columns x y z [intensity ...], float32
/// or float64, little-endian, C order (what `np.save(points)` writes on x86).

#include <cstddef>
#include <string>
#include <vector>

namespace metricmap {

/// \brief A point array read from a .npy file, widened to double, row-major.
struct NpyArray {
  std::size_t rows = 0, cols = 0;
  std::vector<double> values;  ///< rows * cols
};

/// \brief Read a 2-D float32/float64 .npy array with at least 3 columns.
/// \throws InputError naming the file for a bad magic, version, header, dtype (big-endian,
/// integer, object), Fortran order, a shape that is not (N, C>=3) or data shorter or longer than
/// the shape says, or a finite float64 x, y, z or intensity beyond the float range
NpyArray readNpyPoints(const std::string& path);

}  // namespace metricmap
