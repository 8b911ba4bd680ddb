// iecoop-check: reports, like a compiler, what an iecoop program does that CODESYS would reject
// or run differently and C++ does not catch (docs/iecoop-check.md):
//
//     iecoop-check <file>... -- <compiler flags>     e.g. -- -std=c++20 -Iinclude
//     iecoop-check -p <build dir> [<file>...]       flags from <build dir>/compile_commands.json
//
// With -p, a file not in the database takes the flags after -- if there are any, else the
// flags clang's tools infer for it from the files near it.
//
// Each finding is a line `file:line:col: error: iecoop-check: <rule>; <fix>` on stdout (with
// `note:` lines after it). Exit status: 0 clean, 1 findings, 2 bad usage or a file that does not
// compile (its compiler errors go to stderr).
#include <clang-c/CXCompilationDatabase.h>
#include <clang-c/Index.h>

#include <unistd.h>

#include <algorithm>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include "checks.hpp"
#include "cursor.hpp"

namespace {

using iecoop_check::finding;
using iecoop_check::text;

constexpr int exit_clean = 0;
constexpr int exit_findings = 1;
constexpr int exit_error = 2;

constexpr std::string_view usage_text =
    "usage: iecoop-check <file>... -- <compiler flags>\n"
    "       iecoop-check -p <build dir> [<file>...] [-- <flags for files not in the database>]\n"
    "Checks iecoop programs for what CODESYS would reject or run differently and C++ does not\n"
    "catch (docs/iecoop-check.md). -p reads <build dir>/compile_commands.json; without files it\n"
    "checks every file in it; a file not in it takes the flags after --, else flags inferred\n"
    "from the files near it. Exit status: 0 clean, 1 findings, 2 bad usage or a file that does\n"
    "not compile.\n";

struct options {
  std::string build_dir;
  std::vector<std::string> files;
  std::vector<std::string> flags;
  bool has_flags = false;
};

/// One file to parse, with the arguments of its compiler (without the compiler itself).
struct job {
  std::string file;
  std::string directory;  // where relative paths in the arguments start, if not here
  std::vector<std::string> arguments;
  bool file_in_arguments = false;
};

int usage_error(const std::string& message) {
  std::fprintf(stderr, "iecoop-check: error: %s\n%s", message.c_str(), usage_text.data());
  return exit_error;
}

/// Reads the command line; returns the exit status for --help and for bad usage.
int read_options(int argc, char** argv, options& result) {
  for (int i = 1; i < argc; ++i) {
    const std::string_view argument = argv[i];
    if (argument == "--") {
      result.has_flags = true;
      result.flags.assign(argv + i + 1, argv + argc);
      break;
    }
    if (argument == "-h" || argument == "--help") {
      std::fputs(usage_text.data(), stdout);
      return exit_clean;
    }
    if (argument == "-p") {
      if (i + 1 >= argc) return usage_error("-p needs a build directory");
      result.build_dir = argv[++i];
    } else if (argument.rfind("-p=", 0) == 0) {
      result.build_dir = argument.substr(3);
    } else if (argument.size() > 1 && argument[0] == '-') {
      return usage_error("unknown option " + std::string(argument));
    } else {
      result.files.emplace_back(argument);
    }
  }
  if (result.files.empty() && result.build_dir.empty()) return usage_error("no file to check");
  return -1;
}

/// A header precompiled for the build (CMake's cmake_pch.hxx, or any header beside which a
/// .gch or .pch lies): libclang cannot read GCC's precompiled form, nor another Clang's.
bool precompiled_header(const std::string& header) {
  const auto ends_with = [&header](std::string_view end) {
    return header.size() >= end.size() && header.compare(header.size() - end.size(), end.size(), end) == 0;
  };
  return ends_with("cmake_pch.hxx") || ends_with("cmake_pch.hxx.pch") || access((header + ".gch").c_str(), F_OK) == 0 ||
         access((header + ".pch").c_str(), F_OK) == 0;
}

/// The compiler's arguments as libclang takes them: without the compiler, the output, the
/// dependency files and a precompiled header (the sources include what they use; the parse
/// reads the headers themselves), and with no warning as an error (only errors in the code
/// count).
std::vector<std::string> parser_arguments(const std::vector<std::string>& compiler_arguments) {
  std::vector<std::string> result;
  for (std::size_t i = 0; i < compiler_arguments.size(); ++i) {
    const std::string& a = compiler_arguments[i];
    if (a == "-o" || a == "-MF" || a == "-MT" || a == "-MQ") {
      ++i;
      continue;
    }
    // GCC: -include <pch header>; Clang: -Xclang -include-pch -Xclang <pch> and
    // -Xclang -include -Xclang <pch header>.
    if (a == "-include" && i + 1 < compiler_arguments.size() && precompiled_header(compiler_arguments[i + 1])) {
      ++i;
      continue;
    }
    if (a == "-Xclang" && i + 3 < compiler_arguments.size() &&
        (compiler_arguments[i + 1] == "-include-pch" || compiler_arguments[i + 1] == "-include") &&
        compiler_arguments[i + 2] == "-Xclang" && precompiled_header(compiler_arguments[i + 3])) {
      i += 3;
      continue;
    }
    if (a == "-Winvalid-pch") continue;
    if (a == "-c" || a == "-MD" || a == "-MMD" || a.rfind("-Werror", 0) == 0 || a == "-pedantic-errors") continue;
    result.push_back(a);
  }
  result.emplace_back("-w");
  return result;
}

std::string absolute(const std::string& path) {
  char resolved[PATH_MAX];
  if (realpath(path.c_str(), resolved) != nullptr) return resolved;
  return path;
}

/// The files to check and their arguments; returns false (having said why) if one has none.
bool plan(const options& opts, std::vector<job>& jobs) {
  for (const std::string& file : opts.files) {
    if (access(file.c_str(), R_OK) != 0) {
      std::fprintf(stderr, "iecoop-check: error: %s: no such file\n", file.c_str());
      return false;
    }
  }
  if (opts.build_dir.empty()) {
    for (const std::string& file : opts.files) jobs.push_back(job{file, {}, parser_arguments(opts.flags), false});
    return true;
  }
  const std::string database_file = opts.build_dir + "/compile_commands.json";
  CXCompilationDatabase_Error error = CXCompilationDatabase_CanNotLoadDatabase;
  CXCompilationDatabase database = nullptr;
  if (access(database_file.c_str(), R_OK) == 0) {  // else libclang would print its own complaint
    database = clang_CompilationDatabase_fromDirectory(opts.build_dir.c_str(), &error);
  }
  if (error != CXCompilationDatabase_NoError || database == nullptr) {
    std::fprintf(stderr, "iecoop-check: error: cannot read %s (configure with -DCMAKE_EXPORT_COMPILE_COMMANDS=ON)\n",
                 database_file.c_str());
    return false;
  }
  std::set<std::string> seen;
  const auto add_command = [&](CXCompileCommand command) {
    const std::string file = text(clang_CompileCommand_getFilename(command));
    if (!seen.insert(file).second) return;  // a file built twice is checked once
    std::vector<std::string> arguments;
    const unsigned argument_count = clang_CompileCommand_getNumArgs(command);
    for (unsigned k = 1; k < argument_count; ++k) arguments.push_back(text(clang_CompileCommand_getArg(command, k)));
    jobs.push_back(job{file, text(clang_CompileCommand_getDirectory(command)), parser_arguments(arguments), true});
  };
  // The database's own entries, by the file's real path.
  CXCompileCommands all = clang_CompilationDatabase_getAllCompileCommands(database);
  std::map<std::string, CXCompileCommand> entries;
  const unsigned count = all != nullptr ? clang_CompileCommands_getSize(all) : 0;
  for (unsigned i = 0; i < count; ++i) {
    const CXCompileCommand command = clang_CompileCommands_getCommand(all, i);
    std::string file = text(clang_CompileCommand_getFilename(command));
    if (file.empty() || file[0] != '/') file = text(clang_CompileCommand_getDirectory(command)) + "/" + file;
    entries.emplace(absolute(file), command);
    if (opts.files.empty()) add_command(command);
  }
  bool ok = true;
  for (const std::string& file : opts.files) {
    const auto entry = entries.find(absolute(file));
    if (entry != entries.end()) {
      add_command(entry->second);
    } else if (opts.has_flags) {
      jobs.push_back(job{file, {}, parser_arguments(opts.flags), false});
    } else {
      // Not built itself (a header, say): the flags of a file near it, as clang's tools infer them.
      CXCompileCommands inferred = clang_CompilationDatabase_getCompileCommands(database, absolute(file).c_str());
      if (inferred != nullptr && clang_CompileCommands_getSize(inferred) > 0) {
        add_command(clang_CompileCommands_getCommand(inferred, 0));
      } else {
        std::fprintf(stderr, "iecoop-check: error: %s is not in %s; give its flags after --\n", file.c_str(),
                     database_file.c_str());
        ok = false;
      }
      clang_CompileCommands_dispose(inferred);
    }
  }
  clang_CompileCommands_dispose(all);
  clang_CompilationDatabase_dispose(database);
  return ok;
}

/// A driver complaint about a flag clang does not know (a GCC-only one from the build's
/// compile commands): the flag is ignored and the code parsed as usual.
bool is_unknown_flag(CXDiagnostic diagnostic) {
  return text(clang_getDiagnosticSpelling(diagnostic)).rfind("unknown argument", 0) == 0;
}

/// Parses one file and adds its findings; false if it does not compile.
bool check(CXIndex index, const job& task, std::vector<finding>& findings) {
  std::vector<const char*> argv;
  argv.reserve(task.arguments.size());
  for (const std::string& a : task.arguments) argv.push_back(a.c_str());
  char here[PATH_MAX];
  const bool moved =
      !task.directory.empty() && getcwd(here, sizeof here) != nullptr && chdir(task.directory.c_str()) == 0;
  CXTranslationUnit unit = nullptr;
  const CXErrorCode error =
      clang_parseTranslationUnit2(index, task.file_in_arguments ? nullptr : task.file.c_str(), argv.data(),
                                  static_cast<int>(argv.size()), nullptr, 0, CXTranslationUnit_None, &unit);
  bool ok = error == CXError_Success && unit != nullptr;
  if (!ok) {
    std::fprintf(stderr, "iecoop-check: error: %s: libclang could not parse it (error %d)\n", task.file.c_str(),
                 static_cast<int>(error));
  } else {
    const unsigned count = clang_getNumDiagnostics(unit);
    for (unsigned i = 0; i < count; ++i) {
      CXDiagnostic diagnostic = clang_getDiagnostic(unit, i);
      if (clang_getDiagnosticSeverity(diagnostic) >= CXDiagnostic_Error && !is_unknown_flag(diagnostic)) {
        std::fprintf(stderr, "%s\n",
                     text(clang_formatDiagnostic(diagnostic, clang_defaultDiagnosticDisplayOptions())).c_str());
        ok = false;
      }
      clang_disposeDiagnostic(diagnostic);
    }
    if (ok) {
      std::vector<finding> found = iecoop_check::check_translation_unit(unit);
      findings.insert(findings.end(), found.begin(), found.end());
    } else {
      std::fprintf(stderr, "iecoop-check: error: %s does not compile; iecoop-check checks only code that compiles\n",
                   task.file.c_str());
    }
    clang_disposeTranslationUnit(unit);
  }
  if (moved && chdir(here) != 0) ok = false;
  return ok;
}

}  // namespace

/// Under LeakSanitizer (iecoop's sanitizer builds): libclang does not free everything its
/// parser allocates; those are its leaks, not the checker's. (An ordinary build never calls it.)
extern "C" const char* __lsan_default_suppressions() { return "leak:libclang\nleak:libLLVM\n"; }
extern "C" const char* __lsan_default_options() { return "print_suppressions=0"; }

int main(int argc, char** argv) {
  options opts;
  const int status = read_options(argc, argv, opts);
  if (status >= 0) return status;
  std::vector<job> jobs;
  bool ok = plan(opts, jobs);

  CXIndex index = clang_createIndex(0, 0);
  std::vector<finding> findings;
  for (const job& task : jobs) ok = check(index, task, findings) && ok;
  clang_disposeIndex(index);

  // A header included by several files reports once; all in the order of the files.
  const auto key = [](const finding& f) { return std::tie(f.where.file, f.where.line, f.where.column, f.message); };
  std::sort(findings.begin(), findings.end(), [&](const finding& a, const finding& b) { return key(a) < key(b); });
  findings.erase(std::unique(findings.begin(), findings.end(),
                             [&](const finding& a, const finding& b) { return key(a) == key(b); }),
                 findings.end());
  for (const finding& f : findings) {
    std::printf("%s:%u:%u: error: iecoop-check: %s\n", f.where.file.c_str(), f.where.line, f.where.column,
                f.message.c_str());
    for (const iecoop_check::note& n : f.notes) {
      std::printf("%s:%u:%u: note: %s\n", n.where.file.c_str(), n.where.line, n.where.column, n.text.c_str());
    }
  }
  std::fflush(stdout);
  if (!ok) return exit_error;
  return findings.empty() ? exit_clean : exit_findings;
}
