#include "tools/progress.h"

#include <cstdio>
#include <unistd.h>

namespace corridor {

Progress::Progress(std::string label, int total)
    : label_(std::move(label)), total_(total), start_(std::chrono::steady_clock::now()) {}

void Progress::Tick(int done) {
  if (total_ <= 1) return;
  if (done > total_) total_ = done;  // A video's frame count is only its container's estimate.
  const auto now = std::chrono::steady_clock::now();
  if (done < total_ && drawn_ && now - last_draw_ < std::chrono::milliseconds(200)) return;
  last_draw_ = now;
  drawn_ = true;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double fps = elapsed > 0 ? done / elapsed : 0.0;
  const double left = fps > 0 ? (total_ - done) / fps : 0.0;
  const int width = 24;
  const int filled = total_ > 0 ? width * done / total_ : width;
  std::string bar(filled, '#');
  bar.resize(width, '.');
  std::fprintf(stderr, "%s%s [%s] %d/%d frames, %.1f fps, %.0f s left   ",
               isatty(STDERR_FILENO) ? "\r" : "", label_.c_str(), bar.c_str(), done, total_, fps,
               left);
  if (!isatty(STDERR_FILENO)) std::fputc('\n', stderr);
  std::fflush(stderr);
}

void Progress::Finish() {
  if (total_ > 1 && drawn_ && isatty(STDERR_FILENO)) std::fputc('\n', stderr);
}

}  // namespace corridor
