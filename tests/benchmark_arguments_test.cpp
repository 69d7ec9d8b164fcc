// The benchmark programs that write files check their OUTDIR before a run of minutes starts: an
// option where the directory belongs, or a directory that does not exist, is one error line and
// exit code 2 at once (before, `sweep --help` ran the whole ten-minute sweep, then aborted on an
// uncaught exception while writing "--help/sweep.csv").
#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

namespace {

struct Outcome {
  int exitCode = -1;
  std::string err;
};

Outcome runBenchmark(const std::string& program, const std::string& arguments) {
  // One file per process: ctest runs the test cases side by side.
  const std::string err =
      IMPULSE2D_BINARY_DIR "/benchmark_arguments_test." + std::to_string(getpid()) + ".err";
  const std::string command =
      IMPULSE2D_BINARY_DIR "/benchmarks/" + program + " " + arguments + " >/dev/null 2>" + err;
  const int status = std::system(command.c_str());
  std::ifstream in(err);
  std::ostringstream text;
  text << in.rdbuf();
  std::remove(err.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, text.str()};
}

}  // namespace

TEST_CASE("a benchmark refuses an option where its output directory belongs", "[benchmarks]") {
  for (const std::string program : {"sweep", "error_vs_iterations"}) {
    const Outcome outcome = runBenchmark(program, "--help");
    INFO(program << ": " << outcome.err);
    CHECK(outcome.exitCode == 2);
    CHECK(outcome.err.find("'--help' is not a directory name") != std::string::npos);
  }
}

TEST_CASE("a benchmark refuses an output directory that does not exist", "[benchmarks]") {
  const Outcome outcome = runBenchmark("sweep", "--quick /nonexistent/charts");
  INFO(outcome.err);
  CHECK(outcome.exitCode == 2);
  CHECK(outcome.err.find("'/nonexistent/charts' is not an existing directory") !=
        std::string::npos);
}

TEST_CASE("the sweep refuses a method or a panel it does not have, naming it", "[benchmarks]") {
  const Outcome method = runBenchmark("sweep", "--methods micro,bullet /tmp");
  INFO(method.err);
  CHECK(method.exitCode == 2);
  CHECK(method.err.find("--methods: unknown 'bullet'") != std::string::npos);
  const Outcome scene = runBenchmark("sweep", "--scenes rain,stack /tmp");
  INFO(scene.err);
  CHECK(scene.exitCode == 2);
  CHECK(scene.err.find("--scenes: unknown 'stack' (choose from stack20, pyramid20, pyramid40, "
                       "rain)") != std::string::npos);
  const Outcome missing = runBenchmark("sweep", "--methods /tmp");
  INFO(missing.err);
  CHECK(missing.exitCode == 2);
  CHECK(missing.err.find("--methods needs a comma-separated list before OUTDIR") !=
        std::string::npos);
}
