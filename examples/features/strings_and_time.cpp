// One feature: STRING(n) and TIME. A STRING has a fixed capacity and truncates on the right,
// never allocating; the string functions count positions from 1; TIME is written and read as
// ST writes it.
#include <fmt/core.h>

#include <iecoop/fmt.hpp>
#include <iecoop/iecoop.hpp>

using namespace iecoop;

int main() {
  // VAR sName : STRING(12) := 'conveyor belt one'; sLine : STRING(40); iAt : INT; END_VAR
  STRING<12> sName = "conveyor belt one";
  STRING<40> sLine;
  INT iAt;
  fmt::print("STRING(12) := 'conveyor belt one'   '{}'\n", sName);

  sLine = CONCAT("Station ", "A", ": ready");  // sLine := CONCAT('Station ', 'A', ': ready');
  iAt = FIND(sLine, ":");                      // iAt := FIND(sLine, ':');
  fmt::print("FIND(sLine, ':')                    {}\n", iAt);
  if (iAt > 0) {                   // IF iAt > 0 THEN
    sLine = LEFT(sLine, iAt - 1);  //     sLine := LEFT(sLine, iAt - 1);
  }                                // END_IF
  fmt::print("LEFT(sLine, iAt - 1)                '{}'\n", sLine);
  fmt::print("MID('SUSI', 2, 2)                   '{}'\n", MID("SUSI", 2, 2));
  fmt::print("REPLACE('SUXYSI', 'K', 2, 3)        '{}'\n", REPLACE("SUXYSI", "K", 2, 3));

  // VAR tRamp : TIME := T#1m30s; tHalf : TIME; END_VAR
  TIME tRamp = "T#1m30s"_iec;
  TIME tHalf = tRamp / 2;  // tHalf := tRamp / 2;
  fmt::print("T#1m30s / 2                         {}\n", tHalf);
  fmt::print("TIME_TO_DWORD(T#1m30s)              {} ms\n", TIME_TO_DWORD(tRamp));
  fmt::print("TIME_TO_STRING(T#1d2h3m4s5ms)       '{}'\n", TIME_TO_STRING("T#1d2h3m4s5ms"_iec));
  fmt::print("STRING_TO_TIME('T#2.5s')            {}\n", STRING_TO_TIME("T#2.5s"));
  fmt::print("STRING_TO_INT('16#FF')              {}\n", STRING_TO_INT("16#FF"));
  fmt::print("LTIME#1ms500us                      {}\n", "LTIME#1ms500us"_iec);
  fmt::print("sizeof(STRING(12))                  {} bytes, no heap\n", sizeof(sName));
}
