// A run claims its prefix before it touches a file of it, and settles its own checks under the claim.
#include "granular/io/output_claim.hpp"

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "granular/error.hpp"
#include "scratch.hpp"

namespace granular {
namespace {

std::string scratch(const std::string& name) { return testing::scratch_path("output_claim_test", name); }

TEST(OutputClaim, HoldsThePrefixAndRunsItsCheckUnderTheLock) {
  const std::string prefix = scratch("run");
  bool checked = false;
  {
    const OutputClaim claim(prefix, "tool --output run", [&] {
      checked = true;
      EXPECT_TRUE(std::filesystem::exists(prefix + ".lock"));  // the check runs while the prefix is held
    });
    EXPECT_TRUE(checked);
    EXPECT_THROW(OutputClaim(prefix, "a second run"), InvalidInput);
  }
  EXPECT_FALSE(std::filesystem::exists(prefix + ".lock"));
  EXPECT_THROW(OutputClaim(prefix, "", [] { throw InvalidInput("output", ": refused by the caller"); }), InvalidInput);
  EXPECT_FALSE(std::filesystem::exists(prefix + ".lock"));  // a refused claim holds nothing
  EXPECT_NO_THROW(OutputClaim(prefix, ""));
}

TEST(OutputClaim, AnUnwritableFolderIsAnIoError) {
  EXPECT_THROW(OutputClaim(scratch("no-such-folder/run"), ""), IoError);
}

}  // namespace
}  // namespace granular
