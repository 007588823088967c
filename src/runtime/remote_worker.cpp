#include "remote_worker.hpp"

#include <spdlog/spdlog.h>

#include <deque>
#include <memory>
#include <optional>

#include "compute_pool.hpp"
#include "idle_backoff.hpp"
#include "messages.hpp"
#include "pbrfit/core/error.hpp"
#include "pbrfit/runtime/stop_signal.hpp"
#include "peer_watch.hpp"
#include "relay_tree.hpp"

namespace pbrfit::runtime {

namespace {

// How long finished results of short items may wait for company while the rank has work queued
// (dispatch_depth.hpp keeps a reserve of 10 ms of items at a rank, so a thread does not run dry meanwhile).
// Items are short when those last sent took under half of it on average: longer ones would rarely find
// company, and waiting would only delay rank 0's view of the rank.
constexpr std::chrono::milliseconds result_hold{2};
constexpr double short_item_seconds = 0.5 * 1e-3 * double(result_hold.count());

struct Assignment {
  WorkItemId id;
  Bytes input;
};

class Worker {
 public:
  Worker(const MpiSession& mpi, const Workload& workload, const RunSettings& settings)
      : mpi_(mpi), settings_(settings), pool_(workload, settings.seed, settings.threads), peers_(1) {}

  WorkerEnd serve() {
    while (!stopped_ && !coordinator_lost()) {
      if (stop_requested() && !signalled_) {
        spdlog::warn("{} received: asking rank 0 to stop", stop_signal_origin());
        send(Tag::signalled);
        signalled_ = idle_ = true;
      }
      const bool received = receive_all();
      const bool sent = send_finished(false);
      keep_alive();
      const auto pause = backoff_.next(received || sent, pool_.outstanding() == 0);
      if (!received && !sent) pool_.wait(pause, held_since_ ? pool_.finished() : 0);
    }
    if (stopped_) return await_farewell();
    return give_up();
  }

 private:
  void send(Tag tag, Bytes payload = {}) {
    outbox_.send(0, tag, std::move(payload));
    heartbeat_.sent();
  }

  void keep_alive() {
    outbox_.progress();
    if (heartbeat_.due()) send(Tag::heartbeat);
  }

  bool coordinator_lost() const { return peers_.silent_seconds(0) >= settings_.rank_timeout_seconds; }

  bool receive_all() {
    bool any = false;
    while (!stopped_) {
      auto message = try_receive();
      if (!message) break;
      if (message->source == 0) peers_.heard(0);
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
      const auto stage = in.get<std::uint32_t>();
      while (in.remaining() > 0) {
        const auto item = in.get<std::uint64_t>();
        waiting_.push_back({{stage, item}, in.get_bytes()});
      }
      start_waiting();
    } else if (message.tag == Tag::stop) {
      finish_in_grace();
      send(Tag::bye);
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

  // Running items may still finish (or give up) within the grace; their results go to rank 0.
  void finish_in_grace() {
    pool_.cancel();
    const auto grace = std::chrono::duration<double>(settings_.stop_grace_seconds / 2);
    const auto deadline =
        std::chrono::steady_clock::now() + std::chrono::duration_cast<std::chrono::steady_clock::duration>(grace);
    while (!pool_.idle() && std::chrono::steady_clock::now() < deadline) pool_.wait(std::chrono::milliseconds(1));
    send_finished(true);
  }

  // Finished results go to rank 0 in as few messages as batch_bytes allows. Results of short items may
  // wait up to result_hold while every thread has another item queued, so that they share a message and
  // rank 0 handles fewer of them; once a thread could run out, they go at once (the end of a stage
  // never waits). `now`: send whatever there is.
  bool send_finished(bool now) {
    if (!now && holding()) return false;
    bool any = false;
    held_since_.reset();
    ByteWriter out;
    auto results = pool_.take_finished();
    if (!results.empty()) {
      double seconds = 0.0;
      for (const auto& finished : results) seconds += finished.seconds;
      recent_item_seconds_ = seconds / double(results.size());
    }
    for (auto& finished : results) {
      out.put(finished.id.stage);
      out.put(finished.id.item);
      out.put(finished.seconds);
      out.put_bytes(finished.result);
      if (out.bytes().size() >= batch_bytes) send(Tag::result, out.take());
      any = true;
    }
    if (!out.bytes().empty()) send(Tag::result, out.take());
    if (auto failure = pool_.failure(); failure && !reported_failure_) {
      ByteWriter out;
      out.put_string(*failure);
      send(Tag::failed, out.take());
      reported_failure_ = idle_ = true;
    }
    return any;
  }

  bool holding() {
    if (recent_item_seconds_ >= short_item_seconds || pool_.finished() == 0) return false;
    if (pool_.queued() < std::size_t(pool_.threads())) return false;
    const auto now = std::chrono::steady_clock::now();
    if (!held_since_) held_since_ = now;
    return now - *held_since_ < result_hold;
  }

  WorkerEnd await_farewell() {
    while (!coordinator_lost()) {
      keep_alive();
      if (auto message = try_receive()) {
        if (message->source == 0) peers_.heard(0);
        if (message->tag == Tag::farewell) {
          ByteReader in(message->payload);
          return {in.get<std::int32_t>(), false};
        }
        continue;  // late work or stages: nothing more is computed
      }
      pool_.wait(backoff_.next(false, pool_.outstanding() == 0));
    }
    return give_up();
  }

  WorkerEnd give_up() {
    spdlog::error("rank 0 has sent nothing for {:.0f} s (it died or hangs): giving up", peers_.silent_seconds(0));
    pool_.cancel();
    return {exit_interrupted, true};
  }

  const MpiSession& mpi_;
  const RunSettings& settings_;
  ComputePool pool_;
  Outbox outbox_;
  IdleBackoff backoff_;
  PeerWatch peers_;  // only rank 0 is watched
  HeartbeatClock heartbeat_;
  std::uint32_t stage_ = 0;
  std::shared_ptr<const Bytes> context_;
  std::deque<Assignment> waiting_;
  std::optional<std::chrono::steady_clock::time_point> held_since_;  // when results began to wait
  double recent_item_seconds_ = 1e300;  // the mean compute time of the results sent last (none yet: long)
  bool signalled_ = false, idle_ = false, reported_failure_ = false, stopped_ = false;
};

}  // namespace

WorkerEnd serve_as_worker(const MpiSession& mpi, const Workload& workload, const RunSettings& settings) {
  Worker worker(mpi, workload, settings);
  return worker.serve();
}

}  // namespace pbrfit::runtime
