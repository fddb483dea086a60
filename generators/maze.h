#pragma once
// maze: a perfect maze of corridor-wide corridors and walls, braided or cluttered to the density.

#include <string>

#include "core/params.h"
#include "generators/canvas.h"

namespace agv {

struct MazeOptions {
  int corridor = 1;  // corridor and wall width, cells
};

const ParamDecls<MazeOptions>& maze_params();
// A corridor wider than the grid's shorter side: InputError naming `where`.corridor.
void check_maze(const MazeOptions& options, int width, int height, const std::string& where);
void generate_maze(const MazeOptions& options, MapContext& ctx);

}  // namespace agv
