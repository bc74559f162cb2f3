#include "metricmap/viz/view_scene.h"

#include <algorithm>

#include "metricmap/viz/vtk_png.h"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <stdexcept>

#include <unistd.h>
#include <vtkActor.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCubeSource.h>
#include <vtkDoubleArray.h>
#include <vtkGlyph3DMapper.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkLookupTable.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowToImageFilter.h>

namespace metricmap::viz {
namespace {

vtkSmartPointer<vtkLookupTable> rainbow(double lo, double hi) {
  auto lut = vtkSmartPointer<vtkLookupTable>::New();
  lut->SetHueRange(0.667, 0.0);  // blue -> red
  lut->SetTableRange(lo, hi > lo ? hi : lo + 1.0);
  lut->Build();
  return lut;
}

vtkSmartPointer<vtkActor> pointActor(const pcl::PointCloud<pcl::PointXYZRGB>& cloud,
                                     const std::vector<double>& counts, const SceneOptions& o) {
  vtkNew<vtkPoints> pts;
  vtkNew<vtkCellArray> verts;
  vtkNew<vtkUnsignedCharArray> colours;
  colours->SetNumberOfComponents(3);
  double lo = 1e300, hi = -1e300;
  std::vector<double> value(cloud.size(), 0.0);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    value[i] = o.color_by == "count" && !counts.empty() ? counts[i] : (&cloud[i].x)[o.up_axis];
    lo = std::min(lo, value[i]);
    hi = std::max(hi, value[i]);
  }
  auto lut = rainbow(lo, hi);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const auto& p = cloud[i];
    const vtkIdType id = pts->InsertNextPoint(p.x, p.y, p.z);
    verts->InsertNextCell(1, &id);
    unsigned char c[3] = {p.r, p.g, p.b};
    if (o.color_by != "rgb") {
      double rgb[3];
      lut->GetColor(value[i], rgb);
      for (int k = 0; k < 3; ++k) c[k] = static_cast<unsigned char>(255 * rgb[k]);
    }
    colours->InsertNextTypedTuple(c);
  }
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(pts);
  poly->SetVerts(verts);
  poly->GetPointData()->SetScalars(colours);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(poly);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetPointSize(2);
  return actor;
}

/// All boxes in one vtkPolyData of lines (8 points, 12 edges each), scalars = point count.
vtkSmartPointer<vtkActor> boxActor(const std::vector<CountedBox>& boxes, vtkLookupTable* lut) {
  vtkNew<vtkPoints> pts;
  vtkNew<vtkCellArray> lines;
  vtkNew<vtkDoubleArray> counts;
  pts->Allocate(static_cast<vtkIdType>(boxes.size() * 8));
  static const int kEdges[12][2] = {{0, 1}, {1, 3}, {3, 2}, {2, 0}, {4, 5}, {5, 7},
                                    {7, 6}, {6, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
  for (const CountedBox& b : boxes) {
    vtkIdType base = pts->GetNumberOfPoints();
    for (int c = 0; c < 8; ++c) {
      pts->InsertNextPoint((c & 1) ? b.max.x() : b.min.x(), (c & 2) ? b.max.y() : b.min.y(),
                           (c & 4) ? b.max.z() : b.min.z());
      counts->InsertNextValue(b.count);
    }
    for (const auto& e : kEdges) {
      const vtkIdType ids[2] = {base + e[0], base + e[1]};
      lines->InsertNextCell(2, ids);
    }
  }
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(pts);
  poly->SetLines(lines);
  poly->GetPointData()->SetScalars(counts);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(poly);
  mapper->SetLookupTable(lut);
  mapper->SetScalarRange(lut->GetTableRange());
  mapper->SetScalarModeToUsePointData();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  return actor;
}

/// Segments as thick lines at z = 0, one colour each (golden-angle hues), endpoints as points.
vtkSmartPointer<vtkActor> segmentActor(const std::vector<DrawnSegment>& segments) {
  vtkNew<vtkPoints> pts;
  vtkNew<vtkCellArray> lines;
  vtkNew<vtkUnsignedCharArray> colours;
  colours->SetNumberOfComponents(3);
  for (std::size_t k = 0; k < segments.size(); ++k) {
    const vtkIdType a = pts->InsertNextPoint(segments[k].start.x(), segments[k].start.y(), 0.0);
    const vtkIdType b = pts->InsertNextPoint(segments[k].end.x(), segments[k].end.y(), 0.0);
    const vtkIdType ids[2] = {a, b};
    lines->InsertNextCell(2, ids);
    const double h = std::fmod(static_cast<double>(k) * 0.38197, 1.0);
    double rgb[3];
    vtkNew<vtkLookupTable> hue;
    hue->SetHueRange(h, h);
    hue->Build();
    hue->GetColor(0.0, rgb);
    unsigned char c[3] = {static_cast<unsigned char>(255 * rgb[0]),
                          static_cast<unsigned char>(255 * rgb[1]),
                          static_cast<unsigned char>(255 * rgb[2])};
    colours->InsertNextTypedTuple(c);
  }
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(pts);
  poly->SetLines(lines);
  poly->GetCellData()->SetScalars(colours);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(poly);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetLineWidth(4);
  actor->GetProperty()->SetPointSize(8);
  actor->GetProperty()->SetRenderPointsAsSpheres(true);
  actor->GetProperty()->SetVertexVisibility(true);
  return actor;
}

/// Voxels as cube glyphs (one polydata of centres, one cube source): coloured by height through
/// `lut`, or in `grey` when lut is null; `opacity` < 1 for translucent layers.
vtkSmartPointer<vtkActor> voxelActor(const VoxelLayer& layer, int up_axis, vtkLookupTable* lut,
                                     double opacity) {
  vtkNew<vtkPoints> pts;
  vtkNew<vtkDoubleArray> height;
  pts->Allocate(static_cast<vtkIdType>(layer.centers.size()));
  for (const Eigen::Vector3d& c : layer.centers) {
    pts->InsertNextPoint(c.x(), c.y(), c.z());
    height->InsertNextValue(c[up_axis]);
  }
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(pts);
  poly->GetPointData()->SetScalars(height);
  vtkNew<vtkCubeSource> cube;
  cube->SetXLength(layer.size);
  cube->SetYLength(layer.size);
  cube->SetZLength(layer.size);
  vtkNew<vtkGlyph3DMapper> mapper;
  mapper->SetInputData(poly);
  mapper->SetSourceConnection(cube->GetOutputPort());
  mapper->ScalingOff();
  mapper->OrientOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  if (lut != nullptr) {
    mapper->SetLookupTable(lut);
    mapper->SetScalarRange(lut->GetTableRange());
    mapper->SetScalarModeToUsePointData();
  } else {
    mapper->ScalarVisibilityOff();
    actor->GetProperty()->SetColor(0.75, 0.75, 0.75);
  }
  actor->SetMapper(mapper);
  actor->GetProperty()->SetOpacity(opacity);
  return actor;
}

void placeCamera(vtkRenderer* r, const SceneOptions& o) {
  vtkCamera* cam = r->GetActiveCamera();
  Eigen::Vector3d up = Eigen::Vector3d::Zero();
  up[o.up_axis] = 1.0;
  const int side_axis = (o.up_axis + 1) % 3, other = (o.up_axis + 2) % 3;
  Eigen::Vector3d eye = Eigen::Vector3d::Zero();
  if (o.camera == "top") {
    eye[o.up_axis] = 1.0;
    Eigen::Vector3d view_up = Eigen::Vector3d::Zero();
    view_up[side_axis] = 1.0;
    cam->SetViewUp(view_up.data());
  } else if (o.camera == "side") {
    eye[other] = -1.0;
    cam->SetViewUp(up.data());
  } else {
    eye[o.up_axis] = 0.8;
    eye[side_axis] = -1.0;
    eye[other] = -1.0;
    cam->SetViewUp(up.data());
  }
  cam->SetFocalPoint(0, 0, 0);
  cam->SetPosition(eye.data());
  r->ResetCamera();
}

}  // namespace

Scene buildScene(const pcl::PointCloud<pcl::PointXYZRGB>& cloud, const std::vector<double>& counts,
                 const std::vector<CountedBox>& boxes, const SceneOptions& o,
                 const std::vector<DrawnSegment>& segments, const VoxelLayer& occupied,
                 const VoxelLayer& free) {
  Scene s;
  s.renderer = vtkSmartPointer<vtkRenderer>::New();
  s.renderer->SetBackground(0.08, 0.08, 0.1);
  s.points = pointActor(cloud, counts, o);
  s.renderer->AddActor(s.points);
  if (!boxes.empty()) {
    double hi = 1.0;
    for (const CountedBox& b : boxes) hi = std::max(hi, b.count);
    auto lut = rainbow(0.0, hi);
    s.boxes = boxActor(boxes, lut);
    s.renderer->AddActor(s.boxes);
    vtkNew<vtkScalarBarActor> bar;
    bar->SetLookupTable(lut);
    bar->SetTitle("points");
    bar->SetNumberOfLabels(4);
    bar->SetMaximumWidthInPixels(70);
    s.renderer->AddActor2D(bar);
  }
  if (!segments.empty()) s.renderer->AddActor(segmentActor(segments));
  if (!occupied.centers.empty()) {
    // Colours over the 2nd..98th height percentile: a few stray voxels far below the ground
    // would otherwise paint the whole map one colour.
    std::vector<double> h;
    h.reserve(occupied.centers.size());
    for (const Eigen::Vector3d& c : occupied.centers) h.push_back(c[o.up_axis]);
    const std::size_t k_lo = h.size() / 50, k_hi = h.size() - 1 - h.size() / 50;
    std::nth_element(h.begin(), h.begin() + static_cast<std::ptrdiff_t>(k_lo), h.end());
    const double lo = h[k_lo];
    std::nth_element(h.begin(), h.begin() + static_cast<std::ptrdiff_t>(k_hi), h.end());
    auto lut = rainbow(lo, h[k_hi]);
    s.boxes = voxelActor(occupied, o.up_axis, lut, 1.0);
    s.renderer->AddActor(s.boxes);
    vtkNew<vtkScalarBarActor> bar;
    bar->SetLookupTable(lut);
    bar->SetTitle("height");
    bar->SetNumberOfLabels(4);
    bar->SetMaximumWidthInPixels(70);
    s.renderer->AddActor2D(bar);
  }
  if (!free.centers.empty()) s.renderer->AddActor(voxelActor(free, o.up_axis, nullptr, 0.12));
  vtkNew<vtkTextActor> title;
  title->SetInput(o.title.c_str());
  title->GetTextProperty()->SetFontSize(16);
  title->GetTextProperty()->SetColor(1, 1, 1);
  title->SetDisplayPosition(10, 10);
  s.renderer->AddActor2D(title);
  placeCamera(s.renderer, o);
  return s;
}

void writeScreenshot(const Scene& scene, int width, int height, const std::string& path) {
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->AddRenderer(scene.renderer);
  window->SetSize(width, height);
  window->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->Update();
  writeVtkPng(grab->GetOutputPort(), path);
}

void runInteractive(const Scene& scene, int width, int height) {
  vtkNew<vtkRenderWindow> window;
  window->AddRenderer(scene.renderer);
  window->SetSize(width, height);
  window->SetWindowName("metricmap view");
  vtkNew<vtkRenderWindowInteractor> interactor;
  interactor->SetRenderWindow(window);
  vtkNew<vtkInteractorStyleTrackballCamera> style;
  interactor->SetInteractorStyle(style);
  vtkNew<vtkCallbackCommand> keys;
  keys->SetClientData(const_cast<Scene*>(&scene));
  keys->SetCallback([](vtkObject* caller, unsigned long, void* data, void*) {
    auto* s = static_cast<Scene*>(data);
    auto* i = static_cast<vtkRenderWindowInteractor*>(caller);
    const std::string key = i->GetKeySym() ? i->GetKeySym() : "";
    if (key == "h") {
      std::cout << "mouse: left rotate, middle/shift-left pan, wheel/right zoom\n"
                   "keys: p points on/off, c cubes on/off, r reset view, q quit\n";
    } else if (key == "p") {
      s->points->SetVisibility(!s->points->GetVisibility());
    } else if (key == "c" && s->boxes) {
      s->boxes->SetVisibility(!s->boxes->GetVisibility());
    }
    i->Render();
  });
  interactor->AddObserver(vtkCommand::KeyPressEvent, keys);
  window->Render();
  std::cout << "press h for help\n";
  interactor->Start();
}

}  // namespace metricmap::viz
