#include "messages.hpp"

#include <thread>

#include "pbrfit/core/error.hpp"

namespace pbrfit::runtime {

Outbox::~Outbox() { drain(std::chrono::milliseconds(2000)); }

void Outbox::send(int destination, Tag tag, std::shared_ptr<const Bytes> payload) {
  if (payload->size() > std::size_t(std::numeric_limits<int>::max()))
    throw RunError("a message of " + std::to_string(payload->size()) + " bytes is too large for MPI");
  in_flight_.push_back({MPI_REQUEST_NULL, std::move(payload)});
  auto& sent = in_flight_.back();
  if (MPI_Isend(sent.payload->data(), int(sent.payload->size()), MPI_BYTE, destination, int(tag), MPI_COMM_WORLD,
                &sent.request) != MPI_SUCCESS)
    throw RunError("MPI send to rank " + std::to_string(destination) + " failed");
}

void Outbox::send(int destination, Tag tag, Bytes payload) {
  send(destination, tag, std::make_shared<const Bytes>(std::move(payload)));
}

void Outbox::progress() {
  for (auto it = in_flight_.begin(); it != in_flight_.end();) {
    int done = 0;
    MPI_Test(&it->request, &done, MPI_STATUS_IGNORE);
    it = done ? in_flight_.erase(it) : std::next(it);
  }
}

bool Outbox::drain(std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    progress();
    if (in_flight_.empty()) return true;
    if (std::chrono::steady_clock::now() >= deadline) return false;
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
}

std::optional<Message> try_receive() {
  int waiting = 0;
  MPI_Status status;
  if (MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &waiting, &status) != MPI_SUCCESS)
    throw RunError("MPI probe failed");
  if (!waiting) return std::nullopt;
  int size = 0;
  MPI_Get_count(&status, MPI_BYTE, &size);
  Message message{status.MPI_SOURCE, Tag(status.MPI_TAG), Bytes(std::size_t(size))};
  if (MPI_Recv(message.payload.data(), size, MPI_BYTE, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD,
               MPI_STATUS_IGNORE) != MPI_SUCCESS)
    throw RunError("MPI receive from rank " + std::to_string(status.MPI_SOURCE) + " failed");
  return message;
}

}  // namespace pbrfit::runtime
