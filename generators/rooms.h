#pragma once
// rooms: square rooms behind one-cell walls with a door in every wall segment.

#include "core/params.h"
#include "generators/canvas.h"

namespace agv {

struct RoomsOptions {
  int room_size = 8;   // room side, cells
  int door_width = 2;  // opening width, cells
};

const ParamDecls<RoomsOptions>& rooms_params();
void generate_rooms(const RoomsOptions& options, MapContext& ctx);

}  // namespace agv
