// file_storage allocates nothing: its saves (the first, later ones, a failed one), loads and
// set_aside, counted at the C allocator, which operator new and the C library (fopen, say)
// allocate through too. Under AddressSanitizer or ThreadSanitizer, which own malloc, through
// the sanitizer's allocation hooks; otherwise with glibc, by replacing malloc and its kin (as
// glibc's manual allows) with functions that count and forward to glibc's own. Exit status 0
// if nothing was allocated, 1 otherwise, 77 (CTest: skipped) where it cannot count.
#include <iecoop/runtime/file_storage.hpp>

#include <array>
#include <cstddef>
#include <cstdio>
#include <span>

#include <unistd.h>

namespace {

volatile bool counting = false;
volatile long allocations = 0;

void note_allocation() noexcept {
  if (counting) allocations = allocations + 1;
}

}  // namespace

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define IECOOP_TEST_SANITIZER_ALLOCATOR 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || __has_feature(memory_sanitizer)
#define IECOOP_TEST_SANITIZER_ALLOCATOR 1
#endif
#endif

#if defined(IECOOP_TEST_SANITIZER_ALLOCATOR)
extern "C" int __sanitizer_install_malloc_and_free_hooks(void (*malloc_hook)(const volatile void*, std::size_t),
                                                         void (*free_hook)(const volatile void*));

namespace {
void on_malloc(const volatile void*, std::size_t) { note_allocation(); }
void on_free(const volatile void*) {}
bool start_counting() { return __sanitizer_install_malloc_and_free_hooks(&on_malloc, &on_free) != 0; }
}  // namespace
#elif defined(__GLIBC__)
extern "C" {
void* __libc_malloc(std::size_t size) noexcept;
void* __libc_calloc(std::size_t count, std::size_t size) noexcept;
void* __libc_realloc(void* old, std::size_t size) noexcept;
void* __libc_memalign(std::size_t alignment, std::size_t size) noexcept;
void __libc_free(void* memory) noexcept;

void* malloc(std::size_t size) noexcept {
  note_allocation();
  return __libc_malloc(size);
}
void* calloc(std::size_t count, std::size_t size) noexcept {
  note_allocation();
  return __libc_calloc(count, size);
}
void* realloc(void* old, std::size_t size) noexcept {
  note_allocation();
  return __libc_realloc(old, size);
}
void* memalign(std::size_t alignment, std::size_t size) noexcept {
  note_allocation();
  return __libc_memalign(alignment, size);
}
void* aligned_alloc(std::size_t alignment, std::size_t size) noexcept {
  note_allocation();
  return __libc_memalign(alignment, size);
}
int posix_memalign(void** out, std::size_t alignment, std::size_t size) noexcept {
  note_allocation();
  *out = __libc_memalign(alignment, size);
  return *out == nullptr ? 12 /* ENOMEM */ : 0;
}
void free(void* memory) noexcept { __libc_free(memory); }
}

namespace {
bool start_counting() { return true; }
}  // namespace
#else
namespace {
bool start_counting() { return false; }
}  // namespace
#endif

int main() {
  if (!start_counting()) {
    std::puts("file_storage_allocations: cannot count allocations here (no glibc, no sanitizer)");
    return 77;
  }
  char directory[] = "/tmp/iecoop_file_storage_allocations_XXXXXX";
  if (::mkdtemp(directory) == nullptr) {
    std::puts("file_storage_allocations: cannot make a directory in /tmp");
    return 1;
  }
  std::array<char, 128> path{};
  std::array<char, 128> previous{};
  std::array<char, 128> rejected{};
  std::array<char, 128> missing{};
  std::snprintf(path.data(), path.size(), "%s/retain.bin", directory);
  std::snprintf(previous.data(), previous.size(), "%s/retain.bin.previous", directory);
  std::snprintf(rejected.data(), rejected.size(), "%s/retain.bin.rejected", directory);
  std::snprintf(missing.data(), missing.size(), "%s/no_such_directory/retain.bin", directory);
  std::array<std::byte, 5000> image{};
  for (std::size_t i = 0; i < image.size(); ++i) image[i] = static_cast<std::byte>(i);
  std::array<std::byte, 8192> buffer{};

  counting = true;
  iecoop::file_storage storage(path.data());
  const bool first_save = storage.save(image);                                 // no file yet
  const bool second_save = storage.save(std::span(image).first(100));          // the first becomes the previous
  const bool loaded = storage.load(buffer) == 100;                             // the second
  const bool loaded_previous = storage.load_previous(buffer) == image.size();  // the first
  const bool too_small = storage.load(std::span(buffer).first(10)) == 0;
  const bool set_aside = storage.set_aside();
  const bool third_save = storage.save(image);
  iecoop::file_storage nowhere(missing.data());
  const bool failed_save = !nowhere.save(image);
  const bool nothing_loaded = nowhere.load(buffer) == 0;
  counting = false;

  ::unlink(path.data());
  ::unlink(previous.data());
  ::unlink(rejected.data());
  ::rmdir(directory);
  const bool worked = first_save && second_save && loaded && loaded_previous && too_small && set_aside && third_save &&
                      failed_save && nothing_loaded;
  std::printf("file_storage_allocations: %ld allocations; the calls %s\n", allocations,
              worked ? "did what they should" : "did NOT do what they should");
  return allocations == 0 && worked ? 0 : 1;
}
