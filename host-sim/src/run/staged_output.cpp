// All-or-nothing output directory; see staged_output.h.
#include "run/staged_output.h"

#include <filesystem>
#include <stdexcept>
#include <system_error>
#include <unistd.h>

namespace mptrack::sim {

namespace fs = std::filesystem;

StagedOutputDir::StagedOutputDir(std::string final_dir) : final_(std::move(final_dir)) {
  if (final_.empty()) return;
  fs::path f(final_);
  if (!f.has_filename()) f = f.parent_path();  // "out/x/" -> "out/x"
  staging_ = (f.parent_path() / ("." + f.filename().string() + ".partial-" + std::to_string(::getpid()))).string();
  std::error_code ec;
  fs::remove_all(staging_, ec);
}

StagedOutputDir::~StagedOutputDir() {
  if (staging_.empty() || committed_) return;
  std::error_code ec;
  fs::remove_all(staging_, ec);
}

void StagedOutputDir::commit() {
  if (staging_.empty() || committed_) return;
  committed_ = true;
  std::error_code ec;
  if (!fs::exists(staging_, ec)) return;  // nothing was written
  fs::create_directories(final_, ec);
  if (ec) throw std::runtime_error(final_ + ": cannot create (" + ec.message() + ")");
  for (const fs::directory_entry& e : fs::directory_iterator(staging_)) {
    const fs::path to = fs::path(final_) / e.path().filename();
    fs::remove_all(to, ec);
    fs::rename(e.path(), to, ec);
    if (ec) throw std::runtime_error(to.string() + ": cannot move into place (" + ec.message() + ")");
  }
  fs::remove_all(staging_, ec);
}

}  // namespace mptrack::sim
