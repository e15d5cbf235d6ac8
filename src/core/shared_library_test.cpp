#include "core/shared_library.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace rise {
namespace {

TEST(SharedLibrary, GivesAFunctionOfALibraryByItsName) {
  const SharedLibrary math("libm.so.6");
  const auto cosine = math.function<double(double)>("cos");
  EXPECT_EQ(cosine(0.0), 1.0);
  EXPECT_DOUBLE_EQ(cosine(std::acos(0.5)), 0.5);
}

TEST(SharedLibrary, NamesALibraryItCannotLoad) {
  try {
    const SharedLibrary missing("librise-no-such-library.so.1");
    FAIL() << "opened a library that does not exist";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("cannot load librise-no-such-library.so.1"),
              std::string::npos)
        << error.what();
  }
}

TEST(SharedLibrary, NamesAFunctionTheLibraryLacks) {
  const SharedLibrary math("libm.so.6");
  try {
    math.function<void()>("rise_no_such_function");
    FAIL() << "found a function that does not exist";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("libm.so.6 has no function rise_no_such_function"),
              std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace rise
