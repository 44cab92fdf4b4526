#include "progress.h"

#include <unistd.h>

#include <cstdio>
#include <utility>

namespace mptrack::sim {

Progress::Progress(std::string label, std::uint64_t total, bool enabled)
    : label_(std::move(label)), total_(total), enabled_(enabled && total > 0), tty_(isatty(STDERR_FILENO) != 0) {}

Progress::~Progress() { finish(); }

void Progress::tick(std::uint64_t n) {
  done_ += n;
  if (done_ > total_) done_ = total_;
  draw();
}

void Progress::draw() {
  if (!enabled_ || finished_) return;
  const std::uint64_t permille = done_ * 1000 / total_;
  if (tty_) {
    if (static_cast<int>(permille) == last_permille_) return;
    last_permille_ = static_cast<int>(permille);
    constexpr int kWidth = 40;
    const int filled = static_cast<int>(done_ * kWidth / total_);
    std::fprintf(stderr, "\r%s [", label_.c_str());
    for (int i = 0; i < kWidth; ++i) std::fputc(i < filled ? '#' : '.', stderr);
    std::fprintf(stderr, "] %5.1f%% (%llu/%llu)", static_cast<double>(permille) / 10.0,
                 static_cast<unsigned long long>(done_), static_cast<unsigned long long>(total_));
    std::fflush(stderr);
  } else {
    const int decile = static_cast<int>(done_ * 10 / total_);
    if (decile == last_decile_) return;
    last_decile_ = decile;
    std::fprintf(stderr, "%s: %d%% (%llu/%llu)\n", label_.c_str(), decile * 10,
                 static_cast<unsigned long long>(done_), static_cast<unsigned long long>(total_));
  }
}

void Progress::finish() {
  if (!enabled_ || finished_) return;
  done_ = total_;
  draw();
  finished_ = true;
  if (tty_) std::fputc('\n', stderr);
}

}  // namespace mptrack::sim
