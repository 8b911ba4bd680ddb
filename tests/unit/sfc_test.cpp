// Sequential Function Charts (include/iecoop/sfc): every qualifier, both scan orders, branches,
// time limits, flags, the unsafe-chart fault and transition objects under EXTENDS. Each expected
// value is worked out by hand from the rules of docs/sfc.md (reasoning beside it); the reference
// charts' full traces are checked end to end by the replay tests (tests/replay/sfc).
#include "iecoop_test.hpp"

#include <cstdint>

#include <SFC_ALT.hpp>
#include <SFC_FIRST_SCAN.hpp>
#include <SFC_LINEAR.hpp>
#include <SFC_PAR.hpp>
#include <SFC_QUAL.hpp>
#include <SFC_SHARED.hpp>
#include <SFC_TIMED.hpp>

using namespace iecoop;
using namespace iecoop::literals;
using namespace sfc_reference;

namespace {

/// One scan of `pou` at cycle `k` of a 10 ms task (the reference charts' MAINTASK).
template <class POU>
void scan(POU& pou, int k) {
  cycle_clock::set(LTIME::from_ticks(static_cast<std::uint64_t>(k) * 10'000'000u));
  pou();
}

// A small chart for flags, limits and step actions: INIT -> A -> B -> INIT.
template <sfc::ScanOrder Order>
struct FB_Seq : function_block<FB_Seq<Order>> {
  BOOL GO;
  INT entries, actives, exits, tail;
  sfc::step INIT, A, B;
  void A_entry() { entries = entries + 1; }
  void A_active() { actives = actives + 1; }
  void A_exit() { exits = exits + 1; }
  void A_TAIL() { tail = tail + 1; }
  using P = FB_Seq;
  sfc::chart<P, Order, sfc::INITIAL_STEP<&P::INIT>, sfc::TRANSITION<sfc::FROM<&P::INIT>, sfc::TO<&P::A>, &P::GO>,
             sfc::STEP<&P::A, sfc::on_entry<&P::A_entry>, sfc::while_active<&P::A_active>, sfc::on_exit<&P::A_exit>,
                       sfc::min_time<"T#30ms">, sfc::max_time<"T#50ms">>,
             sfc::TRANSITION<sfc::FROM<&P::A>, sfc::TO<&P::B>, &P::GO>, sfc::STEP<&P::B, sfc::N<&P::A_TAIL>>,
             sfc::TRANSITION<sfc::FROM<&P::B>, sfc::TO<&P::INIT>, &P::GO>>
      chart;
  void body() { chart(*this); }
};

}  // namespace

TEST_SUITE("sfc") {
  TEST_CASE("codesys order: a transition's targets are active from the next cycle, and an action has a final scan") {
    P_SFC_LINEAR<sfc::codesys> p;
    for (int k = 0; k <= 2; ++k) scan(p, k);
    CHECK(p.C_INIT == 3);  // INIT active from the first cycle; A_INIT ran in cycles 0, 1, 2
    p.START = TRUE;
    scan(p, 3);  // actions first (A_INIT: 4), then INIT -> FILL fires: FILL._X, not yet FILL.X
    p.START = FALSE;
    CHECK(p.INIT.X);
    CHECK_FALSE(p.FILL.X);
    CHECK(p.FILL._X);
    CHECK_FALSE(p.INIT._X);
    CHECK(p.C_INIT == 4);
    CHECK(p.chart.SFCTrans);
    CHECK(p.chart.SFCCurrentStep == "INIT");  // FILL becomes the current step with FILL.X
    scan(p, 4);  // FILL active (T = 0), A_FILL runs; A_INIT's Q fell: its final scan makes 5
    CHECK(p.FILL.X);
    CHECK(p.FILL.T == "T#0ms"_iec);
    CHECK(p.C_INIT == 5);
    CHECK(p.C_FILL == 1);
    CHECK(p.chart.SFCCurrentStep == "FILL");
    CHECK(p.chart.action<&decltype(p)::A_INIT>().A);  // the final scan: A without Q
    CHECK_FALSE(p.chart.action<&decltype(p)::A_INIT>().Q);
    for (int k = 5; k <= 9; ++k) scan(p, k);  // FILL.T 10..50: in cycle 9 it reaches 50 ms and FILL -> PULSE fires
    CHECK(p.FILL.X);
    CHECK(p.FILL_T_SEEN == "T#50ms"_iec);  // A_FILL ran before the transition, with T = 50 ms
    scan(p, 10);
    CHECK(p.PULSE.X);
    CHECK(p.FILL.T == "T#50ms"_iec);  // T keeps its value after the step is left (IEC)
    CHECK(p.C_FILL == 7);             // cycles 4..9, and the final scan in 10
  }

  TEST_CASE("matiec order: transitions first, the new step's actions in the same scan, no final scan") {
    P_SFC_LINEAR<sfc::matiec> p;
    for (int k = 0; k <= 2; ++k) scan(p, k);
    p.START = TRUE;
    scan(p, 3);  // INIT -> FILL fires first; FILL is active and A_FILL runs now, A_INIT does not
    p.START = FALSE;
    CHECK(p.FILL.X);
    CHECK(p.FILL._X);
    CHECK_FALSE(p.INIT.X);
    CHECK(p.C_INIT == 3);
    CHECK(p.C_FILL == 1);
    CHECK(p.FILL_T_SEEN == "T#0ms"_iec);
    // FILL.T >= 50 ms fires in scan 3 + ceil(50 / 10) = 8, before A_FILL could see 50 ms.
    for (int k = 4; k <= 7; ++k) scan(p, k);
    CHECK(p.FILL.X);
    scan(p, 8);
    CHECK(p.PULSE.X);
    CHECK(p.C_FILL == 5);                  // scans 3..7
    CHECK(p.FILL_T_SEEN == "T#40ms"_iec);  // the last A_FILL saw 40 ms
    // PULSE -> HEAT := TRUE fires in the next scan: one step per scan, never two.
    scan(p, 9);
    CHECK(p.HEAT.X);
    CHECK(p.C_PULSE == 1);
  }

  TEST_CASE("a transition reading a variable an action writes sees it one scan later in matiec order") {
    // CNT: A_K_CLEAR(P) then A_K_INC(N); CNT -> INIT := K >= 3.
    P_SFC_LINEAR<sfc::codesys> c;
    P_SFC_LINEAR<sfc::matiec> m;
    int k = 0;
    const auto run_until_cnt = [&](auto& p) {
      p.START = TRUE;
      for (k = 0; !p.CNT.X; ++k) {
        scan(p, k);
        p.START = FALSE;
      }
      return k;
    };
    const int codesys_cnt = run_until_cnt(c);
    const int matiec_cnt = run_until_cnt(m);
    // codesys: K := 0 then K := 1 in CNT's first cycle (alphabetical: A_K_CLEAR < A_K_INC), the final scan
    // of A_K_CLEAR in the second clears it again (K = 1), 2, 3: the transition fires in CNT's fourth cycle.
    for (int i = 0; i < 3; ++i) scan(c, codesys_cnt + i);
    CHECK(c.CNT.X);
    CHECK(c.K == 3);
    CHECK_FALSE(c.CNT._X);  // fired at the end of this cycle
    // matiec: K = 1, 2, 3 in CNT's first three scans; the fourth scan sees K >= 3 and leaves.
    for (int i = 0; i < 2; ++i) scan(m, matiec_cnt + i);
    CHECK(m.K == 3);
    CHECK(m.CNT.X);
    scan(m, matiec_cnt + 2);
    CHECK(m.INIT.X);
    CHECK(m.K == 3);  // CNT's actions do not run in the scan that leaves it
  }

  TEST_CASE("untimed qualifiers N, S, R, P, P1, P0 and BOOL variables as actions (codesys)") {
    P_SFC_QUAL<sfc::codesys> p;
    const auto row = [&](int k, BOOL next) {
      p.NEXT = next;
      scan(p, k);
    };
    row(0, FALSE);
    row(1, FALSE);
    row(2, TRUE);  // INIT -> S1, active from cycle 3
    row(3, FALSE);
    // S1's first cycle: every action runs once; the variables follow Q.
    CHECK(p.C_N == 1);
    CHECK(p.C_S == 1);
    CHECK(p.C_P == 1);
    CHECK(p.C_P1 == 1);
    CHECK(p.C_P0 == 0);
    CHECK((p.V_N && p.V_S && p.V_P));
    row(4, FALSE);
    CHECK(p.C_P == 2);   // P's Q fell: its final scan (CODESYS runs a P action twice)
    CHECK(p.C_P1 == 1);  // P1 runs once: no final scan after a P1 pulse (CODESYS)
    CHECK_FALSE(p.V_P);  // a variable has no final scan
    row(5, FALSE);
    row(6, TRUE);  // S1 -> S2 for cycle 7
    row(7, FALSE);
    CHECK(p.C_N == 5);   // cycles 3..6 and the final scan in 7
    CHECK(p.C_P0 == 1);  // S1 was left: P0 runs in S2's first cycle
    CHECK(p.C_S == 5);   // stored: runs on in S2
    CHECK(p.V_S);
    CHECK_FALSE(p.V_N);
    row(8, FALSE);
    CHECK(p.C_P0 == 1);  // P0 runs once too
    row(9, FALSE);
    row(10, TRUE);  // S2 -> S3 for cycle 11: S3 resets A_S and V_S
    row(11, FALSE);
    CHECK(p.C_S == 9);  // cycles 3..10, and the final scan in 11 (R made Q FALSE)
    CHECK_FALSE(p.V_S);
    row(12, FALSE);
    CHECK(p.C_S == 9);
  }

  TEST_CASE("untimed qualifiers in matiec order: no final scans, the new step's actions in its activation scan") {
    P_SFC_QUAL<sfc::matiec> p;
    p.NEXT = FALSE;
    scan(p, 0);
    scan(p, 1);
    p.NEXT = TRUE;
    scan(p, 2);  // INIT -> S1 and S1's actions in scan 2
    CHECK((p.C_N == 1 && p.C_S == 1 && p.C_P == 1 && p.C_P1 == 1 && p.V_P));
    p.NEXT = FALSE;
    for (int k = 3; k <= 5; ++k) scan(p, k);
    CHECK((p.C_N == 4 && p.C_S == 4 && p.C_P == 1 && p.C_P1 == 1 && !p.V_P));
    p.NEXT = TRUE;
    scan(p, 6);  // S1 -> S2: P0 in the deactivating scan, N no longer
    CHECK((p.C_N == 4 && p.C_P0 == 1 && p.C_S == 5 && p.V_S && !p.V_N));
    p.NEXT = FALSE;
    for (int k = 7; k <= 9; ++k) scan(p, k);
    p.NEXT = TRUE;
    scan(p, 10);  // S2 -> S3, whose R cuts A_S in this very scan
    CHECK(p.C_S == 8);
    CHECK_FALSE(p.V_S);
  }

  TEST_CASE("timed qualifiers L, D, SD, DS, SL with T#30ms (codesys)") {
    P_SFC_TIMED<sfc::codesys> p;
    int k = 0;
    const auto to = [&](int last, BOOL next_at_last) {
      for (; k <= last; ++k) {
        p.NEXT = BOOL(k == last && next_at_last);
        scan(p, k);
      }
    };
    to(2, TRUE);   // INIT -> S1, active in cycles 3..10
    to(10, TRUE);  // S1 -> S2 at the end of 10
    // L: S1.T < 30 in cycles 3, 4, 5; the final scan in 6. D: T >= 30 in cycles 6..10, the final scan in 11
    // (counted below). The variables follow Q without a final scan.
    CHECK(p.C_L == 4);
    CHECK(p.C_D == 5);
    CHECK_FALSE(p.V_L);
    CHECK(p.V_D);
    to(17, FALSE);  // S2 active in cycles 11..17
    CHECK(p.C_D == 6);
    // SL: stored at 11, runs while its own 30 ms run (11, 12, 13), the final scan in 14.
    CHECK(p.C_SL == 4);
    // SD: stored at 11, active from 14 (its delay); DS: S2.T reaches 30 at 14, stored from then: 14..17.
    CHECK(p.C_SD == 4);
    CHECK(p.C_DS == 4);
    to(18, TRUE);        // S2 -> S3
    to(19, TRUE);        // S3 -> S4, whose R acts in cycle 20
    to(20, TRUE);        // S4 -> INIT
    CHECK(p.C_SD == 7);  // 14..19, the final scan in 20
    CHECK(p.C_DS == 7);
    CHECK_FALSE(p.chart.action<&decltype(p)::A_SD>().Q);
    // A short S2 (cycles 25, 26): SD starts anyway and fires 30 ms after the activation, after the step
    // was left (28); DS never stores (S2.T stopped at 10 ms); SL runs its 30 ms out (25, 26, 27).
    to(21, FALSE);
    to(22, TRUE);  // INIT -> S1 (23)
    to(23, FALSE);
    to(24, TRUE);  // S1 -> S2 (25)
    to(25, FALSE);
    to(26, TRUE);  // S2 -> S3 (27)
    to(27, FALSE);
    CHECK(p.C_SD == 7);
    to(28, FALSE);
    CHECK(p.C_SD == 8);
    CHECK(p.C_DS == 7);
    CHECK(p.C_SL == 8);  // 4, then 25, 26, 27 and the final scan in 28
    to(29, FALSE);
    to(30, TRUE);         // S3 -> S4 (31): R
    to(31, TRUE);         // S4 -> INIT
    CHECK(p.C_SD == 11);  // 28, 29, 30 and the final scan in 31
    // S2 for one cycle (36), S4's R at 38, before SD's 30 ms elapsed: the pending start is cancelled.
    for (; k <= 45; ++k) {  // NEXT held in 34..38: INIT, S1, S2 (36), S3, S4 (38), one cycle each
      p.NEXT = BOOL(k >= 34 && k <= 38);
      scan(p, k);
    }
    CHECK(p.C_SD == 11);
  }

  TEST_CASE("timed qualifiers in matiec order count from the activation scan") {
    P_SFC_TIMED<sfc::matiec> p;
    for (int k = 0; k <= 9; ++k) {
      p.NEXT = BOOL(k == 2);
      scan(p, k);
    }
    // S1 active from scan 2: L while S1.T < 30 ms (scans 2, 3, 4), D from T = 30 ms (5..9).
    CHECK(p.C_L == 3);
    CHECK(p.C_D == 5);
    CHECK(p.V_D);
  }

  TEST_CASE("one action in several steps: the associations combine with OR") {
    P_SFC_SHARED<sfc::codesys> p;
    const auto row = [&](int k, BOOL next, BOOL back) {
      p.NEXT = next;
      p.BACK = back;
      scan(p, k);
    };
    row(0, FALSE, FALSE);
    row(1, FALSE, FALSE);
    row(2, TRUE, FALSE);  // INIT -> S1 (3)
    row(3, FALSE, FALSE);
    row(4, FALSE, FALSE);
    row(5, TRUE, FALSE);  // S1 -> S2 (6)
    row(6, FALSE, FALSE);
    // A_SH is N in S1 and in S2: its Q stays TRUE across the change, so it runs once per cycle and no final
    // scan comes between: 3, 4, 5, 6.
    CHECK(p.C_SH == 4);
    CHECK(p.C_Q == 4);  // A_Q (N in S1 only): 3, 4, 5 and its final scan in 6
    row(7, FALSE, FALSE);
    CHECK(p.C_SH == 5);
    CHECK(p.C_Q == 4);
  }

  TEST_CASE("alternative branches: one transition fires, the first declared unless PRIORITY says otherwise") {
    P_SFC_ALT<sfc::codesys> alt;
    P_SFC_ALT_PRIO<sfc::codesys> prio;
    alt.GO_A = alt.GO_B = TRUE;
    prio.GO_A = prio.GO_B = TRUE;
    scan(alt, 0);
    scan(prio, 0);
    scan(alt, 1);
    scan(prio, 1);
    CHECK(alt.BR_A.X);  // declared first
    CHECK_FALSE(alt.BR_B.X);
    CHECK(prio.BR_B.X);  // PRIORITY := 1
    CHECK_FALSE(prio.BR_A.X);
    // matiec order: the same choice (MatIEC itself would fire both; iecoop follows IEC).
    P_SFC_ALT<sfc::matiec> m;
    m.GO_A = m.GO_B = TRUE;
    scan(m, 0);
    CHECK(m.BR_A.X);
    CHECK_FALSE(m.BR_B.X);
    CHECK_FALSE(m.INIT.X);
  }

  TEST_CASE("a jump back to the initial step, and alternative convergence") {
    P_SFC_ALT<sfc::codesys> p;
    p.GO_B = TRUE;
    scan(p, 0);
    p.GO_B = FALSE;
    scan(p, 1);
    CHECK(p.BR_B.X);
    p.ABORT = TRUE;
    scan(p, 2);  // BR_B -> INIT (the jump), INIT active in 3
    p.ABORT = FALSE;
    scan(p, 3);
    CHECK(p.INIT.X);
    CHECK_FALSE(p.BR_B.X);
    p.GO_A = TRUE;
    scan(p, 4);
    p.GO_A = FALSE;
    p.DONE = TRUE;
    scan(p, 5);  // BR_A -> JOIN
    p.DONE = FALSE;
    scan(p, 6);
    CHECK(p.JOIN.X);
    scan(p, 7);  // JOIN -> INIT := TRUE
    CHECK(p.INIT.X);
    CHECK(p.C_JOIN == 2);  // its cycle, and the final scan
  }

  TEST_CASE("simultaneous divergence activates every branch, and the convergence waits for all of them") {
    P_SFC_PAR<sfc::codesys> p;
    p.IN_J = TRUE;
    p.GO = TRUE;
    scan(p, 0);  // INIT -> (P1, Q1)
    p.GO = FALSE;
    scan(p, 1);
    CHECK((p.P1.X && p.Q1.X && !p.INIT.X));
    for (int k = 2; k <= 4; ++k) scan(p, k);  // P1.T reaches 30 ms in cycle 4: P2 from 5
    scan(p, 5);
    CHECK((p.P2.X && p.Q1.X));
    scan(p, 6);
    CHECK_FALSE(p.JOIN.X);  // IN_J is TRUE, but Q2 is not active
    p.IN_Q = TRUE;
    scan(p, 7);  // Q1 -> Q2
    p.IN_Q = FALSE;
    scan(p, 8);  // both last steps active: (P2, Q2) -> JOIN fires
    CHECK((p.P2.X && p.Q2.X));
    scan(p, 9);
    CHECK((p.JOIN.X && !p.P2.X && !p.Q2.X));
    CHECK(p.chart.SFCCurrentStep == "JOIN");
  }

  TEST_CASE("a self-loop re-activates the step: T restarts, P and P0 run again") {
    P_SFC_FIRST_SCAN<sfc::codesys> p;
    for (int k = 0; k <= 2; ++k) scan(p, k);
    CHECK(p.INIT.T == "T#20ms"_iec);
    CHECK(p.C_INIT_P == 2);  // P in cycle 0 and its final scan in 1
    p.AGAIN = TRUE;
    scan(p, 3);
    p.AGAIN = FALSE;
    scan(p, 4);
    CHECK(p.INIT.X);
    CHECK(p.INIT.T == "T#0ms"_iec);
    CHECK(p.C_INIT_P == 3);
    CHECK(p.C_INIT_P0 == 1);
    CHECK(p.C_INIT_N == 5);  // N's Q never fell: no final scan, one run per cycle
  }

  TEST_CASE("the initial step's P runs in the first scan in both orders, even when it is left at once") {
    P_SFC_FIRST_SCAN<sfc::codesys> c;
    c.GO = TRUE;
    scan(c, 0);
    CHECK((c.C_INIT_P == 1 && c.C_INIT_N == 1));
    P_SFC_FIRST_SCAN<sfc::matiec> m;
    m.GO = TRUE;
    scan(m, 0);  // INIT is left in the first scan: activation and deactivation in one scan
    CHECK(m.S1.X);
    CHECK(m.C_INIT_P == 1);
    CHECK(m.C_INIT_P0 == 1);
    CHECK(m.C_INIT_N == 0);
    CHECK(m.C_S1 == 1);
  }

  TEST_CASE("CODESYS step actions, minimum and maximum times, SFCError and SFCQuitError") {
    FB_Seq<sfc::codesys> f;
    f.GO = TRUE;
    scan(f, 0);  // INIT -> A
    scan(f, 1);  // A's first cycle: entry and active; GO is TRUE, but A's minimum time (30 ms) holds it
    CHECK((f.A.X && f.entries == 1 && f.actives == 1));
    scan(f, 2);
    scan(f, 3);
    CHECK(f.A.X);
    scan(f, 4);  // A.T = 30 ms: A -> B fires now
    CHECK(f.A.X);
    CHECK_FALSE(f.A._X);
    scan(f, 5);
    CHECK((f.B.X && f.exits == 1 && f.actives == 4 && f.entries == 1));
    CHECK_FALSE(f.chart.SFCError);
    // Maximum time: A active longer than 50 ms sets SFCError and names the step.
    f.GO = FALSE;
    f.chart.SFCReset = TRUE;
    scan(f, 6);  // reset to INIT, and INIT's scan
    f.chart.SFCReset = FALSE;
    f.GO = TRUE;
    scan(f, 7);  // INIT -> A
    f.GO = FALSE;
    for (int k = 8; k <= 13; ++k) scan(f, k);  // A.T 0..50
    CHECK_FALSE(f.chart.SFCError);
    scan(f, 14);  // 60 ms > 50 ms
    CHECK(f.chart.SFCError);
    CHECK(f.chart.SFCErrorStep == "A");
    const STRING<> pou = f.chart.SFCErrorPOU;
    CHECK(pou.view().starts_with("FB_Seq"));
    f.chart.SFCQuitError = TRUE;
    scan(f, 15);  // held, error reset
    CHECK_FALSE(f.chart.SFCError);
    CHECK(f.chart.SFCErrorStep == "");
    CHECK(f.A.T == "T#60ms"_iec);  // times stand still while held
    f.chart.SFCQuitError = FALSE;
    scan(f, 16);  // the active steps' times restart
    CHECK(f.A.T == "T#0ms"_iec);
    f.chart.SFCEnableLimit = FALSE;
    for (int k = 17; k <= 25; ++k) scan(f, k);
    CHECK_FALSE(f.chart.SFCError);  // limits off
  }

  TEST_CASE("step actions in matiec order run in the scan of the change") {
    FB_Seq<sfc::matiec> f;
    f.GO = TRUE;
    scan(f, 0);  // INIT -> A in scan 0: entry and active now
    CHECK((f.A.X && f.entries == 1 && f.actives == 1 && f.exits == 0));
    for (int k = 1; k <= 3; ++k) scan(f, k);  // A.T 10, 20, 30: leaves in scan 3
    CHECK((f.B.X && f.exits == 1 && f.actives == 3));
  }

  TEST_CASE("SFCInit holds the chart in its initial step without actions, and SFCPause freezes it") {
    FB_Seq<sfc::codesys> f;
    f.GO = TRUE;
    scan(f, 0);
    scan(f, 1);
    CHECK(f.A.X);
    f.chart.SFCInit = TRUE;
    scan(f, 2);
    scan(f, 3);
    CHECK((f.INIT.X && !f.A.X && f.actives == 1));  // no action ran
    CHECK(f.chart.SFCCurrentStep == "INIT");
    f.chart.SFCInit = FALSE;
    f.GO = FALSE;
    scan(f, 4);
    CHECK(f.INIT.T == "T#0ms"_iec);
    scan(f, 5);
    CHECK(f.INIT.T == "T#10ms"_iec);
    f.chart.SFCPause = TRUE;
    f.GO = TRUE;
    for (int k = 6; k <= 9; ++k) scan(f, k);
    CHECK((f.INIT.X && f.INIT.T == "T#10ms"_iec));  // nothing fired, no time passed
    f.chart.SFCPause = FALSE;
    scan(f, 10);
    CHECK(f.INIT.T == "T#20ms"_iec);  // the paused cycles do not count, the one since the last does
    CHECK_FALSE(f.INIT._X);           // GO: INIT -> A fires again
  }

  TEST_CASE("tip mode: transitions fire on a rising edge of SFCTip, not on their conditions") {
    FB_Seq<sfc::codesys> f;
    f.chart.SFCTipMode = TRUE;
    f.GO = TRUE;
    for (int k = 0; k <= 3; ++k) scan(f, k);
    CHECK(f.INIT.X);  // GO is TRUE, but tip mode waits for SFCTip
    f.GO = FALSE;
    f.chart.SFCTip = TRUE;
    scan(f, 4);  // the edge: INIT -> A although GO is FALSE
    scan(f, 5);  // SFCTip still TRUE: no new edge
    CHECK(f.A.X);
    f.chart.SFCTip = FALSE;
    for (int k = 6; k <= 9; ++k) scan(f, k);
    CHECK(f.A.X);
  }

  TEST_CASE("a chart that activates an active step reports fault_kind::unsafe_chart") {
    struct FB_Unsafe : function_block<FB_Unsafe> {
      BOOL GO;
      sfc::step INIT, A, B, C;
      using P = FB_Unsafe;
      // Two branches started in parallel but closed as alternatives: both lead into C in one scan.
      sfc::chart<P, sfc::INITIAL_STEP<&P::INIT>, sfc::TRANSITION<sfc::FROM<&P::INIT>, sfc::TO<&P::A, &P::B>, &P::GO>,
                 sfc::STEP<&P::A>, sfc::STEP<&P::B>, sfc::TRANSITION<sfc::FROM<&P::A>, sfc::TO<&P::C>, true>,
                 sfc::TRANSITION<sfc::FROM<&P::B>, sfc::TO<&P::C>, true>, sfc::STEP<&P::C>,
                 sfc::TRANSITION<sfc::FROM<&P::C>, sfc::TO<&P::INIT>, false>>
          chart;
      void body() { chart(*this); }
    } f;
    f.GO = TRUE;
    scan(f, 0);                                         // INIT -> (A, B)
    CHECK_FAULT(scan(f, 1), fault_kind::unsafe_chart);  // A -> C and B -> C in one scan
    scan(f, 2);
    CHECK(f.C.X);  // active once
  }
}

namespace {

// The seed's note: a derived POU takes over a transition of its base. FB_Base leaves FILL when its
// transition object T_Full says so; FB_Quick EXTENDS it and overrides T_Full.
struct FB_Base : function_block<FB_Base> {
  virtual ~FB_Base() = default;
  INT level;
  sfc::step IDLE, FILL;
  virtual BOOL T_Full() { return level >= 80; }  // TRANSITION T_Full: level >= 80
  using P = FB_Base;
  sfc::chart<P, sfc::INITIAL_STEP<&P::IDLE>, sfc::TRANSITION<sfc::FROM<&P::IDLE>, sfc::TO<&P::FILL>, true>,
             sfc::STEP<&P::FILL>, sfc::TRANSITION<sfc::FROM<&P::FILL>, sfc::TO<&P::IDLE>, &P::T_Full>>
      chart;
  virtual void body() { chart(*this); }
};
struct FB_Quick : extends<FB_Quick, FB_Base> {
  BOOL T_Full() override { return level >= 50; }  // the derived block's transition
  void body() override { SUPER::body(); }
};

}  // namespace

TEST_SUITE("sfc") {
  TEST_CASE("a transition object is overridden under EXTENDS, also through a reference to the base") {
    FB_Base base;
    FB_Quick quick;
    FB_Base& as_base = quick;
    base.level = 60;
    quick.level = 60;
    for (int k = 0; k <= 2; ++k) {
      scan(base, k);
      cycle_clock::set(LTIME::from_ticks(static_cast<std::uint64_t>(k) * 10'000'000u));
      as_base();
    }
    CHECK(base.FILL.X);   // 60 < 80: the base stays
    CHECK(quick.IDLE.X);  // 60 >= 50: the derived block's transition fired
  }
}
