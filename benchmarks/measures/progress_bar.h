// A one-line progress bar on stderr for long benchmark runs: done/total, the elapsed time and what
// runs now, redrawn in place.
#pragma once

#include <chrono>
#include <cstddef>
#include <string>

namespace benchmarks {

class ProgressBar {
 public:
  explicit ProgressBar(std::size_t total);
  ~ProgressBar();

  /// Redraws the bar with what runs now.
  void show(const std::string& current);
  /// One more item done.
  void advance() { ++done_; }

 private:
  std::size_t total_;
  std::size_t done_ = 0;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace benchmarks
