// The worst-first queue of the micro-collision resolver: after any sequence of key changes, the
// item it names is one with the largest key, as a scan of every key would find, and it is empty
// exactly when no key is above the threshold.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "impulse2d/solvers/worst_first_queue.h"

using namespace impulse2d;

TEST_CASE("the worst-first queue names the largest key after every change", "[micro][queue]") {
  std::mt19937 random(13);  // fixed seed: the same sequence every run
  std::uniform_real_distribution<double> key(-1.0, 1.0);
  std::uniform_int_distribution<int> item(0, 99);
  std::vector<double> keys(100);
  for (double& k : keys) k = key(random);
  const double threshold = -2.0;  // below every key: every item waits
  WorstFirstQueue queue;
  queue.reset(keys, threshold);
  CHECK(queue.worstKey() == *std::max_element(keys.begin(), keys.end()));
  int mismatches = 0;
  for (int change = 0; change < 10000; ++change) {
    const int changed = item(random);
    keys[changed] = key(random);
    queue.update(changed, keys[changed]);
    const double largest = *std::max_element(keys.begin(), keys.end());
    if (queue.worstKey() != largest || keys[queue.worst()] != largest) ++mismatches;
  }
  CHECK(mismatches == 0);
}

TEST_CASE("only the items above the threshold wait in the worst-first queue", "[micro][queue]") {
  std::mt19937 random(17);
  std::uniform_real_distribution<double> key(-1.0, 1.0);
  std::uniform_int_distribution<int> item(0, 11);
  std::vector<double> keys(12);
  for (double& k : keys) k = key(random);
  const double threshold = 0.8;  // a tenth of the keys wait; often none
  WorstFirstQueue queue;
  queue.reset(keys, threshold);
  int mismatches = 0;
  int emptyStates = 0;
  for (int change = 0; change < 20000; ++change) {
    const int changed = item(random);
    keys[changed] = key(random);
    queue.update(changed, keys[changed]);
    const double largest = *std::max_element(keys.begin(), keys.end());
    const int waiting =
        int(std::count_if(keys.begin(), keys.end(), [&](double k) { return k > threshold; }));
    if (queue.size() != waiting) ++mismatches;
    if (largest <= threshold) {
      if (!queue.empty()) ++mismatches;
      ++emptyStates;
    } else if (queue.empty() || queue.worstKey() != largest || keys[queue.worst()] != largest) {
      ++mismatches;
    }
  }
  CHECK(mismatches == 0);
  CHECK(emptyStates > 0);  // the sequence did pass through "nothing left to resolve"
}

TEST_CASE("the worst-first queue keeps the total of the waiting keys", "[micro][queue]") {
  // The resolver's progress measure (passCapWhileProgressing): kept as keys join, change and
  // leave, it must match a sum over the waiting keys; 20,000 changes of keys of order 1 each
  // leave a round-off of a few 1e-16 per change at most.
  std::mt19937 random(19);
  std::uniform_real_distribution<double> key(-1.0, 1.0);
  std::uniform_int_distribution<int> item(0, 49);
  std::vector<double> keys(50);
  for (double& k : keys) k = key(random);
  const double threshold = 0.2;
  WorstFirstQueue queue;
  queue.reset(keys, threshold);
  double largestError = 0.0;
  for (int change = 0; change < 20000; ++change) {
    const int changed = item(random);
    keys[changed] = key(random);
    queue.update(changed, keys[changed]);
    double waitingTotal = 0.0;
    for (double k : keys) waitingTotal += k > threshold ? k : 0.0;
    largestError = std::max(largestError, std::abs(queue.waitingTotal() - waitingTotal));
  }
  CHECK(largestError < 1e-11);
}

TEST_CASE("an empty worst-first queue says so", "[micro][queue]") {
  WorstFirstQueue queue;
  queue.reset({}, 0.0);
  CHECK(queue.empty());
  queue.reset({0.5}, 0.0);
  CHECK_FALSE(queue.empty());
  CHECK(queue.worst() == 0);
  queue.update(0, -0.5);
  CHECK(queue.empty());
}
