// One feature: the Util library's BCD conversions and bit functions — a two-digit BCD thumbwheel
// read and a BCD display written (BCD_TO_INT, INT_TO_BCD), a status DWORD's bits (EXTRACT,
// PUTBIT), eight BOOLs packed into a byte and unpacked again (PACK, UNPACK).
#include <fmt/core.h>

#include <iecoop/fmt.hpp>
#include <iecoop/iecoop.hpp>

using namespace iecoop;

int main() {
  // The documentation's examples.
  fmt::print("BCD_TO_INT(73) = {}, BCD_TO_INT(151) = {}, BCD_TO_INT(15) = {}\n", BCD_TO_INT(73), BCD_TO_INT(151),
             BCD_TO_INT(15));
  fmt::print("INT_TO_BCD(49) = {}, INT_TO_BCD(97) = {}, INT_TO_BCD(100) = {}\n", INT_TO_BCD(49), INT_TO_BCD(97),
             INT_TO_BCD(100));
  fmt::print("EXTRACT(X := 81, N := 4) = {}, EXTRACT(X := 33, N := 0) = {}\n", EXTRACT(81, 4), EXTRACT(33, 0));
  const DWORD var1 = 38;                       // var1 := 38;   (2#100110)
  const DWORD var2 = PUTBIT(var1, 4, TRUE);    // var2 := PUTBIT(var1, 4, TRUE);    (54 = 2#110110)
  const DWORD var3 = PUTBIT(var1, 1, FALSE);   // var3 := PUTBIT(var1, 1, FALSE);   (36 = 2#100100)
  fmt::print("PUTBIT(38, 4, TRUE) = {}, PUTBIT(38, 1, FALSE) = {}\n", var2, var3);

  // A thumbwheel in BCD on %IB0 shows 16#42; the display on %QB0 shows the value + 1 in BCD.
  const BYTE byWheel = BYTE(0x42);
  const INT iValue = BCD_TO_INT(byWheel);              // iValue := BCD_TO_INT(byWheel);
  const BYTE byDisplay = INT_TO_BCD(iValue + INT(1));  // byDisplay := INT_TO_BCD(iValue + 1);
  fmt::print("wheel {} (16#42) -> {} -> display {} (16#43)\n", byWheel, iValue, byDisplay);

  // fbBits : UNPACK;   fbBits(B := PACK(TRUE, FALSE, TRUE, TRUE, FALSE, FALSE, FALSE, TRUE));
  UNPACK fbBits;
  fbBits("B"_ = PACK(TRUE, FALSE, TRUE, TRUE, FALSE, FALSE, FALSE, TRUE));
  fmt::print("PACK: {}; UNPACK: B0 {} B1 {} B2 {} B3 {} B4 {} B5 {} B6 {} B7 {}\n", fbBits.B, fbBits.B0, fbBits.B1,
             fbBits.B2, fbBits.B3, fbBits.B4, fbBits.B5, fbBits.B6, fbBits.B7);
}
