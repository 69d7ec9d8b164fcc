// Parsing the options of `i2d run` and `i2d check`.
#include "options.h"

#include <charconv>
#include <cmath>
#include <functional>
#include <map>
#include <utility>

#include "failures.h"

namespace i2d {
namespace {

/// An argument list read front to back; options find their value in "--name=value" or next.
class Arguments {
 public:
  explicit Arguments(const std::vector<std::string>& arguments) : arguments_(arguments) {}

  bool done() const { return next_ == arguments_.size(); }
  /// The next argument; for "--name=value" just "--name", keeping the value for value().
  std::string take() {
    const std::string& argument = arguments_[next_++];
    const size_t equals = argument.find('=');
    if (argument.rfind("--", 0) != 0 || equals == std::string::npos) return argument;
    inlineValue_ = argument.substr(equals + 1);
    return argument.substr(0, equals);
  }
  /// The value of the option just taken.
  std::string value(const std::string& option) {
    std::string value;
    if (inlineValue_) {
      value = std::exchange(inlineValue_, std::nullopt).value();
    } else if (!done()) {
      value = arguments_[next_++];
    }
    if (value.empty()) throw UsageError("option " + option + " needs a value");
    return value;
  }

 private:
  const std::vector<std::string>& arguments_;
  size_t next_ = 0;
  std::optional<std::string> inlineValue_;
};

int parseInteger(const std::string& text, const std::string& option, int minimum) {
  int value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || value < minimum) {
    throw UsageError("option " + option + " needs an integer >= " + std::to_string(minimum) +
                     ", not '" + text + "'");
  }
  return value;
}

double parsePositive(const std::string& text, const std::string& option) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value) ||
      value <= 0.0) {
    throw UsageError("option " + option + " needs a finite number > 0, not '" + text + "'");
  }
  return value;
}

using OptionHandler = std::function<void(const std::string& value)>;

/// Reads options by their handlers and the one positional argument, the scene.
void parse(const std::vector<std::string>& arguments, const std::string& command,
           const std::map<std::string, OptionHandler>& handlers, std::string& scenePath) {
  Arguments reader(arguments);
  while (!reader.done()) {
    const std::string argument = reader.take();
    if (argument.size() > 1 && argument[0] == '-') {
      const auto handler = handlers.find(argument);
      if (handler == handlers.end()) {
        throw UsageError("unknown option '" + argument + "' for i2d " + command + " (see i2d " +
                         command + " --help)");
      }
      handler->second(reader.value(argument));
    } else if (scenePath.empty()) {
      scenePath = argument;
    } else {
      throw UsageError("unexpected argument '" + argument + "': i2d " + command +
                       " takes one SCENE");
    }
  }
  if (scenePath.empty()) throw UsageError("i2d " + command + " needs a SCENE file");
}

}  // namespace

RunOptions parseRunOptions(const std::vector<std::string>& arguments) {
  RunOptions options;
  const std::map<std::string, OptionHandler> handlers = {
      {"--solver", [&](const std::string& value) { options.solver = value; }},
      {"--steps",
       [&](const std::string& value) { options.steps = parseInteger(value, "--steps", 0); }},
      {"--dt", [&](const std::string& value) { options.dt = parsePositive(value, "--dt"); }},
      {"--set", [&](const std::string& value) { options.settings.push_back(value); }},
      {"--csv", [&](const std::string& value) { options.csvPath = value; }},
      {"--every",
       [&](const std::string& value) { options.every = parseInteger(value, "--every", 1); }},
      {"--frames", [&](const std::string& value) { options.framesDirectory = value; }},
  };
  parse(arguments, "run", handlers, options.scenePath);
  return options;
}

CheckOptions parseCheckOptions(const std::vector<std::string>& arguments) {
  CheckOptions options;
  parse(arguments, "check", {}, options.scenePath);
  return options;
}

}  // namespace i2d
