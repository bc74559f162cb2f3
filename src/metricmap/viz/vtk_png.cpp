#include "metricmap/viz/vtk_png.h"

#include <cstdio>
#include <stdexcept>

#include <unistd.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>

#include "metricmap/io/atomic_file.h"
#include "metricmap/io/output_set.h"

namespace metricmap::viz {

void writeVtkPng(vtkAlgorithmOutput* image, const std::string& path) {
  checkOutputPath(path);
  const std::string tmp = temporaryPathFor(path);
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(tmp.c_str());
  writer->SetInputConnection(image);
  writer->Write();
  if (writer->GetErrorCode() != 0) {
    discardTemporary(tmp);
    throw std::runtime_error(path + ": cannot write PNG");
  }
  commitTemporary(tmp, path);
}

}  // namespace metricmap::viz
