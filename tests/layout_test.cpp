// The architecture, checked: the physics core (the sources of the `impulse2d` target in
// lib/CMakeLists.txt, and every project header they reach) never includes rendering, scene files
// or Box2D, no solver file includes another solver (solvers share contact_math.h and the other
// shared modules instead), and neither the world nor the solver interface names a method
// (Solver2D's shape).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

const fs::path kLib = fs::path(IMPULSE2D_SOURCE_DIR) / "lib";

std::string readText(const fs::path& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// The sources listed in add_library(impulse2d ...) of lib/CMakeLists.txt.
std::vector<fs::path> coreSources() {
  const std::string cmake = readText(kLib / "CMakeLists.txt");
  const std::smatch found = [&] {
    std::smatch match;
    std::regex_search(cmake, match, std::regex(R"(add_library\(impulse2d\s([^)]*)\))"));
    return match;
  }();
  std::vector<fs::path> sources;
  std::istringstream words(found[1].str());
  for (std::string word; words >> word;) sources.push_back(kLib / word);
  return sources;
}

/// Every #include "..." or <...> of a file.
std::vector<std::string> includesOf(const fs::path& file) {
  const std::string text = readText(file);
  const std::regex include(R"(#include\s*[<"]([^>"]+)[>"])");
  std::vector<std::string> names;
  for (std::sregex_iterator it(text.begin(), text.end(), include), end; it != end; ++it) {
    names.push_back((*it)[1].str());
  }
  return names;
}

/// The core's files and every include they reach through project headers.
std::set<std::string> coreIncludesReached(std::set<fs::path>& visited) {
  std::vector<fs::path> pending = coreSources();
  std::set<std::string> reached;
  while (!pending.empty()) {
    const fs::path file = pending.back();
    pending.pop_back();
    if (!visited.insert(file).second) continue;
    for (const std::string& name : includesOf(file)) {
      reached.insert(name);
      const fs::path header = kLib / "include" / name;
      if (name.rfind("impulse2d/", 0) == 0 && fs::exists(header)) pending.push_back(header);
    }
  }
  return reached;
}

std::string lowered(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return text;
}

bool startsWith(const std::string& text, const std::string& prefix) {
  return text.rfind(prefix, 0) == 0;
}

}  // namespace

TEST_CASE("the core lists its sources and they exist", "[layout]") {
  const std::vector<fs::path> sources = coreSources();
  REQUIRE(sources.size() >= 10);
  for (const fs::path& source : sources) CHECK(fs::exists(source));
}

TEST_CASE("the core never includes rendering, scene files or Box2D", "[layout]") {
  std::set<fs::path> visited;
  const std::set<std::string> reached = coreIncludesReached(visited);
  REQUIRE(reached.count("impulse2d/solvers/contact_math.h") == 1);  // the walk does reach deep
  for (const std::string& name : reached) {
    INFO(name);
    CHECK_FALSE(startsWith(name, "impulse2d/render/"));
    CHECK_FALSE(startsWith(name, "impulse2d/box2d/"));
    CHECK_FALSE(startsWith(name, "box2d/"));
    CHECK_FALSE(startsWith(name, "toml++/"));
    CHECK_FALSE(startsWith(name, "stb"));
    CHECK(name != "impulse2d/scene/scene_file.h");
  }
}

TEST_CASE("no solver file includes another solver", "[layout]") {
  const std::set<std::string> solvers = {"micro_collision", "sequential_impulses",
                                         "reference_solver", "soft_step"};
  for (const auto& entry : fs::directory_iterator(kLib / "src" / "solvers")) {
    // A method's named parts (micro_collision_pairs.cpp) are that method's own.
    const std::string stem = entry.path().stem().string();
    std::string own = stem;
    for (const std::string& solver : solvers) {
      if (startsWith(stem, solver + "_")) own = solver;
    }
    for (const std::string& name : includesOf(entry.path())) {
      const std::string included = fs::path(name).stem().string();
      INFO(entry.path().filename().string() << " includes " << name);
      if (included != own) CHECK(solvers.count(included) == 0);
    }
  }
}

TEST_CASE("neither the world nor the solver interface names a method", "[layout]") {
  const std::vector<std::string> methodWords = {"softstep", "soft_step", "soft step", "recycl",
                                                "integratesbodies"};
  const std::vector<fs::path> files = {kLib / "include" / "impulse2d" / "solver.h",
                                       kLib / "include" / "impulse2d" / "world.h",
                                       kLib / "src" / "world.cpp"};
  for (const fs::path& file : files) {
    // Comments joined across their line breaks: "soft\n  /// step" names the method too.
    const std::string text =
        std::regex_replace(lowered(readText(file)), std::regex(R"(\s*\n\s*(///?)?\s*)"), " ");
    REQUIRE(!text.empty());
    for (const std::string& word : methodWords) {
      INFO(file.filename().string() << " mentions " << word);
      CHECK(text.find(word) == std::string::npos);
    }
  }
  // The world has its own speculative-contacts setting; the interface asks only neutral questions.
  const std::string interface = lowered(readText(kLib / "include" / "impulse2d" / "solver.h"));
  CHECK(interface.find("speculative") == std::string::npos);
}

TEST_CASE("a contact point holds no one method's state", "[layout]") {
  // What one method keeps per point lives in its own PointMemory (solvers/point_memory.h);
  // ContactPoint keeps the geometry and the impulses every method reports.
  const std::string contact = lowered(readText(kLib / "include" / "impulse2d" / "contact.h"));
  REQUIRE(contact.find("struct contactpoint") != std::string::npos);
  for (const char* word : {"micro", "soft step", "soft_step", "sequential", "reference's",
                           "substep", "bounce", "exact"}) {
    INFO("contact.h mentions " << word);
    CHECK(contact.find(word) == std::string::npos);
  }
}

namespace {

/// A function definition in a source file: its first line and its length in lines, from the first
/// line of its signature to its closing brace. Definitions start at column 0 and end at the next
/// "}" in column 0, as .clang-format writes them.
struct Definition {
  int line = 0;
  int length = 0;
};

/// Whether a statement starting in column 0 (its lines joined up to its first "{" or ";") opens a
/// function: it has a parameter list before any "=", and is not a type or namespace.
bool opensFunction(const std::string& statement) {
  static const std::regex notFunction(R"(^(namespace|struct|class|enum|union|extern|template)\b)");
  const size_t parameters = statement.find('(');
  return statement.back() == '{' && parameters != std::string::npos &&
         statement.find('=') > parameters && !std::regex_search(statement, notFunction);
}

std::vector<Definition> definitionsIn(const fs::path& file) {
  std::istringstream text(readText(file));
  std::vector<std::string> lines;
  for (std::string line; std::getline(text, line);) lines.push_back(line);
  std::vector<Definition> found;
  for (int first = 0; first < int(lines.size()); ++first) {
    if (lines[first].empty() || !(std::isalpha(lines[first][0]) || lines[first][0] == '_')) {
      continue;
    }
    std::string statement;
    int last = first;
    for (; last < int(lines.size()); ++last) {
      statement += lines[last];
      if (statement.back() == '{' || statement.back() == ';') break;
    }
    if (last == int(lines.size()) || !opensFunction(statement)) continue;
    int end = last;
    while (end < int(lines.size()) && !startsWith(lines[end], "}")) ++end;
    found.push_back({first + 1, end - first + 1});
    first = end;
  }
  return found;
}

}  // namespace

TEST_CASE("no function in the solvers is longer than 40 lines", "[layout]") {
  constexpr int kLongest = 40;
  int definitions = 0;
  for (const auto& entry : fs::directory_iterator(kLib / "src" / "solvers")) {
    for (const Definition& definition : definitionsIn(entry.path())) {
      ++definitions;
      INFO(entry.path().filename().string()
           << ":" << definition.line << " is " << definition.length << " lines long");
      CHECK(definition.length <= kLongest);
    }
  }
  CHECK(definitions > 150);  // the scan does find the solvers' functions
}

TEST_CASE("the solvers index with int, one style throughout", "[layout]") {
  // Indices are int and subscript containers directly; a size is read as static_cast<int>.
  const std::regex sizeCast(R"(static_cast<size_t>|static_cast<std::size_t>|[^\w:]size_t\()");
  int files = 0;
  for (const fs::path& folder :
       {kLib / "src" / "solvers", kLib / "include" / "impulse2d" / "solvers"}) {
    for (const auto& entry : fs::directory_iterator(folder)) {
      ++files;
      INFO(entry.path().filename().string() << " casts an index to size_t");
      const std::string text = readText(entry.path());
      CHECK_FALSE(std::regex_search(text, sizeCast));
    }
  }
  CHECK(files > 20);
}
