#pragma once
// A fresh directory per test, removed afterwards, for files tests write.

#include <set>
#include <string>

namespace hullcover::test {

class TempDir {
public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  /// `name` inside the directory.
  std::string path(const std::string& name) const;
  /// Writes `content` to `name` and returns its path.
  std::string write(const std::string& name, const std::string& content) const;

private:
  std::string dir_;
};

/// The whole of a file, byte for byte ("" when unreadable).
std::string slurp(const std::string& path);

/// Every name in `folder` (not "." or ".."); empty when it cannot be read.
std::set<std::string> folder_entries(const std::string& folder);

} // namespace hullcover::test
