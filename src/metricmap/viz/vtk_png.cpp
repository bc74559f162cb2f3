#include "metricmap/viz/vtk_png.h"

#include <cstdio>
#include <stdexcept>

#include <unistd.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>

namespace metricmap::viz {

void writeVtkPng(vtkAlgorithmOutput* image, const std::string& path) {
  const std::string tmp = path + ".tmp-" + std::to_string(::getpid());
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(tmp.c_str());
  writer->SetInputConnection(image);
  writer->Write();
  if (writer->GetErrorCode() != 0 || std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw std::runtime_error(path + ": cannot write PNG");
  }
}

}  // namespace metricmap::viz
