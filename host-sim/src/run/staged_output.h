// An output directory written all-or-nothing: a command writes into a
// sibling staging directory and commit() moves the files into place, so a
// refused or failed run leaves nothing half-written (issue 17). Without
// commit() (an exception) the staging directory is removed.
#pragma once

#include <string>

namespace mptrack::sim {

class StagedOutputDir {
 public:
  /// final_dir "" = no output: path() is "" and commit() does nothing.
  explicit StagedOutputDir(std::string final_dir);
  ~StagedOutputDir();
  StagedOutputDir(const StagedOutputDir&) = delete;
  StagedOutputDir& operator=(const StagedOutputDir&) = delete;

  /// Where to write until commit().
  const std::string& path() const { return staging_; }
  /// Moves every file written into final_dir (created if needed; files of the
  /// same name are replaced, others kept). Throws std::runtime_error on I/O errors.
  void commit();

 private:
  std::string final_;
  std::string staging_;
  bool committed_ = false;
};

}  // namespace mptrack::sim
