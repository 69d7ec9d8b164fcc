// The progress bar (progress_bar.h).
#include "progress_bar.h"

#include <cstdio>

namespace benchmarks {

namespace {

constexpr int kBarWidth = 30;

}  // namespace

ProgressBar::ProgressBar(std::size_t total)
    : total_(total), start_(std::chrono::steady_clock::now()) {}

ProgressBar::~ProgressBar() {
  std::fprintf(stderr, "\n");
}

void ProgressBar::show(const std::string& current) {
  const int filled = total_ > 0 ? static_cast<int>(kBarWidth * done_ / total_) : kBarWidth;
  const long seconds = static_cast<long>(
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count());
  std::fprintf(stderr, "\r[%s%s] %zu/%zu %ldm%02lds  %-50.50s", std::string(filled, '#').c_str(),
               std::string(kBarWidth - filled, '.').c_str(), done_, total_, seconds / 60,
               seconds % 60, current.c_str());
  std::fflush(stderr);
}

}  // namespace benchmarks
