// STRING(n) and WSTRING(n): CODESYS's layout, truncation on the right, assignment between
// capacities and from std strings, comparison.
#include "iecoop_test.hpp"

#include <string>
#include <string_view>
#include <type_traits>

using namespace iecoop;

// STRING(n) is n+1 bytes, WSTRING(n) n+1 UCS-2 code units (CDS-STRING, CDS-WSTRING).
static_assert(sizeof(STRING<>) == 81 && STRING<>::capacity() == 80);
static_assert(sizeof(STRING<12>) == 13 && sizeof(STRING<1>) == 2);
static_assert(sizeof(WSTRING<>) == 162 && sizeof(WSTRING<10>) == 22);
static_assert(std::is_trivially_copyable_v<STRING<>> && std::is_trivially_copyable_v<WSTRING<5>>);
static_assert(std::is_same_v<STRING<>, STRING<80>> && std::is_same_v<WSTRING<>::char_type, char16_t>);
static_assert(AnyString<STRING<3>> && AnyString<WSTRING<3>> && !AnyString<std::string>);

// Constant evaluation works too.
constexpr STRING<5> constant = "abcdefgh";
static_assert(constant == "abcde" && constant.size() == 5);

TEST_SUITE("STRING and WSTRING") {
  TEST_CASE("a STRING starts empty") {
    STRING<> s;
    CHECK(s.empty());
    CHECK(s.size() == 0u);
    CHECK(s == "");
    CHECK(s.c_str()[0] == '\0');
  }

  TEST_CASE("a literal longer than the capacity is truncated on the right") {
    STRING<12> s = "conveyor belt one";
    CHECK(s == "conveyor bel");
    CHECK(s.size() == 12u);
    s = "short";
    CHECK(s == "short");
    CHECK(s.size() == 5u);
    s = "exactly 12 c";
    CHECK(s == "exactly 12 c");
  }

  TEST_CASE("assignment between capacities truncates like CODESYS") {
    const STRING<> long_text = "The quick brown fox jumps over the lazy dog";
    STRING<9> shorter = long_text;
    CHECK(shorter == "The quick");
    STRING<80> back = shorter;
    CHECK(back == "The quick");
    STRING<3> tiny;
    tiny = long_text;
    CHECK(tiny == "The");
  }

  TEST_CASE("std::string and std::string_view assign and compare") {
    const std::string text = "motor 1 running";
    STRING<7> s = text;
    CHECK(s == "motor 1");
    s = std::string_view("ok");
    CHECK(s == std::string("ok"));
    const std::string_view view = s;
    CHECK(view == "ok");
    const char* none = nullptr;
    s = none;
    CHECK(s.empty());
  }

  TEST_CASE("assigning a view of the string itself") {
    STRING<10> s = "0123456789";
    s = s.view().substr(3);
    CHECK(s == "3456789");
    s.assign(s.view().substr(0, 2));
    CHECK(s == "34");
  }

  TEST_CASE("comparison is lexicographic by code unit") {
    const STRING<5> a = "abc";
    const STRING<20> b = "abd";
    CHECK(a < b);
    CHECK(b > a);
    CHECK(a != b);
    CHECK(a == STRING<3>("abc"));
    CHECK("abc" == a);
    CHECK(STRING<>("ab") < a);
    CHECK(STRING<>("\xE4") > STRING<>("z"));  // Latin-1 a-umlaut sorts after ASCII, as unsigned bytes
  }

  TEST_CASE("equality reads both texts once: a prefix, a longer text and a NUL inside a view differ") {
    // (one pass, character by character, without strlen or memcmp: detail::same_text)
    const STRING<5> a = "abc";
    CHECK(a == "abc");
    CHECK_FALSE(a == "ab");    // a prefix of a
    CHECK_FALSE(a == "abcd");  // a longer text that a is a prefix of
    CHECK_FALSE(a == "abd");   // the last character
    CHECK_FALSE(a == "");      // an empty text
    CHECK(a != "ab");
    CHECK_FALSE(a != "abc");
    CHECK("abc" == a);
    CHECK("abcd" != a);
    CHECK(a == std::string_view("abc"));
    CHECK_FALSE(a == std::string_view("ab"));
    CHECK_FALSE(a == std::string_view("abc\0", 4));  // a view holding a NUL: not a's text
    CHECK_FALSE(a == std::string_view("ab\0", 3));
    CHECK(a == std::string("abc"));
    CHECK(std::string("abc") == a);
    CHECK(std::string("abcd") != a);
    CHECK(a == STRING<3>("abc"));  // capacities apart
    CHECK_FALSE(a == STRING<2>("abc"));
    CHECK_FALSE(STRING<80>("abcde") == a);
    const char* none = nullptr;
    CHECK(STRING<3>() == none);  // a null pointer is the empty text
    CHECK_FALSE(a == none);
    CHECK(a != none);
    CHECK(WSTRING<4>(u"ab") == u"ab");
    CHECK(WSTRING<4>(u"ab") != u"abc");
    CHECK(WSTRING<4>(u"ab") != std::u16string_view(u"a"));
    static_assert(STRING<4>("abc") == "abc" && STRING<4>("abc") != "abcd" && !(STRING<4>("ab") == "abc"));
  }

  TEST_CASE("assignment from a C string reads it up to its NUL or the capacity") {
    STRING<4> s;
    const char text[] = {'w', 'x', 'y', 'z', 'q', '\0'};
    s = text;  // longer: the first four
    CHECK(s == "wxyz");
    CHECK(s.size() == 4u);
    const char* shorter = "ab";
    s = shorter;
    CHECK(s == "ab");
    CHECK(s.c_str()[2] == '\0');
    STRING<10> t = "0123456789";
    t = t.c_str() + 4;  // its own text, further on
    CHECK(t == "456789");
    const STRING<80> wide = "ok";
    STRING<5> narrow = "xxxxx";
    narrow = wide;  // a longer capacity holding a shorter text
    CHECK(narrow == "ok");
    CHECK(narrow.size() == 2u);
  }

  TEST_CASE("WSTRING holds UCS-2 and truncates the same way") {
    WSTRING<5> w = u"hello world";
    CHECK(w == u"hello");
    CHECK(w.size() == 5u);
    w = u"\u00fc\u00df";
    CHECK(w.size() == 2u);
    CHECK(w[0] == u'\u00fc');
    const WSTRING<> wide = w;
    CHECK(wide == w);
  }

  TEST_CASE("iteration and element access") {
    const STRING<> s = "abc";
    std::string copy;
    for (const char c : s) copy += c;
    CHECK(copy == "abc");
    CHECK(s[1] == 'b');
    CHECK(std::string_view(s.data()) == "abc");
  }
}
