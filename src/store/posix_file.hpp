#pragma once
// A file descriptor with the few operations the store needs, each reporting failure with the path and
// the operating system's reason. Reading accepts regular files only: a FIFO, a device or a directory is
// refused at open, before anything blocks or runs out of memory. Private to the store.
#include <cstdint>
#include <span>
#include <string>

namespace pbrfit::store {

class PosixFile {
 public:
  // Opens a regular file for reading; throws InputError naming the file otherwise.
  static PosixFile open_for_reading(const std::string& path);
  // Opens (creating or truncating) for writing; throws RunError.
  static PosixFile create(const std::string& path);
  // Opens an existing regular file for writing, without truncating; throws RunError.
  static PosixFile open_for_writing(const std::string& path);

  PosixFile(PosixFile&& other) noexcept;
  PosixFile& operator=(PosixFile&&) = delete;
  PosixFile(const PosixFile&) = delete;
  ~PosixFile();

  std::uint64_t size() const;
  // Reads exactly `buffer.size()` bytes from `offset`; false if the file ends first.
  bool read_at(std::uint64_t offset, std::span<std::byte> buffer) const;
  void write_all(std::span<const std::byte> content);
  // Appends this whole file to `target` (in the kernel, without a copy through user space).
  void copy_to(PosixFile& target) const;
  void truncate(std::uint64_t length);
  void seek_to_end();
  void sync();
  void close();  // reports a failing close (the last chance to learn of a failed write)
  const std::string& path() const { return path_; }

 private:
  PosixFile(int fd, std::string path) : fd_(fd), path_(std::move(path)) {}
  int fd_ = -1;
  std::string path_;
};

// The operating system's reason for the last failure (strerror of errno).
std::string os_reason();

// fsyncs the directory holding `path`, so that a rename or creation in it is durable.
void sync_directory_of(const std::string& path);

// Copies `from` to `to` + ".tmp" and renames that over `to`: readers of `to` see the old or the new
// content, never a partial copy. On failure `to` is untouched, the temporary removed, RunError thrown.
void copy_then_rename(const std::string& from, const std::string& to);

}  // namespace pbrfit::store
