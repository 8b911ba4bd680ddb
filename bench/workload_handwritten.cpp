// The standard scan workload (workload.hpp) as a careful embedded engineer writes it in
// plain C-style C++, without any framework: a global millisecond time stamp, and each block
// a plain struct with its inputs, outputs and state plus a function that runs it — the
// shape of an IEC function block in C (the instance holds its inputs; a call sets them and
// runs the block) — with the behaviour of the standard TON, CTU and R_TRIG.
#include "workload.hpp"

#include <cstdint>

namespace workload::handwritten_side {
namespace {

std::uint32_t now_ms;  // the time stamp of the running scan

// TON: Q once IN has been TRUE for PT; ET is not updated on the call of the rising edge.
enum : std::uint8_t { TON_IDLE, TON_RUNNING, TON_EXPIRED };
struct ton_t {
  bool IN;
  bool Q;
  std::uint8_t state;
  std::uint32_t PT;
  std::uint32_t ET;
  std::uint32_t start;
};
inline void ton(ton_t* t) {
  if (!t->IN) {
    t->ET = 0;
    t->Q = false;
    t->state = TON_IDLE;
  } else if (t->state == TON_IDLE) {
    t->state = TON_RUNNING;
    t->Q = false;
    t->start = now_ms;
  } else if (t->state == TON_RUNNING) {
    const std::uint32_t elapsed = now_ms - t->start;
    if (elapsed >= t->PT) {
      t->ET = t->PT;
      t->state = TON_EXPIRED;
      t->Q = true;
    } else {
      t->ET = elapsed;
    }
  }
}

// CTU: counts rising edges of CU up to the type's limit; R clears; Q = CV >= PV.
struct ctu_t {
  bool CU;
  bool R;
  bool Q;
  bool cu_prev;
  std::int16_t PV;
  std::int16_t CV;
};
inline void ctu(ctu_t* c) {
  const bool up = c->CU && !c->cu_prev;
  c->cu_prev = c->CU;
  if (c->R) {
    c->CV = 0;
  } else if (up && c->CV < INT16_MAX) {
    ++c->CV;
  }
  c->Q = c->CV >= c->PV;
}

// R_TRIG: Q for one call after CLK rose.
struct r_trig_t {
  bool CLK;
  bool Q;
  bool M;
};
inline void r_trig(r_trig_t* e) {
  e->Q = e->CLK && !e->M;
  e->M = e->CLK;
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
    cell_t* c = &s.cell[K];
    s.PH = static_cast<std::int16_t>((s.CYC + K) % 20);
    c->T.IN = s.PH < 15;
    c->T.PT = 50;
    ton(&c->T);
    if (c->T.Q) ++s.NTON;
    c->C.CU = s.PH % 4 < 2;
    c->C.R = (s.CYC + K) % 500 == 0;
    c->C.PV = 50;
    ctu(&c->C);
    if (c->C.Q) ++s.NCTU;
    c->E.CLK = (s.CYC + 3 * K) % 6 < 3;
    r_trig(&c->E);
    if (c->E.Q) ++s.NEDGE;
    s.ACC = static_cast<std::int16_t>((s.ACC * 3 + K * 3 - s.PH) % 8191);
  }
}

readings read() noexcept { return {s.NTON, s.NCTU, s.NEDGE, s.ACC}; }

}  // namespace workload::handwritten_side
