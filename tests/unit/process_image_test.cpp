// Direct addresses, the process image and located variables (ST's AT %IX0.5): parsing in
// both addressing modes, aliasing of the same bytes at different widths, little-endian
// layout, typed reads and writes, expressions, and the LOCATED overlap check. (Misuse is in
// the compile-fail tests located_*.)
#include "iecoop_test.hpp"

#include <iecoop/io/address.hpp>
#include <iecoop/io/located.hpp>

#include <cstddef>
#include <cstdint>
#include <type_traits>

using namespace iecoop;

namespace {

// ---------------------------------------------------------------------------------------
// Addresses

constexpr io_address parsed(std::string_view text) { return parse_address(text).value(); }
constexpr address_error error_of(std::string_view text) { return parse_address(text).error(); }

// Every width, with and without X.
static_assert(address_of<"%IX0.5"> == io_address{io_area::input, io_width::bit, 0, 5});
static_assert(address_of<"%I5.5"> == io_address{io_area::input, io_width::bit, 5, 5});
static_assert(address_of<"%QX7.0"> == io_address{io_area::output, io_width::bit, 7, 0});
static_assert(address_of<"%QB7"> == io_address{io_area::output, io_width::byte, 7, 0});
static_assert(address_of<"%IW215"> == io_address{io_area::input, io_width::word, 215, 0});
static_assert(address_of<"%MD48"> == io_address{io_area::memory, io_width::dword, 48, 0});
static_assert(address_of<"%ML3"> == io_address{io_area::memory, io_width::lword, 3, 0});
static_assert(address_of<"%ix1.7"> == address_of<"%IX1.7">);  // letters in either case
static_assert(address_of<"%mw2"> == address_of<"%MW2">);

// CODESYS: the number counts units of the size ("%IW5 always addresses word 5").
static_assert(address_of<"%IX5.5">.first_byte(addressing::codesys) == 5);
static_assert(address_of<"%IB5">.first_byte(addressing::codesys) == 5);
static_assert(address_of<"%IW5">.first_byte(addressing::codesys) == 10);
static_assert(address_of<"%ID5">.first_byte(addressing::codesys) == 20);
static_assert(address_of<"%IL5">.first_byte(addressing::codesys) == 40);
static_assert(address_of<"%MD48">.first_byte(addressing::codesys) == 192);
// TwinCAT: the number is the byte offset, whatever the size.
static_assert(address_of<"%IX5.5">.first_byte(addressing::byte_offset) == 5);
static_assert(address_of<"%IW5">.first_byte(addressing::byte_offset) == 5);
static_assert(address_of<"%MD48">.first_byte(addressing::byte_offset) == 48);
static_assert(address_of<"%IL5">.first_byte(addressing::byte_offset) == 5);

static_assert(address_of<"%IX0.5">.byte_count() == 1 && address_of<"%IB0">.byte_count() == 1);
static_assert(address_of<"%IW0">.byte_count() == 2 && address_of<"%ID0">.byte_count() == 4 &&
              address_of<"%IL0">.byte_count() == 8);
static_assert(address_of<"%IX3.5">.first_bit(addressing::codesys) == 29 && address_of<"%IX3.5">.bit_count() == 1);
static_assert(address_of<"%IW1">.first_bit(addressing::codesys) == 16 && address_of<"%IW1">.bit_count() == 16);

// Overlap of two addresses: same area and at least one shared bit.
static_assert(!address_of<"%IX0.0">.overlaps(address_of<"%IX0.1">, addressing::codesys));  // two bits of one byte
static_assert(address_of<"%IX0.5">.overlaps(address_of<"%IB0">, addressing::codesys));
static_assert(!address_of<"%IX0.5">.overlaps(address_of<"%QB0">, addressing::codesys));  // another area
static_assert(address_of<"%IW2">.overlaps(address_of<"%IB5">, addressing::codesys));     // bytes 4..5
static_assert(!address_of<"%IW2">.overlaps(address_of<"%IB3">, addressing::codesys));
static_assert(address_of<"%IW2">.overlaps(address_of<"%IB3">, addressing::byte_offset));  // bytes 2..3
static_assert(address_of<"%MD1">.overlaps(address_of<"%MW3">, addressing::codesys));      // bytes 4..7 and 6..7
static_assert(!address_of<"%MD1">.overlaps(address_of<"%MW4">, addressing::codesys));
static_assert(address_of<"%ML0">.overlaps(address_of<"%MD1">, addressing::codesys));
static_assert(address_of<"%IX4.0">.overlaps(address_of<"%IW2">, addressing::codesys));

// Bounds of the bit number and of the number.
static_assert(parsed("%IX0.7").bit == 7);
static_assert(error_of("%IX0.8") == address_error::bit_out_of_range);
static_assert(error_of("%IX0.99999999999") == address_error::bit_out_of_range);
static_assert(parsed("%IB268435455").number == max_address_number);
static_assert(error_of("%IB268435456") == address_error::number_too_large);
static_assert(address_of<"%IL268435455">.first_byte(addressing::codesys) + 8u > 0u);  // fits 32 bits

// Every error the parser reports (each is a compile error in address_of<>).
static_assert(error_of("") == address_error::empty);
static_assert(error_of("IX0.0") == address_error::missing_percent);
static_assert(error_of("%") == address_error::bad_area);
static_assert(error_of("%AX0.0") == address_error::bad_area);
static_assert(error_of("%I*") == address_error::incomplete);
static_assert(error_of("%QX*") == address_error::incomplete);
static_assert(error_of("%IZ0") == address_error::bad_size);
static_assert(error_of("%IX") == address_error::expected_number);
static_assert(error_of("%IX0.") == address_error::expected_number);
static_assert(error_of("%I-1") == address_error::expected_number);
// Without byte.bit, a bit address is IEC's flat bit number: %IX5 = bit 5 of byte 0.
static_assert(address_of<"%IX5"> == io_address{io_area::input, io_width::bit, 0, 5});
static_assert(address_of<"%I5"> == address_of<"%IX0.5">);
static_assert(address_of<"%QX75"> == address_of<"%QX9.3">);
static_assert(address_of<"%MX8"> == address_of<"%MX1.0">);
static_assert(error_of("%IB2.4") == address_error::bit_on_wide_address);
static_assert(error_of("%IW2.5.7.1") == address_error::hierarchical);
static_assert(error_of("%IX2.5.7") == address_error::hierarchical);
static_assert(error_of("%IW2x") == address_error::trailing_characters);
static_assert(error_of("%IX0.5 ") == address_error::trailing_characters);
static_assert(parse_address("%QW2").has_value() && !parse_address("%QW"));
// Like a literal's parse_result, a failed address says where the text went wrong.
static_assert(parse_address("IX0.0").position() == 0);
static_assert(parse_address("%AX0.0").position() == 1);
static_assert(parse_address("%IW2x").position() == 4);
static_assert(parse_address("%QW").value_or(io_address{io_area::memory, io_width::byte, 7, 0}).number == 7);

// ---------------------------------------------------------------------------------------
// Process images (each test has its own tag, so its bytes are its own)

struct alias_tag;
using alias_image = process_image<16, 16, 64, addressing::codesys, alias_tag>;
struct offset_tag;
using offset_image = process_image<16, 16, 64, addressing::byte_offset, offset_tag>;

static_assert(default_process_image::input_bytes == 64 && default_process_image::output_bytes == 64 &&
              default_process_image::memory_bytes == 256 && default_process_image::mode == addressing::codesys);
static_assert(std::is_same_v<decltype(alias_image::inputs()), std::span<std::byte, 16>>);
static_assert(std::is_same_v<decltype(alias_image::memory()), std::span<std::byte, 64>>);
static_assert(alias_image::size_of(io_area::memory) == 64);

unsigned byte_at(std::span<std::byte> area, std::size_t i) { return std::to_integer<unsigned>(area[i]); }

// On a big-endian machine the values are swapped into the image's little-endian order.
static_assert(detail::byte_swap<std::uint32_t>(0x11223344u) == 0x44332211u);
static_assert(detail::byte_swap<std::uint64_t>(0x0102030405060708u) == 0x0807060504030201u);
static_assert(detail::byte_swap<std::uint16_t>(0xABCD) == 0xCDAB);
static_assert(detail::byte_swap<std::uint8_t>(0x5A) == 0x5A);

// ---------------------------------------------------------------------------------------
// Located variables

struct located_tag;
using io_image = process_image<32, 32, 64, addressing::codesys, located_tag>;

struct GVL_IO {
  [[no_unique_address]] located<BOOL, "%IX0.5", io_image> bStart;
  [[no_unique_address]] located<BOOL, "%IX0.6", io_image> bStop;
  [[no_unique_address]] located<INT, "%IW1", io_image> iSpeed;
  [[no_unique_address]] located<BOOL, "%QX0.0", io_image> bMotor;
  [[no_unique_address]] located<INT, "%QW1", io_image> iSetpoint;
  [[no_unique_address]] located<WORD, "%QW2", io_image> wStatus;
  [[no_unique_address]] located<DINT, "%QD2", io_image> diCount;
  [[no_unique_address]] located<REAL, "%MD0", io_image> rGain;
  [[no_unique_address]] located<LREAL, "%ML1", io_image> lrTotal;
  [[no_unique_address]] located<TIME, "%MD4", io_image> tDelay;
  [[no_unique_address]] located<LINT, "%ML3", io_image> liPosition;
  [[no_unique_address]] located<LTIME, "%ML4", io_image> ltUptime;
  [[no_unique_address]] located<BOOL, "%MB40", io_image> xFlag;  // a BOOL allocated byte-wise
  using LOCATED = pins<&GVL_IO::bStart, &GVL_IO::bStop, &GVL_IO::iSpeed, &GVL_IO::bMotor, &GVL_IO::iSetpoint,
                       &GVL_IO::wStatus, &GVL_IO::diCount, &GVL_IO::rGain, &GVL_IO::lrTotal, &GVL_IO::tDelay,
                       &GVL_IO::liPosition, &GVL_IO::ltUptime, &GVL_IO::xFlag>;
};

// Empty: a located variable is its address; the list of them takes no room.
static_assert(std::is_empty_v<located<BOOL, "%IX0.5">> && std::is_empty_v<located<LREAL, "%ML1">>);
static_assert(sizeof(GVL_IO) == 1);
static_assert(located<INT, "%IW1", io_image>::address == address_of<"%IW1">);
static_assert(std::is_same_v<located<INT, "%IW1">::value_type, INT> &&
              std::is_same_v<located<INT, "%IW1">::image_type, default_process_image>);
static_assert(located_disjoint<GVL_IO>);

// Eight BOOLs in one byte do not overlap; neither do variables in different images.
struct GVL_Bits {
  [[no_unique_address]] located<BOOL, "%IX0.0"> x0;
  [[no_unique_address]] located<BOOL, "%IX0.1"> x1;
  [[no_unique_address]] located<BOOL, "%IX0.2"> x2;
  [[no_unique_address]] located<BOOL, "%IX0.3"> x3;
  [[no_unique_address]] located<BOOL, "%IX0.4"> x4;
  [[no_unique_address]] located<BOOL, "%IX0.5"> x5;
  [[no_unique_address]] located<BOOL, "%IX0.6"> x6;
  [[no_unique_address]] located<BOOL, "%IX0.7"> x7;
  [[no_unique_address]] located<BYTE, "%QB0"> byOut;                 // same byte number, another area
  [[no_unique_address]] located<BYTE, "%IB0", alias_image> byOther;  // same address, another image
  using LOCATED = pins<&GVL_Bits::x0, &GVL_Bits::x1, &GVL_Bits::x2, &GVL_Bits::x3, &GVL_Bits::x4, &GVL_Bits::x5,
                       &GVL_Bits::x6, &GVL_Bits::x7, &GVL_Bits::byOut, &GVL_Bits::byOther>;
};
static_assert(located_disjoint<GVL_Bits>);
static_assert(located_disjoint<GVL_Bits, GVL_IO>);
static_assert(located_disjoint<GVL_IO, GVL_IO>);  // the same variable listed twice is no overlap
static_assert(located_disjoint<int, GVL_Bits>);   // a type without LOCATED lists nothing
static_assert(located_disjoint<>);

// Overlaps are found (check_located<> would stop compilation on them).
struct GVL_Alias {
  [[no_unique_address]] located<BOOL, "%IX0.5"> bStart;
  [[no_unique_address]] located<BYTE, "%IB0"> byInputs;
  using LOCATED = pins<&GVL_Alias::bStart, &GVL_Alias::byInputs>;
};
static_assert(!located_disjoint<GVL_Alias>);
struct PRG_Word {
  [[no_unique_address]] located<INT, "%IW2"> iLevel;  // bytes 4..5
  using LOCATED = pins<&PRG_Word::iLevel>;
};
struct PRG_Byte {
  [[no_unique_address]] located<BYTE, "%IB5"> byStatus;
  using LOCATED = pins<&PRG_Byte::byStatus>;
};
struct PRG_ByteBefore {
  [[no_unique_address]] located<BYTE, "%IB3"> byStatus;
  using LOCATED = pins<&PRG_ByteBefore::byStatus>;
};
static_assert(!located_disjoint<PRG_Word, PRG_Byte>);  // across two programs
static_assert(located_disjoint<PRG_Word, PRG_ByteBefore>);
struct Dup_A {
  [[no_unique_address]] located<BOOL, "%QX1.1"> bLamp;
  using LOCATED = pins<&Dup_A::bLamp>;
};
struct Dup_B {
  [[no_unique_address]] located<BOOL, "%QX1.1"> bHorn;  // the same output in two programs
  using LOCATED = pins<&Dup_B::bHorn>;
};
static_assert(!located_disjoint<Dup_A, Dup_B>);

// byte_offset images: %MW6 is bytes 6..7, so %MW7 overlaps it.
struct Offset_GVL {
  [[no_unique_address]] located<WORD, "%MW6", offset_image> wA;
  [[no_unique_address]] located<WORD, "%MW7", offset_image> wB;
  using LOCATED = pins<&Offset_GVL::wA, &Offset_GVL::wB>;
};
static_assert(!located_disjoint<Offset_GVL>);
struct Codesys_GVL {
  [[no_unique_address]] located<WORD, "%MW6"> wA;  // bytes 12..13
  [[no_unique_address]] located<WORD, "%MW7"> wB;  // bytes 14..15
  using LOCATED = pins<&Codesys_GVL::wA, &Codesys_GVL::wB>;
};
static_assert(located_disjoint<Codesys_GVL>);

}  // namespace

TEST_SUITE("process image") {
  TEST_CASE("a bit and the byte it lies in are the same memory") {
    alias_image::clear();
    alias_image::write<BOOL, "%IX0.5">(TRUE);
    CHECK(alias_image::read<BYTE, "%IB0">() == 32);
    CHECK(byte_at(alias_image::inputs(), 0) == 32u);
    CHECK(alias_image::read<BOOL, "%I0.5">() == TRUE);  // %I0.5 is %IX0.5
    CHECK(alias_image::read<BOOL, "%IX0.4">() == FALSE);

    alias_image::write<BYTE, "%IB0">(BYTE(0xFF));
    alias_image::write<BOOL, "%IX0.3">(FALSE);  // clears one bit, keeps the others
    CHECK(alias_image::read<BYTE, "%IB0">() == 0xF7);
    CHECK(alias_image::read<BOOL, "%IX0.7">() == TRUE);
  }

  TEST_CASE("CODESYS addressing: %IW2 is bytes 4..5, little-endian") {
    alias_image::clear();
    alias_image::write<INT, "%IW2">(INT(0x1234));
    CHECK(alias_image::read<BYTE, "%IB4">() == 0x34);
    CHECK(alias_image::read<BYTE, "%IB5">() == 0x12);
    CHECK(alias_image::read<BYTE, "%IB2">() == 0);
    CHECK(alias_image::read<BOOL, "%IX4.2">() == TRUE);  // 0x34 = 0011'0100
    CHECK(alias_image::read<BOOL, "%IX4.0">() == FALSE);
    CHECK(alias_image::read<BOOL, "%IX5.4">() == TRUE);  // 0x12 = 0001'0010
    CHECK(byte_at(alias_image::inputs(), 4) == 0x34u);
    CHECK(byte_at(alias_image::inputs(), 5) == 0x12u);

    alias_image::write<BOOL, "%IX4.0">(TRUE);
    CHECK(alias_image::read<WORD, "%IW2">() == 0x1235);
    CHECK(alias_image::read<UINT, "%IW2">() == 0x1235u);
  }

  TEST_CASE("%MD1 is %MW2 and %MW3, %ML0 is %MD0 and %MD1") {
    alias_image::clear();
    alias_image::write<DWORD, "%MD1">(DWORD(0x11223344u));
    CHECK(alias_image::read<WORD, "%MW2">() == 0x3344);
    CHECK(alias_image::read<WORD, "%MW3">() == 0x1122);
    CHECK(alias_image::read<DWORD, "%MD0">() == 0u);
    CHECK(byte_at(alias_image::memory(), 4) == 0x44u);
    CHECK(byte_at(alias_image::memory(), 7) == 0x11u);

    alias_image::write<LWORD, "%ML0">(LWORD(0x0102030405060708u));
    CHECK(alias_image::read<DWORD, "%MD0">() == 0x05060708u);
    CHECK(alias_image::read<DWORD, "%MD1">() == 0x01020304u);
    CHECK(alias_image::read<BYTE, "%MB0">() == 0x08);
    CHECK(alias_image::read<BYTE, "%MB7">() == 0x01);
  }

  TEST_CASE("byte_offset addressing: the number is the byte") {
    offset_image::clear();
    offset_image::write<WORD, "%MW6">(WORD(0xABCD));
    CHECK(byte_at(offset_image::memory(), 6) == 0xCDu);
    CHECK(byte_at(offset_image::memory(), 7) == 0xABu);
    CHECK(offset_image::read<BYTE, "%MB7">() == 0xAB);
    CHECK(offset_image::read<WORD, "%MW7">() == 0x00AB);  // bytes 7..8
    offset_image::write<DWORD, "%MD8">(DWORD(0xDEADBEEFu));
    CHECK(offset_image::read<WORD, "%MW8">() == 0xBEEF);
    CHECK(offset_image::read<WORD, "%MW10">() == 0xDEAD);
    offset_image::write<BOOL, "%QX3.1">(TRUE);
    CHECK(offset_image::read<BYTE, "%QB3">() == 2);
  }

  TEST_CASE("values are stored little-endian in their IEC representation") {
    alias_image::clear();
    alias_image::write<REAL, "%QD0">(REAL(1.0f));  // 0x3F800000
    CHECK(byte_at(alias_image::outputs(), 0) == 0x00u);
    CHECK(byte_at(alias_image::outputs(), 2) == 0x80u);
    CHECK(byte_at(alias_image::outputs(), 3) == 0x3Fu);
    CHECK(alias_image::read<DWORD, "%QD0">() == 0x3F800000u);

    alias_image::write<LREAL, "%QL1">(LREAL(-2.5));  // 0xC004000000000000
    CHECK(alias_image::read<LWORD, "%QL1">() == 0xC004000000000000u);
    CHECK(byte_at(alias_image::outputs(), 15) == 0xC0u);

    alias_image::write<SINT, "%QB4">(SINT(-1));
    CHECK(alias_image::read<USINT, "%QB4">() == 255u);
    alias_image::write<DINT, "%QD1">(DINT(-2));
    CHECK(alias_image::read<UDINT, "%QD1">() == 0xFFFFFFFEu);
    alias_image::write<TIME, "%MD2">("T#1s500ms"_iec);
    CHECK(alias_image::read<UDINT, "%MD2">() == 1500u);
    alias_image::write<LTIME, "%ML2">("LTIME#1ms"_iec);
    CHECK(alias_image::read<ULINT, "%ML2">() == 1000000u);
  }

  TEST_CASE("a BOOL at a byte address is the whole byte: TRUE is 1, any other value than 0 reads TRUE") {
    alias_image::clear();
    alias_image::write<BOOL, "%MB3">(TRUE);
    CHECK(alias_image::read<BYTE, "%MB3">() == 1);
    alias_image::write<BYTE, "%MB3">(BYTE(0x10));
    CHECK(alias_image::read<BOOL, "%MB3">() == TRUE);
    alias_image::write<BOOL, "%MB3">(FALSE);
    CHECK(alias_image::read<BYTE, "%MB3">() == 0);
  }

  TEST_CASE("area() and clear()") {
    alias_image::write<BYTE, "%IB1">(BYTE(1));
    alias_image::write<BYTE, "%QB2">(BYTE(2));
    alias_image::write<BYTE, "%MB3">(BYTE(3));
    CHECK(alias_image::area(io_area::input).size() == 16u);
    CHECK(alias_image::area(io_area::memory).size() == 64u);
    CHECK(byte_at(alias_image::area(io_area::input), 1) == 1u);
    CHECK(byte_at(alias_image::area(io_area::output), 2) == 2u);
    CHECK(byte_at(alias_image::area(io_area::memory), 3) == 3u);
    CHECK(alias_image::area(io_area::output).data() == alias_image::outputs().data());
    alias_image::clear();
    for (std::byte b : alias_image::inputs()) CHECK(b == std::byte{0});
    for (std::byte b : alias_image::outputs()) CHECK(b == std::byte{0});
    for (std::byte b : alias_image::memory()) CHECK(b == std::byte{0});
  }

  TEST_CASE("images with different tags have different bytes") {
    alias_image::clear();
    offset_image::clear();
    alias_image::write<BYTE, "%IB0">(BYTE(7));
    CHECK(offset_image::read<BYTE, "%IB0">() == 0);
    CHECK(alias_image::inputs().data() != offset_image::inputs().data());
  }
}

// A derived block lists only the located variables it adds; the check sees its base's too.
struct FB_IoBase : function_block<FB_IoBase> {
  [[no_unique_address]] located<BOOL, "%QX3.0", io_image> bBaseOut;
  using LOCATED = pins<&FB_IoBase::bBaseOut>;
  virtual void body() {}
  virtual ~FB_IoBase() = default;
};
struct FB_IoDerived : extends<FB_IoDerived, FB_IoBase> {
  [[no_unique_address]] located<BYTE, "%QB3", io_image> byDerived;  // shares bit 0 of byte 3 with bBaseOut
  using LOCATED = pins<&FB_IoDerived::byDerived>;
  void body() override {}
};
struct FB_IoDerivedApart : extends<FB_IoDerivedApart, FB_IoBase> {
  [[no_unique_address]] located<BYTE, "%QB4", io_image> byDerived;
  using LOCATED = pins<&FB_IoDerivedApart::byDerived>;
  void body() override {}
};
static_assert(!located_disjoint<FB_IoDerived>);
static_assert(located_disjoint<FB_IoDerivedApart>);
static_assert(located_disjoint<FB_IoBase>);

TEST_SUITE("located variables") {
  TEST_CASE("at<\"%...\"> is a directly represented variable: %IX5 in an expression, %QX1.0 := TRUE") {
    io_image::clear();
    io_image::write<BYTE, "%IB0">(BYTE(0x20));
    CHECK(static_cast<bool>(at<"%IX5", io_image>));  // IEC's flat bit 5: bit 5 of byte 0
    CHECK_FALSE(static_cast<bool>(at<"%IX4", io_image>));
    at<"%QX1.0", io_image> = TRUE;  // %QX1.0 := TRUE;
    CHECK(io_image::read<BYTE, "%QB1">() == 1);
    at<"%MW2", io_image> = WORD(0x1234);  // %MW2 := 16#1234; (a WORD: the size's type)
    CHECK(io_image::read<BYTE, "%MB4">() == 0x34);
    const WORD w = at<"%MW2", io_image>;
    CHECK(w == 0x1234);
    static_assert(std::is_same_v<decltype(at<"%ID1", io_image>)::value_type, DWORD>);
    static_assert(std::is_same_v<decltype(at<"%QL0", io_image>)::value_type, LWORD>);
    io_image::clear();
  }

  TEST_CASE("reading inputs and writing outputs of every size") {
    io_image::clear();
    GVL_IO io;
    io_image::write<BOOL, "%IX0.5">(TRUE);
    io_image::write<INT, "%IW1">(INT(-300));
    CHECK(io.bStart == TRUE);
    CHECK(io.bStop == FALSE);
    CHECK(io.iSpeed == -300);
    CHECK(io.iSpeed.get() == INT(-300));
    const INT speed = io.iSpeed;
    CHECK(speed == -300);

    io.bMotor = TRUE;
    io.iSetpoint = 1234;
    io.wStatus = WORD(0xBEEF);
    io.diCount = DINT(-100000);
    io.rGain = 0.5f;
    io.lrTotal = 1e10;
    io.tDelay = "T#2s"_iec;
    io.liPosition = LINT(-5);
    io.ltUptime = "LTIME#3h"_iec;
    io.xFlag = TRUE;

    CHECK(io_image::read<BOOL, "%QX0.0">() == TRUE);
    CHECK(io_image::read<BYTE, "%QB0">() == 1);
    CHECK(io_image::read<INT, "%QW1">() == 1234);
    CHECK(io_image::read<WORD, "%QW2">() == 0xBEEF);
    CHECK(io_image::read<DINT, "%QD2">() == -100000);  // bytes 8..11, after %QW2 (bytes 4..5)
    CHECK(io_image::read<REAL, "%MD0">() == 0.5f);
    CHECK(io_image::read<LREAL, "%ML1">() == 1e10);
    CHECK(io_image::read<TIME, "%MD4">() == "T#2s"_iec);
    CHECK(io_image::read<ULINT, "%ML3">() == 0xFFFFFFFFFFFFFFFBu);
    CHECK(io_image::read<LTIME, "%ML4">() == "LTIME#3h"_iec);
    CHECK(io_image::read<BYTE, "%MB40">() == 1);

    // ... and read back through the variables.
    CHECK(io.bMotor == TRUE);
    CHECK(io.iSetpoint == 1234);
    CHECK(io.wStatus == WORD(0xBEEF));
    CHECK(io.diCount == -100000);
    CHECK(io.rGain == 0.5f);
    CHECK(io.lrTotal == 1e10);
    CHECK(io.tDelay == "T#2s"_iec);
    CHECK(io.liPosition == -5);
    CHECK(io.ltUptime == "LTIME#3h"_iec);
    CHECK(io.xFlag == TRUE);
  }

  TEST_CASE("located variables in expressions and conditions") {
    io_image::clear();
    GVL_IO io;
    io_image::write<BOOL, "%IX0.5">(TRUE);
    io_image::write<INT, "%IW1">(INT(120));

    io.bMotor = io.bStart & !io.bStop;  // bMotor := bStart AND NOT bStop;
    CHECK(io.bMotor == TRUE);
    io.iSetpoint = io.iSpeed + 1;  // iSetpoint := iSpeed + 1;
    CHECK(io.iSetpoint == 121);
    io.iSetpoint = io.iSpeed * io.iSetpoint - INT(20000);
    CHECK(io.iSetpoint == static_cast<INT>(120 * 121 - 20000));
    CHECK(io.iSpeed > 100);
    CHECK(io.iSpeed != io.iSetpoint);
    int branch = 0;
    if (io.bStart) branch = 1;
    if (!io.bStop) branch += 2;
    if (io.bStart && io.iSpeed > 100) branch += 4;
    CHECK(branch == 7);

    io.rGain = 1.5f;
    io.lrTotal = io.rGain * 2.0f;
    CHECK(io.lrTotal == 3.0);
    const DINT wide = io.iSpeed.get();  // implicit widening of the value, as from an INT
    CHECK(wide == 120);

    io_image::write<BOOL, "%IX0.6">(TRUE);
    io.bMotor = io.bStart & !io.bStop;
    CHECK(io.bMotor == FALSE);
    io.bMotor = io.bStart;  // one located variable to another: copies the value
    CHECK(io_image::read<BOOL, "%QX0.0">() == TRUE);
  }

  TEST_CASE("compound assignment, increment and BOOL operators") {
    io_image::clear();
    GVL_IO io;
    io.iSetpoint = 10;
    io.iSetpoint += 5;
    io.iSetpoint -= 1;
    io.iSetpoint *= 3;
    io.iSetpoint /= 2;
    ++io.iSetpoint;
    CHECK(io.iSetpoint == 22);
    --io.iSetpoint;
    CHECK(io.iSetpoint == 21);
    io.iSetpoint = 32767;
    ++io.iSetpoint;  // wraps, as every INT does
    CHECK(io.iSetpoint == -32768);
    io.wStatus = WORD(0x00F0);
    io.wStatus |= WORD(0x000F);
    io.wStatus &= WORD(0x0FF0);
    io.wStatus ^= WORD(0x0001);
    CHECK(io.wStatus == 0x00F1);
    io.bMotor = FALSE;
    io.bMotor |= TRUE;
    CHECK(io.bMotor == TRUE);
    io.bMotor ^= TRUE;
    CHECK(io.bMotor == FALSE);
  }

  TEST_CASE("a located variable is its address: two objects are one variable") {
    io_image::clear();
    located<INT, "%QW1", io_image> a;
    located<INT, "%QW1", io_image> b;
    a = 42;
    CHECK(b == 42);
    b = a;  // the same variable: nothing to copy
    CHECK(a == 42);
    GVL_IO first;
    GVL_IO second = first;  // copying a list of located variables copies no I/O
    second.iSetpoint = 7;
    CHECK(first.iSetpoint == 7);
  }

  TEST_CASE("located variables as the inputs and outputs of a block call") {
    io_image::clear();
    GVL_IO io;
    io_image::write<BOOL, "%IX0.5">(TRUE);
    R_TRIG trig;
    trig("CLK"_ = io.bStart, "Q"_ >> io.bMotor);  // trig(CLK := bStart, Q => bMotor);
    CHECK(io.bMotor == TRUE);
    trig("CLK"_ = io.bStart, "Q"_ >> io.bMotor);
    CHECK(io.bMotor == FALSE);
    CTU ctu;
    ctu("CU"_ = io.bStart, "PV"_ = 5, "CV"_ >> io.wStatus);  // CODESYS's CV is a WORD
    CHECK(io.wStatus == 1);
  }

  TEST_CASE("located variables of the default image, and a program listing them") {
    default_process_image::clear();
    struct PLC_PRG {
      [[no_unique_address]] located<BOOL, "%IX0.0"> bIn;
      [[no_unique_address]] located<BOOL, "%QX0.0"> bOut;
      [[no_unique_address]] located<INT, "%MW0"> iCycles;
      using LOCATED = pins<&PLC_PRG::bIn, &PLC_PRG::bOut, &PLC_PRG::iCycles>;
      void body() {
        bOut = !bIn;
        ++iCycles;
      }
    };
    check_located<PLC_PRG, GVL_IO>();                     // disjoint: compiles
    static_assert(!located_disjoint<PLC_PRG, GVL_Bits>);  // %IX0.0 twice (and %QX0.0 in %QB0)
    static_assert(PLC_PRG::LOCATED::names[2] == "iCycles");
    PLC_PRG prg;
    prg.body();
    CHECK(default_process_image::read<BOOL, "%QX0.0">() == TRUE);
    default_process_image::write<BOOL, "%IX0.0">(TRUE);
    prg.body();
    CHECK(prg.bOut == FALSE);
    CHECK(prg.iCycles == 2);
    default_process_image::clear();
  }
}
