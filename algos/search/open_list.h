#pragma once
// The open list of the grid search core (algos/search/search_core.h): a binary min-heap with
// decrease-key, plus one "held" slot outside the heap. perf/README.md "Grid search" has the
// designs measured before this one (lazy deletion, 4-ary, bottom-up pop, node layouts).
//
// Keys are 16-byte OpenKeys compared as one unsigned 128-bit integer, which gives the
// deterministic order of every grid search:
//   1. smaller priority (the policy's key(), usually f = g + h) first;
//   2. equal priority: larger g first (g compared in single precision, so g values closer than
//      ~1e-7 relative tie and fall through to 3);
//   3. then the lower padded cell index.
// A cell is in the list at most once, so keys are unique and the pop order is a function of the
// keys alone, whatever the heap's shape.
//
// Held slot: the smallest key pushed or lowered since the last pop waits outside the heap.
// Popping compares it with the heap's top: it is returned without touching the heap when it is
// the minimum, and otherwise replaces the top in a single sift-down, so an expansion costs one
// sift-down instead of a pop plus a push (perf/README.md "Grid search": designs E -> F). A
// decrease-key that beats the held key (or finds the slot empty) takes the slot and leaves the
// old held key (or the heap's last key) in its heap position: on open maps the best child of an
// expansion is usually a cell already open whose g just improved, and the next pop returns it
// directly instead of sifting from the root (design G: 12-18% less A* time on MovingAI's open
// maps, perf/README.md "A* side by side").
//
// Positions: each cell's heap slot lives in its SearchNode (kHeldSlot for the held key), written
// on every move, so update() finds a cell's key in O(1).

#include <bit>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace agv {

__extension__ typedef unsigned __int128 OpenKey;

// A search's record of one cell, indexed by the grid's padded index.
struct SearchNode {
  double g;
  std::uint32_t heap_pos;   // owned by OpenList while the cell is open
  std::uint8_t parent_dir;  // direction of the move parent -> cell (corner_rule.h numbering)
  std::uint8_t unused[3];
};
static_assert(sizeof(SearchNode) == 16);

namespace open_key {

// Order-preserving maps of IEEE values onto unsigned integers (any sign).
inline std::uint64_t order_bits(double v) {
  const auto b = std::bit_cast<std::uint64_t>(v);
  return b ^ (static_cast<std::uint64_t>(static_cast<std::int64_t>(b) >> 63) | (1ULL << 63));
}
inline std::uint32_t order_bits(float v) {
  const auto b = std::bit_cast<std::uint32_t>(v);
  return b ^ (static_cast<std::uint32_t>(static_cast<std::int32_t>(b) >> 31) | (1U << 31));
}

// priority in the high 64 bits; then ~g (larger g first); then the cell index.
inline OpenKey pack(double priority, double g, int index) {
  const std::uint64_t lo = (static_cast<std::uint64_t>(~order_bits(static_cast<float>(g))) << 32) |
                           static_cast<std::uint32_t>(index);
  return (static_cast<OpenKey>(order_bits(priority)) << 64) | lo;
}
inline int index_of(OpenKey key) { return static_cast<int>(static_cast<std::uint32_t>(key)); }

}  // namespace open_key

class OpenList {
 public:
  static constexpr std::uint32_t kHeldSlot = 0xFFFFFFFFU;

  // Empties the list; positions are written into `nodes` from now on.
  void reset(SearchNode* nodes) {
    nodes_ = nodes;
    size_ = 0;
    has_held_ = false;
  }
  bool empty() const { return size_ == 0 && !has_held_; }

  // The key pop() would return. Not empty.
  OpenKey top() const { return has_held_ && (size_ == 0 || held_ < heap_[0]) ? held_ : heap_[0]; }

  // Inserts the key of a cell that is not in the list.
  void push(OpenKey key) {
    if (!has_held_) {
      hold(key);
    } else if (key < held_) {
      heap_push(held_);
      hold(key);
    } else {
      heap_push(key);
    }
  }

  // Replaces the key of a cell that is in the list (the new key may be larger or smaller).
  void update(OpenKey key) {
    const std::uint32_t pos = nodes_[open_key::index_of(key)].heap_pos;
    if (pos == kHeldSlot) {
      held_ = key;
    } else if (!has_held_) {
      hold(key);
      remove_at(pos);
    } else if (key < held_) {
      const OpenKey displaced = held_;
      hold(key);
      reposition(pos, displaced);
    } else {
      reposition(pos, key);
    }
  }

  // Removes and returns the smallest key. Not empty.
  OpenKey pop() {
    if (has_held_) {
      has_held_ = false;
      if (size_ == 0 || held_ < heap_[0]) return held_;
      const OpenKey top = heap_[0];
      sift_down(0, held_);
      return top;
    }
    const OpenKey top = heap_[0];
    --size_;
    if (size_ > 0) sift_down(0, heap_[size_]);
    return top;
  }

 private:
  void hold(OpenKey key) {
    held_ = key;
    has_held_ = true;
    nodes_[open_key::index_of(key)].heap_pos = kHeldSlot;
  }
  void place(std::size_t pos, OpenKey key) {
    heap_[pos] = key;
    nodes_[open_key::index_of(key)].heap_pos = static_cast<std::uint32_t>(pos);
  }
  // Puts `key` at `pos`, whose current key is heap_[pos], and restores the heap order.
  void reposition(std::size_t pos, OpenKey key) {
    if (key < heap_[pos]) {
      sift_up(pos, key);
    } else {
      sift_down(pos, key);
    }
  }
  // Takes the key at `pos` out of the heap (its cell's position is the caller's to rewrite).
  void remove_at(std::size_t pos) {
    --size_;
    if (pos < size_) reposition(pos, heap_[size_]);
  }
  void heap_push(OpenKey key) {
    if (size_ == capacity_) grow();
    sift_up(size_++, key);
  }
  void sift_up(std::size_t pos, OpenKey key) {
    while (pos > 0) {
      const std::size_t parent = (pos - 1) >> 1;
      if (!(key < heap_[parent])) break;
      place(pos, heap_[parent]);
      pos = parent;
    }
    place(pos, key);
  }
  void sift_down(std::size_t pos, OpenKey key) {
    const std::size_t n = size_;
    for (;;) {
      const std::size_t child = 2 * pos + 1;
      std::size_t best;
      if (child + 1 < n) {
        best = heap_[child + 1] < heap_[child] ? child + 1 : child;
      } else if (child < n) {
        best = child;
      } else {
        break;
      }
      if (!(heap_[best] < key)) break;
      place(pos, heap_[best]);
      pos = best;
    }
    place(pos, key);
  }
  void grow();

  std::vector<OpenKey> storage_;
  OpenKey* heap_ = nullptr;  // inside storage_, siblings 2i+1, 2i+2 on one 32-byte half line
  std::size_t size_ = 0;
  std::size_t capacity_ = 0;
  SearchNode* nodes_ = nullptr;
  OpenKey held_ = 0;
  bool has_held_ = false;
};

}  // namespace agv
