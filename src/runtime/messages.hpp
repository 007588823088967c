#pragma once
// The coordinator/worker protocol, point to point on MPI_COMM_WORLD. Private to the runtime.
//   stage     (u32 stage, bytes context)        rank 0 -> tree children; each rank relays it to its own
//   work      (u32 stage, then (u64 item, bytes input) to the end)
//                                                rank 0 -> worker: one or more items of one stage
//   stop                                         rank 0 -> worker: start nothing new, report, say bye
//   result    ((u32 stage, u64 item, f64 s, bytes) to the end)
//                                                worker -> rank 0: one or more results (s: how long
//                                                computing took)
//   failed    (text)                             worker -> rank 0: an item threw; the worker idles
//   signalled                                    worker -> rank 0: the worker got a stop signal
//   bye                                          worker -> rank 0: nothing more will come
//   farewell  (i32 exit code)                    rank 0 -> worker, after bye: exit with this code
//   heartbeat                                    either way, when nothing else was sent for a second
// Messages from one sender to one receiver arrive in order, so every result a worker sent before `bye`
// has been received once `bye` is. Sends never block: an Outbox keeps each payload until MPI is done.
// Work and results travel in batches: what one side has ready for the other goes in one message (up to
// batch_bytes, then another), so rank 0's cost per item is not a message's cost when items are short.
#include <mpi.h>

#include <chrono>
#include <list>
#include <memory>
#include <optional>

#include "pbrfit/core/bytes.hpp"

namespace pbrfit::runtime {

// A batch grows past this size only by its first entry.
inline constexpr std::size_t batch_bytes = std::size_t(1) << 20;

enum class Tag : int { stage = 1, work, stop, result, failed, signalled, bye, farewell, heartbeat };

struct Message {
  int source = 0;
  Tag tag = Tag::stop;
  Bytes payload;
};

class Outbox {
 public:
  Outbox() = default;
  Outbox(const Outbox&) = delete;
  Outbox& operator=(const Outbox&) = delete;
  ~Outbox();  // waits for what is still in flight

  void send(int destination, Tag tag, std::shared_ptr<const Bytes> payload);
  void send(int destination, Tag tag, Bytes payload = {});
  // Releases the payloads MPI has finished with.
  void progress();
  // Waits until everything has been sent, or `timeout` passed; true when everything was sent.
  bool drain(std::chrono::milliseconds timeout);

 private:
  struct InFlight {
    MPI_Request request;
    std::shared_ptr<const Bytes> payload;
  };
  std::list<InFlight> in_flight_;
};

// A message from anyone if one is waiting. Errors are returned, not fatal (MpiSession sets
// MPI_ERRORS_RETURN): a failed receive or send throws RunError instead of aborting every rank.
std::optional<Message> try_receive();

}  // namespace pbrfit::runtime
