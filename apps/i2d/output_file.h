// The files i2d writes where the user names them: --csv, --contacts, --error-vs-reference.
#pragma once

#include <fstream>
#include <ostream>
#include <string>

namespace i2d {

/// Where a file option's bytes go. A path that names a regular file, or nothing yet, is written
/// as PATH.tmp beside the file and renamed over it by commit(): PATH appears only when complete,
/// and a run that fails removes PATH.tmp and leaves an older PATH as it was. A symbolic link is
/// followed, so the file it names is replaced and the link stays. "-" and /dev/stdout are i2d's
/// standard output. Any other device (/dev/null, /dev/fd/3), a named pipe or a socket is written
/// in place: renaming over it would replace the device with a file. A directory is refused when
/// the file is opened. An interrupt (Ctrl-C, SIGTERM, SIGHUP) while PATH.tmp is open removes it
/// before i2d ends as the signal says.
class OutputFile {
 public:
  /// Opens the file, or PATH.tmp; throws RunFailure naming the path when it cannot.
  explicit OutputFile(const std::string& path);
  /// Removes PATH.tmp unless commit() renamed it.
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  std::ostream& stream() { return *out_; }
  /// Throws RunFailure naming the file written when a write has failed (a full disk).
  void throwIfWriteFailed() const;
  /// Closes the file and renames PATH.tmp over PATH; throws RunFailure on any write error.
  void commit();

 private:
  std::string target_;   ///< the file the bytes end in: PATH, its link followed
  std::string written_;  ///< the file opened: target_ + ".tmp", or target_ when in place
  std::ofstream file_;
  std::ostream* out_ = &file_;
  bool committed_ = false;
  int interruptSlot_ = -1;  ///< where an interrupt finds written_ to remove it; -1: none
};

/// Whether two file options would write one file: both standard output ("-", /dev/stdout), or
/// one regular file by two names (a link, "./"). A device such as /dev/null takes both.
bool sameOutputFile(const std::string& a, const std::string& b);

}  // namespace i2d
