#pragma once
// The coordinator/worker protocol, point to point on MPI_COMM_WORLD. Private to the runtime.
//   coordinator -> worker: stage (u32 stage, bytes context), work (u64 item), stop
//   worker -> coordinator: result (u32 stage, u64 item, bytes), failed (text), signalled, bye
// After `stop` a worker sends nothing but `bye`; messages from one sender arrive in order, so every
// result a worker sent before `bye` has been received once `bye` is.
#include <mpi.h>

#include <optional>

#include "pbrfit/core/bytes.hpp"

namespace pbrfit::runtime {

enum class Tag : int { stage = 1, work, stop, result, failed, signalled, bye };

struct Message {
  int source = 0;
  Tag tag = Tag::stop;
  Bytes payload;
};

void send(int destination, Tag tag, const Bytes& payload = {});
// A message from anyone if one is waiting.
std::optional<Message> try_receive();
// Waits for a message, sleeping briefly between polls so an idle rank leaves its core to others.
Message receive();

}  // namespace pbrfit::runtime
