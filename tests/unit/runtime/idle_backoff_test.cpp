// The polling pauses: sleeps that grow while a rank has work of its own running, a short spin (no sleep)
// while it has none and something happened within the last millisecond.
#include <catch2/catch_test_macros.hpp>

#include <chrono>

#include "idle_backoff.hpp"

using namespace std::chrono_literals;
using pbrfit::runtime::IdleBackoff;

TEST_CASE("idle backoff: pauses grow from 250 us to 1 ms while compute threads run", "[runtime]") {
  IdleBackoff backoff;
  CHECK(backoff.next(true, false) == 250us);
  CHECK(backoff.next(false, false) == 250us);
  CHECK(backoff.next(false, false) == 500us);
  CHECK(backoff.next(false, false) == 1000us);
  CHECK(backoff.next(false, false) == 1000us);
  CHECK(backoff.next(true, false) == 250us);
}

TEST_CASE("idle backoff: a rank with nothing running polls without sleeping, for a millisecond at most", "[runtime]") {
  IdleBackoff backoff;
  const auto t = IdleBackoff::Clock::now();
  CHECK(backoff.next(true, true, t) == 0us);
  CHECK(backoff.next(false, true, t + 999us) == 0us);  // just after activity: the next message is probably near
  CHECK(backoff.next(false, true, t + 1000us) == 250us);  // the spin is over: sleeping pauses as usual
  CHECK(backoff.next(false, true, t + 1300us) == 500us);
  CHECK(backoff.next(false, false, t + 1400us) == 1000us);  // something runs here: no spin at all
  CHECK(backoff.next(true, true, t + 5000us) == 0us);  // activity starts a new spin
  CHECK(backoff.next(false, true, t + 5500us) == 0us);
}
