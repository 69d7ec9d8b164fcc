// The fenced blocks of a page in docs/, so tests can run what a page shows rather than a copy of
// it: a block's info string is its language and, optionally, a file name ("toml ramp.toml").
#pragma once

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace doc_blocks {

struct Block {
  std::string language;  ///< the info string's first word: sh, toml, text, ...
  std::string name;      ///< its second word, if any: the file a toml block is saved as
  std::string text;      ///< the lines between the fences, each ending in '\n'
  int line = 0;          ///< the line of the opening fence, from 1
};

/// Every ``` fenced block of the page at `path` (relative to the source directory), in order.
inline std::vector<Block> readBlocks(const std::string& path) {
  std::ifstream in(IMPULSE2D_SOURCE_DIR "/" + path);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::vector<Block> blocks;
  std::string line;
  bool inside = false;
  for (int number = 1; std::getline(in, line); ++number) {
    if (line.rfind("```", 0) == 0) {
      if (inside) {
        inside = false;
        continue;
      }
      inside = true;
      Block block;
      block.line = number;
      std::istringstream info(line.substr(3));
      info >> block.language >> block.name;
      blocks.push_back(block);
    } else if (inside) {
      blocks.back().text += line + "\n";
    }
  }
  return blocks;
}

/// The text of the block saved as `name`; throws if the page has none, so a renamed scene fails
/// its test instead of silently testing nothing.
inline std::string namedBlock(const std::vector<Block>& blocks, const std::string& name) {
  for (const Block& block : blocks) {
    if (block.name == name) return block.text;
  }
  throw std::runtime_error("no block named " + name);
}

}  // namespace doc_blocks
