// SPDX-License-Identifier: MIT
// iecoop/trace/svg.hpp — a trace as a self-contained SVG timing chart, as CODESYS Trace or a
// logic analyser shows it: one lane per channel, BOOLs as digital lanes, numbers (integers, bit
// strings, REAL, TIME, dates, enumerations) as stepped lines between their minimum and maximum,
// values in IEC text, a time axis in IEC notation and the trigger. No scripts, no external fonts
// or style sheets: a browser shows the file as it is.
//
//     std::string svg;
//     write_svg(trace.view(), [&](std::string_view s) { svg += s; }, {.title = "IO_PRG"});
//
// The writer allocates nothing: it formats into a buffer on the stack and hands the text to
// `put(std::string_view)` in pieces. Path data is written at changes only, one pixel column at
// a time: a lane that changes inside a column shows a vertical stroke over the values it took
// there, so a one-cycle pulse in a long trace never vanishes. Same trace, same bytes.
// IWYU pragma: private, include <iecoop/trace.hpp>
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
#include <iecoop/trace/detail/svg_scales.hpp>
#include <iecoop/trace/detail/svg_writer.hpp>
#include <iecoop/trace/view.hpp>
#include <iecoop/types/literal_text.hpp>
#include <iecoop/types/time.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

/// How write_svg lays out a chart. Sizes in pixels; colours as CSS writes them.
struct svg_options {
  int width = 1200;                               ///< the whole chart (at least the labels + 100 px of plot)
  int lane_height = 44;                           ///< a numeric lane: a row for the values, then the line
  int bool_lane_height = 26;                      ///< a BOOL lane
  int label_width = 0;                            ///< the names' column; 0: fitted to the longest name
  std::string_view title{};                       ///< written at the top (left out if empty)
  std::string_view line_colour = "#1f5fa8";       ///< the numeric lanes' line
  std::string_view bool_colour = "#1e7b4f";       ///< the BOOL lanes' line
  std::string_view bool_fill_colour = "#d4efdf";  ///< under a BOOL while it is TRUE
  std::string_view trigger_colour = "#d9480f";    ///< the trigger marker
};

namespace detail::svg {

// The text it writes (trace/detail/svg_writer.hpp) and the chart's geometry
// (trace/detail/svg_scales.hpp) come first.

template <class Put>
void header(out<Put>& o, const layout& l, const svg_options& options) {
  o.raw("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"");
  o.num(l.width);
  o.raw("\" height=\"");
  o.num(l.height);
  o.raw("\" viewBox=\"0 0 ");
  o.num(l.width);
  o.raw(" ");
  o.num(l.height);
  o.raw("\" font-family=\"sans-serif\" font-size=\"12\">\n");
  if (!options.title.empty()) {  // the document's title (a browser's tab)
    o.raw("<title>");
    o.escaped(options.title);
    o.raw("</title>\n");
  }
  o.raw("<style>\ntext{font-family:sans-serif;fill:#1c2430}\n");
  o.raw(".title{font-size:13px;font-weight:bold}\n.info{font-size:11px;fill:#5b6773}\n");
  o.raw(".name{font-size:12px}\n.val{font-size:11px;fill:#2d3a48}\n.scale{font-size:10px;fill:#6a7785}\n");
  o.raw(".tick{font-size:11px;fill:#4a5663;text-anchor:middle}\n");
  o.raw(".grid{stroke:#e2e6eb;stroke-width:1}\n.axis{stroke:#8a96a3;stroke-width:1}\n");
  o.raw(".num{fill:none;stroke:");
  o.escaped(options.line_colour);
  o.raw(";stroke-width:1.5;stroke-linejoin:round}\n.bit{fill:none;stroke:");
  o.escaped(options.bool_colour);
  o.raw(";stroke-width:1.5}\n.high{fill:");
  o.escaped(options.bool_fill_colour);
  o.raw(";stroke:none}\n.trigger{stroke:");
  o.escaped(options.trigger_colour);
  o.raw(";stroke-width:1.5;stroke-dasharray:4 3}\n.trigger-label{font-size:11px;font-weight:bold;fill:");
  o.escaped(options.trigger_colour);
  o.raw(";text-anchor:middle}\n</style>\n<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n");
  if (!options.title.empty()) {
    o.raw("<text class=\"title\" x=\"8\" y=\"18\">");
    o.escaped(options.title);
    o.raw("</text>\n");
  }
}

template <class Put>
void text_at(out<Put>& o, std::string_view cls, std::int64_t x, std::int64_t y, std::string_view text,
             std::string_view anchor = {}) {
  o.raw("<text class=\"");
  o.raw(cls);
  o.raw("\" x=\"");
  o.num(x);
  o.raw("\" y=\"");
  o.num(y);
  if (!anchor.empty()) {
    o.raw("\" text-anchor=\"");
    o.raw(anchor);
  }
  o.raw("\">");
  o.escaped(text);
  o.raw("</text>\n");
}

/// The value labels of a numeric lane: at a change where there is room since the last label,
/// else, shifted right, over the rest of that value's step if it is wide enough.
template <class Put>
void value_labels(out<Put>& o, const trace_view& view, std::size_t c, const time_scale& scale, std::int64_t y) {
  constexpr double font = 11;
  char buffer[text_room];
  double free_from = scale.left;  // where the next label may start
  bool pending = false;           // a change that got no label yet
  std::size_t pending_i = 0;
  double pending_x = 0;
  const auto place = [&](std::size_t i, double x, double end, bool shifted) {
    const std::string_view text = value_text(view, i, c, buffer);
    const double w = text_px(text, font);
    if (x + 3 + w > scale.right) return false;
    if (shifted && x + 3 + w > end) return false;
    text_at(o, "val", to_int(x) + 3, y, text);
    free_from = x + (w + 14 > 40 ? w + 14 : 40);
    return true;
  };
  std::uint64_t t = scale.t0;
  trace_value previous;
  for (std::size_t i = 0; i < view.size(); ++i) {
    t = time_at(view, i, t);
    if (i > 0) {
      if (view.same_values(i, i - 1)) continue;
      const trace_value v = view.value(i, c);
      if (v.u == previous.u) continue;
      previous = v;
    } else {
      previous = view.value(0, c);
    }
    const double x = scale.x(t);
    if (pending) {
      const double from = pending_x > free_from ? pending_x : free_from;
      if (x - from >= 20) place(pending_i, from, x, true);
    }
    pending = false;
    if (x >= free_from && place(i, x, x, false)) continue;
    pending = true;
    pending_i = i;
    pending_x = x;
  }
  if (pending && pending_x < free_from) place(pending_i, free_from, scale.right, true);
}

template <class Put>
void numeric_lane(out<Put>& o, const trace_view& view, std::size_t c, const time_scale& scale, std::int64_t top,
                  std::int64_t height) {
  const trace_type& type = *view.channels()[c].type;
  const double y_top = static_cast<double>(top + 17);
  const double y_bottom = static_cast<double>(top + height - 6);
  const value_range r = range_of(view, c);
  const double lo = r.any ? number(type, view.value(r.least, c)) : 0;
  const double hi = r.any ? number(type, view.value(r.greatest, c)) : 0;
  const double mid = (y_top + y_bottom) / 2;
  const auto y_of = [&](const trace_value& v) {
    const double n = number(type, v);
    if (std::isnan(n)) return to_tenths(mid);
    if (std::isinf(n)) return to_tenths(n > 0 ? y_top : y_bottom);
    if (!(hi > lo)) return to_tenths(mid);
    double y = y_bottom - (n - lo) / (hi - lo) * (y_bottom - y_top);
    y = y < y_top ? y_top : y > y_bottom ? y_bottom : y;
    return to_tenths(y);
  };
  o.raw("<path class=\"num\" d=\"");
  step_path(o, view, c, scale, y_of, -1);
  o.raw("\"/>\n");
  value_labels(o, view, c, scale, top + 12);
  // The scale at the right: the greatest value at the top, the least at the bottom.
  if (r.any) {
    char buffer[text_room];
    const std::int64_t x = to_int(scale.right) + 6;
    if (hi > lo) {
      text_at(o, "scale", x, to_int(y_top) + 4, value_text(view, r.greatest, c, buffer));
      text_at(o, "scale", x, to_int(y_bottom) + 3, value_text(view, r.least, c, buffer));
    } else {
      text_at(o, "scale", x, to_int(mid) + 4, value_text(view, r.least, c, buffer));
    }
  }
}

template <class Put>
void bool_lane(out<Put>& o, const trace_view& view, std::size_t c, const time_scale& scale, std::int64_t top,
               std::int64_t height) {
  const std::int64_t high = (top + 5) * 10;
  const std::int64_t low = (top + height - 5) * 10;
  const auto y_of = [&](const trace_value& v) { return v.u != 0 ? high : low; };
  o.raw("<path class=\"high\" d=\"");
  step_path(o, view, c, scale, y_of, low);
  o.raw("\"/>\n<path class=\"bit\" d=\"");
  step_path(o, view, c, scale, y_of, -1);
  o.raw("\"/>\n");
}

/// The widest text of the right-hand scale over the numeric channels.
inline double scale_px(const trace_view& view) {
  char buffer[text_room];
  double widest = 0;
  for (std::size_t c = 0; c < view.channels().size(); ++c) {
    if (view.channels()[c].type->kind == trace_kind::boolean) continue;
    const value_range r = range_of(view, c);
    if (!r.any) continue;
    const double a = text_px(value_text(view, r.least, c, buffer), 10);
    const double b = text_px(value_text(view, r.greatest, c, buffer), 10);
    widest = a > widest ? a : widest;
    widest = b > widest ? b : widest;
  }
  return widest;
}

template <class Put>
void empty_chart(out<Put>& o, const svg_options& options, std::string_view why) {
  layout l;
  l.width = clamp(options.width, 200, 100'000);
  l.height = options.title.empty() ? 60 : 80;
  header(o, l, options);
  text_at(o, "info", l.width / 2, l.height - 26, why, "middle");
  o.raw("</svg>\n");
}

/// The faint grid lines through the lanes, the axis below them with its ticks and their labels.
template <class Put>
void time_axis(out<Put>& o, const layout& l, const time_scale& scale) {
  const ticks k = ticks_of(scale);
  if (k.step != 0) {
    o.raw("<path class=\"grid\" d=\"");
    for_each_tick(k, scale, [&](std::uint64_t t) {
      o.raw("M");
      o.tenths(to_int(scale.x(t)) * 10 + 5);
      o.raw(" ");
      o.num(l.lanes_top);
      o.raw("V");
      o.num(l.lanes_bottom);
    });
    o.raw("\"/>\n");
  }
  o.raw("<path class=\"axis\" d=\"M");
  o.num(l.plot_left);
  o.raw(" ");
  o.tenths(l.lanes_bottom * 10 + 5);
  o.raw("H");
  o.num(l.plot_right);
  for_each_tick(k, scale, [&](std::uint64_t t) {
    o.raw("M");
    o.tenths(to_int(scale.x(t)) * 10 + 5);
    o.raw(" ");
    o.num(l.lanes_bottom);
    o.raw("v5");
  });
  o.raw("\"/>\n");
  for_each_tick(k, scale, [&](std::uint64_t t) {
    char text[max_text_length<LTIME>];
    const char* const e = tick_text(text, t, k.as_time);
    o.raw("<text class=\"tick\" x=\"");
    o.num(to_int(scale.x(t)));
    o.raw("\" y=\"");
    o.num(l.lanes_bottom + 19);
    o.raw("\">");
    o.raw(std::string_view(text, static_cast<std::size_t>(e - text)));
    o.raw("</text>\n");
  });
}

template <class P>
void write_chart(const trace_view& view, P& put, const svg_options& options) {
  out<P> o(put);
  const auto channels = view.channels();
  if (view.empty() || channels.empty()) {
    empty_chart(o, options, channels.empty() && !view.empty() ? "no samples (no channels)" : "no samples");
    return;
  }
  const std::size_t n = view.size();

  layout l;
  l.lane_height = clamp(options.lane_height, 30, 1000);
  l.bool_lane_height = clamp(options.bool_lane_height, 14, 1000);
  l.width = clamp(options.width, 200, 100'000);
  if (options.label_width > 0) {
    l.label_width = clamp(options.label_width, 20, 10'000);
  } else {
    double widest = 0;
    for (const trace_channel& ch : channels) {
      const double w = name_px(ch, 12);
      widest = w > widest ? w : widest;
    }
    l.label_width = clamp(static_cast<std::int64_t>(std::ceil(widest)) + 20, 60, l.width * 2 / 5);
  }
  const std::int64_t scale_width = clamp(static_cast<std::int64_t>(std::ceil(scale_px(view))) + 14, 40, 240);
  l.plot_left = l.label_width;
  l.plot_right = l.width - scale_width;
  if (l.plot_right - l.plot_left < 100) {
    l.plot_right = l.plot_left + 100;
    l.width = l.plot_right + scale_width;
  }
  const bool has_trigger = view.trigger_index() < n;
  l.lanes_top = has_trigger ? 44 : 30;
  std::int64_t lanes_height = 0;
  for (const trace_channel& ch : channels) {
    lanes_height += ch.type->kind == trace_kind::boolean ? l.bool_lane_height : l.lane_height;
  }
  l.lanes_bottom = l.lanes_top + lanes_height;
  l.height = l.lanes_bottom + 30;

  const time_scale scale = scale_of(view, static_cast<double>(l.plot_left), static_cast<double>(l.plot_right));

  header(o, l, options);
  {
    o.raw("<text class=\"info\" x=\"");
    o.num(l.width - 8);
    o.raw("\" y=\"18\" text-anchor=\"end\">");
    o.unum(n);
    o.raw(n == 1 ? " sample, cycle " : " samples, cycles ");
    o.unum(view.cycle(0));
    if (n > 1) {
      o.raw(" to ");
      o.unum(view.cycle(n - 1));
    }
    o.raw("</text>\n");
  }

  // Lane backgrounds, every other one shaded.
  {
    std::int64_t top = l.lanes_top;
    for (std::size_t c = 0; c < channels.size(); ++c) {
      const std::int64_t h = channels[c].type->kind == trace_kind::boolean ? l.bool_lane_height : l.lane_height;
      if (c % 2 == 1) {
        o.raw("<rect x=\"0\" y=\"");
        o.num(top);
        o.raw("\" width=\"");
        o.num(l.width);
        o.raw("\" height=\"");
        o.num(h);
        o.raw("\" fill=\"#f4f6f9\"/>\n");
      }
      top += h;
    }
  }

  time_axis(o, l, scale);

  // The lanes.
  {
    std::int64_t top = l.lanes_top;
    for (std::size_t c = 0; c < channels.size(); ++c) {
      const trace_channel& ch = channels[c];
      const bool digital = ch.type->kind == trace_kind::boolean;
      const std::int64_t h = digital ? l.bool_lane_height : l.lane_height;
      o.raw("<g id=\"lane-");
      o.unum(c);
      o.raw("\"><title>");
      put_channel_name(ch, [&](std::string_view s) { o.escaped(s); });
      o.raw(" : ");
      o.escaped(ch.type->name);
      o.raw("</title>\n");
      if (digital) {
        bool_lane(o, view, c, scale, top, h);
      } else {
        numeric_lane(o, view, c, scale, top, h);
      }
      o.raw("</g>\n");
      top += h;
    }
  }

  // The names, clipped to their column.
  o.raw("<clipPath id=\"iecoop-names\"><rect x=\"0\" y=\"0\" width=\"");
  o.num(l.label_width - 6);
  o.raw("\" height=\"");
  o.num(l.height);
  o.raw("\"/></clipPath>\n<g clip-path=\"url(#iecoop-names)\">\n");
  {
    std::int64_t top = l.lanes_top;
    for (const trace_channel& ch : channels) {
      const std::int64_t h = ch.type->kind == trace_kind::boolean ? l.bool_lane_height : l.lane_height;
      o.raw("<text class=\"name\" x=\"8\" y=\"");
      o.num(top + h / 2 + 4);
      o.raw("\">");
      put_channel_name(ch, [&](std::string_view s) { o.escaped(s); });
      o.raw("</text>\n");
      top += h;
    }
  }
  o.raw("</g>\n");

  if (has_trigger) {
    std::uint64_t t = scale.t0;
    for (std::size_t i = 1; i <= view.trigger_index(); ++i) t = time_at(view, i, t);
    const std::int64_t x = to_int(scale.x(t));
    o.raw("<path class=\"trigger\" d=\"M");
    o.tenths(x * 10 + 5);
    o.raw(" ");
    o.num(l.lanes_top - 12);
    o.raw("V");
    o.num(l.lanes_bottom);
    o.raw("\"/>\n");
    text_at(o, "trigger-label", x, l.lanes_top - 16, "trigger");
  }
  o.raw("</svg>\n");
}

}  // namespace detail::svg

/**
 * Writes the samples of `view` as an SVG timing chart through `put(std::string_view)`: one lane
 * per channel in channel order, named on the left (scope.name); a BOOL as a digital lane
 * (filled while TRUE); any other value as a stepped line between its least and greatest value
 * (written at the right), with its IEC text where it changes and there is room (enumerations
 * by their component's name); below, the time axis in the cycle clock's time as IEC text
 * (`T#1s500ms`, or `LTIME#...` for steps below a millisecond), with a faint grid line at each
 * tick; the trigger's sample marked "trigger". A sample's values hold until the next sample;
 * the last one for one more median sample interval. No samples or no channels: a chart that
 * says "no samples". Allocates nothing; the same trace gives the same bytes.
 */
template <class Put>
void write_svg(const trace_view& view, Put&& put, const svg_options& options = {}) {
  detail::svg::write_chart<std::remove_reference_t<Put>>(view, put, options);
}

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
