// Output files: a temporary file renamed into place, or a device written in place.
#include "output_file.h"

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <system_error>

#include "failures.h"

namespace i2d {
namespace {

namespace fs = std::filesystem;

/// The file PATH ends in: when PATH is a symbolic link to an existing file, that file.
std::string followLinks(const std::string& path) {
  std::error_code error;
  if (!fs::is_symlink(path, error)) return path;
  const fs::path resolved = fs::canonical(path, error);
  return error ? path : resolved.string();
}

/// True for a device, a pipe or a socket, which a rename would replace rather than update, and
/// for any name under /dev or a process's open file under /proc (/dev/fd/3 redirected to a
/// file), which a rename would take away from the process writing to it.
bool writesInPlace(const std::string& path, const std::string& target) {
  if (path.rfind("/dev/", 0) == 0 || target.rfind("/proc/", 0) == 0) return true;
  std::error_code error;
  const fs::file_status status = fs::status(target, error);
  return !error && fs::exists(status) && !fs::is_regular_file(status) && !fs::is_directory(status);
}

bool isStandardOutput(const std::string& path) {
  return path == "-" || path == "/dev/stdout";
}

/// The temporary files an interrupt must remove. The handler may only call async-signal-safe
/// functions (unlink, signal, raise), so the paths wait in fixed arrays, each marked used only
/// once it is complete.
struct InterruptSlot {
  char path[4096];
  volatile std::sig_atomic_t used;
};
constexpr int kInterruptSlots = 4;  // --csv and --contacts, or --error-vs-reference
InterruptSlot interruptSlots[kInterruptSlots];

extern "C" void removeTemporariesAndEnd(int signal) {
  for (InterruptSlot& slot : interruptSlots) {
    if (slot.used) unlink(slot.path);
  }
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

/// Routes SIGINT, SIGTERM and SIGHUP through removeTemporariesAndEnd, once; a signal the caller
/// ignores (nohup's SIGHUP) stays ignored.
void catchInterrupts() {
  static bool caught = false;
  if (caught) return;
  caught = true;
  for (const int signal : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction action {};
    sigaction(signal, nullptr, &action);
    if (action.sa_handler == SIG_IGN) continue;
    action.sa_handler = removeTemporariesAndEnd;
    sigemptyset(&action.sa_mask);
    action.sa_flags = 0;
    sigaction(signal, &action, nullptr);
  }
}

/// A slot holding `path` for the handler, or -1 when none is free or the path is too long.
int holdForInterrupt(const std::string& path) {
  for (int i = 0; i < kInterruptSlots; ++i) {
    InterruptSlot& slot = interruptSlots[i];
    if (slot.used || path.size() >= sizeof slot.path) continue;
    std::memcpy(slot.path, path.c_str(), path.size() + 1);
    catchInterrupts();
    slot.used = 1;
    return i;
  }
  return -1;
}

void release(int slot) {
  if (slot >= 0) interruptSlots[slot].used = 0;
}

}  // namespace

bool sameOutputFile(const std::string& a, const std::string& b) {
  if (isStandardOutput(a) || isStandardOutput(b)) return isStandardOutput(a) && isStandardOutput(b);
  std::error_code errorA;
  std::error_code errorB;
  const fs::path fileA = fs::weakly_canonical(fs::absolute(a, errorA), errorA);
  const fs::path fileB = fs::weakly_canonical(fs::absolute(b, errorB), errorB);
  if (errorA || errorB) return a == b;
  return fileA == fileB && !writesInPlace(a, fileA.string());
}

OutputFile::OutputFile(const std::string& path) : target_(followLinks(path)), written_(path) {
  if (isStandardOutput(path)) {
    out_ = &std::cout;
    target_ = written_ = "standard output";
    return;
  }
  std::error_code error;
  if (fs::is_directory(target_, error)) {
    throw RunFailure("cannot write " + path + ": " + std::strerror(EISDIR));
  }
  if (writesInPlace(path, target_)) {
    target_ = path;
  } else {
    written_ = target_ + ".tmp";
  }
  if (written_ != target_) interruptSlot_ = holdForInterrupt(written_);
  file_.open(written_, std::ios::binary | std::ios::trunc);
  if (!file_) {
    release(interruptSlot_);
    throw RunFailure("cannot write " + written_ + ": " + std::strerror(errno));
  }
}

OutputFile::~OutputFile() {
  release(interruptSlot_);
  if (committed_ || written_ == target_) return;
  file_.close();
  std::remove(written_.c_str());
}

void OutputFile::throwIfWriteFailed() const {
  if (out_->fail()) throw RunFailure("cannot write " + written_ + ": " + std::strerror(errno));
}

void OutputFile::commit() {
  if (out_ == &file_) {
    file_.close();
  } else {
    out_->flush();
  }
  throwIfWriteFailed();
  if (written_ != target_ && std::rename(written_.c_str(), target_.c_str()) != 0) {
    throw RunFailure("cannot write " + target_ + ": " + std::strerror(errno));
  }
  release(interruptSlot_);
  interruptSlot_ = -1;
  committed_ = true;
}

}  // namespace i2d
