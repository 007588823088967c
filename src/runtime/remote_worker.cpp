#include "remote_worker.hpp"

#include <chrono>
#include <deque>
#include <thread>

#include "messages.hpp"
#include "pbrfit/runtime/stop_signal.hpp"

namespace pbrfit::runtime {

namespace {

struct WorkerState {
  std::uint32_t stage = 0;
  Bytes context;
  std::deque<std::uint64_t> queue;
  bool idle_until_stop = false;  // signalled or failed: start nothing new
};

void compute_next(const Workload& workload, WorkerState& state) {
  const std::uint64_t item = state.queue.front();
  state.queue.pop_front();
  try {
    Bytes result = workload.compute(state.stage, item, state.context);
    ByteWriter out;
    out.put(state.stage);
    out.put(item);
    out.put_bytes(result);
    send(0, Tag::result, out.bytes());
  } catch (const std::exception& e) {
    ByteWriter out;
    out.put_string("item " + std::to_string(item) + ": " + e.what());
    send(0, Tag::failed, out.bytes());
    state.idle_until_stop = true;
  }
}

}  // namespace

void serve_as_worker(const Workload& workload) {
  WorkerState state;
  auto pause = std::chrono::microseconds(20);
  for (;;) {
    if (stop_requested() && !state.idle_until_stop) {
      send(0, Tag::signalled);
      state.idle_until_stop = true;
    }
    if (auto message = try_receive()) {
      pause = std::chrono::microseconds(20);
      ByteReader in(message->payload);
      if (message->tag == Tag::stop) {
        send(0, Tag::bye);
        return;
      }
      if (message->tag == Tag::stage) {
        state.stage = in.get<std::uint32_t>();
        state.context = in.get_bytes();
      } else if (message->tag == Tag::work) {
        state.queue.push_back(in.get<std::uint64_t>());
      }
      continue;
    }
    if (!state.queue.empty() && !state.idle_until_stop) {
      compute_next(workload, state);
      continue;
    }
    std::this_thread::sleep_for(pause);
    pause = std::min(pause * 2, std::chrono::microseconds(1000));
  }
}

}  // namespace pbrfit::runtime
