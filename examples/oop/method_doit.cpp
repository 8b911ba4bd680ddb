// Seed: CODESYS "Object 'Method'" — the tests of the method DoIt, called with named arguments
// in any order, positionally, and with inputs left out. The block, with the seed's ST beside
// it, is in method_doit.hpp, which the firmware example
// embedded/examples/property_and_method.cpp runs on a Cortex-M as well.
#include <doctest/doctest.h>

#include <iecoop/iecoop.hpp>
#include <iecoop/ostream.hpp>

#include "method_doit.hpp"

using namespace iecoop;
using seed_method_doit::FB_DoIt;

TEST_SUITE("seed: method DoIt") {
  TEST_CASE("named arguments in any order") {
    // PROGRAM PLC_PRG  VAR fbInstance : FB_DoIt; bFinishedMethod : BOOL; END_VAR
    FB_DoIt fbInstance;
    BOOL bFinishedMethod;
    // bFinishedMethod := fbInstance.DoIt(sInput_3 := 'Hello World ', iInput_2 := 16#FFFF, iInput_1 := 16);
    bFinishedMethod = fbInstance.DoIt({"sInput_3"_ = "Hello World ", "iInput_2"_ = 0xFFFF, "iInput_1"_ = 16});
    CHECK(bFinishedMethod == FALSE);  // 16 <> 16#FFFF
    CHECK(fbInstance.sLastText == "Hello World ");
    bFinishedMethod = fbInstance.DoIt({"iInput_2"_ = 16, "sInput_3"_ = "x", "iInput_1"_ = 0x10});
    CHECK(bFinishedMethod == TRUE);
  }

  TEST_CASE("positional arguments in declaration order") {
    FB_DoIt fbInstance;
    // bFinishedMethod := fbInstance.DoIt( 16, 16#FFFF,'Hello World ');    (English page)
    CHECK(fbInstance.DoIt({16, 0xFFFF, "Hello World "}) == FALSE);
    // bFinishedMethod := fbInstance.DoIt( 16, 16#0010,'Hello World ');    (German page)
    CHECK(fbInstance.DoIt({16, 0x0010, "Hello World "}) == TRUE);
    CHECK(fbInstance.sLastText == "Hello World ");
  }

  TEST_CASE("inputs left out take their initial values") {
    FB_DoIt fbInstance;
    // fbInstance.DoIt(iInput_1 := 0): iInput_2 starts at its initial value 0, sInput_3 at ''
    CHECK(fbInstance.DoIt({"iInput_1"_ = 0}) == TRUE);
    CHECK(fbInstance.sLastText == "");
    // Every call starts afresh: what the previous call passed is not remembered.
    CHECK(fbInstance.DoIt({"iInput_1"_ = 5, "iInput_2"_ = 5, "sInput_3"_ = "abc"}) == TRUE);
    CHECK(fbInstance.DoIt({"iInput_1"_ = 5}) == FALSE);
    CHECK(fbInstance.sLastText == "");
    // DoItWithDefault(iInput_1 := 16#10): iInput_2 takes its declared initial value 16#10
    CHECK(fbInstance.DoItWithDefault({"iInput_1"_ = 0x10}) == TRUE);
    CHECK(fbInstance.DoItWithDefault(0x10) == TRUE);  // one positional argument, no braces
    CHECK(fbInstance.DoItWithDefault({0x10, 0x11}) == FALSE);
  }

  TEST_CASE("STRING(12) truncates a longer third input on the right") {
    FB_DoIt fbInstance;
    fbInstance.DoIt({"sInput_3"_ = "Hello World, again", "iInput_1"_ = 1});
    CHECK(fbInstance.sLastText == "Hello World,");
    fbInstance.DoIt({1, 2, "0123456789ABCDEF"});
    CHECK(fbInstance.sLastText == "0123456789AB");
    CHECK(LEN(fbInstance.sLastText) == 12);
  }
}
