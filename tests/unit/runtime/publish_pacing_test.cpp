#include <catch2/catch_test_macros.hpp>

#include "publish_pacing.hpp"

using pbrfit::runtime::PublishPacing;

TEST_CASE("publication waits the flush interval while copies are cheap", "[runtime][persistence]") {
  PublishPacing pacing(1.0);
  CHECK(pacing.wait_seconds() == 1.0);
  pacing.copied(0.01);
  CHECK(pacing.wait_seconds() == 1.0);
}

TEST_CASE("publication keeps copying to 5 % of the time as the file grows", "[runtime][persistence]") {
  PublishPacing pacing(1.0);
  for (double cost : {0.2, 0.3, 0.4, 0.5, 0.6}) pacing.copied(cost);
  CHECK(pacing.wait_seconds() == 0.4 / 0.05);
}

TEST_CASE("a slow first copy does not silence readers", "[runtime][persistence]") {
  // A cold disk often makes the first copy the slowest; judged alone it would silence `status` for 15 s.
  PublishPacing pacing(1.0);
  pacing.copied(0.75);
  CHECK(pacing.wait_seconds() == 1.0);
  pacing.copied(0.75);
  CHECK(pacing.wait_seconds() == 1.0);
  pacing.copied(0.75);
  CHECK(pacing.wait_seconds() == 0.75 / 0.05);
}

TEST_CASE("one stalled copy does not hold back the next publication", "[runtime][persistence]") {
  PublishPacing pacing(1.0);
  for (double cost : {0.01, 0.01, 2.0, 0.01}) pacing.copied(cost);
  CHECK(pacing.wait_seconds() == 1.0);
  SECTION("copies that stay slow are believed") {
    for (double cost : {2.0, 2.0}) pacing.copied(cost);
    CHECK(pacing.wait_seconds() == 2.0 / 0.05);
  }
  SECTION("only the last five copies count") {
    for (int i = 0; i < 5; ++i) pacing.copied(0.5);
    for (int i = 0; i < 3; ++i) pacing.copied(0.02);
    CHECK(pacing.wait_seconds() == 1.0);
  }
}
