// iecoop-replay: drives one standard function block, or one of the reference SFC charts, from a
// stimulus file and writes the trace of its outputs, for conformance checks against other IEC
// 61131-3 implementations.
//
//     iecoop-replay [--dialect NAME] [--prefix NAME] FB < stimulus.csv > trace.csv
//     iecoop-replay [--dialect codesys|matiec] CHART < CHART.stimulus.csv > trace.csv
//
// FB is one of TON TOF TP CTU CTD CTUD R_TRIG F_TRIG SR RS (counters: their INT variants), in
// the dialect NAME (codesys, the default; iec; matiec). The stimulus has the header
// `cycle,time_ms,<inputs...>` and one row per cycle; for each row the tool sets the cycle clock
// to time_ms, assigns the row's inputs, calls the block once and writes the row of the trace:
// `cycle,time_ms,<inputs as given...>,<outputs...>[,extra columns]`. BOOL is 0 or 1, INT a
// signed decimal, a TIME a whole number of milliseconds in a column named <pin>_ms. Columns
// that are no input are copied through, at the end. With --prefix P, the inputs are the columns
// named P.<input>: a CSV the trace recorder wrote (<iecoop/trace/csv.hpp>) with the block's pins
// recorded as P replays as it stands. Bad input: one line on stderr naming the row and column,
// exit status 2, and nothing on stdout.
//
// CHART is one of the eight reference charts of examples/sfc (SFC_LINEAR, SFC_PAR, ...), in the
// scan order NAME: codesys (the default) or matiec (docs/sfc.md). Per row the tool sets the cycle
// clock, assigns the inputs and runs one scan; the trace has the columns of the chart's .columns
// file: the inputs, <step>_X and <step>_T_ms for each step, the program's variables, the note.
#include "replay.hpp"
#include "sfc_charts.hpp"

#include <cstdio>
#include <iostream>
#include <new>
#include <optional>
#include <string>
#include <string_view>

namespace {

using namespace iecoop;
using namespace iecoop_replay;

constexpr int exit_bad_input = 2;

constexpr std::string_view usage =
    "usage: iecoop-replay [--dialect NAME] [--prefix NAME] FB < stimulus.csv > trace.csv\n"
    "       iecoop-replay [--dialect codesys|matiec] CHART < stimulus.csv > trace.csv\n"
    "  FB:      TON TOF TP CTU CTD CTUD R_TRIG F_TRIG SR RS (counters: their INT variants)\n"
    "  CHART:   SFC_ALT SFC_ALT_PRIO SFC_FIRST_SCAN SFC_LINEAR SFC_PAR SFC_QUAL SFC_SHARED SFC_TIMED\n"
    "  --dialect: codesys (default), iec, matiec (charts: their scan order, codesys or matiec)\n"
    "  --prefix:  the inputs are the columns NAME.<input> (a recorded trace's, e.g. IO_PRG.tJam)\n"
    "  stimulus: header cycle,time_ms,<inputs...>; BOOL 0/1, INT decimal, TIME as <pin>_ms\n";

int fail(const std::string& message) {
  std::cerr << "iecoop-replay: " << visible(message) << '\n';
  return exit_bad_input;
}

std::string upper(std::string_view text) {
  std::string result(text);
  for (char& c : result) {
    if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
  }
  return result;
}

}  // namespace

int main(int argc, char** argv) {
  std::string dialect = "codesys";
  std::optional<std::string> fb;
  std::string prefix;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--help" || arg == "-h") {
      std::cout << usage;
      return 0;
    }
    if (arg == "--dialect") {
      if (i + 1 >= argc) return fail("--dialect needs a name: codesys, iec or matiec");
      dialect = argv[++i];
    } else if (arg.starts_with("--dialect=")) {
      dialect = std::string(arg.substr(10));
    } else if (arg == "--prefix") {
      if (i + 1 >= argc) return fail("--prefix needs a name, e.g. IO_PRG.tJam");
      prefix = argv[++i];
    } else if (arg.starts_with("--prefix=")) {
      prefix = std::string(arg.substr(9));
    } else if (arg.starts_with("-")) {
      return fail("unknown option " + std::string(arg) + "; see iecoop-replay --help");
    } else if (fb) {
      return fail("one FB only, got " + *fb + " and " + std::string(arg));
    } else {
      fb = upper(arg);  // ST names are case-insensitive
    }
  }
  if (!fb) return fail("which FB? usage: iecoop-replay [--dialect NAME] FB < stimulus.csv > trace.csv");

  // Arguments first, so that a wrong one does not wait for a stimulus.
  if (dialect != codesys::dialect::name && dialect != iec::dialect::name && dialect != matiec::dialect::name) {
    return fail("unknown dialect \"" + dialect + "\"; use codesys, iec or matiec");
  }
  const bool is_chart = replay_chart<sfc::codesys>(*fb, {}, /*check_name_only=*/true).has_value();
  if (!is_chart && !replay_in<codesys::dialect>(*fb, {}, /*check_name_only=*/true)) {
    return fail("unknown FB \"" + *fb +
                "\"; use one of TON TOF TP CTU CTD CTUD R_TRIG F_TRIG SR RS, or a chart: " + std::string(chart_names));
  }
  if (is_chart && dialect == iec::dialect::name) {
    return fail("a chart's scan order is codesys or matiec, not iec; use --dialect codesys or --dialect matiec");
  }
  if (is_chart && !prefix.empty()) return fail("--prefix is for FBs, not for charts");

  try {
    std::string stimulus;
    char chunk[65536];
    while (std::cin.read(chunk, sizeof chunk) || std::cin.gcount() > 0) {
      stimulus.append(chunk, static_cast<std::size_t>(std::cin.gcount()));
    }
    // std::cin reads through stdio (synchronised): a read error there is only ferror(stdin).
    if (std::cin.bad() || std::ferror(stdin) != 0) return fail("could not read the stimulus from standard input");
    std::optional<std::string> trace;
    if (is_chart) {
      trace = dialect == matiec::dialect::name ? replay_chart<sfc::matiec>(*fb, stimulus)
                                               : replay_chart<sfc::codesys>(*fb, stimulus);
    } else if (dialect == codesys::dialect::name) {
      trace = replay_in<codesys::dialect>(*fb, stimulus, false, prefix);
    } else if (dialect == iec::dialect::name) {
      trace = replay_in<iec::dialect>(*fb, stimulus, false, prefix);
    } else {
      trace = replay_in<matiec::dialect>(*fb, stimulus, false, prefix);
    }
    std::cout << *trace;  // all or nothing: written only once the whole stimulus is good
    std::cout.flush();
    if (!std::cout) {
      std::cerr << "iecoop-replay: could not write the trace\n";
      return 1;
    }
  } catch (const input_error& error) {
    return fail(error.message);
  } catch (const std::bad_alloc&) {
    return fail("the stimulus does not fit in memory");
  }
  return 0;
}
