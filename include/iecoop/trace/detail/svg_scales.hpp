// SPDX-License-Identifier: MIT
// iecoop/trace/detail/svg_scales.hpp — the geometry of an SVG chart: each lane's value range, the
// time scale and its ticks, the step paths of the values, the layout of lanes and labels.
// IWYU pragma: private, include <iecoop/trace/svg.hpp>
#pragma once

#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string_view>
#include <type_traits>

#include <iecoop/config.hpp>
#include <iecoop/trace/channels.hpp>
#include <iecoop/trace/detail/svg_writer.hpp>
#include <iecoop/trace/view.hpp>
#include <iecoop/types/literal_text.hpp>
#include <iecoop/types/time.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop::detail::svg {

/// Room for a value's text; a longer one (an enumeration with very long names) is shown as its number.
inline constexpr std::size_t text_room = 256;

inline std::string_view value_text(const trace_view& view, std::size_t i, std::size_t c, char (&buffer)[text_room]) {
  const trace_channel& channel = view.channels()[c];
  if (channel.type->max_text <= text_room) return {buffer, static_cast<std::size_t>(view.text(i, c, buffer) - buffer)};
  const trace_value v = view.value(i, c);
  const auto r = channel.type->is_signed ? std::to_chars(buffer, buffer + text_room, v.i)
                                         : std::to_chars(buffer, buffer + text_room, v.u);
  return {buffer, static_cast<std::size_t>(r.ptr - buffer)};
}

/// TRUE if a < b, as the channel's type orders its values.
inline bool value_less(const trace_type& type, const trace_value& a, const trace_value& b) noexcept {
  if (type.kind == trace_kind::real) return a.f < b.f;
  if (type.is_signed) return a.i < b.i;
  return a.u < b.u;
}
inline double number(const trace_type& type, const trace_value& v) noexcept {
  if (type.kind == trace_kind::real) return v.f;
  if (type.is_signed) return static_cast<double>(v.i);
  return static_cast<double>(v.u);
}

/// The samples where a numeric channel takes its least and greatest (finite) value.
struct value_range {
  bool any = false;  // FALSE: no finite value (a REAL that is only NaN or infinite)
  std::size_t least = 0;
  std::size_t greatest = 0;
};
inline value_range range_of(const trace_view& view, std::size_t c) {
  const trace_type& type = *view.channels()[c].type;
  value_range r;
  trace_value lo;
  trace_value hi;
  for (std::size_t i = 0; i < view.size(); ++i) {
    if (i > 0 && view.same_values(i, i - 1)) continue;
    const trace_value v = view.value(i, c);
    if (type.kind == trace_kind::real && !std::isfinite(v.f)) continue;
    if (!r.any) {
      r = value_range{true, i, i};
      lo = hi = v;
    } else if (value_less(type, v, lo)) {
      r.least = i;
      lo = v;
    } else if (value_less(type, hi, v)) {
      r.greatest = i;
      hi = v;
    }
  }
  return r;
}

/// Sample time, clamped so that it never goes back (a cycle clock set backwards draws as a step
/// at the same time).
inline std::uint64_t time_at(const trace_view& view, std::size_t i, std::uint64_t before) noexcept {
  const std::uint64_t t = view.time(i).count();
  return t < before ? before : t;
}

/// The time scale of the plot: [t0, t0 + span) over [left, right) pixels.
struct time_scale {
  std::uint64_t t0 = 0;
  std::uint64_t span = 1;
  double left = 0;
  double right = 1;
  [[nodiscard]] double x(std::uint64_t t) const noexcept {
    return left + static_cast<double>(t - t0) * (right - left) / static_cast<double>(span);
  }
};

inline time_scale scale_of(const trace_view& view, double left, double right) {
  const std::size_t n = view.size();
  time_scale s;
  s.left = left;
  s.right = right;
  s.t0 = view.time(0).count();
  std::uint64_t last = s.t0;
  for (std::size_t i = 1; i < n; ++i) last = time_at(view, i, last);
  // The last sample holds for one more median sample interval (of at most 255 intervals spread
  // over the trace), and at least 3 px.
  std::uint64_t intervals[255];
  const std::size_t m = n - 1 < 255 ? n - 1 : 255;
  for (std::size_t k = 0; k < m; ++k) {
    const std::size_t i = 1 + k * (n - 1) / m;
    const std::uint64_t a = view.time(i - 1).count();
    const std::uint64_t b = view.time(i).count();
    std::uint64_t v = b > a ? b - a : 0;
    std::size_t j = k;
    for (; j > 0 && intervals[j - 1] > v; --j) intervals[j] = intervals[j - 1];
    intervals[j] = v;
  }
  std::uint64_t extra = m == 0 ? 0 : intervals[m / 2];
  const std::uint64_t covered = last - s.t0;
  const double plot = right - left;
  const auto least = static_cast<std::uint64_t>(std::ceil(static_cast<double>(covered) * 3 / (plot - 3)));
  if (extra < least) extra = least;
  if (extra == 0) extra = 1'000'000;  // one sample, or all at one time: 1 ms
  const std::uint64_t room = std::numeric_limits<std::uint64_t>::max() - s.t0;
  s.span = covered > room - extra || extra > room ? room : covered + extra;
  if (s.span == 0) s.span = 1;
  return s;
}

/// Writes path data with a pen that skips moves to where it is.
template <class Put>
struct pen {
  out<Put>& o;
  std::int64_t x;  // px
  std::int64_t y;  // tenths of a px
  void h(std::int64_t to) {
    if (to == x) return;
    o.raw("H");
    o.num(to);
    x = to;
  }
  void v(std::int64_t to) {
    if (to == y) return;
    o.raw("V");
    o.tenths(to);
    y = to;
  }
};

/**
 * The step line of channel c: a value holds until the next sample's time; the last one up to
 * the right edge. Changes that fall into one pixel column become one vertical stroke over the
 * values taken there, ending at the last one. With `base` >= 0 the path starts and ends on
 * that level (a fill's outline).
 */
template <class Put, class YOf>
void step_path(out<Put>& o, const trace_view& view, std::size_t c, const time_scale& scale, YOf y_of,
               std::int64_t base) {
  const auto left = to_int(scale.left);
  const auto right = to_int(scale.right);
  trace_value previous = view.value(0, c);
  const std::int64_t y0 = y_of(previous);
  pen<Put> p{o, left, base >= 0 ? base : y0};
  o.raw("M");
  o.num(left);
  o.raw(" ");
  o.tenths(p.y);
  p.v(y0);
  bool pending = false;
  std::int64_t column = 0;
  std::int64_t lo = 0;
  std::int64_t hi = 0;
  std::int64_t last = 0;
  const auto flush = [&] {
    if (lo == hi) return;  // no visible change
    p.h(column);
    if (last == hi) {
      p.v(lo);
      p.v(hi);
    } else if (last == lo) {
      p.v(hi);
      p.v(lo);
    } else {
      p.v(lo);
      p.v(hi);
      p.v(last);
    }
  };
  std::uint64_t t = scale.t0;
  for (std::size_t i = 1; i < view.size(); ++i) {
    t = time_at(view, i, t);
    if (view.same_values(i, i - 1)) continue;
    const trace_value v = view.value(i, c);
    if (v.u == previous.u) continue;
    previous = v;
    const std::int64_t y = y_of(v);
    std::int64_t at = to_int(scale.x(t));
    if (at > right) at = right;
    if (pending && at == column) {
      lo = y < lo ? y : lo;
      hi = y > hi ? y : hi;
      last = y;
      continue;
    }
    if (pending) flush();
    pending = true;
    column = at;
    lo = y < p.y ? y : p.y;
    hi = y > p.y ? y : p.y;
    last = y;
  }
  if (pending) flush();
  p.h(right);
  if (base >= 0) p.v(base);
}

/// The ticks of the time axis: a step of 1, 2 or 5 x 10^k ns whose labels do not collide.
struct ticks {
  std::uint64_t step = 0;  // 0: none
  std::uint64_t first = 0;
  bool as_time = false;  // T#... (whole ms that fit a TIME), else LTIME#...
};

inline char* tick_text(char* out, std::uint64_t ns, bool as_time) {
  if (as_time) return to_text(out, TIME::from_ticks(static_cast<std::uint32_t>(ns / 1'000'000)));
  return to_text(out, LTIME::from_ticks(ns));
}

/// Calls f(t) for each tick's time.
template <class F>
void for_each_tick(const ticks& k, const time_scale& scale, F f) {
  if (k.step == 0) return;
  const std::uint64_t end = scale.t0 + scale.span;
  for (std::uint64_t t = k.first; t <= end; t += k.step) {
    f(t);
    if (t > std::numeric_limits<std::uint64_t>::max() - k.step) break;
  }
}

inline ticks ticks_of(const time_scale& scale) {
  const double px_per_ns = (scale.right - scale.left) / static_cast<double>(scale.span);
  const std::uint64_t end = scale.t0 + scale.span;
  constexpr std::uint64_t factors[3] = {1, 2, 5};
  for (std::uint64_t decade = 1; decade <= 1'000'000'000'000'000'000ULL; decade *= 10) {
    for (const std::uint64_t f : factors) {
      const std::uint64_t step = decade * f;
      const double spacing = static_cast<double>(step) * px_per_ns;
      if (spacing < 50) continue;
      ticks k;
      k.step = step;
      k.first = (scale.t0 / step) * step;
      if (k.first < scale.t0) {
        if (k.first > std::numeric_limits<std::uint64_t>::max() - step) return ticks{};
        k.first += step;
      }
      k.as_time = step % 1'000'000 == 0 && end / 1'000'000 <= std::numeric_limits<std::uint32_t>::max();
      double widest = 0;
      for_each_tick(k, scale, [&](std::uint64_t t) {
        char text[max_text_length<LTIME>];
        const char* const e = tick_text(text, t, k.as_time);
        const double w = text_px(std::string_view(text, static_cast<std::size_t>(e - text)), 11);
        widest = w > widest ? w : widest;
      });
      if (spacing >= widest + 16) return k;
    }
  }
  return ticks{};
}

/// The geometry of the chart.
struct layout {
  std::int64_t width = 0;
  std::int64_t height = 0;
  std::int64_t label_width = 0;
  std::int64_t plot_left = 0;
  std::int64_t plot_right = 0;
  std::int64_t lanes_top = 0;
  std::int64_t lanes_bottom = 0;
  std::int64_t lane_height = 0;
  std::int64_t bool_lane_height = 0;
};

constexpr std::int64_t clamp(std::int64_t v, std::int64_t lo, std::int64_t hi) noexcept {
  return v < lo ? lo : v > hi ? hi : v;
}

}  // namespace iecoop::detail::svg

#include <iecoop/detail/pop_macros.hpp>
