#include "io/isolated_child.h"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace corridor {

bool RecordWriter::Write(char tag, const void* bytes, size_t size) {
  const uint64_t length = size;
  char head[1 + sizeof(length)];
  head[0] = tag;
  std::memcpy(head + 1, &length, sizeof(length));
  const char* parts[2] = {head, static_cast<const char*>(bytes)};
  const size_t sizes[2] = {sizeof(head), size};
  for (int p = 0; p < 2; ++p) {
    size_t done = 0;
    while (done < sizes[p]) {
      const ssize_t n = ::write(fd_, parts[p] + done, sizes[p] - done);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) return false;
      done += static_cast<size_t>(n);
    }
  }
  return true;
}

Status IsolatedChild::Start(const std::function<void(RecordWriter*)>& work,
                            std::unique_ptr<IsolatedChild>* child) {
  int fds[2];
  if (::pipe(fds) != 0) return Status::IoError(std::string("pipe: ") + std::strerror(errno));
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    return Status::IoError(std::string("fork: ") + std::strerror(errno));
  }
  if (pid == 0) {
    ::close(fds[0]);
    ::signal(SIGPIPE, SIG_DFL);  // The parent stopped reading: end quietly.
    RecordWriter writer(fds[1]);
    work(&writer);
    ::close(fds[1]);
    ::_exit(0);  // No destructors or atexit handlers of the parent's state.
  }
  ::close(fds[1]);
  child->reset(new IsolatedChild(pid, fds[0]));
  return Status::Ok();
}

bool IsolatedChild::ReadExact(void* buffer, size_t size) {
  char* out = static_cast<char*>(buffer);
  size_t done = 0;
  while (done < size) {
    const ssize_t n = ::read(fd_, out + done, size - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<size_t>(n);
  }
  return true;
}

bool IsolatedChild::Read(char* tag, std::string* bytes) {
  char head[1 + sizeof(uint64_t)];
  if (fd_ < 0 || !ReadExact(head, sizeof(head))) return false;
  uint64_t length = 0;
  std::memcpy(&length, head + 1, sizeof(length));
  if (length > (uint64_t{1} << 32)) return false;  // A record is a message: never 4 GB.
  bytes->resize(static_cast<size_t>(length));
  if (!ReadExact(bytes->data(), bytes->size())) return false;
  *tag = head[0];
  return true;
}

Status IsolatedChild::Finish(const std::string& what) {
  if (fd_ >= 0) {
    ::close(fd_);
    fd_ = -1;
  }
  if (!reaped_) {
    while (::waitpid(pid_, &wait_status_, 0) < 0 && errno == EINTR) {
    }
    reaped_ = true;
  }
  if (WIFSIGNALED(wait_status_)) {
    const int sig = WTERMSIG(wait_status_);
    if (sig == SIGPIPE) return Status::Ok();  // We stopped reading first.
    return Status::InvalidArgument(what + " (signal " + std::to_string(sig) + ": " +
                                   strsignal(sig) + ")");
  }
  if (WIFEXITED(wait_status_) && WEXITSTATUS(wait_status_) != 0) {
    return Status::InvalidArgument(what + " (exit code " +
                                   std::to_string(WEXITSTATUS(wait_status_)) + ")");
  }
  return Status::Ok();
}

IsolatedChild::~IsolatedChild() {
  if (!reaped_) {
    ::kill(pid_, SIGKILL);
    (void)Finish("");
  }
  if (fd_ >= 0) ::close(fd_);
}

}  // namespace corridor
