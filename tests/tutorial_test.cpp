// docs/tutorial.md cannot rot: every sh block of the page runs, in order, in one fresh directory
// that looks like the repository root (build/ and demos/ link to the real ones), and must exit 0;
// every output block shown beneath one must appear in what it printed, and every file path in
// those lines must exist. The scenes and scripts the page writes are saved from the page itself.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "doc_blocks.h"
#include "i2d_process.h"

namespace {

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> result;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) result.push_back(line);
  return result;
}

/// The pieces of an expected line between its "…" marks.
std::vector<std::string> piecesOf(const std::string& pattern) {
  static const std::string kAnything = "…";
  std::vector<std::string> pieces;
  size_t start = 0;
  for (size_t at; (at = pattern.find(kAnything, start)) != std::string::npos;) {
    pieces.push_back(pattern.substr(start, at - start));
    start = at + kAnything.size();
  }
  pieces.push_back(pattern.substr(start));
  return pieces;
}

/// `line` matches `pattern` when the pattern's pieces appear in it in order, the first at its
/// start: "…" stands for any text.
bool matches(const std::string& line, const std::string& pattern) {
  size_t at = 0;
  const std::vector<std::string> pieces = piecesOf(pattern);
  for (size_t i = 0; i < pieces.size(); ++i) {
    const size_t found = line.find(pieces[i], at);
    if (found == std::string::npos || (i == 0 && found != 0)) return false;
    at = found + pieces[i].size();
  }
  return true;
}

/// Checks each line of `expected` (except a lone "…") against the output, in order, and that
/// every path in it (a word with a '/' and a '.') exists in `directory`.
void checkOutput(const std::string& output, const std::string& expected,
                 const std::filesystem::path& directory) {
  const std::vector<std::string> printed = lines(output);
  size_t next = 0;
  for (const std::string& pattern : lines(expected)) {
    if (pattern == "…" || pattern.empty()) continue;
    while (next < printed.size() && !matches(printed[next], pattern)) ++next;
    INFO("expected line: " << pattern << "\nprinted:\n" << output);
    REQUIRE(next < printed.size());
    ++next;
    std::istringstream words(pattern);
    for (std::string word; words >> word;) {
      if (word.find('/') == std::string::npos || word.find('.') == std::string::npos) continue;
      INFO("file " << word);
      CHECK(std::filesystem::exists(directory / word));
    }
  }
}

}  // namespace

TEST_CASE("every command of the tutorial runs and prints what the page shows", "[docs][tutorial]") {
  namespace fs = std::filesystem;
  const i2d_process::Scratch scratch;
  fs::create_directory_symlink(IMPULSE2D_BINARY_DIR, scratch.path / "build");
  fs::create_directory_symlink(IMPULSE2D_SOURCE_DIR "/demos", scratch.path / "demos");
  int commandsRun = 0;
  int outputsChecked = 0;
  std::string lastOutput;
  for (const doc_blocks::Block& block : doc_blocks::readBlocks("docs/tutorial.md")) {
    INFO("docs/tutorial.md:" << block.line);
    if (block.language == "sh") {
      i2d_process::writeFile(scratch / "block.sh", block.text);
      const std::string command =
          "cd " + scratch.path.string() + " && sh -e block.sh >output.txt 2>&1";
      const int status = std::system(command.c_str());
      lastOutput = i2d_process::readFile(scratch / "output.txt");
      INFO(block.text << lastOutput);
      REQUIRE(WIFEXITED(status));
      REQUIRE(WEXITSTATUS(status) == 0);
      ++commandsRun;
    } else if (block.language == "text" && block.name == "output") {
      checkOutput(lastOutput, block.text, scratch.path);
      ++outputsChecked;
    } else if (!block.name.empty()) {
      i2d_process::writeFile(scratch / block.name, block.text);
    }
  }
  // The page's six sections run at least this many; fewer means the blocks were not found.
  CHECK(commandsRun >= 8);
  CHECK(outputsChecked == commandsRun);
  // The tutorial writes its frames to a directory of its own: the demos' frames/ and their front
  // page stay as scripts/demos made them.
  CHECK_FALSE(fs::exists(scratch.path / "frames"));
}
