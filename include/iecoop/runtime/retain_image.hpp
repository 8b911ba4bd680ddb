// SPDX-License-Identifier: MIT
// iecoop/runtime/retain_image.hpp — the byte image in which a runtime keeps the RETAIN and
// PERSISTENT values of its instances over a reset or a restart: saved from the variables that
// lie inside each instance, checked (magic, version, checksum, each section's layout hash) and
// restored into them when every value is one of its type. See docs/retain.md, "How the values
// are kept".
// IWYU pragma: private, include <iecoop/runtime/application.hpp>
#pragma once

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>

#include <iecoop/config.hpp>
#include <iecoop/detail/lifecycle_state.hpp>
#include <iecoop/fault.hpp>
#include <iecoop/runtime/retain.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

// ---------------------------------------------------------------------------------------
// The image

namespace detail {

/// An instance whose remanent variables are saved and restored: a program instance, a
/// global variable list (a struct of variables), or a single global variable. A remanent
/// variable belongs to it if its value lies within [base, base + size).
struct retained_object {
  const void* base;
  std::size_t size;
};

// The image (every number little-endian):
//   header, 16 bytes:  "IECR", version u16 (1), section count u16, total size u32,
//                      FNV-1a u32 of the bytes after the header
//   per section:       kind u8 (1 RETAIN, 2 PERSISTENT), 3 zero bytes, layout hash u32,
//                      variable count u32, data size u32; then the values, unpadded
inline constexpr std::size_t retain_image_header_size = 16;
inline constexpr std::size_t retain_section_header_size = 16;
inline constexpr std::uint16_t retain_image_version = 1;
inline constexpr std::array<unsigned char, 4> retain_image_magic{'I', 'E', 'C', 'R'};

inline std::uintptr_t retained_address(const void* pointer) noexcept {
  return reinterpret_cast<std::uintptr_t>(pointer);
}

/// Calls f(node, offset) for each remanent variable of `kind` that lies in `object`, in
/// increasing order of its offset in the object. O(variables) when the variables were
/// constructed in address order (as C++ constructs members, bases and nested blocks);
/// otherwise O(variables²), without allocating.
template <class F>
void for_each_retained_in(const retained_object& object, retain_kind kind, F&& f) {
  const std::uintptr_t begin = retained_address(object.base);
  auto offset_of = [&](const retained_node& node, std::size_t& offset) {
    if (node.type->kind != kind) return false;
    const std::uintptr_t at = retained_address(node.value);
    if (at < begin) return false;
    offset = static_cast<std::size_t>(at - begin);
    return offset < object.size && object.size - offset >= node.type->size;
  };
  bool sorted = true;
  bool any = false;
  std::size_t last = 0;
  std::size_t offset = 0;
  for (const retained_node* node = retained_first; node != nullptr && sorted; node = node->next) {
    if (!offset_of(*node, offset)) continue;
    if (any && offset <= last) sorted = false;
    last = offset;
    any = true;
  }
  if (sorted) {
    for (retained_node* node = retained_first; node != nullptr; node = node->next) {
      if (offset_of(*node, offset)) f(*node, offset);
    }
    return;
  }
  // Selection: each round visits the variable with the smallest offset above the last one.
  bool started = false;
  std::size_t previous = 0;
  for (;;) {
    retained_node* best = nullptr;
    std::size_t best_offset = 0;
    for (retained_node* node = retained_first; node != nullptr; node = node->next) {
      if (!offset_of(*node, offset) || (started && offset <= previous)) continue;
      if (best == nullptr || offset < best_offset) {
        best = node;
        best_offset = offset;
      }
    }
    if (best == nullptr) return;
    f(*best, best_offset);
    previous = best_offset;
    started = true;
  }
}

/// The layout of the variables of one kind: what a section's header records.
struct retained_layout {
  std::uint32_t hash = 0;
  std::size_t count = 0;
  std::size_t data_size = 0;
};

/// The current layout of the variables of `kind` in `objects`: the hash runs over the byte
/// order of the machine (values are saved as they are in memory) and, for each variable in
/// object order and then offset order, the object's index, the offset, the size and the
/// type's hash.
inline retained_layout retained_layout_of(std::span<const retained_object> objects, retain_kind kind) {
  fnv1a hash;
  hash.add_byte(std::endian::native == std::endian::little ? 1 : 2);
  retained_layout layout;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    for_each_retained_in(objects[i], kind, [&](const retained_node& node, std::size_t offset) {
      hash.add_number(i).add_number(offset).add_number(node.type->size).add_number(node.type->type_hash);
      ++layout.count;
      layout.data_size += node.type->size;
    });
  }
  layout.hash = hash.value();
  return layout;
}

/// The number of remanent variables of `kinds` that lie in `objects`.
inline std::size_t retained_count(std::span<const retained_object> objects, retain_kinds kinds) {
  std::size_t count = 0;
  for (const retain_kind kind : {retain_kind::retain, retain_kind::persistent}) {
    if (kinds.contains(kind)) count += retained_layout_of(objects, kind).count;
  }
  return count;
}

inline void retained_put(std::byte* at, std::uint64_t value, int bytes) noexcept {
  for (int i = 0; i < bytes; ++i) {
    at[i] = static_cast<std::byte>(value & 0xFFU);
    value >>= 8U;
  }
}
inline std::uint32_t retained_get(const std::byte* at, int bytes) noexcept {
  std::uint32_t value = 0;
  for (int i = bytes - 1; i >= 0; --i) value = (value << 8U) | std::to_integer<std::uint32_t>(at[i]);
  return value;
}
inline std::uint32_t retained_checksum(std::span<const std::byte> bytes) noexcept {
  fnv1a hash;
  for (const std::byte b : bytes) hash.add_byte(std::to_integer<std::uint8_t>(b));
  return hash.value();
}

/// The bytes the image of both kinds of the variables in `objects` takes (retained_image_size
/// with retain_kinds::both), 0 where none lies in them: one pass over the variables, without
/// the order and the layout's hash, so that an application without RETAIN variables (the
/// check that start() makes) links none of the image's code.
inline std::size_t retained_image_size_needed(std::span<const retained_object> objects) noexcept {
  std::size_t data = 0;
  bool any = false;
  for (const retained_node* node = retained_first; node != nullptr; node = node->next) {
    const std::uintptr_t at = retained_address(node->value);
    for (const retained_object& object : objects) {
      const std::uintptr_t begin = retained_address(object.base);
      if (at >= begin && at - begin < object.size && object.size - (at - begin) >= node->type->size) {
        data += node->type->size;
        any = true;
        break;
      }
    }
  }
  return any ? retain_image_header_size + 2 * retain_section_header_size + data : 0;
}

/// The number of bytes save_retained writes for `kinds` of the variables in `objects`.
inline std::size_t retained_image_size(std::span<const retained_object> objects, retain_kinds kinds) {
  std::size_t size = retain_image_header_size;
  for (const retain_kind kind : {retain_kind::retain, retain_kind::persistent}) {
    if (kinds.contains(kind)) size += retain_section_header_size + retained_layout_of(objects, kind).data_size;
  }
  return size;
}

/**
 * Writes the values of the remanent variables of `kinds` that lie in `objects` to `out`, as a
 * self-describing image (a header, then one section per kind in `kinds`, RETAIN first).
 * Returns the bytes written; if `out` is smaller than retained_image_size(objects, kinds),
 * reports fault_kind::invalid_value, writes nothing and returns 0.
 */
inline std::size_t save_retained(std::span<const retained_object> objects, retain_kinds kinds,
                                 std::span<std::byte> out) {
  const std::size_t needed = retained_image_size(objects, kinds);
  if (out.size() < needed) {
    fault(fault_kind::invalid_value,
          "the RETAIN/PERSISTENT image does not fit the buffer; size it with retained_image_size");
    return 0;
  }
  if constexpr (sizeof(std::size_t) > 4) {  // a 32-bit target cannot hold more (and GCC warns the test is always false)
    if (needed > 0xFFFFFFFFU) {
      fault(fault_kind::invalid_value, "the RETAIN/PERSISTENT image exceeds 4 GiB");
      return 0;
    }
  }
  std::size_t position = retain_image_header_size;
  std::uint64_t sections = 0;
  for (const retain_kind kind : {retain_kind::retain, retain_kind::persistent}) {
    if (!kinds.contains(kind)) continue;
    const retained_layout layout = retained_layout_of(objects, kind);
    std::byte* header = out.data() + position;
    retained_put(header, static_cast<std::uint8_t>(kind), 1);
    retained_put(header + 1, 0, 3);
    retained_put(header + 4, layout.hash, 4);
    retained_put(header + 8, layout.count, 4);
    retained_put(header + 12, layout.data_size, 4);
    position += retain_section_header_size;
    for (const retained_object& object : objects) {
      for_each_retained_in(object, kind, [&](const retained_node& node, std::size_t) {
        std::memcpy(out.data() + position, node.value, node.type->size);
        position += node.type->size;
      });
    }
    ++sections;
  }
  std::byte* header = out.data();
  for (std::size_t i = 0; i < retain_image_magic.size(); ++i) header[i] = static_cast<std::byte>(retain_image_magic[i]);
  retained_put(header + 4, retain_image_version, 2);
  retained_put(header + 6, sections, 2);
  retained_put(header + 8, position, 4);
  const std::span<const std::byte> body = out.subspan(retain_image_header_size, position - retain_image_header_size);
  retained_put(header + 12, retained_checksum(body), 4);
  return position;
}

/// TRUE if `in` is a complete image of a version this iecoop reads, nothing before or after
/// it, whose checksum and section structure are intact.
inline bool valid_retained_image(std::span<const std::byte> in) noexcept {
  if (in.size() < retain_image_header_size) return false;
  for (std::size_t i = 0; i < retain_image_magic.size(); ++i) {
    if (std::to_integer<unsigned char>(in[i]) != retain_image_magic[i]) return false;
  }
  if (retained_get(in.data() + 4, 2) != retain_image_version) return false;
  const std::size_t total = retained_get(in.data() + 8, 4);
  // Exactly what a save wrote: bytes after the image (junk appended, another file's tail) make
  // it as damaged as bytes missing (docs/retain.md, "What a start finds").
  if (total < retain_image_header_size || total != in.size()) return false;
  const std::span<const std::byte> body = in.subspan(retain_image_header_size, total - retain_image_header_size);
  if (retained_get(in.data() + 12, 4) != retained_checksum(body)) return false;
  const std::size_t sections = retained_get(in.data() + 6, 2);
  std::size_t position = retain_image_header_size;
  for (std::size_t s = 0; s < sections; ++s) {
    if (total - position < retain_section_header_size) return false;
    const std::uint32_t kind = retained_get(in.data() + position, 1);
    if (kind != 1 && kind != 2) return false;
    const std::size_t data_size = retained_get(in.data() + position + 12, 4);
    if (total - position - retain_section_header_size < data_size) return false;
    position += retain_section_header_size + data_size;
  }
  return position == total;
}

/// What restoring an image would do with each kind of remanent variable (check_retained).
struct retained_verdict {
  retain_load retain = retain_load::initial;
  retain_load persistent = retain_load::initial;

  [[nodiscard]] constexpr retain_load& operator[](retain_kind kind) noexcept {
    return kind == retain_kind::retain ? retain : persistent;
  }
  [[nodiscard]] constexpr retain_load operator[](retain_kind kind) const noexcept {
    return kind == retain_kind::retain ? retain : persistent;
  }
  /// Nothing found yet: `initial` for the kinds in `kinds`, `not_kept` for the others.
  [[nodiscard]] static constexpr retained_verdict nothing_found(retain_kinds kinds) noexcept {
    retained_verdict verdict;
    verdict.retain = kinds.contains(retain_kind::retain) ? retain_load::initial : retain_load::not_kept;
    verdict.persistent = kinds.contains(retain_kind::persistent) ? retain_load::initial : retain_load::not_kept;
    return verdict;
  }
  /// The kinds whose values would be restored (restored, or restored_previous where the
  /// image is the storage's previous one).
  [[nodiscard]] constexpr retain_kinds restorable() const noexcept {
    auto usable = [](retain_load load) {
      return load == retain_load::restored || load == retain_load::restored_previous;
    };
    retain_kinds kinds;
    if (usable(retain)) kinds |= retain_kind::retain;
    if (usable(persistent)) kinds |= retain_kind::persistent;
    return kinds;
  }
};

/// Calls f(kind, position of the section's values, its header) for each section of an image
/// valid_retained_image accepts (and of no other).
template <class F>
void for_each_retained_section(std::span<const std::byte> in, F&& f) {
  const std::size_t sections = retained_get(in.data() + 6, 2);
  std::size_t position = retain_image_header_size;
  for (std::size_t s = 0; s < sections; ++s) {
    const std::byte* header = in.data() + position;
    position += retain_section_header_size;
    f(static_cast<retain_kind>(retained_get(header, 1)), position, header);
    position += retained_get(header + 12, 4);
  }
}

/// TRUE if every value of the section of `kind` at `position` is a value of its variable's
/// type (the section's layout being the variables' current one).
inline bool retained_values_valid(std::span<const retained_object> objects, retain_kind kind,
                                  std::span<const std::byte> in, std::size_t position) {
  bool valid = true;
  for (const retained_object& object : objects) {
    for_each_retained_in(object, kind, [&](const retained_node& node, std::size_t) {
      if (valid && !node.type->valid(in.data() + position)) valid = false;
      position += node.type->size;
    });
  }
  return valid;
}

/**
 * What restoring `in` into the remanent variables of `objects` would do, without changing
 * them: for each kind in `kinds`, retain_load::restored if the image has a section of it whose
 * layout is the variables' current layout (same variables, in the same objects, at the same
 * offsets, of the same sizes and types) and whose every value is a value of its type;
 * retain_load::changed if the layout differs, retain_load::invalid_value if a value is none,
 * retain_load::initial if the image has no section of that kind. Every kind in `kinds` is
 * retain_load::damaged if the image is not intact (magic, version, size, checksum,
 * structure); a kind not in `kinds` is retain_load::not_kept.
 */
inline retained_verdict check_retained(std::span<const retained_object> objects, retain_kinds kinds,
                                       std::span<const std::byte> in) {
  retained_verdict verdict = retained_verdict::nothing_found(kinds);
  if (!valid_retained_image(in)) {
    for (const retain_kind kind : {retain_kind::retain, retain_kind::persistent}) {
      if (kinds.contains(kind)) verdict[kind] = retain_load::damaged;
    }
    return verdict;
  }
  retain_kinds seen;
  for_each_retained_section(in, [&](retain_kind kind, std::size_t position, const std::byte* header) {
    if (!kinds.contains(kind) || seen.contains(kind)) return;  // the first section of a kind counts
    seen |= kind;
    const retained_layout layout = retained_layout_of(objects, kind);
    if (layout.hash != retained_get(header + 4, 4) || layout.count != retained_get(header + 8, 4) ||
        layout.data_size != retained_get(header + 12, 4)) {
      verdict[kind] = retain_load::changed;
    } else if (!retained_values_valid(objects, kind, in, position)) {
      verdict[kind] = retain_load::invalid_value;
    } else {
      verdict[kind] = retain_load::restored;
    }
  });
  return verdict;
}

/**
 * Copies the values of the kinds `verdict` found restorable (check_retained on the same
 * objects and image) back into the remanent variables of `objects`. Returns those kinds.
 */
inline retain_kinds restore_checked(std::span<const retained_object> objects, const retained_verdict& verdict,
                                    std::span<const std::byte> in) {
  const retain_kinds kinds = verdict.restorable();
  retain_kinds restored;
  if (kinds.empty()) return restored;  // and the image may not be intact
  for_each_retained_section(in, [&](retain_kind kind, std::size_t position, const std::byte*) {
    if (!kinds.contains(kind) || restored.contains(kind)) return;
    for (const retained_object& object : objects) {
      for_each_retained_in(object, kind, [&](retained_node& node, std::size_t) {
        std::memcpy(node.value, in.data() + position, node.type->size);
        position += node.type->size;
      });
    }
    restored |= kind;
  });
  return restored;
}

// ---------------------------------------------------------------------------------------
// Restoring while the instances are constructed

/// Where a remanent variable lies: the index of the object it lies in, and its offset there.
struct retained_place {
  std::size_t object = 0;
  std::size_t offset = 0;
};

/// FALSE if the variable at `node` lies in none of `objects`.
inline bool retained_place_of(std::span<const retained_object> objects, const retained_node& node,
                              retained_place& place) noexcept {
  const std::uintptr_t at = retained_address(node.value);
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const std::uintptr_t begin = retained_address(objects[i].base);
    if (at < begin) continue;
    const std::size_t offset = static_cast<std::size_t>(at - begin);
    if (offset < objects[i].size && objects[i].size - offset >= node.type->size) {
      place = {i, offset};
      return true;
    }
  }
  return false;
}

/**
 * The kinds in `kinds` whose variables in `objects` were constructed in the order in which
 * save_retained writes them (object by object, each by address), as C++ constructs members,
 * bases and nested blocks: for those, the next construction of the same instances can take
 * the values from the image one after the other (retained_restore_session).
 */
inline retain_kinds retained_in_construction_order(std::span<const retained_object> objects, retain_kinds kinds) {
  retain_kinds ordered;
  for (const retain_kind kind : {retain_kind::retain, retain_kind::persistent}) {
    if (!kinds.contains(kind)) continue;
    bool in_order = true;
    bool any = false;
    retained_place last;
    for (const retained_node* node = retained_first; node != nullptr && in_order; node = node->next) {
      retained_place place;
      if (node->type->kind != kind || !retained_place_of(objects, *node, place)) continue;
      if (any && (place.object < last.object || (place.object == last.object && place.offset <= last.offset))) {
        in_order = false;
      }
      last = place;
      any = true;
    }
    if (in_order) ordered |= kind;
  }
  return ordered;
}

/**
 * Restores the remanent variables of `objects` as they are constructed, so that each has its
 * kept value before the FB_Init of the block around it runs — CODESYS's order, where the
 * retain memory keeps the values and FB_Init(bInitRetains := FALSE) sees them
 * (docs/retain.md, "Start-up order"). While the session exists, every remanent variable
 * constructed in one of `objects`, of a kind in `kinds`, takes the next value of that kind's
 * section of `in`, in the order save_retained wrote them.
 *
 * Use it for kinds that check_retained found restorable in `in` (for these very objects, or a
 * probe of them) and that retained_in_construction_order found in order; `in` must outlive
 * the session. Each value taken is checked again (within the section, after the one before it
 * in the image's order, a value of its type); a variable that breaks that, or a construction
 * that ends with other variables than the image's (count, size, layout hash), makes its kind
 * fail: finish() leaves it out, and the caller must not trust the values of that kind (the
 * application ends and rebuilds its instances). Not thread-safe, allocates nothing; sessions
 * nest (the one before is active again when one ends).
 */
class retained_restore_session : private retained_restore_hook {
 public:
  retained_restore_session(std::span<const retained_object> objects, retain_kinds kinds,
                           std::span<const std::byte> in) noexcept
      : objects_(objects), in_(in), previous_(retained_restoring), previous_kept_(kept_at_construction) {
    take = &take_value;
    if (!kinds.empty() && valid_retained_image(in)) {
      retain_kinds seen;
      for_each_retained_section(in, [&](retain_kind kind, std::size_t position, const std::byte* header) {
        if (!kinds.contains(kind) || seen.contains(kind)) return;  // the first section of a kind counts
        seen |= kind;
        cursor& c = cursor_of(kind);
        c.active = true;
        c.position = position;
        c.end = position + retained_get(header + 12, 4);
        c.expected_hash = retained_get(header + 4, 4);
        c.expected_count = retained_get(header + 8, 4);
        c.expected_size = retained_get(header + 12, 4);
        c.hash.add_byte(std::endian::native == std::endian::little ? 1 : 2);
      });
    }
    retained_restoring = this;
    kept_at_construction = &kept;
  }
  ~retained_restore_session() {
    retained_restoring = previous_;
    kept_at_construction = previous_kept_;
  }
  retained_restore_session(const retained_restore_session&) = delete;
  retained_restore_session& operator=(const retained_restore_session&) = delete;

  /// The kinds whose every variable got its value at construction, exactly the image's
  /// variables (count, size, layout hash). Call it when the instances are constructed.
  [[nodiscard]] retain_kinds finish() const noexcept {
    retain_kinds restored;
    for (const retain_kind kind : {retain_kind::retain, retain_kind::persistent}) {
      const cursor& c = cursors_[index_of(kind)];
      if (c.active && !c.failed && c.count == c.expected_count && c.taken_size == c.expected_size &&
          c.hash.value() == c.expected_hash) {
        restored |= kind;
      }
    }
    return restored;
  }
  /// The kinds the session was to restore (those of `kinds` the image has a section of).
  [[nodiscard]] retain_kinds kinds() const noexcept {
    retain_kinds kinds;
    for (const retain_kind kind : {retain_kind::retain, retain_kind::persistent}) {
      if (cursors_[index_of(kind)].active) kinds |= kind;
    }
    return kinds;
  }

 private:
  struct cursor {
    bool active = false;
    bool failed = false;
    bool any = false;
    std::size_t position = 0;
    std::size_t end = 0;
    retained_place last;
    std::size_t count = 0;
    std::size_t taken_size = 0;
    std::uint32_t expected_hash = 0;
    std::size_t expected_count = 0;
    std::size_t expected_size = 0;
    fnv1a hash;
  };

  static constexpr std::size_t index_of(retain_kind kind) noexcept { return kind == retain_kind::retain ? 0 : 1; }
  cursor& cursor_of(retain_kind kind) noexcept { return cursors_[index_of(kind)]; }

  static void take_value(retained_restore_hook& hook, retained_node& node) noexcept {
    static_cast<retained_restore_session&>(hook).take_one(node);
  }

  void take_one(retained_node& node) noexcept {
    cursor& c = cursor_of(node.type->kind);
    retained_place place;
    if (!c.active || c.failed || !retained_place_of(objects_, node, place)) return;
    const bool after =
        !c.any || place.object > c.last.object || (place.object == c.last.object && place.offset > c.last.offset);
    const std::size_t size = node.type->size;
    if (!after || c.end - c.position < size || !node.type->valid(in_.data() + c.position)) {
      c.failed = true;  // not the image's next variable: the construction differs from the saved one
      return;
    }
    std::memcpy(node.value, in_.data() + c.position, size);
    c.hash.add_number(place.object).add_number(place.offset).add_number(size).add_number(node.type->type_hash);
    c.position += size;
    c.taken_size += size;
    ++c.count;
    c.last = place;
    c.any = true;
  }

  /// kept_at_construction: a remanent variable of an active kind that got its kept value.
  static bool kept(const void* address, std::size_t size) noexcept {
    auto* session = static_cast<retained_restore_session*>(retained_restoring);
    if (session == nullptr) return false;
    const std::uintptr_t begin = retained_address(address);
    for (const retained_node* node = retained_first; node != nullptr; node = node->next) {
      const std::uintptr_t at = retained_address(node->value);
      if (at < begin || at - begin >= size) continue;
      const cursor& c = session->cursor_of(node->type->kind);
      retained_place place;
      if (!c.active || c.failed || !c.any || !retained_place_of(session->objects_, *node, place)) return false;
      return place.object < c.last.object || (place.object == c.last.object && place.offset <= c.last.offset);
    }
    return false;
  }

  std::span<const retained_object> objects_;
  std::span<const std::byte> in_;
  retained_restore_hook* previous_;
  bool (*previous_kept_)(const void*, std::size_t) noexcept;
  std::array<cursor, 2> cursors_{};
};

/**
 * Copies values from an image save_retained wrote back into the remanent variables of
 * `objects`, for each kind in `kinds` that check_retained finds restorable; the others keep
 * the values they have (their initial values, after a rebuild). An image that is not intact
 * restores nothing. Returns the kinds restored.
 */
inline retain_kinds restore_retained(std::span<const retained_object> objects, retain_kinds kinds,
                                     std::span<const std::byte> in) {
  return restore_checked(objects, check_retained(objects, kinds, in), in);
}

}  // namespace detail

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
