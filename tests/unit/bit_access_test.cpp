// ST's bit access x.N as bit<N>(x): read and written, on integers, bit strings and every kind
// of variable, with the bit number checked while compiling.
#include <type_traits>

#include "iecoop_test.hpp"

using namespace iecoop;
using iecoop_test::opaque;

namespace {

struct FB_Drive : function_block<FB_Drive> {
  WORD wControl;        // VAR_INPUT wControl : WORD; END_VAR
  var<WORD> wStatus;    // VAR wStatus : WORD; END_VAR
  retain<DWORD> dwLog;  // VAR RETAIN dwLog : DWORD; END_VAR
  using VAR_INPUT = pins<&FB_Drive::wControl>;
  void body() {
    bit<0>(wStatus) = bit<0>(wControl);  // wStatus.0 := wControl.0;
    bit<15>(wStatus) = TRUE;             // wStatus.15 := TRUE;
    bit<31>(dwLog) = bit<7>(wControl);   // dwLog.31 := wControl.7;
  }
};

}  // namespace

TEST_SUITE("bit access x.N") {
  TEST_CASE("reading a bit of a bit string and of an integer") {
    const WORD w = opaque(WORD(0x8005));
    CHECK(bit<0>(w) == TRUE);
    CHECK(bit<1>(w) == FALSE);
    CHECK(bit<2>(w) == TRUE);
    CHECK(bit<15>(w) == TRUE);
    const INT i = opaque(INT(-1));
    CHECK(bit<15>(i) == TRUE);  // the sign bit of an INT
    CHECK(bit<0>(DINT(6)) == FALSE);
    CHECK(bit<63>(LWORD(0x8000'0000'0000'0000ull)) == TRUE);
    static_assert(bit<3>(BYTE(0x08)) == TRUE);
    static_assert(std::is_same_v<decltype(bit<3>(std::declval<const BYTE&>())), BOOL>);
  }

  TEST_CASE("writing a bit sets or clears it and leaves the others") {
    WORD w = 0x00F0;
    bit<0>(w) = TRUE;
    CHECK(w == 0x00F1);
    bit<4>(w) = FALSE;
    CHECK(w == 0x00E1);
    bit<15>(w) = opaque(TRUE);
    CHECK(w == 0x80E1);
    BYTE b = 0;
    bit<7>(b) = bit<15>(w);  // b.7 := w.15;
    CHECK(b == 0x80);
    SINT si = 0;
    bit<7>(si) = TRUE;
    CHECK(si == -128);
  }

  TEST_CASE("a bit is a BOOL in conditions, expressions and standard functions") {
    WORD w = 0x0003;
    int taken = 0;
    if (bit<1>(w)) ++taken;
    CHECK(taken == 1);
    const BOOL both = bit<0>(w) & bit<1>(w);
    CHECK(both == TRUE);
    CHECK((bit<0>(w) & !bit<2>(w)) == TRUE);
    CHECK(AND(bit<0>(w), bit<1>(w), TRUE) == TRUE);
    CHECK(SEL(bit<2>(w), INT(10), INT(20)) == 10);
  }

  TEST_CASE("bits of a block's variables: VAR, inputs, RETAIN") {
    FB_Drive fb;
    fb("wControl"_ = WORD(0x0081));
    CHECK(fb.wStatus == 0x8001);
    CHECK(fb.dwLog == 0x8000'0000u);
    CHECK(bit<15>(fb.wStatus) == TRUE);  // read from outside
    bit<0>(fb.wControl) = FALSE;         // fbDrive.wControl.0 := FALSE;
    CHECK(fb.wControl == 0x0080);
  }

  TEST_CASE("bits of located variables") {
    struct GVL {
      [[no_unique_address]] located<WORD, "%QW3"> wOut;
      [[no_unique_address]] located<BYTE, "%IB5"> byIn;
    } gvl;
    gvl.wOut = 0;
    bit<9>(gvl.wOut) = TRUE;  // wOut.9 := TRUE;
    CHECK(gvl.wOut == 0x0200);
    CHECK(default_process_image::read<BOOL, "%QX7.1">() == TRUE);  // byte 7 (high byte of word 3), bit 1
    CHECK(bit<0>(gvl.byIn) == FALSE);
  }
}
