// The library's exceptions (granular/error.hpp): one base, granular::Error, under every one of them,
// each still its standard exception, and what() the same message through either.
#include <stdexcept>
#include <string>
#include <type_traits>

#include <gtest/gtest.h>

#include "granular/error.hpp"
#include "granular/study/transport_study.hpp"

namespace granular {
namespace {

static_assert(std::is_base_of_v<Error, InvalidInput> && std::is_base_of_v<std::invalid_argument, InvalidInput>);
static_assert(std::is_base_of_v<Error, IoError> && std::is_base_of_v<std::runtime_error, IoError>);
static_assert(std::is_base_of_v<Error, NumericalError> && std::is_base_of_v<std::runtime_error, NumericalError>);
static_assert(std::is_base_of_v<Error, Cancelled> && std::is_base_of_v<std::runtime_error, Cancelled>);
static_assert(std::is_base_of_v<Error, RealizationFailed>);

template <class E, class Catch>
std::string caught_as(const E& thrown) {
  try {
    throw thrown;
  } catch (const Catch& e) {
    return e.what();
  }
  return "not caught";
}

TEST(Errors, OneBaseCatchesEveryLibraryErrorWithItsMessage) {
  EXPECT_EQ((caught_as<InvalidInput, Error>(InvalidInput("q", " 2: must be in [0, 1]"))), "q 2: must be in [0, 1]");
  EXPECT_EQ((caught_as<IoError, Error>(IoError("cannot write 'x'"))), "cannot write 'x'");
  EXPECT_EQ((caught_as<NumericalError, Error>(NumericalError("no convergence"))), "no convergence");
  EXPECT_EQ((caught_as<Cancelled, Error>(Cancelled())), "cancelled");
  // The standard bases still catch them, with the same message.
  EXPECT_EQ((caught_as<InvalidInput, std::invalid_argument>(InvalidInput("bad"))), "bad");
  EXPECT_EQ((caught_as<IoError, std::exception>(IoError("disk"))), "disk");
  EXPECT_EQ((caught_as<NumericalError, std::runtime_error>(NumericalError("nan"))), "nan");
}

}  // namespace
}  // namespace granular
