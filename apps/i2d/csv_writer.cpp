// Atomic CSV writing: the temporary file, the rows, the rename.
#include "csv_writer.h"

#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>

#include "failures.h"

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

CsvWriter::CsvWriter(const std::string& path) : path_(path), temporaryPath_(path + ".tmp") {
  out_.open(temporaryPath_, std::ios::binary | std::ios::trunc);
  if (!out_) {
    throw RunFailure("cannot write " + temporaryPath_ + ": " + std::strerror(errno));
  }
  out_ << kHeader << '\n';
  throwIfWriteFailed();
}

CsvWriter::~CsvWriter() {
  if (committed_) return;
  out_.close();
  std::remove(temporaryPath_.c_str());
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
    out_ << line << '\n';
    ++rowCount_;
  }
  throwIfWriteFailed();
}

void CsvWriter::commit() {
  out_.close();
  throwIfWriteFailed();
  if (std::rename(temporaryPath_.c_str(), path_.c_str()) != 0) {
    throw RunFailure("cannot write " + path_ + ": " + std::strerror(errno));
  }
  committed_ = true;
}

void CsvWriter::throwIfWriteFailed() {
  if (out_.fail()) throw RunFailure("cannot write " + temporaryPath_ + ": " + std::strerror(errno));
}

}  // namespace i2d
