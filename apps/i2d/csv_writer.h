// The CSVs of `i2d run`, the trajectory (--csv) and the contact forces (--contacts), written
// through an OutputFile: rows go to FILE.tmp, which becomes FILE only when commit() succeeds, so
// a failed run never leaves a half-written FILE behind.
#pragma once

#include <string>
#include <vector>

#include "impulse2d/body.h"
#include "impulse2d/contact.h"
#include "output_file.h"

namespace i2d {

class CsvWriter {
 public:
  /// The header every trajectory file starts with.
  static constexpr const char* kHeader = "step,t,body,x,y,angle_rad,vx,vy,omega_rad_s";

  /// The header of the contact-force file: per step and contact point the bodies, the point and
  /// normal, the step's impulses and the forces they stand for (impulse / dt), the friction
  /// limit μN, whether the point held (static) or slid, and each body's applied load.
  static constexpr const char* kContactsHeader =
      "step,t,body_a,body_b,point,x,y,nx,ny,normal_impulse_Ns,friction_impulse_Ns,normal_force_N,"
      "friction_force_N,mu,friction_limit_N,friction,load_a_x_N,load_a_y_N,load_b_x_N,load_b_y_N";

  /// Opens the file (OutputFile) and writes the header; throws RunFailure when it cannot.
  explicit CsvWriter(const std::string& path, const std::string& header = kHeader);

  /// One row per dynamic body: its centre of mass, angle and velocities at time t.
  void writeStep(long step, double time, const std::vector<impulse2d::Body>& bodies);
  /// One row per contact point (kContactsHeader) at time t; the impulses acted over `impulseTime`
  /// (the step, or its last substep), under the loads of that (sub)step's start.
  void writeContacts(long step, double time, double impulseTime,
                     const std::vector<impulse2d::Body>& bodies,
                     const std::vector<impulse2d::Manifold>& manifolds);
  /// Closes the file and renames FILE.tmp to FILE; throws RunFailure on any write error.
  void commit() { file_.commit(); }

  const std::string& path() const { return path_; }
  long rowCount() const { return rowCount_; }

 private:
  std::string path_;
  OutputFile file_;
  long rowCount_ = 0;
};

}  // namespace i2d
