// One feature: FB_Init, FB_Reinit and FB_Exit. FB_Init's own parameters are given where the
// instance is declared; a reset runs FB_Exit and FB_Init again, with the flags of what is
// under way.
#include <fmt/core.h>

#include <iecoop/fmt.hpp>
#include <iecoop/iecoop.hpp>

using namespace iecoop;

// FUNCTION_BLOCK FB_Station
struct FB_Station : function_block<FB_Station> {
  INT iId;       // VAR iId : INT;
  TIME tCycle;   //     tCycle : TIME; END_VAR
  using VAR_INPUT = pins<&FB_Station::tCycle>;

  template <NamedInput... Initial>
  explicit FB_Station(INT id, Initial&&... initial) {
    run_fb_init(*this, id, std::forward<Initial>(initial)...);
  }
  ~FB_Station() { run_fb_exit(*this); }
  FB_Station(const FB_Station&) = default;
  FB_Station& operator=(const FB_Station&) = default;

  // METHOD FB_Init : BOOL
  //   VAR_INPUT bInitRetains : BOOL; bInCopyCode : BOOL; id : INT; END_VAR
  BOOL FB_Init(BOOL bInitRetains, BOOL bInCopyCode, INT id) {
    iId = id;  // iId := id;
    fmt::print("  station {}: FB_Init(bInitRetains := {}, bInCopyCode := {})\n", iId, bInitRetains, bInCopyCode);
    return TRUE;
  }
  // METHOD FB_Reinit : BOOL
  BOOL FB_Reinit() {
    fmt::print("  station {}: FB_Reinit()\n", iId);
    return TRUE;
  }
  // METHOD FB_Exit : BOOL  VAR_INPUT bInCopyCode : BOOL; END_VAR
  BOOL FB_Exit(BOOL bInCopyCode) {
    fmt::print("  station {}: FB_Exit(bInCopyCode := {})\n", iId, bInCopyCode);
    return TRUE;
  }
  void body() {}
};

int main() {
  fmt::print("declare (download):\n");
  FB_Station station1{1};                          // station1 : FB_Station(id := 1);
  FB_Station station2{2, "tCycle"_ = "T#50ms"_iec};  // station2 : FB_Station(id := 2) := (tCycle := T#50ms);
  fmt::print("  station 2 tCycle {}\n", station2.tCycle);

  fmt::print("reset warm:\n");
  reset(station1, reset_kind::warm, INT(1));
  fmt::print("reset cold:\n");
  reset(station1, reset_kind::cold, INT(1));

  fmt::print("online change (an instance in memory of its own moves):\n");
  alignas(FB_Station) unsigned char old_memory[sizeof(FB_Station)];
  alignas(FB_Station) unsigned char new_memory[sizeof(FB_Station)];
  FB_Station& station3 = first_start<FB_Station>(old_memory, INT(3), "tCycle"_ = "T#20ms"_iec);
  FB_Station& moved = online_change(station3, new_memory, INT(3));
  fmt::print("  moved station {} keeps tCycle {}\n", moved.iId, moved.tCycle);
  moved.~FB_Station();

  fmt::print("end of scope:\n");
}
