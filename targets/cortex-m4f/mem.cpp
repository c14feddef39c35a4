// SPDX-License-Identifier: Apache-2.0
// memcpy, memmove and memset for the Cortex-M4F image, small rather than
// fast: newlib-nano's are the speed-tuned Thumb-2 versions (about 720 bytes
// together), while the image copies a few hundred bytes per track and per
// frame (filter state, reports, the frame assembler's buffer). Defined here,
// the linker takes these and pulls no libc member for them. Word moves when
// both pointers are 4-byte aligned (the filter's float arrays always are),
// bytes otherwise and for the tail. Compiled without LTO and without loop
// distribution (CMakeLists.txt), so the compiler can neither turn these
// loops back into calls to themselves nor inline them into the image.
#include <cstddef>
#include <cstdint>

namespace {

// A word that may alias any object, as the C library's own routines do.
using Word = std::uint32_t __attribute__((may_alias));

bool word_aligned(const void* a, const void* b) {
  return ((reinterpret_cast<std::uintptr_t>(a) | reinterpret_cast<std::uintptr_t>(b)) & 3u) == 0;
}

void copy_forward(unsigned char* d, const unsigned char* s, std::size_t n) {
  if (word_aligned(d, s)) {
    for (; n >= 4; n -= 4, d += 4, s += 4) *reinterpret_cast<Word*>(d) = *reinterpret_cast<const Word*>(s);
  }
  for (; n != 0; --n) *d++ = *s++;
}

}  // namespace

extern "C" void* memcpy(void* dst, const void* src, std::size_t n) {
  copy_forward(static_cast<unsigned char*>(dst), static_cast<const unsigned char*>(src), n);
  return dst;
}

extern "C" void* memmove(void* dst, const void* src, std::size_t n) {
  auto* d = static_cast<unsigned char*>(dst);
  const auto* s = static_cast<const unsigned char*>(src);
  // Forward is safe unless the destination starts inside the source.
  if (reinterpret_cast<std::uintptr_t>(d) - reinterpret_cast<std::uintptr_t>(s) >= n) {
    copy_forward(d, s, n);
    return dst;
  }
  d += n;
  s += n;
  if (word_aligned(d, s)) {
    for (; n >= 4; n -= 4) {
      d -= 4;
      s -= 4;
      *reinterpret_cast<Word*>(d) = *reinterpret_cast<const Word*>(s);
    }
  }
  for (; n != 0; --n) *--d = *--s;
  return dst;
}

extern "C" void* memset(void* dst, int c, std::size_t n) {
  auto* d = static_cast<unsigned char*>(dst);
  const auto byte = static_cast<unsigned char>(c);
  if ((reinterpret_cast<std::uintptr_t>(d) & 3u) == 0) {
    const std::uint32_t word = 0x01010101u * byte;
    for (; n >= 4; n -= 4, d += 4) *reinterpret_cast<Word*>(d) = word;
  }
  for (; n != 0; --n) *d++ = byte;
  return dst;
}
