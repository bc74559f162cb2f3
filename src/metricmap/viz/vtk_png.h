#pragma once
/// \file vtk_png.h
/// \brief Write the image a VTK pipeline produces as PNG, through a temporary file and a rename.

#include <string>

class vtkAlgorithmOutput;

namespace metricmap::viz {

/// \throws std::runtime_error naming the file when writing or renaming fails
void writeVtkPng(vtkAlgorithmOutput* image, const std::string& path);

}  // namespace metricmap::viz
