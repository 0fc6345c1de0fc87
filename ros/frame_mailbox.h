#pragma once

#include <condition_variable>
#include <mutex>
#include <optional>
#include <utility>

namespace corridor {

// A one-slot mailbox between the subscriber callback and the worker thread: a new item replaces
// one that the worker has not taken yet (the node keeps only the newest frame), so memory and
// latency never grow when the camera is faster than the node.
template <class T>
class FrameMailbox {
 public:
  // Puts the item; true when it replaced one that was never taken (a dropped frame).
  bool Put(T item) {
    bool replaced;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      replaced = slot_.has_value();
      slot_ = std::move(item);
    }
    ready_.notify_one();
    return replaced;
  }
  // Waits for an item; false once Close() was called.
  bool Take(T* item) {
    std::unique_lock<std::mutex> lock(mutex_);
    ready_.wait(lock, [this] { return closed_ || slot_.has_value(); });
    if (closed_) return false;
    *item = std::move(*slot_);
    slot_.reset();
    return true;
  }
  void Close() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      closed_ = true;
    }
    ready_.notify_all();
  }

 private:
  std::mutex mutex_;
  std::condition_variable ready_;
  std::optional<T> slot_;
  bool closed_ = false;
};

}  // namespace corridor
