#pragma once
// A private folder under the system's temporary directory for one test's files, removed with everything
// in it when the object goes, unless the test asked to keep it (a failed run's logs, for a look).

#include <filesystem>
#include <string>

namespace ifar::test_support {

class TemporaryDirectory {
 public:
  /// Creates <temp>/<prefix>-XXXXXX (mkdtemp); path() is empty when that failed.
  explicit TemporaryDirectory(const std::string& prefix);
  ~TemporaryDirectory();
  TemporaryDirectory(const TemporaryDirectory&) = delete;
  TemporaryDirectory& operator=(const TemporaryDirectory&) = delete;

  const std::filesystem::path& path() const { return path_; }
  /// Leaves the folder in place on destruction.
  void keep() { keep_ = true; }

 private:
  std::filesystem::path path_;
  bool keep_ = false;
};

}  // namespace ifar::test_support
