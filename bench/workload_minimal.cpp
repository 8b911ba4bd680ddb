// The standard scan workload (workload.hpp), hand-written at its leanest: like
// workload_handwritten.cpp, but the TON, CTU and R_TRIG keep only their state and outputs —
// the inputs are function arguments and are not stored. That is less than the ST program
// does (after `T(IN := x, PT := t)`, T.IN and T.PT hold x and t, and a later `T()` uses
// them), so it is not the same program; bench/ reports it to show what storing the inputs
// costs.
#include "workload.hpp"

#include <cstdint>

namespace workload::minimal_side {
namespace {

std::uint32_t now_ms;  // the time stamp of the running scan

// TON: Q once IN has been TRUE for PT; ET is not updated on the call of the rising edge.
enum : std::uint8_t { TON_IDLE, TON_RUNNING, TON_EXPIRED };
struct ton_t {
  bool q;
  std::uint8_t state;
  std::uint32_t et;
  std::uint32_t start;
};
inline void ton(ton_t& t, bool in, std::uint32_t pt) {
  if (!in) {
    t.et = 0;
    t.q = false;
    t.state = TON_IDLE;
  } else if (t.state == TON_IDLE) {
    t.state = TON_RUNNING;
    t.q = false;
    t.start = now_ms;
  } else if (t.state == TON_RUNNING) {
    const std::uint32_t elapsed = now_ms - t.start;
    if (elapsed >= pt) {
      t.et = pt;
      t.state = TON_EXPIRED;
      t.q = true;
    } else {
      t.et = elapsed;
    }
  }
}

// CTU: counts rising edges of CU up to the type's limit; R clears; Q = CV >= PV.
struct ctu_t {
  bool q;
  bool cu_prev;
  std::int16_t cv;
};
inline void ctu(ctu_t& c, bool cu, bool r, std::int16_t pv) {
  const bool up = cu && !c.cu_prev;
  c.cu_prev = cu;
  if (r) {
    c.cv = 0;
  } else if (up && c.cv < INT16_MAX) {
    ++c.cv;
  }
  c.q = c.cv >= pv;
}

// R_TRIG: Q for one call after CLK rose.
struct r_trig_t {
  bool q;
  bool m;
};
inline void r_trig(r_trig_t& e, bool clk) {
  e.q = clk && !e.m;
  e.m = clk;
}

struct cell_t {
  ton_t T;
  ctu_t C;
  r_trig_t E;
};

constexpr int cells = 1000;

struct state_t {
  cell_t cell[cells];
  std::int16_t CYC;
  std::int16_t NTON;
  std::int16_t NCTU;
  std::int16_t NEDGE;
  std::int16_t ACC;
  std::int16_t PH;
};
state_t s;

}  // namespace

void reset() noexcept { s = state_t{}; }

void scan(std::uint32_t k) noexcept {
  now_ms = k * scan_period_ms;
  s.CYC = static_cast<std::int16_t>((s.CYC + 1) % 24000);
  s.NTON = 0;
  s.NCTU = 0;
  s.NEDGE = 0;
  for (int K = 0; K < cells; ++K) {
    cell_t& c = s.cell[K];
    s.PH = static_cast<std::int16_t>((s.CYC + K) % 20);
    ton(c.T, s.PH < 15, 50);
    if (c.T.q) ++s.NTON;
    ctu(c.C, s.PH % 4 < 2, (s.CYC + K) % 500 == 0, 50);
    if (c.C.q) ++s.NCTU;
    r_trig(c.E, (s.CYC + 3 * K) % 6 < 3);
    if (c.E.q) ++s.NEDGE;
    s.ACC = static_cast<std::int16_t>((s.ACC * 3 + K * 3 - s.PH) % 8191);
  }
}

readings read() noexcept { return {s.NTON, s.NCTU, s.NEDGE, s.ACC}; }

}  // namespace workload::minimal_side
