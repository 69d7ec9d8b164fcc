// The OUTDIR check (output_directory.h).
#include "output_directory.h"

#include <filesystem>
#include <system_error>

namespace benchmarks {

std::string outputDirectoryProblem(const std::string& directory) {
  if (directory.empty() || directory[0] == '-') {
    return "'" + directory + "' is not a directory name (options come before OUTDIR)";
  }
  std::error_code error;
  if (!std::filesystem::is_directory(directory, error)) {
    return "'" + directory + "' is not an existing directory";
  }
  return "";
}

}  // namespace benchmarks
