#pragma once
// blocks: rectangular obstacles, the workshop production areas of paper 002 section 5.1 ("large
// in area and simple in shape").

#include <string>

#include "core/params.h"
#include "generators/canvas.h"

namespace agv {

struct BlocksOptions {
  int block_min = 2;  // side range of the rectangles, cells
  int block_max = 5;
};

const ParamDecls<BlocksOptions>& blocks_params();
// block_max below block_min: InputError naming `where`.block_max.
void check_blocks(const BlocksOptions& options, int width, int height, const std::string& where);
void generate_blocks(const BlocksOptions& options, MapContext& ctx);

}  // namespace agv
