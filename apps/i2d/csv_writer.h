// The trajectory CSV of `i2d run`, written atomically: rows go to FILE.tmp, which becomes FILE
// only when commit() succeeds, so a failed run never leaves a half-written FILE behind.
#pragma once

#include <fstream>
#include <string>
#include <vector>

#include "impulse2d/body.h"

namespace i2d {

class CsvWriter {
 public:
  /// The header every trajectory file starts with.
  static constexpr const char* kHeader = "step,t,body,x,y,angle_rad,vx,vy,omega_rad_s";

  /// Opens FILE.tmp and writes the header; throws RunFailure when it cannot.
  explicit CsvWriter(const std::string& path);
  /// Removes FILE.tmp unless commit() renamed it.
  ~CsvWriter();
  CsvWriter(const CsvWriter&) = delete;
  CsvWriter& operator=(const CsvWriter&) = delete;

  /// One row per dynamic body: its centre of mass, angle and velocities at time t.
  void writeStep(long step, double time, const std::vector<impulse2d::Body>& bodies);
  /// Closes FILE.tmp and renames it to FILE; throws RunFailure on any write error.
  void commit();

  const std::string& path() const { return path_; }
  long rowCount() const { return rowCount_; }

 private:
  void throwIfWriteFailed();

  std::string path_;
  std::string temporaryPath_;
  std::ofstream out_;
  long rowCount_ = 0;
  bool committed_ = false;
};

}  // namespace i2d
