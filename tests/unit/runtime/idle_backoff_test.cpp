// The polling pauses: sleeps that grow while a rank has work of its own running, a short spin (no sleep)
// while it has none and something happened within the last millisecond.
#include <catch2/catch_test_macros.hpp>

#include <chrono>
#include <thread>

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
  CHECK(backoff.next(true, true) == 0us);
  CHECK(backoff.next(false, true) == 0us);  // just after activity: the next message is probably near
  std::this_thread::sleep_for(2ms);
  CHECK(backoff.next(false, true) == 250us);  // the spin is over: sleeping pauses as usual
  CHECK(backoff.next(false, true) == 500us);
  CHECK(backoff.next(true, true) == 0us);  // activity starts a new spin
}
