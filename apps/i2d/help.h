// What `i2d --help` and `i2d COMMAND --help` print.
#pragma once

namespace i2d {

extern const char* const kGeneralHelp;
extern const char* const kRunHelp;
extern const char* const kCheckHelp;
extern const char* const kCompareHelp;
extern const char* const kAgreeHelp;
extern const char* const kPresetsHelp;

}  // namespace i2d
