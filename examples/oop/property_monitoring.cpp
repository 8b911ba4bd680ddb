// Seed: CODESYS "Object 'Property'" (English page, "Monitoring of properties in online mode";
// the Chinese pages "属性" and "面向对象的方法，属性，动作，接口" say the same) — the two pragmas
// put at the top of a property definition:
//
//   {attribute 'monitoring' := 'variable'}  Each time the property is accessed, CODESYS saves
//       the actual value to a variable and displays the value of this variable. This value can
//       become outdated if no more access to the property takes place in the code.
//   {attribute 'monitoring' := 'call'}  Each time the value is displayed, CODESYS calls the
//       code of the Get accessor. If this code contains a side effect, then the monitoring
//       executes the side effect.
//
// The seed gives the pragmas without code. We put them on the seed's own example, FB_A with
// prop_iA and PLC_PRG (prop_ia_plc_prg.hpp), and add what the text talks about: a Get with a
// side effect (it counts its calls in iGets) and, in PLC_PRG, bRead, so that the code can stop
// accessing the property. FB_A has the property twice, once per pragma, so that the tests
// show the two side by side. A watch list's display of a property is `p.monitor()`.
//
// One difference remains: in CODESYS a property without the pragma is not monitored at all
// (its "Attribute 'monitoring'" page); iecoop has no such mode, and a property declared without
// a monitoring option is monitored as 'call'. We write `monitoring::call` out where ST has it.
#include <iecoop/testing.hpp>

#include <type_traits>

namespace seed_property_monitoring {

using namespace iecoop;

// FUNCTION_BLOCK FB_A
struct FB_A : function_block<FB_A> {
  // VAR
  var<INT> iA;     // iA : INT;
  var<INT> iGets;  // iGets : INT;         (ours: how often a Get accessor ran)
  // END_VAR

  void body() {
    iA = iA + 1;  // iA := iA + 1;
  }

  // {attribute 'monitoring' := 'call'}
  // PROPERTY PUBLIC prop_iA_call : INT
  // FB_A.prop_iA_call.Get
  INT prop_iA_call_Get() {
    iGets = iGets + 1;  // iGets := iGets + 1;     (the side effect)
    return iA;          // prop_iA_call := iA;
  }
  // FB_A.prop_iA_call.Set
  void prop_iA_call_Set(INT value) { iA = value; }  // iA := prop_iA_call;
  [[no_unique_address]] property<INT, &FB_A::prop_iA_call_Get, &FB_A::prop_iA_call_Set, monitoring::call>
      prop_iA_call{this};

  // {attribute 'monitoring' := 'variable'}
  // PROPERTY PUBLIC prop_iA_variable : INT
  INT prop_iA_variable_monitor;  // (implicit in CODESYS: the variable that 'variable' monitoring shows)
  // FB_A.prop_iA_variable.Get
  INT prop_iA_variable_Get() {
    iGets = iGets + 1;  // iGets := iGets + 1;     (the side effect)
    return iA;          // prop_iA_variable := iA;
  }
  // FB_A.prop_iA_variable.Set
  void prop_iA_variable_Set(INT value) { iA = value; }  // iA := prop_iA_variable;
  [[no_unique_address]] property<INT, &FB_A::prop_iA_variable_Get, &FB_A::prop_iA_variable_Set,
                                 monitoring::variable<&FB_A::prop_iA_variable_monitor>>
      prop_iA_variable{this};
};

// PROGRAM PLC_PRG                             (the seed's, on prop_iA_variable; bRead is ours)
struct PLC_PRG : program<PLC_PRG> {
  // VAR
  FB_A fbA;              // fbA : FB_A;
  var<INT> iVar;         // iVar : INT;
  BOOL bRead = TRUE;     // bRead : BOOL := TRUE;   (written online, by the test)
  // END_VAR

  void body() {
    fbA();                               // fbA();
    if (bRead) {                         // IF bRead THEN
      if (fbA.prop_iA_variable > 500) {  //     IF fbA.prop_iA_variable > 500 THEN
        fbA.prop_iA_variable = 0;        //         fbA.prop_iA_variable := 0;
      }                                  //     END_IF
      iVar = fbA.prop_iA_variable;       //     iVar := fbA.prop_iA_variable;
    }                                    // END_IF
  }
};

}  // namespace seed_property_monitoring

using namespace iecoop;
using seed_property_monitoring::FB_A;
using seed_property_monitoring::PLC_PRG;

static_assert(std::is_same_v<decltype(FB_A::prop_iA_call)::monitoring_mode, monitoring::call>);
static_assert(std::is_same_v<decltype(FB_A::prop_iA_variable)::monitoring_mode,
                             monitoring::variable<&FB_A::prop_iA_variable_monitor>>);

TEST_SUITE("seed: property monitoring, {attribute 'monitoring' := 'call'} and 'variable'") {
  TEST_CASE("'call': each display calls Get, so the watch list runs its side effect and shows the current value") {
    FB_A fbA;
    testing::cycles run{fbA};
    run.step(3);
    CHECK(fbA.iGets == 0);  // nothing has read the property yet
    INT shown = fbA.prop_iA_call.monitor();
    CHECK(shown == 3);
    CHECK(fbA.iGets == 1);  // the display ran Get
    shown = fbA.prop_iA_call.monitor();
    CHECK(shown == 3);
    CHECK(fbA.iGets == 2);  // and again, on each display
    run.step();
    shown = fbA.prop_iA_call.monitor();
    CHECK(shown == 4);  // never outdated: the value is fetched when it is shown
    CHECK(fbA.iGets == 3);
  }

  TEST_CASE("'variable': each access saves the value, the display shows it and calls nothing") {
    PLC_PRG plc_prg;
    testing::cycles run{plc_prg};
    run.step();  // iA = 1; the comparison and the assignment call Get twice
    CHECK(plc_prg.fbA.iGets == 2);
    CHECK(plc_prg.iVar == 1);
    INT shown = plc_prg.fbA.prop_iA_variable.monitor();
    CHECK(shown == 1);
    shown = plc_prg.fbA.prop_iA_variable.monitor();
    CHECK(shown == 1);
    CHECK(plc_prg.fbA.iGets == 2);  // displaying did not run Get: no side effect
    CHECK(plc_prg.fbA.prop_iA_variable_monitor == 1);

    run.step();
    shown = plc_prg.fbA.prop_iA_variable.monitor();
    CHECK(shown == 2);  // the code accessed the property again: the display follows
    CHECK(plc_prg.fbA.iGets == 4);
  }

  TEST_CASE("'variable': the shown value becomes outdated when the code no longer accesses the property") {
    PLC_PRG plc_prg;
    testing::cycles run{plc_prg};
    run.step(5);
    CHECK(plc_prg.fbA.prop_iA_variable.monitor() == 5);
    plc_prg.bRead = FALSE;  // from now on only the body of fbA runs: iA goes on counting
    run.step(5);  // cycles 6 to 10
    CHECK(plc_prg.fbA.iA == 10);
    CHECK(plc_prg.fbA.prop_iA_variable.monitor() == 5);  // outdated, as the seed warns
    CHECK(plc_prg.fbA.iGets == 10);                       // 2 per cycle while bRead, none since
    // 'call' on the same data shows the current value (and runs Get to do so).
    CHECK(plc_prg.fbA.prop_iA_call.monitor() == 10);
    CHECK(plc_prg.fbA.iGets == 11);
    plc_prg.bRead = TRUE;
    run.step();
    CHECK(plc_prg.fbA.prop_iA_variable.monitor() == 11);
  }

  TEST_CASE("'variable': a Set is an access too, the display shows the value written") {
    PLC_PRG plc_prg;
    testing::cycles run{plc_prg};
    run.step(501);
    // Cycle 501: Get saw 501 (> 500), the Set saved 0, the last Get 0.
    CHECK(plc_prg.iVar == 0);
    CHECK(plc_prg.fbA.prop_iA_variable.monitor() == 0);
    plc_prg.fbA.prop_iA_variable = 42;  // written online: Set
    CHECK(plc_prg.fbA.prop_iA_variable.monitor() == 42);
    CHECK(plc_prg.fbA.iA == 42);
    const INT gets = plc_prg.fbA.iGets;
    plc_prg.fbA.prop_iA_call = 7;  // a Set through the 'call' property saves nothing
    CHECK(plc_prg.fbA.iA == 7);
    CHECK(plc_prg.fbA.prop_iA_variable.monitor() == 42);  // still the last access through prop_iA_variable
    CHECK(plc_prg.fbA.iGets == gets);                     // no Get ran
  }

  TEST_CASE("the two properties cost FB_A nothing, only the saved value takes room") {
    struct FB_A_data : function_block<FB_A_data> {
      INT iA;
      INT iGets;
      INT prop_iA_variable_monitor;
    };
    static_assert(sizeof(FB_A) == sizeof(FB_A_data));
  }
}
