// SPDX-License-Identifier: Apache-2.0
// Reset and exception entry of the RP2040 image. The image runs from SRAM
// (rp2040_ram.ld): a debugger loads it over SWD and starts Reset_Handler,
// which sets the stack pointer itself (a debugger's "jump" does not load SP
// from the table), zeroes .bss (.data is loaded in place), points VTOR at
// the table, runs the static constructors and calls firmware_main(). No FPU
// to enable: ARMv6-M, soft float.
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "registers.hpp"
#include "system.hpp"

extern "C" {
extern std::uint32_t _estack;
extern std::uint8_t _sbss;
extern std::uint8_t _ebss;

using InitFunction = void (*)();
extern InitFunction __preinit_array_start[];
extern InitFunction __preinit_array_end[];
extern InitFunction __init_array_start[];
extern InitFunction __init_array_end[];
}

namespace kestrel::m0plus {
[[noreturn]] void firmware_main();  // main.cpp
}

extern "C" {

[[noreturn]] void Reset_Handler();
[[noreturn]] void kestrel_m0plus_start();
void Default_Handler();

void NMI_Handler() __attribute__((weak, alias("Default_Handler")));
void HardFault_Handler() __attribute__((weak, alias("Default_Handler")));
void SVC_Handler() __attribute__((weak, alias("Default_Handler")));
void PendSV_Handler() __attribute__((weak, alias("Default_Handler")));
void SysTick_Handler() __attribute__((weak, alias("Default_Handler")));
void UART0_IRQHandler() __attribute__((weak, alias("Default_Handler")));

}  // extern "C"

namespace {

using Handler = void (*)();

/// ARMv6-M vector table (B1.5.2): initial SP, 15 system exceptions (most
/// reserved on ARMv6-M), then the RP2040's 26 interrupts.
struct VectorTable {
  const void* initial_sp;
  Handler system[15];
  Handler irq[kestrel::m0plus::regs::kIrqCount];
};

constexpr VectorTable make_vector_table() {
  VectorTable t{&_estack,
                {Reset_Handler, NMI_Handler, HardFault_Handler, nullptr, nullptr, nullptr, nullptr, nullptr, nullptr,
                 nullptr, SVC_Handler, nullptr, nullptr, PendSV_Handler, SysTick_Handler},
                {}};
  for (Handler& h : t.irq) h = Default_Handler;
  t.irq[kestrel::m0plus::regs::kUart0Irq] = UART0_IRQHandler;
  return t;
}

}  // namespace

extern "C" __attribute__((section(".isr_vector"), used)) constinit const VectorTable g_vector_table =
    make_vector_table();

/// Entry: set SP to the top of the stack section, then continue in C++.
extern "C" __attribute__((naked, noreturn)) void Reset_Handler() {
  __asm volatile(
      "ldr r0, =_estack\n\t"
      "mov sp, r0\n\t"
      "bl kestrel_m0plus_start\n\t"
      ".ltorg");
}

extern "C" [[noreturn]] void kestrel_m0plus_start() {
  std::memset(&_sbss, 0, static_cast<std::size_t>(&_ebss - &_sbss));

  using namespace kestrel::m0plus::regs;
  reg(kScbVtor) = static_cast<std::uint32_t>(reinterpret_cast<std::uintptr_t>(&g_vector_table));

  for (InitFunction* f = __preinit_array_start; f != __preinit_array_end; ++f) (*f)();
  for (InitFunction* f = __init_array_start; f != __init_array_end; ++f) (*f)();

  kestrel::m0plus::firmware_main();
}

extern "C" void Default_Handler() { kestrel::m0plus::halt_and_reset(); }
