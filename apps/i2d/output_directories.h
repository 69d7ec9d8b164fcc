// Where i2d's outputs go. Every output option (--csv, --contacts, --error-vs-reference, --plots,
// --frames) creates the directories its path needs, as `mkdir -p` does, once the scene has been
// read and before the run starts; a directory that cannot be created is one error line and exit 1.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <system_error>

#include "failures.h"

namespace i2d {

/// Creates `directory` and every missing directory above it; throws RunFailure naming the
/// option and the path when that is impossible (a file is in the way, no permission).
inline void createOutputDirectory(const std::optional<std::string>& directory,
                                  const std::string& option) {
  if (!directory || directory->empty()) return;
  std::error_code error;
  std::filesystem::create_directories(*directory, error);
  if (error || !std::filesystem::is_directory(*directory)) {
    const std::string reason = error ? error.message() : "a file of that name is in the way";
    throw RunFailure("cannot create directory '" + *directory + "' for " + option + ": " + reason);
  }
}

/// The directory a file option such as --csv FILE writes into.
inline std::optional<std::string> directoryOf(const std::optional<std::string>& file) {
  if (!file) return std::nullopt;
  return std::filesystem::path(*file).parent_path().string();
}

}  // namespace i2d
