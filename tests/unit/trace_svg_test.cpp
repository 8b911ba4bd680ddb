// The SVG timing chart of a trace (<iecoop/trace/svg.hpp>): checked with a real XML parser
// (xmllint, Debian package libxml2-utils) and a real renderer (rsvg-convert, librsvg2-bin), and
// for what a PLC engineer reads in it: the channels' names, enumerations by name, the time axis
// in IEC text, a one-cycle pulse in a long trace, the trigger, its size.
#include "iecoop_test.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include <iecoop/trace.hpp>

using namespace iecoop;

namespace svg_test {

// TYPE E_Phase : (Idle, Filling := 5, Draining, Done); END_TYPE
enum class E_Phase : INT::rep { Idle, Filling = 5, Draining, Done };

}  // namespace svg_test

template <>
inline constexpr auto iecoop::enum_components<svg_test::E_Phase> =
    components<svg_test::E_Phase::Idle, svg_test::E_Phase::Filling, svg_test::E_Phase::Draining,
               svg_test::E_Phase::Done>{};

namespace {

using svg_test::E_Phase;

std::string to_svg(const trace_view& view, const svg_options& options = {}) {
  std::string svg;
  write_svg(
      view, [&](std::string_view s) { svg += s; }, options);
  return svg;
}

std::size_t count(const std::string& text, std::string_view what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

bool has_tool(const char* tool) {
  return std::system((std::string("command -v ") + tool + " >/dev/null 2>&1").c_str()) == 0;
}

/// A directory of its own for the files a test case hands to the tools (test cases may run in
/// parallel processes), removed at the end.
class temp_dir {
 public:
  temp_dir() {
    std::random_device random;
    path_ = std::filesystem::temp_directory_path() /
            ("iecoop_svg_" + std::to_string(random()) + "_" + std::to_string(random()));
    std::filesystem::create_directory(path_);
  }
  ~temp_dir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  temp_dir(const temp_dir&) = delete;
  temp_dir& operator=(const temp_dir&) = delete;
  [[nodiscard]] std::string file(const char* name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

void write_file(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
}
std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// xmllint's verdict on `xml`: empty if it is well-formed, else xmllint's messages (or that
/// xmllint is missing: the check fails then, it is not skipped).
std::string xml_errors(const std::string& xml) {
  if (!has_tool("xmllint")) {
    return "xmllint is missing: install the Debian package libxml2-utils (apt-get install libxml2-utils)";
  }
  const temp_dir dir;
  const std::string file = dir.file("chart.svg");
  const std::string errors = dir.file("errors.txt");
  write_file(file, xml);
  const int status = std::system(("xmllint --noout '" + file + "' 2>'" + errors + "'").c_str());
  if (status == 0) return {};
  const std::string text = read_file(errors);
  return text.empty() ? std::string("xmllint failed without a message") : text;
}

struct png_info {
  bool ok = false;
  std::size_t bytes = 0;
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::string errors;
};

/// Renders `svg` with rsvg-convert into a PNG and reads its size from the PNG's header (not
/// ok, with a message, if rsvg-convert is missing).
png_info render(const std::string& svg) {
  png_info info;
  if (!has_tool("rsvg-convert")) {
    info.errors = "rsvg-convert is missing: install the Debian package librsvg2-bin (apt-get install librsvg2-bin)";
    return info;
  }
  const temp_dir dir;
  const std::string file = dir.file("chart.svg");
  const std::string png = dir.file("chart.png");
  const std::string errors = dir.file("errors.txt");
  write_file(file, svg);
  const int status = std::system(("rsvg-convert -o '" + png + "' '" + file + "' 2>'" + errors + "'").c_str());
  info.errors = read_file(errors);
  const std::string bytes = read_file(png);
  info.bytes = bytes.size();
  if (status != 0 || bytes.size() < 24 || bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") != 0) return info;
  const auto be32 = [&](std::size_t at) {
    std::uint32_t v = 0;
    for (std::size_t k = 0; k < 4; ++k) v = v << 8 | static_cast<unsigned char>(bytes[at + k]);
    return v;
  };
  info.width = be32(16);  // IHDR
  info.height = be32(20);
  info.ok = true;
  return info;
}

/// The `d` of the path of class `cls` in lane `lane`.
std::string lane_path(const std::string& svg, std::size_t lane, std::string_view cls) {
  const std::string open = "<g id=\"lane-" + std::to_string(lane) + "\">";
  const std::size_t begin = svg.find(open);
  if (begin == std::string::npos) return {};
  const std::size_t end = svg.find("</g>", begin);
  const std::string key = "<path class=\"" + std::string(cls) + "\" d=\"";
  const std::size_t at = svg.find(key, begin);
  if (at == std::string::npos || at > end) return {};
  const std::size_t from = at + key.size();
  return svg.substr(from, svg.find('"', from) - from);
}

/// The numbers after each command letter `command` in path data.
std::vector<double> coordinates(const std::string& d, char command) {
  std::vector<double> found;
  for (std::size_t i = 0; i < d.size(); ++i) {
    if (d[i] == command) found.push_back(std::strtod(d.c_str() + i + 1, nullptr));
  }
  return found;
}

/// The texts of class `cls` in `svg` (or in lane `lane` of it), in the order written.
std::vector<std::string> texts(std::string_view svg, std::string_view cls) {
  std::vector<std::string> found;
  const std::string key = "<text class=\"" + std::string(cls) + "\"";
  for (std::size_t at = svg.find(key); at != std::string::npos; at = svg.find(key, at + 1)) {
    const std::size_t from = svg.find('>', at) + 1;
    found.emplace_back(svg.substr(from, svg.find('<', from) - from));
  }
  return found;
}
std::vector<std::string> texts(std::string_view svg, std::string_view cls, std::size_t lane) {
  const std::string open = "<g id=\"lane-" + std::to_string(lane) + "\">";
  const std::size_t begin = svg.find(open);
  if (begin == std::string::npos) return {};
  return texts(svg.substr(begin, svg.find("</g>", begin) - begin), cls);
}
/// The labels of the time axis, left to right.
std::vector<std::string> tick_texts(const std::string& svg) { return texts(svg, "tick"); }

/// A small machine: a start button, a counter, a temperature, a running time, the phase of
/// a fill cycle, and a variable whose scope and name need XML escapes.
struct machine {
  BOOL bStart;
  INT iCount;
  REAL rTemp;
  TIME tRun;
  E_Phase ePhase = E_Phase::Idle;
  INT iOdd;

  std::unique_ptr<trace_recorder<64 * 1024, 16>> trace = std::make_unique<trace_recorder<64 * 1024, 16>>();

  machine() {
    trace->add("IO_PRG", "bStart", bStart);
    trace->add("IO_PRG", "iCount", iCount);
    trace->add("IO_PRG", "rTemp", rTemp);
    trace->add("IO_PRG", "tRun", tRun);
    trace->add("IO_PRG", "ePhase", ePhase);
    trace->add("GVL<\"A&B\">", "x'y", iOdd);
  }

  /// `cycles` cycles of `cycle_ns` each, from time 0.
  void run(std::size_t cycles, std::uint64_t cycle_ns = 1'000'000) {
    REQUIRE(trace->start());
    for (std::size_t i = 0; i < cycles; ++i) {
      cycle_clock::set(LTIME::from_ticks(i * cycle_ns));
      bStart = BOOL(i >= 20 && i < 60);
      iCount = INT(static_cast<INT::rep>(i / 3));
      rTemp = REAL(20.5f + static_cast<float>(i) * 0.25f);
      tRun = TIME::from_ticks(static_cast<std::uint32_t>(i >= 20 ? i - 20 : 0));
      ePhase = i < 20 ? E_Phase::Idle : i < 50 ? E_Phase::Filling : i < 80 ? E_Phase::Draining : E_Phase::Done;
      iOdd = INT(static_cast<INT::rep>(i % 7 == 0 ? -3 : 4));
      trace->sample();
    }
    trace->stop();
  }
};

}  // namespace

TEST_CASE("svg: the chart of a trace is well-formed XML and renders") {
  machine m;
  m.run(100);
  const std::string svg = to_svg(m.trace->view(), {.title = "iecoop trace"});
  CHECK(svg.starts_with("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\""));
  CHECK(svg.ends_with("</svg>\n"));
  CHECK(svg.find("<script") == std::string::npos);
  CHECK(svg.find("href") == std::string::npos);  // nothing external
  CHECK(xml_errors(svg) == "");
  const png_info png = render(svg);
  REQUIRE_MESSAGE(png.ok, png.errors);
  CHECK(png.bytes > 1000);
  CHECK(png.width == 1200);  // the default width
  CHECK(png.height > 200);
}

TEST_CASE("svg: the test's XML check finds what is not well-formed") {
  CHECK(xml_errors("<svg><text>a & b</text></svg>") != "");
  CHECK(xml_errors("<svg><text>a &amp; b</text></svg>") == "");
}

TEST_CASE("svg: every channel is named on its lane, special characters escaped") {
  machine m;
  m.run(100);
  const std::string svg = to_svg(m.trace->view(), {.title = "Line 1 <north> & \"south\""});
  for (const char* name : {"IO_PRG.bStart", "IO_PRG.iCount", "IO_PRG.rTemp", "IO_PRG.tRun", "IO_PRG.ePhase"}) {
    CAPTURE(name);
    CHECK(count(svg, std::string(">") + name + "</text>") == 1);    // the label
    CHECK(count(svg, std::string("<title>") + name + " : ") == 1);  // the lane's tooltip
  }
  CHECK(count(svg, ">GVL&lt;&quot;A&amp;B&quot;&gt;.x&apos;y</text>") == 1);
  CHECK(svg.find("GVL<") == std::string::npos);
  CHECK(svg.find("x'y") == std::string::npos);
  CHECK(count(svg, ">Line 1 &lt;north&gt; &amp; &quot;south&quot;</text>") == 1);
  CHECK(count(svg, "<title>Line 1 &lt;north&gt; &amp; &quot;south&quot;</title>") == 1);
  // The lane tooltips name the types as ST declares them.
  CHECK(count(svg, "<title>IO_PRG.ePhase : E_Phase</title>") == 1);
  CHECK(count(svg, "<title>IO_PRG.tRun : TIME</title>") == 1);
  CHECK(xml_errors(svg) == "");
}

TEST_CASE("svg: names that are not UTF-8 or hold control characters still give XML") {
  BOOL b;
  trace_recorder<4096, 4> trace;
  trace.add("bad\x01scope", "n\xff\xc3x\xe2\x82\xac", b);  // a control character, stray bytes, then a euro sign
  REQUIRE(trace.start());
  trace.sample();
  trace.stop();
  const std::string svg = to_svg(trace.view());
  CHECK(count(svg, ">bad?scope.n??x\xe2\x82\xac</text>") == 1);
  CHECK(xml_errors(svg) == "");
}

TEST_CASE("svg: values are written as IEC text, enumerations by their names") {
  machine m;
  m.run(100);
  const std::string svg = to_svg(m.trace->view());
  // Value labels where a value changes (and there is room): ePhase by its components' names.
  CHECK(texts(svg, "val", 4) == std::vector<std::string>{"Idle", "Filling", "Draining", "Done"});
  CHECK(texts(svg, "val", 0).empty());  // a BOOL lane shows its level, no text
  const std::vector<std::string> temperatures = texts(svg, "val", 2);
  REQUIRE(temperatures.size() >= 5);
  CHECK(temperatures[0] == "20.5");  // REAL as ST writes it
  CHECK(texts(svg, "val", 3).at(0) == "T#0ms");
  // The scale at the right of each numeric lane: its greatest and least value, as IEC text.
  CHECK(texts(svg, "scale", 1) == std::vector<std::string>{"33", "0"});
  CHECK(texts(svg, "scale", 2) == std::vector<std::string>{"45.25", "20.5"});
  CHECK(texts(svg, "scale", 3) == std::vector<std::string>{"T#79ms", "T#0ms"});
  CHECK(texts(svg, "scale", 4) == std::vector<std::string>{"Done", "Idle"});
  CHECK(texts(svg, "scale", 5) == std::vector<std::string>{"4", "-3"});
}

TEST_CASE("svg: the time axis shows the cycle clock's time as IEC text") {
  SUBCASE("milliseconds as TIME") {
    machine m;
    m.run(100);  // 1 ms cycles: 0 .. 99 ms, and the last one held for 1 ms more
    const std::vector<std::string> ticks = tick_texts(to_svg(m.trace->view()));
    CHECK(ticks == std::vector<std::string>{"T#0ms", "T#10ms", "T#20ms", "T#30ms", "T#40ms", "T#50ms", "T#60ms",
                                            "T#70ms", "T#80ms", "T#90ms", "T#100ms"});
  }
  SUBCASE("absolute time: ticks count from the cycle clock's origin, not from the first sample") {
    machine m;
    REQUIRE(m.trace->start());
    for (std::uint64_t i = 0; i < 100; ++i) {
      cycle_clock::set(LTIME::from_ticks(3'600'000'000'000ULL + i * 10'000'000));  // from T#1h, 10 ms cycles
      m.trace->sample();
    }
    m.trace->stop();
    const std::vector<std::string> ticks = tick_texts(to_svg(m.trace->view()));
    REQUIRE(ticks.size() >= 3);
    CHECK(ticks.front() == "T#1h");
    CHECK(ticks.back() == "T#1h1s");
  }
  SUBCASE("microseconds as LTIME") {
    machine m;
    m.run(100, 10'000);  // 10 us cycles
    const std::string svg = to_svg(m.trace->view());
    const std::vector<std::string> ticks = tick_texts(svg);
    REQUIRE(ticks.size() >= 3);
    CHECK(ticks.front() == "LTIME#0ns");
    for (const std::string& tick : ticks) {
      CAPTURE(tick);
      CHECK(tick.starts_with("LTIME#"));
    }
    CHECK(std::find(ticks.begin(), ticks.end(), "LTIME#1ms") != ticks.end());
    CHECK(xml_errors(svg) == "");
  }
  SUBCASE("grid lines at the ticks") {
    machine m;
    m.run(100);
    const std::string svg = to_svg(m.trace->view());
    const std::size_t at = svg.find("<path class=\"grid\" d=\"");
    REQUIRE(at != std::string::npos);
    CHECK(coordinates(svg.substr(at, svg.find("/>", at) - at), 'M').size() == 11);
  }
}

TEST_CASE("svg: a value holds until the next sample, the last one for a median interval more") {
  INT i;
  trace_recorder<4096, 4> trace;
  trace.add("i", i);
  REQUIRE(trace.start());
  cycle_clock::set(LTIME::from_ticks(0));
  i = 0;
  trace.sample();
  cycle_clock::set(LTIME::from_ticks(10'000'000));
  i = 5;
  trace.sample();
  trace.stop();
  const std::string d = lane_path(to_svg(trace.view()), 0, "num");
  CAPTURE(d);
  // M<left> <low>H<change>V<high>H<right>: the change halfway (0 and 10 ms, then 10 ms more).
  const std::vector<double> m = coordinates(d, 'M');
  const std::vector<double> h = coordinates(d, 'H');
  const std::vector<double> v = coordinates(d, 'V');
  REQUIRE(m.size() == 1);
  REQUIRE(h.size() == 2);
  REQUIRE(v.size() == 1);
  CHECK(h[0] == std::floor((m[0] + h[1]) / 2));
  const double low = std::strtod(d.c_str() + d.find(' ') + 1, nullptr);
  CHECK(v[0] < low);  // 5 is above 0
}

TEST_CASE("svg: one sample, or samples all at one time, still show") {
  BOOL b{true};
  INT i{7};
  trace_recorder<4096, 4> trace;
  trace.add("b", b);
  trace.add("i", i);
  REQUIRE(trace.start());
  cycle_clock::set(LTIME::from_ticks(5'000'000));
  trace.sample();
  std::string svg = to_svg(trace.view());
  CHECK(lane_path(svg, 0, "bit").find('H') != std::string::npos);
  CHECK(svg.find(">7</text>") != std::string::npos);
  CHECK(svg.find("1 sample, cycle 0<") != std::string::npos);
  CHECK(xml_errors(svg) == "");
  trace.sample();  // the same time
  trace.stop();
  svg = to_svg(trace.view());
  CHECK(svg.find("2 samples, cycles 0 to 1<") != std::string::npos);
  CHECK(xml_errors(svg) == "");
  const png_info png = render(svg);
  CHECK_MESSAGE(png.ok, png.errors);
}

TEST_CASE("svg: the trigger is marked only when the trace has one") {
  BOOL bJam;
  INT iLevel;
  trace_recorder<8192, 4> trace;
  trace.add("IO_PRG", "bJam", bJam);
  trace.add("IO_PRG", "iLevel", iLevel);
  const auto run = [&] {
    REQUIRE(trace.start());
    for (std::uint64_t i = 0; i < 200; ++i) {
      cycle_clock::set(LTIME::from_ticks(i * 1'000'000));
      bJam = BOOL(i >= 120);
      iLevel = INT(static_cast<INT::rep>(i));
      trace.sample();
    }
    trace.stop();
  };
  run();
  std::string svg = to_svg(trace.view());
  CHECK(trace.view().trigger_index() == trace_view::no_trigger);
  CHECK(svg.find("trigger\"") == std::string::npos);
  CHECK(svg.find(">trigger<") == std::string::npos);

  trace.trigger_on(bJam, trace_edge::rising, 10, 20);
  run();
  REQUIRE(trace.view().trigger_index() == 10);
  svg = to_svg(trace.view());
  CHECK(count(svg, "<path class=\"trigger\" d=\"M") == 1);
  CHECK(count(svg, ">trigger</text>") == 1);
  // The marker stands where bJam rises: at the column of its step.
  const std::string d = lane_path(svg, 0, "bit");
  const std::vector<double> h = coordinates(d, 'H');
  REQUIRE(h.size() >= 1);
  const std::size_t at = svg.find("<path class=\"trigger\" d=\"M") + 26;
  CHECK(std::strtod(svg.c_str() + at, nullptr) == h[0] + 0.5);
  CHECK(xml_errors(svg) == "");
  const png_info png = render(svg);
  CHECK_MESSAGE(png.ok, png.errors);
}

TEST_CASE("svg: an empty trace gives a chart that says so") {
  const std::string none = to_svg(trace_view{}, {.title = "iecoop trace"});
  CHECK(none.find(">no samples</text>") != std::string::npos);
  CHECK(xml_errors(none) == "");
  const png_info png = render(none);
  CHECK_MESSAGE(png.ok, png.errors);

  BOOL b;
  trace_recorder<4096, 4> trace;
  trace.add("b", b);
  REQUIRE(trace.start());
  trace.stop();
  CHECK(to_svg(trace.view()).find(">no samples</text>") != std::string::npos);

  trace_recorder<4096, 4> no_channels;
  REQUIRE(no_channels.start());
  no_channels.sample();
  no_channels.stop();
  REQUIRE(no_channels.view().size() == 1);
  const std::string svg = to_svg(no_channels.view());
  CHECK(svg.find(">no samples (no channels)</text>") != std::string::npos);
  CHECK(xml_errors(svg) == "");
}

TEST_CASE("svg: the same trace gives the same bytes") {
  machine m;
  m.run(100);
  const std::string a = to_svg(m.trace->view());
  std::size_t pieces = 0;
  std::string b;
  write_svg(m.trace->view(), [&](std::string_view s) {
    ++pieces;
    b += s;
  });
  CHECK(a == b);
  CHECK(pieces >= 2);  // handed over in buffered pieces
  CHECK(a != to_svg(m.trace->view(), {.width = 800}));
}

TEST_CASE("svg: 21000 samples of 20 channels, with a one-cycle pulse") {
  constexpr std::size_t samples = 21'000;
  constexpr std::size_t pulse_at = 12'345;
  // Ten BOOLs, from never changing to changing every cycle, and ten numbers.
  BOOL bits[10];
  INT iCount;
  DINT diNoise;
  REAL rSine;
  LREAL lrRamp;
  TIME tRun;
  LTIME ltRun;
  E_Phase ePhase = E_Phase::Idle;
  UINT uiSpike;
  WORD wStatus;
  SINT siSaw;
  const char* const bit_names[10] = {"bConstant", "bPulse",     "bEvery1",    "bEvery2", "bEvery10",
                                     "bEvery100", "bEvery1000", "bEvery5000", "bEvery7", "bEvery3"};
  auto trace = std::make_unique<trace_recorder<2 * 1024 * 1024, 20>>();
  for (std::size_t k = 0; k < 10; ++k) trace->add("MAIN", bit_names[k], bits[k]);
  trace->add("MAIN", "iCount", iCount);
  trace->add("MAIN", "diNoise", diNoise);
  trace->add("MAIN", "rSine", rSine);
  trace->add("MAIN", "lrRamp", lrRamp);
  trace->add("MAIN", "tRun", tRun);
  trace->add("MAIN", "ltRun", ltRun);
  trace->add("MAIN", "ePhase", ePhase);
  trace->add("MAIN", "uiSpike", uiSpike);
  trace->add("MAIN", "wStatus", wStatus);
  trace->add("MAIN", "siSaw", siSaw);
  REQUIRE(trace->start());
  REQUIRE(trace->capacity() >= samples);
  std::uint32_t noise = 12345;
  for (std::size_t i = 0; i < samples; ++i) {
    cycle_clock::set(LTIME::from_ticks(i * 1'000'000));
    bits[0] = BOOL(false);
    bits[1] = BOOL(i == pulse_at);
    bits[2] = BOOL(i % 2 == 1);
    bits[3] = BOOL(i / 2 % 2 == 1);
    bits[4] = BOOL(i / 10 % 2 == 1);
    bits[5] = BOOL(i / 100 % 2 == 1);
    bits[6] = BOOL(i / 1000 % 2 == 1);
    bits[7] = BOOL(i / 5000 % 2 == 1);
    bits[8] = BOOL(i / 7 % 2 == 1);
    bits[9] = BOOL(i / 3 % 2 == 1);
    iCount = INT(static_cast<INT::rep>(i % 30'000));
    noise = noise * 1'103'515'245U + 12'345U;
    diNoise = DINT(static_cast<DINT::rep>(noise >> 8));
    rSine = REAL(static_cast<float>(std::sin(static_cast<double>(i) / 500.0) * 100.0));
    lrRamp = LREAL(static_cast<double>(i) * 0.001);
    tRun = TIME::from_ticks(static_cast<std::uint32_t>(i));
    ltRun = LTIME::from_ticks(i * 1'000'000);
    ePhase = static_cast<E_Phase>(i / 700 % 4 == 0 ? 0 : 4 + i / 700 % 4);
    uiSpike = UINT(static_cast<UINT::rep>(i == pulse_at + 1 ? 1000 : 0));
    wStatus = WORD(static_cast<WORD::rep>(i / 250 % 16));
    siSaw = SINT(static_cast<SINT::rep>(static_cast<int>(i % 200) - 100));
    trace->sample();
  }
  trace->stop();
  REQUIRE(trace->view().size() == samples);
  const std::string svg = to_svg(trace->view(), {.title = "iecoop trace"});
  MESSAGE("SVG of 21000 samples x 20 channels: " << svg.size() << " bytes");
  CHECK(svg.size() < 1'000'000);
  // The pulse: bPulse's line leaves its level and comes back, though the pulse is a
  // 21000th of the trace, far below a pixel; bConstant's line never does.
  CHECK(coordinates(lane_path(svg, 1, "bit"), 'V').size() >= 2);
  CHECK(coordinates(lane_path(svg, 1, "high"), 'V').size() >= 2);
  CHECK(coordinates(lane_path(svg, 0, "bit"), 'V').empty());
  // The same for a number: uiSpike reaches 1000 for one cycle.
  const std::vector<double> spike = coordinates(lane_path(svg, 17, "num"), 'V');
  CHECK(spike.size() >= 2);
  CHECK(svg.find(">1000</text>") != std::string::npos);  // its greatest value, on the scale
  // A BOOL changing every cycle is drawn once per pixel column, not once per sample.
  const std::string every1 = lane_path(svg, 2, "bit");
  CHECK(coordinates(every1, 'H').size() <= 1200);
  CHECK(coordinates(every1, 'H').size() >= 500);
  // Enumerations by name, the time axis in seconds.
  const std::vector<std::string> phases = texts(svg, "val", 16);
  CHECK(phases.size() >= 10);
  for (const std::string& phase : phases) {
    CAPTURE(phase);
    CHECK((phase == "Idle" || phase == "Filling" || phase == "Draining" || phase == "Done"));
  }
  CHECK(svg.find(">T#10s</text>") != std::string::npos);
  CHECK(svg.find("21000 samples, cycles 0 to 20999<") != std::string::npos);
  CHECK(xml_errors(svg) == "");
  const png_info png = render(svg);
  REQUIRE_MESSAGE(png.ok, png.errors);
  CHECK(png.width == 1200);
}
