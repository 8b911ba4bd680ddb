// The demo's trace of the shift written as files: VCD for GTKWave, CSV for iecoop-replay, SVG for
// a browser (--vcd, --csv, --svg; demo.hpp says why this is a file of its own).
#include "demo.hpp"

#include <cstdio>
#include <string_view>

namespace demo_host {
namespace {

// Writes the trace to `path` with `write(view, put)`; FALSE if the file could not be written.
template <class Write>
bool write_trace(const shift_trace& trace, const char* path, Write write) {
  std::FILE* file = std::fopen(path, "wb");
  if (file == nullptr) return false;
  bool good = true;
  write(trace.view(), [&](std::string_view text) { good = good && std::fwrite(text.data(), 1, text.size(), file) == text.size(); });
  return std::fclose(file) == 0 && good;
}

}  // namespace

bool write_vcd_file(const shift_trace& trace, const char* path) {
  return write_trace(trace, path, [](const iecoop::trace_view& v, auto put) { iecoop::write_vcd(v, put); });
}

bool write_csv_file(const shift_trace& trace, const char* path) {
  return write_trace(trace, path, [](const iecoop::trace_view& v, auto put) { iecoop::write_csv(v, put); });
}

bool write_svg_file(const shift_trace& trace, const char* path) {
  return write_trace(trace, path, [](const iecoop::trace_view& v, auto put) {
    iecoop::svg_options chart;
    chart.title = "iecoop demo: the conveyor's shift, task Fast (on change)";
    iecoop::write_svg(v, put, chart);
  });
}

}  // namespace demo_host
