// The grid search's open list (algos/search/open_list.h) against an ordered set: random pushes,
// key changes up and down (turn-dependent keys raise them too) and pops, with priorities from a
// small range so that ties on priority and on g are common. Every pop and top() must be the
// set's minimum, whichever of the held slot's paths the sequence takes.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <set>
#include <vector>

#include "algos/search/open_list.h"

namespace agv {
namespace {

constexpr int kCells = 600;

struct Reference {
  std::set<OpenKey> keys;
  std::vector<OpenKey> key_of = std::vector<OpenKey>(kCells, 0);
  std::vector<bool> open = std::vector<bool>(kCells, false);
};

OpenKey random_key(std::mt19937_64& rng, int cell) {
  std::uniform_int_distribution<int> priority(0, 40);
  std::uniform_int_distribution<int> g(0, 6);
  return open_key::pack(0.5 * priority(rng), 0.25 * g(rng), cell);
}

// One random operation on both lists (a push of a cell already open, a change of one not open or
// a pop of an empty list is skipped).
void step(std::mt19937_64& rng, OpenList& list, Reference& ref) {
  std::uniform_int_distribution<int> op(0, 9);
  std::uniform_int_distribution<int> cell(0, kCells - 1);
  const int what = op(rng);
  if (what < 4) {  // push a cell that is not open
    const int c = cell(rng);
    if (ref.open[c]) return;
    const OpenKey key = random_key(rng, c);
    list.push(key);
    ref.keys.insert(key);
    ref.key_of[c] = key;
    ref.open[c] = true;
  } else if (what < 7) {  // change an open cell's key (up or down)
    const int c = cell(rng);
    if (!ref.open[c]) return;
    const OpenKey key = random_key(rng, c);
    if (ref.keys.count(key) != 0) return;  // unchanged key: the search never updates to equal
    list.update(key);
    ref.keys.erase(ref.key_of[c]);
    ref.keys.insert(key);
    ref.key_of[c] = key;
  } else {  // pop
    ASSERT_EQ(list.empty(), ref.keys.empty());
    if (ref.keys.empty()) return;
    ASSERT_EQ(list.top(), *ref.keys.begin());
    const OpenKey got = list.pop();
    ASSERT_EQ(got, *ref.keys.begin());
    ref.keys.erase(ref.keys.begin());
    ref.open[open_key::index_of(got)] = false;
  }
}

TEST(OpenListOrder, MatchesAnOrderedSetUnderRandomPushesUpdatesAndPops) {
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    std::mt19937_64 rng(seed);
    std::vector<SearchNode> nodes(kCells);
    OpenList list;
    list.reset(nodes.data());
    Reference ref;
    for (int i = 0; i < 20000; ++i) {
      step(rng, list, ref);
      if (HasFatalFailure()) FAIL() << "seed " << seed << ", operation " << i;
    }
    while (!ref.keys.empty()) {  // drain: the remaining order must match too
      ASSERT_EQ(list.pop(), *ref.keys.begin()) << "seed " << seed;
      ref.keys.erase(ref.keys.begin());
    }
    EXPECT_TRUE(list.empty());
  }
}

}  // namespace
}  // namespace agv
