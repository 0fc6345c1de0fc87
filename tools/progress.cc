#include "tools/progress.h"

#include <unistd.h>

#include <cstdio>

namespace corridor {

Progress::Progress(std::string label, int total, std::string unit)
    : label_(std::move(label)),
      unit_(std::move(unit)),
      total_(total),
      terminal_(isatty(STDERR_FILENO) != 0),
      start_(std::chrono::steady_clock::now()) {}

void Progress::Tick(int done) {
  if (total_ <= 1) return;
  if (done > total_) total_ = done;  // A video's frame count is only its container's estimate.
  const auto now = std::chrono::steady_clock::now();
  const auto interval = terminal_ ? std::chrono::milliseconds(200) : std::chrono::seconds(5);
  if (done < total_ && drawn_ && now - last_draw_ < interval) return;
  last_draw_ = now;
  drawn_ = true;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double rate = elapsed > 0 ? done / elapsed : 0.0;
  const double left = rate > 0 ? (total_ - done) / rate : 0.0;
  if (terminal_) {
    const int width = 24;
    const int filled = total_ > 0 ? width * done / total_ : width;
    std::string bar(filled, '#');
    bar.resize(width, '.');
    std::fprintf(stderr, "\r%s [%s] %d/%d %s, %.1f/s, %.0f s left   ", label_.c_str(), bar.c_str(),
                 done, total_, unit_.c_str(), rate, left);
    open_line_ = true;
  } else {
    std::fprintf(stderr, "%s: %d/%d %s, %.1f/s, %.0f s left\n", label_.c_str(), done, total_,
                 unit_.c_str(), rate, left);
  }
  std::fflush(stderr);
}

void Progress::Break() {
  if (!open_line_) return;
  std::fputc('\n', stderr);
  std::fflush(stderr);
  open_line_ = false;
}

void Progress::Finish() { Break(); }

}  // namespace corridor
