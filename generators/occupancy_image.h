#pragma once
// Occupancy images as ROS map_server reads them: a `.yaml` map description (image, resolution,
// origin, negate, occupied_thresh, free_thresh, mode) naming a `.pgm` or `.png` image, or such an
// image on its own (map_server's default thresholds, negate 0, trinary). Image row 0 is grid row
// 0, as in a MovingAI `.map`. Malformed input throws InputError naming the file and, where the
// format has lines, the line ("FILE:LINE: what is wrong").

#include <string>
#include <vector>

#include "core/grid.h"
#include "core/input_error.h"

namespace agv {

struct OccupancyImage {
  Grid grid;  // obstacles: occupied and unknown cells (a planner may not enter either)
  bool has_resolution = false;  // a .yaml gave the cell edge (grid.cell_edge())
  std::string image_path;       // the image read (the .yaml's `image`, or the file itself)
};

// Thresholds of map_server's trinary interpretation (ROS map_server defaults).
struct OccupancyThresholds {
  double occupied = 0.65;
  double free = 0.196;
  bool negate = false;
  bool scale = false;  // mode "scale": a pixel with alpha below 255 is unknown
};

// Dispatches on the extension: .yaml/.yml, .pgm, .png. `cell_edge` is the edge of an image read
// without a .yaml (a .yaml's resolution replaces it).
OccupancyImage read_occupancy_image(const std::string& path, double cell_edge);

// Samples of an image: 8-bit grey values (the average of the colour channels) and alpha.
struct ImagePixels {
  int width = 0;
  int height = 0;
  std::vector<unsigned char> grey;   // row-major
  std::vector<unsigned char> alpha;  // empty when the image has none
};
ImagePixels read_pgm(const std::string& path);
ImagePixels read_png(const std::string& path);

// map_server's trinary rule per pixel: occupancy p = (255 - grey) / 255 (grey / 255 when
// negated); p > occupied: occupied, p < free: free, otherwise unknown. Unknown cells are
// obstacles here (a grid planner knows no third state).
Grid occupancy_grid(const ImagePixels& pixels, const OccupancyThresholds& t, double cell_edge);

}  // namespace agv
