// One feature: ENUM — enumerations with a base type, 'qualified_only', 'strict' and
// 'to_string', a state machine in a CASE, TO_STRING and traces that name the components.
#include <fmt/core.h>

#include <iecoop/fmt.hpp>
#include <iecoop/iecoop.hpp>

using namespace iecoop;

// {attribute 'qualified_only'}
// {attribute 'strict'}
// {attribute 'to_string'}
// TYPE E_Step :
// (
//     Idle,
//     Filling := 10,
//     Heating,
//     Draining := 20,
//     Fault := 99
// );
// END_TYPE
enum class E_Step : INT::rep { Idle, Filling = 10, Heating, Draining = 20, Fault = 99 };
template <>
inline constexpr bool iecoop::enum_strict<E_Step> = true;
template <>
inline constexpr bool iecoop::enum_to_string<E_Step> = true;
template <>
inline constexpr auto iecoop::enum_components<E_Step> =
    components<E_Step::Idle, E_Step::Filling, E_Step::Heating, E_Step::Draining, E_Step::Fault>{};

// TYPE E_Valve : (Closed, Open) BYTE; END_TYPE     (no attributes: Closed, E_Valve.Closed)
enum E_Valve : BYTE::rep { Closed, Open };
template <>
struct iecoop::enum_base<E_Valve> {
  using type = BYTE;
};
template <>  // the names, for traces (TO_STRING stays the value: no 'to_string')
inline constexpr auto iecoop::enum_components<E_Valve> = components<Closed, Open>{};

// FUNCTION_BLOCK FB_Tank
struct FB_Tank : function_block<FB_Tank> {
  BOOL bStart;                  // VAR_INPUT bStart : BOOL;
  BOOL bFull;                   //           bFull : BOOL;
  BOOL bHot;                    //           bHot : BOOL;
  BOOL bEmpty;                  //           bEmpty : BOOL; END_VAR
  E_Step eStep = E_Step::Idle;  // VAR_OUTPUT eStep : E_Step;
  E_Valve eInlet = Closed;      //            eInlet : E_Valve;
  E_Valve eOutlet = Closed;     //            eOutlet : E_Valve; END_VAR
  using VAR_INPUT = pins<&FB_Tank::bStart, &FB_Tank::bFull, &FB_Tank::bHot, &FB_Tank::bEmpty>;
  using VAR_OUTPUT = pins<&FB_Tank::eStep, &FB_Tank::eInlet, &FB_Tank::eOutlet>;

  void body() {
    switch (eStep) {                               // CASE eStep OF
      case E_Step::Idle:                           //   E_Step.Idle:
        if (bStart) eStep = E_Step::Filling;       //     IF bStart THEN eStep := E_Step.Filling; END_IF
        break;
      case E_Step::Filling:                        //   E_Step.Filling:
        if (bFull) eStep = E_Step::Heating;        //     IF bFull THEN eStep := E_Step.Heating; END_IF
        break;
      case E_Step::Heating:                        //   E_Step.Heating:
        if (bHot) eStep = E_Step::Draining;        //     IF bHot THEN eStep := E_Step.Draining; END_IF
        break;
      case E_Step::Draining:                       //   E_Step.Draining:
        if (bEmpty) eStep = E_Step::Idle;          //     IF bEmpty THEN eStep := E_Step.Idle; END_IF
        break;
      default:                                     // ELSE
        eStep = E_Step::Fault;                     //   eStep := E_Step.Fault;
        break;
    }                                              // END_CASE
    eInlet = SEL(eStep == E_Step::Filling, Closed, Open);    // eInlet := SEL(eStep = E_Step.Filling, Closed, Open);
    eOutlet = SEL(eStep == E_Step::Draining, Closed, Open);  // eOutlet := SEL(eStep = E_Step.Draining, Closed, Open);
  }
};

int main() {
  FB_Tank fbTank;  // fbTank : FB_Tank;
  fbTank();
  fmt::print("start              step {:<9} inlet {:<6} outlet {}\n", fbTank.eStep, fbTank.eInlet, fbTank.eOutlet);
  fbTank("bStart"_ = TRUE);
  fmt::print("bStart             step {:<9} inlet {:<6} outlet {}\n", fbTank.eStep, fbTank.eInlet, fbTank.eOutlet);
  fbTank("bStart"_ = FALSE, "bFull"_ = TRUE);
  fmt::print("bFull              step {:<9} inlet {:<6} outlet {}\n", fbTank.eStep, fbTank.eInlet, fbTank.eOutlet);
  fbTank("bHot"_ = TRUE);
  fmt::print("bHot               step {:<9} inlet {:<6} outlet {}\n", fbTank.eStep, fbTank.eInlet, fbTank.eOutlet);
  fbTank("bEmpty"_ = TRUE);
  fmt::print("bEmpty             step {:<9} inlet {:<6} outlet {}\n", fbTank.eStep, fbTank.eInlet, fbTank.eOutlet);

  // VAR iStep : INT; sStep : STRING; END_VAR
  const INT iStep = E_Step::Heating;                  // iStep := E_Step.Heating;  (a component reads as its INT)
  const STRING<> sStep = TO_STRING(E_Step::Heating);  // sStep := TO_STRING(E_Step.Heating);  (with 'to_string')
  fmt::print("iStep := E_Step.Heating            {}\n", iStep);
  fmt::print("TO_STRING(E_Step.Heating)          '{}'\n", sStep);
  fmt::print("TO_STRING(Open)                    '{}'   (no 'to_string': the value)\n", TO_STRING(Open));
  fmt::print("is_component(12 as an E_Step)      {}\n", is_component(static_cast<E_Step>(12)));
  fmt::print("12 as an E_Step in a trace        {}\n", static_cast<E_Step>(12));
  fmt::print("parse_enum<E_Step>('e_step.fault') {}\n", *parse_enum<E_Step>("e_step.fault"));
  fmt::print("MAX(E_Step.Filling, E_Step.Idle)   {}\n", MAX(E_Step::Filling, E_Step::Idle));
}
