// Access modifiers: PUBLIC, PRIVATE, PROTECTED as C++'s, INTERNAL as a library pass key.
// (That misuse does not compile is shown by tests/compile_fail/access_*.cpp.)
#include "iecoop_test.hpp"

#include <type_traits>

using namespace iecoop;

namespace motion_lib {  // NAMESPACE motion_lib (a library)
struct tag {};

struct FB_Drive : function_block<FB_Drive>, member_of<tag, FB_Drive> {
  void body() { Move(); }
  INT iMoves;
  // METHOD INTERNAL Calibrate: only for the library's own POUs
  void Calibrate(internal_access<tag>) { bCalibrated = TRUE; }
  BOOL bCalibrated;

 protected:
  // METHOD PROTECTED Move: the block and its extensions
  void Move() { iMoves = iMoves + 1; }

 private:
  // METHOD PRIVATE Secret: the block only
  void Secret() {}
};

struct FB_Machine : function_block<FB_Machine>, member_of<tag, FB_Machine> {
  FB_Drive drive;
  void body() { drive.Calibrate(internal()); }  // inside the library
};
}  // namespace motion_lib

namespace {
template <class B>
concept can_call_internal_without_key = requires(B b) { b.Calibrate(); };
template <class K>
concept key_constructible_outside = requires { K{}; };
template <class B>
concept can_call_move = requires(B b) { b.Move(); };
}  // namespace

static_assert(!key_constructible_outside<internal_access<motion_lib::tag>>);
static_assert(!std::is_default_constructible_v<internal_access<motion_lib::tag>>);
static_assert(!can_call_internal_without_key<motion_lib::FB_Drive>);
static_assert(!can_call_move<motion_lib::FB_Drive>);
static_assert(sizeof(motion_lib::FB_Machine) == sizeof(motion_lib::FB_Drive));  // member_of<> costs nothing

TEST_SUITE("access modifiers") {
  TEST_CASE("an INTERNAL method is callable inside its library") {
    motion_lib::FB_Machine machine;
    machine();
    CHECK(machine.drive.bCalibrated == TRUE);
  }

  TEST_CASE("a PROTECTED method is callable inside its block") {
    motion_lib::FB_Drive drive;
    drive();
    CHECK(drive.iMoves == 1);
  }
}
