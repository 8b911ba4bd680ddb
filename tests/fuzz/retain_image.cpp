// Fuzz target: the RETAIN/PERSISTENT image loader (<iecoop/runtime/retain_image.hpp>). Any bytes
// go through check_retained and restore_checked into an object with remanent variables of the
// types whose bytes are not all values (BOOL, STRING, WSTRING, a subrange, a strict enumeration,
// an ARRAY of BOOL, a STRUCT with a BOOL and a STRING) beside others (INT, REAL, TIME). Checked:
// nothing is read or written out of bounds (AddressSanitizer), every variable holds a value of its
// type afterwards (each is read as its type: UndefinedBehaviorSanitizer sees a bool that is
// neither 0 nor 1), a kind is restored only if check_retained said so, and saving the restored
// variables gives an image that check_retained accepts wholly and that restores the same values.
//
// Input: an image, as save_retained writes it; the seeds are images of this object. A mutated
// image almost never carries a correct checksum, which would stop every input at the first
// check: so the target also tries each input resealed — its total size and checksum made
// right — so that the mutations reach the section, layout and value checks.
#include "fuzz_check.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <span>

namespace {

using namespace iecoop;
using iecoop_fuzz::require;

enum class E_Mode : INT::rep { Off, Manual, Auto = 5 };

struct ST_Entry {
  BOOL bDone;
  STRING<6> sTag;
  USINT nCount;
};

struct object_under_test {
  retain<BOOL> bFlag;
  retain<STRING<8>> sName;
  retain<subrange<INT, -10, 10>> iSmall;
  retain<ARRAY<BOOL, 1, 3>> aBits;
  persistent<INT> iCount;
  persistent<WSTRING<3>> wsText;
  persistent<E_Mode> eMode;
  persistent<ST_Entry> stEntry;
  persistent<REAL> rValue;
  persistent<TIME> tLast;
};

}  // namespace

template <>
inline constexpr bool iecoop::enum_strict<E_Mode> = true;
template <>
inline constexpr auto iecoop::enum_components<E_Mode> = iecoop::components<E_Mode::Off, E_Mode::Manual, E_Mode::Auto>{};

namespace {

/// Reads every variable as its type (a BOOL that is not 0 or 1 is undefined behaviour, which
/// UBSan reports) and checks the invariants the loader promises.
void check_values(const object_under_test& o) {
  require(o.bFlag.get() == TRUE || o.bFlag.get() == FALSE, "BOOL restored as neither TRUE nor FALSE");
  require(LEN(o.sName.get()) <= 8, "STRING(8) restored longer than 8");
  require(LEN(o.wsText.get()) <= 3, "WSTRING(3) restored longer than 3");
  require(o.iSmall.get().get() >= -10 && o.iSmall.get().get() <= 10, "subrange restored outside its limits");
  require(is_component(o.eMode.get()), "strict enumeration restored as a number that names no component");
  for (DINT i = 1; i <= 3; i = i + 1) {
    const BOOL bit = o.aBits.get()[i];
    require(bit == TRUE || bit == FALSE, "ARRAY OF BOOL element restored as neither TRUE nor FALSE");
  }
  require(o.stEntry.get().bDone == TRUE || o.stEntry.get().bDone == FALSE, "STRUCT member BOOL invalid");
  require(LEN(o.stEntry.get().sTag) <= 6, "STRUCT member STRING(6) restored longer than 6");
}

bool same_bytes(const object_under_test& a, const object_under_test& b) {
  std::array<std::byte, 512> image_a{};
  std::array<std::byte, 512> image_b{};
  const std::array<detail::retained_object, 1> objects_a{detail::retained_object{&a, sizeof a}};
  const std::array<detail::retained_object, 1> objects_b{detail::retained_object{&b, sizeof b}};
  const std::size_t size_a = detail::save_retained(objects_a, retain_kinds::both, image_a);
  const std::size_t size_b = detail::save_retained(objects_b, retain_kinds::both, image_b);
  return size_a == size_b && std::memcmp(image_a.data(), image_b.data(), size_a) == 0;
}

}  // namespace

namespace {

void check_image(std::span<const std::byte> image) {
  object_under_test target;
  const std::array<detail::retained_object, 1> objects{detail::retained_object{&target, sizeof target}};
  const detail::retained_verdict verdict = detail::check_retained(objects, retain_kinds::both, image);
  const retain_kinds restored = detail::restore_checked(objects, verdict, image);
  require(restored == verdict.restorable(), "restore_checked restored other kinds than check_retained found usable");
  if (!detail::valid_retained_image(image)) {
    require(restored.empty(), "a damaged image restored something");
    require(verdict.retain == retain_load::damaged && verdict.persistent == retain_load::damaged,
            "a damaged image not reported as damaged");
  }
  check_values(target);

  // What was restored saves and restores again to the same values.
  std::array<std::byte, 512> again{};
  const std::size_t again_size = detail::save_retained(objects, retain_kinds::both, again);
  require(again_size > 0, "the restored variables do not save");
  const std::span<const std::byte> second(again.data(), again_size);
  const detail::retained_verdict verdict2 = detail::check_retained(objects, retain_kinds::both, second);
  require(verdict2.retain == retain_load::restored && verdict2.persistent == retain_load::restored,
          "an image of the restored variables is not accepted");
  object_under_test copy;
  const std::array<detail::retained_object, 1> copy_objects{detail::retained_object{&copy, sizeof copy}};
  require(detail::restore_retained(copy_objects, retain_kinds::both, second) == retain_kinds::both,
          "an image of the restored variables does not restore");
  require(same_bytes(target, copy), "restoring the saved image changed a value");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // The bytes in a buffer of exactly their size, so that any read past them is seen.
  const auto input = std::make_unique<std::byte[]>(size == 0 ? 1 : size);
  if (size > 0) std::memcpy(input.get(), data, size);
  const std::span<std::byte> image(input.get(), size);
  check_image(image);
  if (size >= detail::retain_image_header_size) {
    detail::retained_put(image.data() + 8, size, 4);
    detail::retained_put(image.data() + 12, detail::retained_checksum(image.subspan(detail::retain_image_header_size)),
                         4);
    check_image(image);
  }
  return 0;
}
