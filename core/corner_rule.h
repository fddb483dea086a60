#pragma once
// The neighbour rule of docs/PLANNERS.md, one shared implementation for every grid planner and for
// the validator. Directions are numbered 0..7; a cell's 8-neighbourhood is summarised as a byte
// (bit d set = neighbour in direction d is free) and a 256-entry table per rule turns that byte
// into the mask of allowed moves: one lookup per expansion, no per-move branches.

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

namespace agv {

enum class CornerRule {
  allow,          // any diagonal to a free cell ("traditional A*")
  no_squeeze,     // paper 002: diagonal refused only when BOTH adjacent cardinals are blocked
  no_corner_cut,  // paper 003 / MovingAI: diagonal refused when EITHER adjacent cardinal is blocked
};

std::string_view to_string(CornerRule rule);
std::optional<CornerRule> corner_rule_from_string(std::string_view name);

// Direction d: (kDx[d], kDy[d]). Cardinals 0..3 (E, S, W, N with y down), diagonals 4..7
// (SE, SW, NW, NE); diagonal 4 + k lies between cardinals k and (k + 1) % 4.
inline constexpr std::array<int, 8> kDx = {1, 0, -1, 0, 1, -1, -1, 1};
inline constexpr std::array<int, 8> kDy = {0, 1, 0, -1, 1, 1, -1, -1};
inline constexpr bool is_diagonal(int d) { return d >= 4; }

// The allowed-move mask for a free-neighbour byte under a rule.
constexpr std::uint8_t allowed_moves(std::uint8_t free_mask, CornerRule rule) {
  std::uint8_t allowed = free_mask & 0x0F;
  for (int k = 0; k < 4; ++k) {
    const int d = 4 + k;
    if (!(free_mask & (1U << d))) continue;
    const bool a = free_mask & (1U << k);
    const bool b = free_mask & (1U << ((k + 1) % 4));
    const bool ok = rule == CornerRule::allow        ? true
                    : rule == CornerRule::no_squeeze ? (a || b)
                                                     : (a && b);
    if (ok) allowed = static_cast<std::uint8_t>(allowed | (1U << d));
  }
  return allowed;
}

using MoveTable = std::array<std::uint8_t, 256>;
constexpr MoveTable make_move_table(CornerRule rule) {
  MoveTable t{};
  for (int m = 0; m < 256; ++m) t[m] = allowed_moves(static_cast<std::uint8_t>(m), rule);
  return t;
}
inline constexpr MoveTable kMovesAllow = make_move_table(CornerRule::allow);
inline constexpr MoveTable kMovesNoSqueeze = make_move_table(CornerRule::no_squeeze);
inline constexpr MoveTable kMovesNoCornerCut = make_move_table(CornerRule::no_corner_cut);
inline const MoveTable& move_table(CornerRule rule) {
  return rule == CornerRule::allow        ? kMovesAllow
         : rule == CornerRule::no_squeeze ? kMovesNoSqueeze
                                          : kMovesNoCornerCut;
}

// Is the single move from (x, y) in direction d legal under the rule? `blocked(x, y)` must be
// valid one cell outside the grid (the padded border).
template <class BlockedFn>
bool move_allowed(BlockedFn&& blocked, int x, int y, int d, CornerRule rule) {
  if (blocked(x + kDx[d], y + kDy[d])) return false;
  if (!is_diagonal(d)) return true;
  const int k = d - 4;
  const bool a = !blocked(x + kDx[k], y + kDy[k]);
  const bool b = !blocked(x + kDx[(k + 1) % 4], y + kDy[(k + 1) % 4]);
  return rule == CornerRule::allow ? true : rule == CornerRule::no_squeeze ? (a || b) : (a && b);
}

}  // namespace agv
