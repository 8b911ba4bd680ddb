// Lifecycle operations on blocks without user parameters, and on blocks without lifecycle
// methods at all; the flags each operation passes. (The seed port fb_init_lifecycle.cpp
// covers FB_Init with a user parameter, derived blocks and programs.)
#include "iecoop_test.hpp"

#include <memory>
#include <string>

using namespace iecoop;

namespace {

std::string events;

struct FB_Logged : function_block<FB_Logged> {
  FB_Logged() { run_fb_init(*this); }
  ~FB_Logged() { run_fb_exit(*this); }
  FB_Logged(const FB_Logged&) = default;
  FB_Logged& operator=(const FB_Logged&) = default;

  INT iValue = 1;  // the declaration's initial value
  using VAR_INPUT = pins<&FB_Logged::iValue>;
  void body() {}

 private:
  friend struct iecoop::block_access;  // lifecycle methods kept private
  BOOL FB_Init(BOOL bInitRetains, BOOL bInCopyCode) {
    events += std::string("init:") + (bInitRetains ? "T" : "F") + (bInCopyCode ? "T" : "F") + " ";
    iValue = iValue + 10;
    return TRUE;
  }
  BOOL FB_Exit(BOOL bInCopyCode) {
    events += std::string("exit:") + (bInCopyCode ? "T" : "F") + " ";
    return TRUE;
  }
};

struct FB_WithInit : function_block<FB_WithInit> {
  template <NamedInput... I>
  explicit FB_WithInit(I&&... initial) {
    run_fb_init(*this, std::forward<I>(initial)...);
  }
  INT iValue = 1;
  using VAR_INPUT = pins<&FB_WithInit::iValue>;
  void body() {}
  BOOL FB_Init(BOOL, BOOL) {
    iValue = 2;
    return TRUE;
  }
};

struct FB_Plain : function_block<FB_Plain> {
  INT iValue;
  void body() { iValue = iValue + 1; }
};

}  // namespace

TEST_SUITE("lifecycle") {
  TEST_CASE("FB_Init without user parameters runs at construction, after the initial values") {
    events.clear();
    FB_Logged logged;
    CHECK(events == "init:TF ");
    CHECK(logged.iValue == 11);
  }

  TEST_CASE("each operation passes its flags") {
    events.clear();
    alignas(FB_Logged) unsigned char a[sizeof(FB_Logged)];
    alignas(FB_Logged) unsigned char b[sizeof(FB_Logged)];
    FB_Logged& first = first_start<FB_Logged>(a);
    CHECK(events == "init:TF ");
    events.clear();
    reset(first, reset_kind::warm);
    CHECK(events == "exit:F init:FF ");
    events.clear();
    reset(first, reset_kind::cold);
    CHECK(events == "exit:F init:TF ");
    first.iValue = 99;
    events.clear();
    FB_Logged& moved = online_change(first, b);
    CHECK(events == "exit:T init:FT ");  // no FB_Reinit declared: none called
    CHECK(moved.iValue == 99);
    events.clear();
    std::destroy_at(&moved);
    CHECK(events == "exit:F ");
  }

  TEST_CASE("named initial values after FB_Init") {
    events.clear();
    FB_WithInit plain;
    CHECK(plain.iValue == 2);
    FB_WithInit declared{"iValue"_ = 3};
    CHECK(declared.iValue == 3);
  }

  TEST_CASE("blocks without lifecycle methods reset and move too") {
    FB_Plain plain;
    plain();
    plain();
    CHECK(plain.iValue == 2);
    reset(plain, reset_kind::cold);
    CHECK(plain.iValue == 0);
    plain();
    alignas(FB_Plain) unsigned char storage[sizeof(FB_Plain)];
    FB_Plain& moved = online_change(plain, storage);
    CHECK(moved.iValue == 1);
  }
}
