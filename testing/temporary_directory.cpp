#include "testing/temporary_directory.hpp"

#include <stdlib.h>

#include <system_error>

namespace ifar::test_support {

TemporaryDirectory::TemporaryDirectory(const std::string& prefix)
{
  std::string pattern = (std::filesystem::temp_directory_path() / (prefix + "-XXXXXX")).string();
  if (mkdtemp(pattern.data()) != nullptr) {
    path_ = pattern;
  }
}

TemporaryDirectory::~TemporaryDirectory()
{
  if (!path_.empty() && !keep_) {
    std::error_code ignored;  // a destructor must not throw; a leftover folder is only untidy
    std::filesystem::remove_all(path_, ignored);
  }
}

}  // namespace ifar::test_support
