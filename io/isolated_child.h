#pragma once

// Private helper of corridor_rosbag: runs a reader in a forked child process that sends its
// results through a pipe, so that a library that crashes on corrupt input (rosbag_storage reads
// out of bounds on some damaged bags: a SIGSEGV found by flipping bytes of a valid bag) costs a
// status, never the caller's process. Not installed.

#include <sys/types.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "corridor_depth/status.h"

namespace corridor {

// The child's end of the pipe: length-prefixed records.
class RecordWriter {
 public:
  explicit RecordWriter(int fd) : fd_(fd) {}
  // Writes a record: a tag byte, a 64-bit length, the bytes. False when the parent has gone.
  bool Write(char tag, const void* bytes, size_t size);
  bool Write(char tag, const std::string& bytes) { return Write(tag, bytes.data(), bytes.size()); }

 private:
  int fd_;
};

class IsolatedChild {
 public:
  ~IsolatedChild();  // Kills a child that is still running and reaps it.

  // Forks; the child runs `work` (which must not start threads or use OpenCV) and exits.
  static Status Start(const std::function<void(RecordWriter*)>& work,
                      std::unique_ptr<IsolatedChild>* child);

  // The next record; false at the end of the stream (the child has exited or crashed).
  bool Read(char* tag, std::string* bytes);

  // Waits for the child. Ok when it exited normally; otherwise a status that says how it died,
  // prefixed by `what` (e.g. "<bag>: the rosbag library crashed (signal 11)").
  Status Finish(const std::string& what);

 private:
  IsolatedChild(pid_t pid, int fd) : pid_(pid), fd_(fd) {}
  bool ReadExact(void* buffer, size_t size);
  pid_t pid_;
  int fd_;
  bool reaped_ = false;
  int wait_status_ = 0;
};

}  // namespace corridor
