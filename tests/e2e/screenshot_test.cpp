// Runs `metricmap view --screenshot` (under the X server ctest gives it: xvfb-run) on a bundled
// scan with and without octree cubes and checks the pictures: the size asked, not blank, and
// the cubes change it.
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <set>
#include <string>
#include <vector>

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>

namespace {

struct Picture {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;
};

Picture read(const std::string& path) {
  vtkNew<vtkPNGReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  Picture p;
  int dims[3];
  reader->GetOutput()->GetDimensions(dims);
  p.width = dims[0];
  p.height = dims[1];
  const int comps = reader->GetOutput()->GetNumberOfScalarComponents();
  const auto* data = static_cast<const unsigned char*>(reader->GetOutput()->GetScalarPointer());
  for (int i = 0; i < dims[0] * dims[1]; ++i) {
    for (int c = 0; c < 3; ++c) p.rgb.push_back(data[i * comps + c]);
  }
  return p;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) {
    std::cerr << "usage: screenshot_test METRICMAP DATA_DIR TMP_DIR\n";
    return 2;
  }
  const std::string mm = argv[1],
                    scan = std::string(argv[2]) + "/ua_mapas_metricos_pcd/ciencias000.pcd";
  const std::string plain = std::string(argv[3]) + "/view_plain.png";
  const std::string cubes = std::string(argv[3]) + "/view_cubes.png";
  const std::string common = " --up y --window-size 640x480 --camera iso";
  if (std::system((mm + " view " + scan + common + " --screenshot " + plain).c_str()) != 0 ||
      std::system((mm + " view " + scan + common + " --octree --max-points 100 --min-cell-size 1" +
                   " --screenshot " + cubes)
                      .c_str()) != 0) {
    std::cerr << "FAIL: metricmap view exited with an error\n";
    return 1;
  }
  int failures = 0;
  const Picture a = read(plain), b = read(cubes);
  for (const Picture* p : {&a, &b}) {
    if (p->width != 640 || p->height != 480) {
      std::cerr << "FAIL: size " << p->width << "x" << p->height << ", asked 640x480\n";
      ++failures;
    }
    std::set<int> colours;
    std::size_t lit = 0;
    for (std::size_t i = 0; i + 2 < p->rgb.size(); i += 3) {
      colours.insert(p->rgb[i] << 16 | p->rgb[i + 1] << 8 | p->rgb[i + 2]);
      lit += (p->rgb[i] + p->rgb[i + 1] + p->rgb[i + 2]) > 150;
    }
    std::cout << "picture: " << colours.size() << " colours, " << lit << " bright pixels\n";
    if (colours.size() < 20 || lit < 500) {
      std::cerr << "FAIL: the picture looks blank\n";
      ++failures;
    }
  }
  // Split & Merge segments over a 2D scan.
  const std::string csv = std::string(argv[2]) + "/pythonrobotics_lidar01/lidar01.csv";
  const std::string json = std::string(argv[3]) + "/lidar01_lines.json";
  const std::string scan_only = std::string(argv[3]) + "/view_scan.png";
  const std::string with_segments = std::string(argv[3]) + "/view_segments.png";
  if (std::system((mm + " lines " + csv + " --format json > " + json).c_str()) != 0 ||
      std::system(
          (mm + " view " + csv + " --window-size 640x480 --screenshot " + scan_only).c_str()) !=
          0 ||
      std::system((mm + " view " + csv + " --segments " + json +
                   " --window-size 640x480 --screenshot " + with_segments)
                      .c_str()) != 0) {
    std::cerr << "FAIL: view --segments\n";
    ++failures;
  } else {
    const Picture s0 = read(scan_only), s1 = read(with_segments);
    std::size_t diff = 0;
    for (std::size_t i = 0; i < s0.rgb.size() && i < s1.rgb.size(); ++i)
      diff += s0.rgb[i] != s1.rgb[i];
    std::cout << "segments changed " << diff / 3 << " pixel channels/3\n";
    if (diff < s0.rgb.size() / 200) {
      std::cerr << "FAIL: the segments did not change the picture\n";
      ++failures;
    }
  }

  // The study plot, as PNG and as SVG.
  const std::string scans = std::string(argv[2]) + "/ua_mapas_metricos_pcd/";
  const std::string png = std::string(argv[3]) + "/study.png",
                    svg = std::string(argv[3]) + "/study.svg";
  for (const std::string& out : {png, svg}) {
    const std::string cmd = mm + " compare " + scans + "museo000.pcd " + scans +
                            "poli000.pcd --format csv --plot " + out + " > /dev/null";
    if (std::system(cmd.c_str()) != 0) {
      std::cerr << "FAIL: " << cmd << "\n";
      ++failures;
    }
  }
  const Picture plot = read(png);
  std::set<int> plot_colours;
  for (std::size_t i = 0; i + 2 < plot.rgb.size(); i += 3) {
    plot_colours.insert(plot.rgb[i] << 16 | plot.rgb[i + 1] << 8 | plot.rgb[i + 2]);
  }
  std::cout << "plot: " << plot.width << "x" << plot.height << ", " << plot_colours.size()
            << " colours\n";
  if (plot.width < 200 || plot_colours.size() < 10) {
    std::cerr << "FAIL: the study plot looks blank\n";
    ++failures;
  }
  // The first panel (all cells / nodes: grid 10^4-10^5, octree 10^3) is drawn on a log scale:
  // the octree's orange bars stand a good share of the panel's height (on a linear axis they
  // are a few pixels tall). Orange = the second series' colour (220, 90, 40).
  std::size_t orange = 0;
  for (int y = 0; y < plot.height / 2; ++y) {
    for (int x = 0; x < plot.width / 2; ++x) {
      const std::size_t at = 3 * (static_cast<std::size_t>(y) * plot.width + x);
      orange += plot.rgb[at] == 220 && plot.rgb[at + 1] == 90 && plot.rgb[at + 2] == 40;
    }
  }
  std::cout << "plot: " << orange << " orange pixels in the first panel\n";
  if (orange < static_cast<std::size_t>(plot.width / 2) * (plot.height / 2) / 100) {
    std::cerr << "FAIL: the octree's bars in the first panel are (nearly) invisible\n";
    ++failures;
  }
  std::FILE* f = std::fopen(svg.c_str(), "r");
  char head[512] = {0};
  if (f == nullptr || std::fread(head, 1, sizeof head - 1, f) == 0 ||
      std::string(head).find("<svg") == std::string::npos) {
    std::cerr << "FAIL: " << svg << " is not an SVG\n";
    ++failures;
  }
  if (f != nullptr) std::fclose(f);

  // An OctoMap file: occupied voxels as cubes coloured by height; --free adds translucent ones.
  const std::string bt = std::string(argv[2]) + "/octomap_geb079/geb079.bt";
  const std::string occ_png = std::string(argv[3]) + "/view_bt.png",
                    free_png = std::string(argv[3]) + "/view_bt_free.png";
  if (std::system(
          (mm + " view " + bt + " --window-size 640x480 --screenshot " + occ_png).c_str()) != 0 ||
      std::system((mm + " view " + bt + " --free --window-size 640x480 --screenshot " + free_png)
                      .c_str()) != 0) {
    std::cerr << "FAIL: view of an OctoMap file\n";
    ++failures;
  } else {
    const Picture v0 = read(occ_png), v1 = read(free_png);
    std::set<int> hues;
    for (std::size_t i = 0; i + 2 < v0.rgb.size(); i += 3)
      hues.insert(v0.rgb[i] << 16 | v0.rgb[i + 1] << 8 | v0.rgb[i + 2]);
    std::size_t diff = 0;
    for (std::size_t i = 0; i < v0.rgb.size() && i < v1.rgb.size(); ++i)
      diff += v0.rgb[i] != v1.rgb[i];
    std::cout << "octomap: " << hues.size() << " colours; free voxels changed " << diff / 3
              << " pixel channels/3\n";
    if (hues.size() < 50 || diff < v0.rgb.size() / 100) {
      std::cerr << "FAIL: the OctoMap view looks blank or --free changed nothing\n";
      ++failures;
    }
  }

  std::size_t changed = 0;
  for (std::size_t i = 0; i < a.rgb.size() && i < b.rgb.size(); ++i)
    changed += a.rgb[i] != b.rgb[i];
  std::cout << "cubes changed " << changed / 3 << " pixel channels/3\n";
  if (changed < a.rgb.size() / 100) {
    std::cerr << "FAIL: the cubes did not change the picture\n";
    ++failures;
  }
  return failures == 0 ? 0 : 1;
}
