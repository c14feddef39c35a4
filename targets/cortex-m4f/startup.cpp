// SPDX-License-Identifier: Apache-2.0
// Reset and exception entry of the STM32F407 image: the vector table (placed
// first in flash by stm32f407.ld, section .isr_vector), Reset_Handler and
// the default handlers. Reset_Handler enables the FPU before any code that
// may use it, copies .data from flash, zeroes .bss, runs the static
// constructors from .preinit_array/.init_array itself (the image links with
// -nostartfiles, so no crt0 and no __libc_init_array/_init), then calls
// kestrel::m4f::firmware_main() (main.cpp), which never returns. It is not
// named main because ISO C++ forbids calling main, and here nothing else
// would: without crt0 there is no other caller.
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "system.hpp"
#include "registers.hpp"

// Symbols defined by stm32f407.ld.
extern "C" {
extern std::uint32_t _estack;  // initial stack pointer (top of the stack)
extern std::uint8_t _sidata;   // load address of .data in flash
extern std::uint8_t _sdata;    // .data in RAM: start
extern std::uint8_t _edata;    //              end
extern std::uint8_t _sbss;     // .bss: start
extern std::uint8_t _ebss;     //       end

using InitFunction = void (*)();
extern InitFunction __preinit_array_start[];
extern InitFunction __preinit_array_end[];
extern InitFunction __init_array_start[];
extern InitFunction __init_array_end[];
}

namespace kestrel::m4f {
[[noreturn]] void firmware_main();  // main.cpp
}

extern "C" {

[[noreturn]] void Reset_Handler();
void Default_Handler();

// Every handler is weak and defaults to Default_Handler; a driver overrides
// one by defining a function of the same name (uart_feed.cpp: USART2).
void NMI_Handler() __attribute__((weak, alias("Default_Handler")));
void HardFault_Handler() __attribute__((weak, alias("Default_Handler")));
void MemManage_Handler() __attribute__((weak, alias("Default_Handler")));
void BusFault_Handler() __attribute__((weak, alias("Default_Handler")));
void UsageFault_Handler() __attribute__((weak, alias("Default_Handler")));
void SVC_Handler() __attribute__((weak, alias("Default_Handler")));
void DebugMon_Handler() __attribute__((weak, alias("Default_Handler")));
void PendSV_Handler() __attribute__((weak, alias("Default_Handler")));
void SysTick_Handler() __attribute__((weak, alias("Default_Handler")));
void USART2_IRQHandler() __attribute__((weak, alias("Default_Handler")));

}  // extern "C"

namespace {

using Handler = void (*)();

/// ARMv7-M vector table (B1.5.3): initial SP, 15 system exceptions, then the
/// STM32F407's 82 interrupts (RM0090 table 61).
struct VectorTable {
  const void* initial_sp;
  Handler system[15];
  Handler irq[kestrel::m4f::regs::kIrqCount];
};

constexpr VectorTable make_vector_table() {
  VectorTable t{&_estack,
                {Reset_Handler, NMI_Handler, HardFault_Handler, MemManage_Handler, BusFault_Handler,
                 UsageFault_Handler, nullptr, nullptr, nullptr, nullptr, SVC_Handler, DebugMon_Handler,
                 nullptr, PendSV_Handler, SysTick_Handler},
                {}};
  for (Handler& h : t.irq) h = Default_Handler;
  t.irq[kestrel::m4f::regs::kUsart2Irq] = USART2_IRQHandler;
  return t;
}

}  // namespace

// constinit: the table is data in flash, never a run-time initialiser.
extern "C" __attribute__((section(".isr_vector"), used)) constinit const VectorTable g_vector_table =
    make_vector_table();

namespace {

/// Everything after the FPU is on. Kept out of line so the compiler cannot
/// hoist floating-point register use above the CPACR write.
[[noreturn]] __attribute__((noinline)) void start_runtime() {
  std::memcpy(&_sdata, &_sidata, static_cast<std::size_t>(&_edata - &_sdata));
  std::memset(&_sbss, 0, static_cast<std::size_t>(&_ebss - &_sbss));

  using namespace kestrel::m4f::regs;
  reg(kScbVtor) = static_cast<std::uint32_t>(reinterpret_cast<std::uintptr_t>(&g_vector_table));

  for (InitFunction* f = __preinit_array_start; f != __preinit_array_end; ++f) (*f)();
  for (InitFunction* f = __init_array_start; f != __init_array_end; ++f) (*f)();

  kestrel::m4f::firmware_main();
}

}  // namespace

extern "C" [[noreturn]] void Reset_Handler() {
  // FPU first (ARMv7-M B3.2.20): CP10 and CP11 full access, then barriers so
  // the next instruction sees it.
  using namespace kestrel::m4f::regs;
  reg(kScbCpacr) |= kCpacrCp10Cp11Full;
  __asm volatile("dsb\n\tisb" ::: "memory");
  start_runtime();
}

/// Unexpected interrupt or fault: stop in the debugger if one is attached,
/// otherwise reset.
extern "C" void Default_Handler() { kestrel::m4f::halt_and_reset(); }
