// iecoop-check: the rules of IEC 61131-3 (as CODESYS applies them) that C++ does not enforce
// on iecoop's blocks, checked on one parsed translation unit. See docs/iecoop-check.md.
#pragma once

#include <clang-c/Index.h>

#include <string>
#include <vector>

namespace iecoop_check {

struct location {
  std::string file;
  unsigned line = 0;
  unsigned column = 0;
};

/// A second place a finding points at (the base's method it hides, say).
struct note {
  location where;
  std::string text;
};

/// One violation: "<where>: error: iecoop-check: <message>".
struct finding {
  location where;
  std::string message;
  std::vector<note> notes;
};

/// The findings of every check in `unit`, located in the user's files only (not in system
/// headers, nor in iecoop's own headers).
std::vector<finding> check_translation_unit(CXTranslationUnit unit);

}  // namespace iecoop_check
