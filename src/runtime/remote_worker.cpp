#include "remote_worker.hpp"

#include <deque>
#include <memory>

#include "compute_pool.hpp"
#include "idle_backoff.hpp"
#include "messages.hpp"
#include "pbrfit/core/error.hpp"
#include "pbrfit/runtime/stop_signal.hpp"
#include "relay_tree.hpp"

namespace pbrfit::runtime {

namespace {

struct Assignment {
  WorkItemId id;
  Bytes input;
};

class Worker {
 public:
  Worker(const MpiSession& mpi, const Workload& workload, std::uint64_t seed, int threads)
      : mpi_(mpi), pool_(workload, seed, threads) {}

  int serve() {
    while (!stopped_) {
      if (stop_requested() && !signalled_) {
        outbox_.send(0, Tag::signalled);
        signalled_ = idle_ = true;
      }
      const bool received = receive_all();
      const bool sent = send_finished();
      outbox_.progress();
      const auto pause = backoff_.next(received || sent);
      if (!received && !sent) pool_.wait(pause);
    }
    return await_farewell();
  }

 private:
  bool receive_all() {
    bool any = false;
    while (!stopped_) {
      auto message = try_receive();
      if (!message) break;
      handle(*message);
      any = true;
    }
    return any;
  }

  void handle(Message& message) {
    ByteReader in(message.payload);
    if (message.tag == Tag::stage) {
      auto payload = std::make_shared<const Bytes>(std::move(message.payload));
      for (int child : relay_children(mpi_.rank(), mpi_.size())) outbox_.send(child, Tag::stage, payload);
      ByteReader header(*payload);
      stage_ = header.get<std::uint32_t>();
      context_ = std::make_shared<const Bytes>(header.get_bytes());
      start_waiting();
    } else if (message.tag == Tag::work) {
      Assignment a{{in.get<std::uint32_t>(), in.get<std::uint64_t>()}, in.get_bytes()};
      waiting_.push_back(std::move(a));
      start_waiting();
    } else if (message.tag == Tag::stop) {
      pool_.stop();
      send_finished();
      outbox_.send(0, Tag::bye);
      stopped_ = true;
    }
  }

  // Items can arrive before their stage's context, which travels another way: they wait for it.
  void start_waiting() {
    while (context_ && !idle_ && !waiting_.empty() && waiting_.front().id.stage == stage_) {
      pool_.assign(waiting_.front().id, context_, std::move(waiting_.front().input));
      waiting_.pop_front();
    }
  }

  bool send_finished() {
    bool any = false;
    for (auto& finished : pool_.take_finished()) {
      ByteWriter out;
      out.put(finished.id.stage);
      out.put(finished.id.item);
      out.put_bytes(finished.result);
      outbox_.send(0, Tag::result, out.take());
      any = true;
    }
    if (auto failure = pool_.failure(); failure && !reported_failure_) {
      ByteWriter out;
      out.put_string(*failure);
      outbox_.send(0, Tag::failed, out.take());
      reported_failure_ = idle_ = true;
    }
    return any;
  }

  int await_farewell() {
    for (;;) {
      outbox_.progress();
      if (auto message = try_receive()) {
        if (message->tag == Tag::farewell) {
          ByteReader in(message->payload);
          return in.get<std::int32_t>();
        }
        continue;  // late work or stages: nothing more is computed
      }
      pool_.wait(backoff_.next(false));
    }
  }

  const MpiSession& mpi_;
  ComputePool pool_;
  Outbox outbox_;
  IdleBackoff backoff_;
  std::uint32_t stage_ = 0;
  std::shared_ptr<const Bytes> context_;
  std::deque<Assignment> waiting_;
  bool signalled_ = false, idle_ = false, reported_failure_ = false, stopped_ = false;
};

}  // namespace

int serve_as_worker(const MpiSession& mpi, const Workload& workload, std::uint64_t seed, int threads) {
  Worker worker(mpi, workload, seed, threads);
  return worker.serve();
}

}  // namespace pbrfit::runtime
