// <iecoop/ostream.hpp>: operator<< prints IEC values as ST writes them.
#include "iecoop_test.hpp"

#include <sstream>
#include <string>

using namespace iecoop;

namespace {
template <class T>
std::string printed(const T& value) {
  std::ostringstream out;
  out << value;
  return out.str();
}
}  // namespace

TEST_SUITE("ostream") {
  TEST_CASE("IEC values print as ST writes them") {
    CHECK(printed("T#1h2m3s4ms"_iec) == "T#1h2m3s4ms");
    CHECK(printed("LTIME#1us"_iec) == "LTIME#1us");
    CHECK(printed(TRUE) == "TRUE");
    CHECK(printed(SINT(-128)) == "-128");
    CHECK(printed(BYTE(200)) == "200");
    CHECK(printed(REAL(0.5f)) == "0.5");
    CHECK(printed(STRING<>("abc")) == "abc");
    CHECK(printed(WSTRING<>(u"\u00e4")) == "\xC3\xA4");
  }

  TEST_CASE("an ARRAY prints as ST writes its initial value") {
    CHECK(printed(ARRAY<INT, 1, 3>{1, -2, 3}) == "[1, -2, 3]");
    CHECK(printed(ARRAY<INT, 1, 2, 1, 2>{1, 2, 3, 4}) == "[1, 2, 3, 4]");  // row by row
    CHECK(printed(ARRAY<ARRAY<BYTE, 0, 1>, 0, 1>{ARRAY<BYTE, 0, 1>{1, 2}}) == "[[1, 2], [0, 0]]");
    CHECK(printed(ARRAY<TIME, 1, 2>{"T#1s"_iec}) == "[T#1s, T#0ms]");
    CHECK(printed(ARRAY<STRING<>, 1, 2>{STRING<>("a b")}) == "[a b, ]");
  }
}
