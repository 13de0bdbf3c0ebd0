// The fixed text hash (io/text_hash.hpp) is FNV-1a 64 exactly (its published test values), so a
// checkpoint's checksums and a replay file's name do not change with the platform or compiler.
#include "granular/io/text_hash.hpp"

#include <gtest/gtest.h>

namespace granular {
namespace {

TEST(TextHash, IsFnv1a64) {
  static_assert(text_hash("") == 0xcbf29ce484222325ull, "the FNV-1a 64 offset basis");
  EXPECT_EQ(text_hash("a"), 0xaf63dc4c8601ec8cull);
  EXPECT_EQ(text_hash("foobar"), 0x85944171f73967e8ull);
  EXPECT_NE(text_hash("ab"), text_hash("ba"));
  // The checkpoint format's basis (ensemble/checkpoint_log.cpp), its value for a record's text
  // computed apart (Python, the same recurrence): a changed basis would orphan every checkpoint.
  EXPECT_EQ(text_hash("0 1 0.5", 1469598103934665603ull), 0x38903571ef2f14full);
}

}  // namespace
}  // namespace granular
