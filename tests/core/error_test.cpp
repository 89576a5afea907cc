#include "catena/core/error.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace catena {
namespace {

TEST(InputError, ListsEveryIssueInItsMessage) {
  std::vector<Issue> issues;
  check::finite_positive(issues, "pitch", -1.0, "m");
  check::finite_positive(issues, "wire", NAN, "m");
  check::finite(issues, "height", INFINITY, "m");
  check::finite(issues, "ok", 1.0, "m");
  ASSERT_EQ(issues.size(), 3u);
  try {
    throw_if_any(issues);
    FAIL() << "expected InputError";
  } catch (const InputError& error) {
    const std::string text = error.what();
    EXPECT_NE(text.find("3 problems"), std::string::npos) << text;
    EXPECT_NE(text.find("pitch = -1 m: expected a finite value > 0 m"), std::string::npos) << text;
    EXPECT_NE(text.find("wire = nan m"), std::string::npos) << text;
    EXPECT_NE(text.find("height = inf m: expected a finite value"), std::string::npos) << text;
    EXPECT_EQ(error.issues().size(), 3u);
  }
}

TEST(InputError, NothingToThrowWhenThereAreNoIssues) { EXPECT_NO_THROW(throw_if_any({})); }

}  // namespace
}  // namespace catena
