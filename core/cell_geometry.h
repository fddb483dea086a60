#pragma once
// Exact distances between points, segments and cell squares: the one implementation behind the
// distance transform's segment clearance, the DWA world, the fusion driver and the engine's
// trajectory judge. A cell square is closed: cell c covers [c.x, c.x + 1] x [c.y, c.y + 1].

#include "core/grid.h"

namespace agv {

double point_distance(Point a, Point b);
// Distance from p to the closest point of segment a-b (a point when a == b).
double point_segment_distance(Point p, Point a, Point b);
// Distance from p to cell c's square (0 inside it).
double point_cell_distance(Point p, Cell c);
// Distance between segment a-b and cell c's square (0 when they meet).
double segment_cell_distance(Point a, Point b, Cell c);

}  // namespace agv
