// Progress bar on stderr. On a TTY it redraws one line; otherwise (CI, a
// pipe) it prints a plain line at every 10 % so logs stay readable.
#pragma once

#include <cstdint>
#include <string>

namespace mptrack::sim {

class Progress {
 public:
  Progress(std::string label, std::uint64_t total, bool enabled);
  ~Progress();
  void tick(std::uint64_t n = 1);
  void finish();

 private:
  void draw();
  std::string label_;
  std::uint64_t total_ = 0;
  std::uint64_t done_ = 0;
  bool enabled_ = false;
  bool tty_ = false;
  bool finished_ = false;
  int last_decile_ = -1;
  int last_permille_ = -1;
};

}  // namespace mptrack::sim
