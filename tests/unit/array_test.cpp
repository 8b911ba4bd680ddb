// ARRAY with IEC bounds: layout, indexing, initial values, LOWER_BOUND/UPPER_BOUND, ARRAY[*]
// in-outs, ARRAY OF blocks, comparing ARRAYs, and CheckBounds' fault path.
#include <cstdint>
#include <cstring>
#include <type_traits>

#include "iecoop_test.hpp"

using namespace iecoop;
using iecoop_test::fault_recorder;
using iecoop_test::opaque;

namespace {

struct ST_Part {
  INT p1;
  INT p2;
  DWORD p3;
};

enum E_Axis : std::int16_t { X = 1, Y, Z };
}  // namespace
template <>
inline constexpr auto iecoop::enum_components<E_Axis> = iecoop::components<X, Y, Z>{};
namespace {

// FUNCTION F_Sum : DINT  VAR_IN_OUT aValues : ARRAY[*] OF INT; END_VAR
DINT F_Sum(in_out<ARRAY<INT, '*'>> aValues) {
  DINT sum = 0;
  for (DINT i = LOWER_BOUND(aValues, 1); i <= UPPER_BOUND(aValues, 1); i = i + 1) sum = sum + aValues[i];
  return sum;
}

// A block with a two-dimensional ARRAY[*, *] in-out, called with ST's named argument.
struct FB_Total : function_block<FB_Total> {
  in_out<ARRAY<REAL, '*', '*'>> aGrid;
  var<LREAL> lrTotal;
  var<DINT> nRows;
  using VAR_IN_OUT = pins<&FB_Total::aGrid>;
  void body() {
    lrTotal = 0.0;
    nRows = UPPER_BOUND(aGrid, 1) - LOWER_BOUND(aGrid, 1) + 1;
    for (DINT i = LOWER_BOUND(aGrid, 1); i <= UPPER_BOUND(aGrid, 1); i = i + 1) {
      for (DINT j = LOWER_BOUND(aGrid, 2); j <= UPPER_BOUND(aGrid, 2); j = j + 1) {
        lrTotal = lrTotal + aGrid(i, j);
      }
    }
  }
};

// A block holding ARRAYs as VARs: indexing goes through var<>.
struct FB_Buffer : function_block<FB_Buffer> {
  INT iIn;
  var<ARRAY<INT, 1, 4>> aLast;
  var<ARRAY<INT, 0, 1, 0, 1>> aPairs;
  var<INT> iNext{1};
  using VAR_INPUT = pins<&FB_Buffer::iIn>;
  void body() {
    aLast[iNext] = iIn;
    aPairs(iNext % 2, 1) = iIn;
    iNext = iNext % 4 + 1;
  }
};

// A STRUCT with `=` of its own: ARRAYs of it compare element by element.
struct ST_Point {
  INT x;
  REAL y;
  bool operator==(const ST_Point&) const = default;
};

// Whether reading a[I] of an ARRAY[1..3] is a constant expression: the fault is not.
template <int I>
constexpr bool reads_element() {
  constexpr ARRAY<INT, 1, 3> a{1, 2, 3};
  return a[I].value() != 0;
}
template <int I>
concept constant_index = requires { typename std::integral_constant<bool, reads_element<I>()>; };

}  // namespace

TEST_SUITE("ARRAY") {
  TEST_CASE("an ARRAY is as large as its elements, zero-initialised and trivially copyable") {
    static_assert(sizeof(ARRAY<INT, 1, 10>) == 20);
    static_assert(sizeof(ARRAY<REAL, -5, 5, 0, 2>) == 4 * 11 * 3);
    static_assert(sizeof(ARRAY<BYTE, -2147483647 - 1, -2147483647 - 1>) == 1);
    static_assert(std::is_trivially_copyable_v<ARRAY<INT, 1, 10>>);
    static_assert(std::is_aggregate_v<ARRAY<INT, 1, 10>>);
    static_assert(ARRAY<INT, 1, 10>::rank == 1 && ARRAY<REAL, -5, 5, 0, 2>::rank == 2);
    static_assert(ARRAY<REAL, -5, 5, 0, 2>::element_count == 33);
    ARRAY<DINT, 1, 8> a;
    for (const DINT& x : a) CHECK(x == 0);
  }

  TEST_CASE("IEC bounds index the ARRAY from its lower bound") {
    ARRAY<INT, -3, 3> a;
    for (INT i = -3; i <= 3; i = i + 1) a[i] = i * 10;
    CHECK(a.data()[0] == -30);
    CHECK(a.data()[6] == 30);
    CHECK(a[0] == 0);
    CHECK(a[-3] == -30);
    // Any integer indexes: IEC types, C++ integers, intermediate results, enumerations.
    CHECK(a[SINT(2)] == 20);
    CHECK(a[ULINT(1)] == 10);
    CHECK(a[1U] == 10);
    const INT i = 2;
    CHECK(a[i - 1] == 10);
    ARRAY<BOOL, 1, 3> abAxis;
    abAxis[Y] = TRUE;
    CHECK(abAxis.data()[1] == TRUE);
  }

  TEST_CASE("multi-dimensional ARRAYs are stored row by row") {
    ARRAY<INT, 1, 2, 3, 4> a = array_init(repeat<2>(10), repeat<2>(20));  // [2(10), 2(20)]
    CHECK(a(1, 3) == 10);
    CHECK(a(1, 4) == 10);
    CHECK(a(2, 3) == 20);
    CHECK(a(2, 4) == 20);
    ARRAY<INT, 0, 1, -1, 1, 1, 2> b;
    b(1, -1, 2) = 7;
    CHECK(b.data()[1 * 6 + 0 * 2 + 1] == 7);
    CHECK(LOWER_BOUND(b, 2) == -1);
    CHECK(UPPER_BOUND(b, 3) == 2);
  }

  TEST_CASE("initial values as in ST: the rest start at 0") {
    ARRAY<INT, 0, 9> aiCounter{0, 10, 20, 30, 40, 50, 60, 70, 80, 90};
    CHECK(aiCounter[2] == 20);
    ARRAY<INT, 1, 10> aiPart{1, 2};  // := [1, 2]
    CHECK(aiPart[2] == 2);
    CHECK(aiPart[3] == 0);
    CHECK(aiPart[10] == 0);
    ARRAY<INT, 1, 2, 2, 3, 3, 4> aiRep = array_init(repeat<2>(0), repeat<4>(4), 2, 3);  // [2(0), 4(4), 2, 3]
    const INT expected[] = {0, 0, 4, 4, 4, 4, 2, 3};
    for (std::size_t k = 0; k < 8; ++k) CHECK(aiRep.data()[k] == expected[k]);
    ARRAY<TIME, 1, 3> atDelay = array_init(repeat<3>("T#1s"_iec));
    CHECK(atDelay[3] == "T#1s"_iec);
    ARRAY<ST_Part, 1, 3> aParts{ST_Part{1, 10, 4723}, ST_Part{2, 0, 299}};
    CHECK(aParts[1].p3 == 4723);
    CHECK(aParts[2].p1 == 2);
    CHECK(aParts[3].p1 == 0);
    constexpr ARRAY<INT, 1, 3> aConst = array_init(repeat<2>(5));
    // .value(): GCC 12 rejects binding a reference to a defaulted element of a constexpr array
    // of IEC values (`constexpr INT a[3]{}; a[2] == 0` already), ARRAY or not.
    static_assert(aConst[1].value() == 5 && aConst[3].value() == 0);
  }

  TEST_CASE("an initial value out of the elements' range is a fault at run time") {
    fault_recorder faults;
    ARRAY<SINT, 1, 3> aLimits = array_init(1, repeat<2>(300));
    CHECK(faults.count == 1);
    CHECK(faults.last_kind == fault_kind::invalid_value);
    CHECK(aLimits[1] == 1);
  }

  TEST_CASE("LOWER_BOUND and UPPER_BOUND are DINTs of any dimension") {
    ARRAY<REAL, -5, 5, 0, 2> arGrid;
    static_assert(std::is_same_v<decltype(LOWER_BOUND(arGrid, 1)), DINT>);
    CHECK(LOWER_BOUND(arGrid, 1) == -5);
    CHECK(UPPER_BOUND(arGrid, 1) == 5);
    CHECK(LOWER_BOUND(arGrid, 2) == 0);
    CHECK(UPPER_BOUND(arGrid, 2) == 2);
    static_assert(UPPER_BOUND(ARRAY<INT, 1, 10>{}, 1) == 10);
  }

  TEST_CASE("an ARRAY[*] in-out takes any ARRAY of its element type and rank, with its bounds") {
    ARRAY<INT, 1, 5> a{1, 2, 3, 4, 5};
    ARRAY<INT, -2, 0> b{10, 20, 30};
    CHECK(F_Sum(a) == 15);
    CHECK(F_Sum(b) == 60);
    ARRAY<REAL, 1, 2, 0, 2> grid{1.0f, 2.0f, 3.0f, 4.0f, 5.0f, 6.0f};
    FB_Total fbTotal;
    fbTotal("aGrid"_ = grid);
    CHECK(fbTotal.lrTotal == 21.0);
    CHECK(fbTotal.nRows == 2);
    in_out<ARRAY<INT, '*'>> view;
    CHECK_FALSE(view.bound());
    view.bind(b);
    CHECK(view.bound());
    CHECK(view.size() == 3);
    view[-1] = 99;
    CHECK(b[-1] == 99);
    CHECK(LOWER_BOUND(view, 1) == -2);
    CHECK(UPPER_BOUND(view, 1) == 0);
  }

  TEST_CASE("an ARRAY[*] in-out checks its indices against the bound ARRAY's bounds") {
    fault_recorder faults;
    ARRAY<INT, 10, 12> a{1, 2, 3};
    in_out<ARRAY<INT, '*'>> view(a);
    CHECK(view[opaque(INT(9))] == 1);
    CHECK(faults.count == 1);
    CHECK(faults.last_kind == fault_kind::array_bounds);
    CHECK(view[opaque(INT(13))] == 3);
    CHECK(faults.count == 2);
  }

  TEST_CASE("an unbound ARRAY[*] in-out is a fault, and its body is skipped") {
    fault_recorder faults;
    in_out<ARRAY<INT, '*'>> view;
    view[1] = 5;
    CHECK(faults.count == 1);
    CHECK(faults.last_kind == fault_kind::unbound_in_out);
    FB_Total fbTotal;
    fbTotal.lrTotal = 7.0;
    fbTotal();
    CHECK(faults.count == 2);
    CHECK(fbTotal.lrTotal == 7.0);
  }

  TEST_CASE("an ARRAY in a block's VAR is indexed through var<>") {
    FB_Buffer fbBuffer;
    for (INT v = 1; v <= 5; v = v + 1) fbBuffer("iIn"_ = v * 100);
    CHECK(fbBuffer.aLast[1] == 500);
    CHECK(fbBuffer.aLast[4] == 400);
    CHECK(fbBuffer.aPairs(1, 1) == 500);
    CHECK(fbBuffer.aPairs(0, 1) == 400);
    CHECK(UPPER_BOUND(fbBuffer.aLast, 1) == 4);
  }

  TEST_CASE("ARRAY OF blocks: each element is called as in ST") {
    cycle_clock::set(LTIME::from_ticks(0));
    ARRAY<TON, 1, 8> aTimers;
    ARRAY<BOOL, 1, 8> abIn;
    abIn[3] = TRUE;
    for (INT i = 1; i <= 8; i = i + 1) aTimers[i]("IN"_ = abIn[i], "PT"_ = "T#1s"_iec);
    cycle_clock::advance(LTIME::from_ticks(1'000'000'000));
    for (INT i = 1; i <= 8; i = i + 1) aTimers[i]("IN"_ = abIn[i], "PT"_ = "T#1s"_iec);
    CHECK(aTimers[3].Q == TRUE);
    CHECK(aTimers[4].Q == FALSE);
  }

  TEST_CASE("ARRAY OF ARRAY is indexed a[i][j]") {
    ARRAY<ARRAY<INT, 1, 3>, 1, 2> aa{ARRAY<INT, 1, 3>{1, 2, 3}, ARRAY<INT, 1, 3>{4, 5, 6}};
    CHECK(aa[2][1] == 4);
    aa[1][3] = 9;
    CHECK(aa.data()[0].data()[2] == 9);
  }

  TEST_CASE("assigning an ARRAY copies it, as ST's a := b") {
    ARRAY<INT, 1, 3> a{1, 2, 3};
    ARRAY<INT, 1, 3> b;
    b = a;
    a[1] = 7;
    CHECK(b[1] == 1);
  }

  TEST_CASE("ARRAYs of one type compare element by element, as TcUnit's AssertArrayEquals") {
    const ARRAY<INT, 1, 3> aiExpected{1, 2, 3};
    ARRAY<INT, 1, 3> aiResult{1, 2, 3};
    CHECK(aiResult == aiExpected);
    CHECK_FALSE(aiResult != aiExpected);
    static_assert(std::is_same_v<decltype(aiResult == aiExpected), BOOL>);  // ST's comparisons yield BOOL
    static_assert(std::is_same_v<decltype(aiResult != aiExpected), BOOL>);
    for (DINT i = 1; i <= 3; i = i + 1) {  // each element counts, the first and the last too
      aiResult[i] = aiResult[i] + 1;
      CHECK(aiResult != aiExpected);
      CHECK_FALSE(aiResult == aiExpected);
      aiResult[i] = aiResult[i] - 1;
      CHECK(aiResult == aiExpected);
    }
    static_assert(ARRAY<INT, 1, 3>{1, 2, 3} == ARRAY<INT, 1, 3>{1, 2, 3});  // a constant expression
    static_assert(ARRAY<INT, 1, 3>{1, 2, 3} != ARRAY<INT, 1, 3>{1, 2});
  }

  TEST_CASE("multi-dimensional ARRAYs and ARRAYs OF ARRAY compare every element") {
    ARRAY<REAL, 1, 2, 0, 2> arA{1.0f, 2.0f, 3.0f, 4.0f, 5.0f, 6.0f};
    ARRAY<REAL, 1, 2, 0, 2> arB = arA;
    CHECK(arA == arB);
    arB(2, 2) = 6.5f;
    CHECK(arA != arB);
    ARRAY<ARRAY<INT, 1, 2>, 1, 2> aaA{ARRAY<INT, 1, 2>{1, 2}, ARRAY<INT, 1, 2>{3, 4}};
    ARRAY<ARRAY<INT, 1, 2>, 1, 2> aaB = aaA;
    CHECK(aaA == aaB);
    aaB[2][1] = 0;
    CHECK(aaA != aaB);
  }

  TEST_CASE("ARRAYs of STRING, enumerations, TIME and STRUCTs with = compare") {
    ARRAY<STRING<10>, 1, 2> asA{STRING<10>("on"), STRING<10>("off")};
    ARRAY<STRING<10>, 1, 2> asB = asA;
    CHECK(asA == asB);
    asB[2] = STRING<10>("of");
    CHECK(asA != asB);
    ARRAY<E_Axis, 1, 2> aeA{X, Y};
    CHECK(aeA == ARRAY<E_Axis, 1, 2>{X, Y});
    CHECK(aeA != ARRAY<E_Axis, 1, 2>{X, Z});
    ARRAY<TIME, 0, 1> atA{"T#1s"_iec, "T#2s"_iec};
    CHECK(atA == ARRAY<TIME, 0, 1>{"T#1s"_iec, "T#2s"_iec});
    CHECK(atA != ARRAY<TIME, 0, 1>{"T#1s"_iec, "T#2s1ms"_iec});
    ARRAY<ST_Point, 1, 2> apA{ST_Point{1, 0.5f}, ST_Point{2, 1.5f}};
    ARRAY<ST_Point, 1, 2> apB = apA;
    CHECK(apA == apB);
    apB[2].y = 1.25f;
    CHECK(apA != apB);
  }

  TEST_CASE("a block's ARRAY variable compares with an ARRAY, either side") {
    FB_Buffer fb;
    fb("iIn"_ = INT(7));
    fb("iIn"_ = INT(8));
    const ARRAY<INT, 1, 4> aiExpected{7, 8};
    CHECK(fb.aLast == aiExpected);
    CHECK(aiExpected == fb.aLast);
    CHECK(fb.aLast != ARRAY<INT, 1, 4>{7, 8, 9});
  }

  TEST_CASE("ARRAYs that differ only in their index check compare") {
    const basic_array<array_check::bounds, INT, 1, 3> a{1, 2, 3};
    const basic_array<array_check::none, INT, 1, 3> b{1, 2, 3};
    CHECK(a == b);
    CHECK(b == a);
    CHECK_FALSE(a != b);
    CHECK(a != basic_array<array_check::none, INT, 1, 3>{1, 2, 4});
  }

  TEST_CASE("CheckBounds: an index out of range is a fault, then the nearest bound is used") {
    fault_recorder faults;
    basic_array<array_check::bounds, INT, 1, 3> a{1, 2, 3};
    CHECK(a[opaque(INT(0))] == 1);
    CHECK(faults.count == 1);
    CHECK(faults.last_kind == fault_kind::array_bounds);
    CHECK(a[opaque(INT(4))] == 3);
    a[opaque(DINT(-2147483647 - 1))] = 50;  // far below: the lower bound's element
    CHECK(a[1] == 50);
    a[opaque(ULINT(18446744073709551615ULL))] = 60;  // beyond every bound: the upper one
    CHECK(a[3] == 60);
    CHECK(faults.count == 4);
    basic_array<array_check::bounds, INT, 1, 2, 1, 2> m;
    m(opaque(INT(3)), opaque(INT(0))) = 5;  // each index to its nearest bound: m[2, 1]
    CHECK(m(2, 1) == 5);
    CHECK(faults.count == 6);
    CHECK(std::strstr(faults.last_message.c_str(), "ARRAY index") != nullptr);
  }

  TEST_CASE("an ARRAY without the check indexes without a fault path") {
    basic_array<array_check::none, INT, 1, 3> a{1, 2, 3};
    static_assert(noexcept(a[1]));
    CHECK(a[2] == 2);
    basic_array<array_check::bounds, INT, 1, 3> b{1, 2, 3};
    CHECK(b[2] == 2);
    static_assert(default_array_check == (IECOOP_CHECK_BOUNDS ? array_check::bounds : array_check::none));
  }

  TEST_CASE("an index out of range is no constant expression") {
    static_assert(constant_index<1> && constant_index<3>);
    static_assert(!constant_index<0> && !constant_index<4>);
  }
}
