#pragma once
// The only way Assimp reaches the file system during an import: the scene
// file the user named, and files it refers to inside that file's folder.

#include <assimp/DefaultIOSystem.h>

#include <cstdint>
#include <filesystem>
#include <set>
#include <string>

namespace hullcover::detail {

/// An Assimp IOSystem that opens the scene file itself and regular files
/// that resolve (symlinks followed, `..` applied) inside its folder, each at
/// most `max_file_bytes` long. Any other path is refused: Exists says no,
/// Open returns null, and the first refusal is kept for the caller's message
/// (an importer may carry on without a material library, but the file still
/// reached outside its folder).
class ConfinedIOSystem : public Assimp::DefaultIOSystem {
public:
  ConfinedIOSystem(const std::string& scene_path, std::uint64_t max_file_bytes);

  bool Exists(const char* file) const override;
  Assimp::IOStream* Open(const char* file, const char* mode = "rb") override;

  /// Why the first refused path was refused ("" when none was): the
  /// reference as the importer asked for it, and the rule it broke.
  const std::string& refusal() const { return refusal_; }
  /// True when the refusal was a file over max_file_bytes (a limit, not
  /// confinement).
  bool refused_for_size() const { return refused_for_size_; }
  /// Bytes of the distinct files opened so far (each counted once, however
  /// often the importer opens it): what the default triangle limit scales
  /// with.
  std::uint64_t bytes_opened() const { return bytes_opened_; }

private:
  enum class Verdict { allowed, outside, too_large };
  /// Whether `file` may be read; when it may, `resolved` (if given) gets
  /// its canonical path, which counts each file once in bytes_opened.
  Verdict judge(const char* file, std::filesystem::path* resolved = nullptr) const;
  void note(const char* file, Verdict verdict) const;

  std::string scene_path_;
  std::filesystem::path folder_; // canonical
  std::uint64_t max_file_bytes_;
  // Kept by Exists too (const in Assimp's interface): an importer may ask
  // before it opens, and give up quietly on a no.
  mutable std::string refusal_;
  mutable bool refused_for_size_ = false;
  std::set<std::filesystem::path> opened_;
  std::uint64_t bytes_opened_ = 0;
};

} // namespace hullcover::detail
