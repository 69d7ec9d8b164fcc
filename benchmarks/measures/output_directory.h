// The OUTDIR argument of the benchmark programs that write files, checked before a run of minutes
// starts: an option where a directory belongs (`sweep --help`) or a directory that does not
// exist is reported at once, not after the run.
#pragma once

#include <string>

namespace benchmarks {

/// Empty when `directory` is an existing directory; otherwise what is wrong with it.
std::string outputDirectoryProblem(const std::string& directory);

}  // namespace benchmarks
