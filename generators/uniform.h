#pragma once
// uniform: exactly T obstacle cells, a uniform random T-subset of the M candidate cells.

#include "core/params.h"
#include "generators/canvas.h"

namespace agv {

struct UniformOptions {};

const ParamDecls<UniformOptions>& uniform_params();
void generate_uniform(const UniformOptions& options, MapContext& ctx);

}  // namespace agv
