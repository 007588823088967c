#include <catch2/catch_test_macros.hpp>

#include <string>
#include <vector>

#include "pbrfit/spec/schema.hpp"

using pbrfit::spec::closest_match;

TEST_CASE("closest_match suggests near misses") {
  const std::vector<std::string> lut_keys = {"function", "tolerance", "resolution", "max_evaluations"};
  CHECK(closest_match("tolerence", lut_keys) == "tolerance");       // substitution
  CHECK(closest_match("resolutoin", lut_keys) == "resolution");     // transposition costs 2
  CHECK(closest_match("fuction", lut_keys) == "function");          // deletion
  CHECK(closest_match("max_evaluationss", lut_keys) == "max_evaluations");  // insertion
  CHECK(closest_match("sed", {"name", "kind", "seed"}) == "seed");
  CHECK(closest_match("Seed", {"seed"}) == "seed");
  CHECK(closest_match("seed", {"seed", "speed"}) == "seed");        // exact
}

TEST_CASE("closest_match allows a third of a long word to differ") {
  // Distance 3 to "interval_seconds", allowed for a 13-character word (but not for a shorter one).
  CHECK(closest_match("interval_secs", {"interval_seconds", "interval_items"}) == "interval_seconds");
  CHECK(closest_match("abcxyz", {"abc"}) == "");  // distance 3, only 6 characters
}

TEST_CASE("closest_match refuses far-fetched matches") {
  CHECK(closest_match("priority", {"name", "kind", "seed", "output"}) == "");
  CHECK(closest_match("xy", {"ab"}) == "");   // distance 2, but a complete rewrite
  CHECK(closest_match("x", {"y", "z"}) == "");
  CHECK(closest_match("", {"a"}) == "");
  CHECK(closest_match("seed", {}) == "");
}

TEST_CASE("closest_match breaks ties by candidate order") {
  CHECK(closest_match("cat", {"bat", "hat"}) == "bat");
  CHECK(closest_match("cat", {"hat", "bat"}) == "hat");
  CHECK(closest_match("cat", {"hats", "bat"}) == "bat");  // a strictly closer one wins
}
