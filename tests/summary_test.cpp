// What `i2d run`'s summary says about the run's end, checked against the run's own CSV.
#include <catch2/catch.hpp>

#include <sstream>
#include <string>

#include "i2d_process.h"

using namespace i2d_process;

TEST_CASE("the summary's penetration is that of the run's last state", "[outputs][penetration]") {
  // A 1 m box set 5 cm into the ground; sequential impulses push it out over several steps. After
  // one step the summary's penetration is the box's depth in the CSV's last row, 0.5 m − y, not
  // the 5 cm its contact had when the step began.
  const Scratch scratch;
  writeFile(scratch / "deep.toml", R"([world]
solver = "sequential"

[[body]]
name = "ground"
type = "static"
shape = "box"
size = [10.0, 1.0]
position = [0.0, -0.5]

[[body]]
name = "box"
shape = "box"
size = [1.0, 1.0]
position = [0.0, 0.45]
)");
  const Outcome run =
      i2d("run " + (scratch / "deep.toml") + " --steps 1 --csv " + (scratch / "deep.csv"), scratch);
  REQUIRE(run.exitCode == 0);
  double penetration = -1.0;
  const auto at = run.out.find("penetration ");
  REQUIRE(at != std::string::npos);
  CHECK(run.out.find(" m in the last state", at) != std::string::npos);
  penetration = std::stod(run.out.substr(at + std::string("penetration ").size()));
  const std::string rows = readFile(scratch / "deep.csv");
  const std::string last = rows.substr(rows.rfind('\n', rows.size() - 2) + 1);
  std::istringstream fields(last);
  std::string field;
  for (int i = 0; i < 5; ++i) std::getline(fields, field, ',');  // step, t, body, x, y
  const double depth = 0.5 - std::stod(field);
  REQUIRE(depth > 0.001);  // still in: the case where the start-of-step contacts lag
  CHECK(depth < 0.045);
  // The summary prints 6 significant digits.
  CHECK(penetration == Approx(depth).epsilon(1e-5));
}
