#include "messages.hpp"

#include <chrono>
#include <thread>

#include "pbrfit/core/error.hpp"

namespace pbrfit::runtime {

void send(int destination, Tag tag, const Bytes& payload) {
  if (MPI_Send(payload.data(), int(payload.size()), MPI_BYTE, destination, int(tag), MPI_COMM_WORLD) != MPI_SUCCESS)
    throw RunError("MPI send to rank " + std::to_string(destination) + " failed");
}

std::optional<Message> try_receive() {
  int waiting = 0;
  MPI_Status status;
  MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &waiting, &status);
  if (!waiting) return std::nullopt;
  int size = 0;
  MPI_Get_count(&status, MPI_BYTE, &size);
  Message message{status.MPI_SOURCE, Tag(status.MPI_TAG), Bytes(std::size_t(size))};
  MPI_Recv(message.payload.data(), size, MPI_BYTE, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD,
           MPI_STATUS_IGNORE);
  return message;
}

Message receive() {
  auto pause = std::chrono::microseconds(20);
  for (;;) {
    if (auto message = try_receive()) return std::move(*message);
    std::this_thread::sleep_for(pause);
    pause = std::min(pause * 2, std::chrono::microseconds(1000));
  }
}

}  // namespace pbrfit::runtime
