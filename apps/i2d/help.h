// What `i2d --help` and `i2d COMMAND --help` print: CLI11 makes them from the declarations in
// options.cpp, laid out by HelpFormatter; the footers say what no option declares.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

namespace i2d {

/// The help's layout: the usage line, the command's description, each group of options with its
/// descriptions wrapped at kHelpWidth, then the footer. Each option's line adds the values it
/// takes (from its validators), what it needs, what it excludes, and whether it is required.
class HelpFormatter : public CLI::Formatter {
 public:
  std::string make_help(const CLI::App* app, std::string name,
                        CLI::AppFormatMode mode) const override;
  std::string make_group(std::string group, bool positional,
                         std::vector<const CLI::Option*> options) const override;
  std::string make_usage(const CLI::App* app, std::string name) const override;
  std::string make_option(const CLI::Option* option, bool positional) const override;
  std::string make_subcommand(const CLI::App* command) const override;
};

/// The general help's footer: scenes, solvers and their presets, examples, exit codes.
std::string generalFooter();

extern const char* const kRunFooter;
extern const char* const kCompareFooter;
extern const char* const kAgreeFooter;
extern const char* const kCheckFooter;
extern const char* const kPresetsFooter;

}  // namespace i2d
