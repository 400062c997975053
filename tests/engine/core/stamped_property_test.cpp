// StampedSet and StampedMap (stamped_property.hpp), the hashed tables every stage keeps its
// per-cut state in, against std::unordered_map under the same random operations: inserts,
// erases (which shift entries back), clears (a generation each), growth past the reserve, and ids
// spread like a mesh's (consecutive runs and far ids).
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <unordered_map>
#include <unordered_set>

#include "tetcut/detail/stamped_property.hpp"
#include "tetcut/ids.hpp"

namespace tetcut {
namespace {

TEST(StampedProperty, SetAgreesWithAStandardSetUnderRandomOperations) {
  std::mt19937_64 random(3);
  StampedSet<TetId> set;
  set.reserve(64);
  std::unordered_set<std::uint32_t> expected;
  for (int round = 0; round < 200; ++round) {
    // Some rounds stay small, some grow far past the reserve; ids near a base or anywhere.
    const std::uint32_t base = static_cast<std::uint32_t>(random() % 1000000);
    const int operations = round % 7 == 0 ? 40000 : 500;
    for (int i = 0; i < operations; ++i) {
      const std::uint32_t id = random() % 4 == 0 ? static_cast<std::uint32_t>(random() % 0xFFFFFFF0u)
                                                 : base + static_cast<std::uint32_t>(random() % 3000);
      switch (random() % 3) {
        case 0:
        case 1: ASSERT_EQ(set.insert(TetId{id}), expected.insert(id).second); break;
        default:
          set.erase(TetId{id});
          expected.erase(id);
      }
      const std::uint32_t probe = base + static_cast<std::uint32_t>(random() % 3000);
      ASSERT_EQ(set.contains(TetId{probe}), expected.count(probe) == 1) << "round " << round << " id " << probe;
    }
    for (std::uint32_t id : expected) ASSERT_TRUE(set.contains(TetId{id}));
    set.clear();
    for (std::uint32_t id : expected) ASSERT_FALSE(set.contains(TetId{id}));
    expected.clear();
  }
}

TEST(StampedProperty, MapAgreesWithAStandardMapUnderRandomOperations) {
  std::mt19937_64 random(5);
  StampedMap<VertId, std::uint32_t> map;
  std::unordered_map<std::uint32_t, std::uint32_t> expected;
  for (int round = 0; round < 100; ++round) {
    for (int i = 0; i < 5000; ++i) {
      const std::uint32_t id = static_cast<std::uint32_t>(random() % 6000);
      switch (random() % 4) {
        case 0:
        case 1: {
          const auto value = static_cast<std::uint32_t>(random());
          map.set(VertId{id}, value);
          expected[id] = value;
          break;
        }
        case 2:
          map.erase(VertId{id});
          expected.erase(id);
          break;
        default: {
          const auto it = expected.find(id);
          const std::uint32_t* found = map.find(VertId{id});
          ASSERT_EQ(found != nullptr, it != expected.end());
          if (found) {
            ASSERT_EQ(*found, it->second);
          }
          ASSERT_EQ(map.get(VertId{id}, 7u), it == expected.end() ? 7u : it->second);
        }
      }
    }
    if (round % 3 == 0) {
      map.clear();
      expected.clear();
    }
  }
}

// A clear() is a new generation: entries of the last one never show through, however many
// generations pass, and a slot reused in a new generation starts from a fresh value.
TEST(StampedProperty, ClearedEntriesStayClearedAcrossGenerations) {
  StampedMap<TetId, std::uint32_t> map;
  for (std::uint32_t generation = 0; generation < 100000; ++generation) {
    map.set(TetId{generation % 50}, generation);
    ASSERT_EQ(*map.find(TetId{generation % 50}), generation);
    ASSERT_FALSE(map.contains(TetId{(generation + 1) % 50}));
    map.clear();
  }
}

}  // namespace
}  // namespace tetcut
