// CSV writing: the header and the rows of the trajectory and of the contact forces.
#include "csv_writer.h"

#include <algorithm>
#include <charconv>

namespace i2d {
namespace {

/// The shortest text that reads back as exactly this double.
void appendNumber(std::string& line, double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  line.append(buffer, result.ptr);
}

/// A CSV field: quoted, with quotes doubled, when it holds a comma, quote or line break.
std::string csvField(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

}  // namespace

CsvWriter::CsvWriter(const std::string& path, const std::string& header)
    : path_(path), file_(path) {
  file_.stream() << header << '\n';
  file_.throwIfWriteFailed();
}

void CsvWriter::writeStep(long step, double time, const std::vector<impulse2d::Body>& bodies) {
  std::string line;
  for (const impulse2d::Body& body : bodies) {
    if (body.isStatic()) continue;
    line = std::to_string(step) + ',';
    appendNumber(line, time);
    line += ',' + csvField(body.name);
    for (double value : {body.position.x(), body.position.y(), body.angle, body.velocity.x(),
                         body.velocity.y(), body.angularVelocity}) {
      line += ',';
      appendNumber(line, value);
    }
    file_.stream() << line << '\n';
    ++rowCount_;
  }
  file_.throwIfWriteFailed();
}

void CsvWriter::writeContacts(long step, double time, double impulseTime,
                              const std::vector<impulse2d::Body>& bodies,
                              const std::vector<impulse2d::Manifold>& manifolds) {
  for (const impulse2d::Manifold& manifold : manifolds) {
    const impulse2d::Body& a = bodies[std::size_t(manifold.bodyA)];
    const impulse2d::Body& b = bodies[std::size_t(manifold.bodyB)];
    for (int i = 0; i < manifold.pointCount; ++i) {
      const impulse2d::ContactPoint& point = manifold.points[i];
      std::string line = std::to_string(step) + ',';
      appendNumber(line, time);
      line += ',' + csvField(a.name) + ',' + csvField(b.name) + ',' + std::to_string(i);
      const double normalForce = point.normalImpulse / impulseTime;
      // The loads as they acted while these impulses were applied: from the (sub)step's start.
      const double loadTime = std::max(0.0, time - impulseTime);
      const impulse2d::Vec2 loadA =
          a.isStatic() ? impulse2d::Vec2::Zero() : a.load.forceAt(loadTime);
      const impulse2d::Vec2 loadB =
          b.isStatic() ? impulse2d::Vec2::Zero() : b.load.forceAt(loadTime);
      for (double value : {point.point.x(), point.point.y(), manifold.normal.x(),
                           manifold.normal.y(), point.normalImpulse, point.tangentImpulse,
                           normalForce, point.tangentImpulse / impulseTime, manifold.friction,
                           manifold.friction * normalForce}) {
        line += ',';
        appendNumber(line, value);
      }
      line += point.friction == impulse2d::FrictionState::Dynamic  ? ",sliding"
              : point.friction == impulse2d::FrictionState::Static ? ",static"
                                                                   : ",none";
      for (double value : {loadA.x(), loadA.y(), loadB.x(), loadB.y()}) {
        line += ',';
        appendNumber(line, value);
      }
      file_.stream() << line << '\n';
      ++rowCount_;
    }
  }
  file_.throwIfWriteFailed();
}

}  // namespace i2d
