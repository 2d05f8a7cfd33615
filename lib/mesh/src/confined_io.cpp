#include "confined_io.h"

#include <assimp/IOStream.hpp>

#include <algorithm>
#include <cstring>
#include <system_error>

namespace hullcover::detail {
namespace {

// True when `inner` (canonical) lies under `folder` (canonical).
bool lies_under(const std::filesystem::path& inner, const std::filesystem::path& folder) {
  const auto mismatch = std::mismatch(folder.begin(), folder.end(), inner.begin(), inner.end());
  return mismatch.first == folder.end() && mismatch.second != inner.end();
}

} // namespace

ConfinedIOSystem::ConfinedIOSystem(const std::string& scene_path, std::uint64_t max_file_bytes)
    : scene_path_(scene_path), max_file_bytes_(max_file_bytes) {
  std::error_code error;
  folder_ = std::filesystem::canonical(std::filesystem::absolute(scene_path, error).parent_path(), error);
}

ConfinedIOSystem::Verdict ConfinedIOSystem::judge(const char* file, std::filesystem::path* resolved_out) const {
  if (file == nullptr || folder_.empty()) return Verdict::outside;
  std::error_code error;
  // Only plain relative or absolute paths: a URI scheme (http:, file:) is
  // never a file here, and the importer must not reach the network.
  const std::string text(file);
  if (text != scene_path_ && text.find("://") != std::string::npos) return Verdict::outside;
  const std::filesystem::path resolved =
      std::filesystem::weakly_canonical(std::filesystem::absolute(text, error), error);
  if (error) return Verdict::outside;
  if (text != scene_path_ && !lies_under(resolved, folder_)) return Verdict::outside;
  // A FIFO or a device inside the folder would block or never end.
  if (std::filesystem::exists(resolved, error) && !std::filesystem::is_regular_file(resolved, error))
    return Verdict::outside;
  if (std::filesystem::is_regular_file(resolved, error) &&
      std::filesystem::file_size(resolved, error) > max_file_bytes_)
    return Verdict::too_large;
  if (resolved_out != nullptr) *resolved_out = resolved;
  return Verdict::allowed;
}

void ConfinedIOSystem::note(const char* file, Verdict verdict) const {
  if (!refusal_.empty() || verdict == Verdict::allowed) return;
  const std::string name = file == nullptr ? std::string("(none)") : std::string(file);
  if (verdict == Verdict::too_large) {
    refused_for_size_ = true;
    refusal_ = "refers to '" + name + "', larger than the file size limit of " + std::to_string(max_file_bytes_) +
               " bytes (raise it with --max-file-size)";
  } else {
    refusal_ = "refers to '" + name + "', outside the scene file's folder " + folder_.string() +
               " (references are read only inside it: no absolute paths, no '..', no symlinks out, no URLs)";
  }
}

bool ConfinedIOSystem::Exists(const char* file) const {
  const Verdict verdict = judge(file);
  note(file, verdict);
  return verdict == Verdict::allowed && Assimp::DefaultIOSystem::Exists(file);
}

Assimp::IOStream* ConfinedIOSystem::Open(const char* file, const char* mode) {
  // Reading only: an importer has no business writing.
  if (mode == nullptr || std::strchr(mode, 'w') != nullptr || std::strchr(mode, 'a') != nullptr) return nullptr;
  std::filesystem::path resolved;
  const Verdict verdict = judge(file, &resolved);
  note(file, verdict);
  if (verdict != Verdict::allowed) return nullptr;
  Assimp::IOStream* stream = Assimp::DefaultIOSystem::Open(file, mode);
  if (stream != nullptr && opened_.insert(resolved).second) bytes_opened_ += stream->FileSize();
  return stream;
}

} // namespace hullcover::detail
