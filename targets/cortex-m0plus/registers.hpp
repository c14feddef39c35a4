// SPDX-License-Identifier: Apache-2.0
// The few RP2040 and Cortex-M0+ registers this board touches, as constexpr
// addresses with the datasheet name, offset and the bits used. No Pico SDK
// is available, so this file is the register map: RP2040 datasheet
// (chapter 2: RESETS, CLOCKS, XOSC, PLL, IO_BANK0; chapter 4: UART, an ARM
// PL011) and the ARMv6-M Architecture Reference Manual (DDI 0419) for the
// core. Access goes through reg(), a volatile 32-bit lvalue at an address.
// Every RP2040 peripheral register also has atomic set and clear aliases at
// +0x2000 and +0x3000 (datasheet 2.1.2).
#pragma once

#include <cstdint>

namespace kestrel::m0plus::regs {

using Address = std::uintptr_t;

/// The memory-mapped 32-bit register at `address`.
inline volatile std::uint32_t& reg(Address address) {
  return *reinterpret_cast<volatile std::uint32_t*>(address);
}
inline constexpr Address kAliasSet = 0x2000;  ///< Write 1s to set bits atomically.
inline constexpr Address kAliasClr = 0x3000;  ///< Write 1s to clear bits atomically.

// ------------------------------------------------------------- Core (SCS) --

inline constexpr Address kSysTickCsr = 0xE000E010;  ///< SysTick control and status (B3.3.3).
inline constexpr std::uint32_t kSysTickEnable = 1u << 0;
inline constexpr std::uint32_t kSysTickTickInt = 1u << 1;
inline constexpr std::uint32_t kSysTickClkSourceCpu = 1u << 2;  ///< Count the processor clock.
inline constexpr Address kSysTickRvr = 0xE000E014;  ///< Reload value, 24 bits.
inline constexpr Address kSysTickCvr = 0xE000E018;  ///< Current value, counts down.
inline constexpr Address kScbIcsr = 0xE000ED04;     ///< Interrupt control and state.
inline constexpr std::uint32_t kIcsrPendStSet = 1u << 26;  ///< SysTick exception pending.
inline constexpr Address kScbVtor = 0xE000ED08;     ///< Vector table offset.
inline constexpr Address kScbAircr = 0xE000ED0C;    ///< Application interrupt and reset control.
inline constexpr std::uint32_t kAircrVectKey = 0x05FAu << 16;
inline constexpr std::uint32_t kAircrSysResetReq = 1u << 2;
inline constexpr Address kDhcsr = 0xE000EDF0;  ///< Debug halting control and status.
inline constexpr std::uint32_t kDhcsrCDebugEn = 1u << 0;
/// NVIC: set-enable register and priority registers (word access only on ARMv6-M).
inline constexpr Address kNvicIser = 0xE000E100;
inline constexpr Address kNvicIpr0 = 0xE000E400;

// --------------------------------------------------------- RP2040 (datasheet) --

/// RESETS, base 0x4000 C000 (2.14): a peripheral is held in reset until its bit is cleared.
inline constexpr Address kResetsBase = 0x4000C000;
inline constexpr Address kResetsReset = kResetsBase + 0x0;
inline constexpr Address kResetsResetDone = kResetsBase + 0x8;
inline constexpr std::uint32_t kResetIoBank0 = 1u << 5;
inline constexpr std::uint32_t kResetPadsBank0 = 1u << 8;
inline constexpr std::uint32_t kResetPllSys = 1u << 12;
inline constexpr std::uint32_t kResetUart0 = 1u << 22;

/// XOSC, base 0x4002 4000 (2.16).
inline constexpr Address kXoscBase = 0x40024000;
inline constexpr Address kXoscCtrl = kXoscBase + 0x00;
inline constexpr std::uint32_t kXoscFreqRange1To15MHz = 0xAA0u;
inline constexpr std::uint32_t kXoscEnable = 0xFABu << 12;
inline constexpr Address kXoscStatus = kXoscBase + 0x04;
inline constexpr std::uint32_t kXoscStable = 1u << 31;
inline constexpr Address kXoscStartup = kXoscBase + 0x0C;  ///< Start-up delay in units of 256 XOSC cycles.

/// PLL_SYS, base 0x4002 8000 (2.18).
inline constexpr Address kPllSysBase = 0x40028000;
inline constexpr Address kPllCs = kPllSysBase + 0x0;        ///< REFDIV (5:0), LOCK (31).
inline constexpr std::uint32_t kPllCsLock = 1u << 31;
inline constexpr Address kPllPwr = kPllSysBase + 0x4;       ///< Power-down bits.
inline constexpr std::uint32_t kPllPwrPd = 1u << 0;
inline constexpr std::uint32_t kPllPwrPostDivPd = 1u << 3;
inline constexpr std::uint32_t kPllPwrVcoPd = 1u << 5;
inline constexpr Address kPllFbdivInt = kPllSysBase + 0x8;  ///< Feedback divider.
inline constexpr Address kPllPrim = kPllSysBase + 0xC;      ///< POSTDIV1 (18:16), POSTDIV2 (14:12).

/// CLOCKS, base 0x4000 8000 (2.15).
inline constexpr Address kClocksBase = 0x40008000;
inline constexpr Address kClkRefCtrl = kClocksBase + 0x30;      ///< SRC (1:0): 2 = XOSC.
inline constexpr Address kClkRefSelected = kClocksBase + 0x38;  ///< One-hot of the selected source.
inline constexpr std::uint32_t kClkRefSrcRosc = 0u;
inline constexpr std::uint32_t kClkRefSrcXosc = 2u;
inline constexpr Address kClkSysCtrl = kClocksBase + 0x3C;      ///< SRC (0): 1 = aux; AUXSRC (7:5): 0 = PLL_SYS.
inline constexpr std::uint32_t kClkSysSrcAux = 1u << 0;
inline constexpr Address kClkSysSelected = kClocksBase + 0x44;
inline constexpr Address kClkPeriCtrl = kClocksBase + 0x48;     ///< ENABLE (11); AUXSRC (7:5): 0 = clk_sys.
inline constexpr std::uint32_t kClkPeriEnable = 1u << 11;

/// IO_BANK0, base 0x4001 4000 (2.19.6): GPIOn_CTRL at 0x004 + 8 n, FUNCSEL (4:0).
inline constexpr Address kIoBank0Base = 0x40014000;
inline constexpr Address kGpio0Ctrl = kIoBank0Base + 0x004;
inline constexpr Address kGpio1Ctrl = kIoBank0Base + 0x00C;
inline constexpr std::uint32_t kFuncSelUart = 2u;

/// UART0, base 0x4003 4000 (4.2, ARM PL011).
inline constexpr Address kUart0Base = 0x40034000;
inline constexpr Address kUartDr = kUart0Base + 0x000;     ///< Data; bits 11:8 are the receive error flags.
inline constexpr std::uint32_t kUartDrOe = 1u << 11;       ///< Overrun.
inline constexpr std::uint32_t kUartDrFe = 1u << 8;        ///< Framing error.
inline constexpr Address kUartFr = kUart0Base + 0x018;     ///< Flags.
inline constexpr std::uint32_t kUartFrRxfe = 1u << 4;      ///< Receive FIFO empty.
inline constexpr std::uint32_t kUartFrTxff = 1u << 5;      ///< Transmit FIFO full.
inline constexpr Address kUartIbrd = kUart0Base + 0x024;   ///< Integer baud divisor.
inline constexpr Address kUartFbrd = kUart0Base + 0x028;   ///< Fractional baud divisor (1/64).
inline constexpr Address kUartLcrH = kUart0Base + 0x02C;   ///< Line control; writing it latches the divisors.
inline constexpr std::uint32_t kUartLcrHWlen8 = 3u << 5;
inline constexpr std::uint32_t kUartLcrHFen = 1u << 4;     ///< FIFOs on (32 bytes each way).
inline constexpr Address kUartCr = kUart0Base + 0x030;     ///< Control.
inline constexpr std::uint32_t kUartCrEn = 1u << 0;
inline constexpr std::uint32_t kUartCrTxe = 1u << 8;
inline constexpr std::uint32_t kUartCrRxe = 1u << 9;
inline constexpr Address kUartImsc = kUart0Base + 0x038;   ///< Interrupt mask set/clear.
inline constexpr std::uint32_t kUartIntRx = 1u << 4;       ///< Receive FIFO at its level.
inline constexpr std::uint32_t kUartIntTx = 1u << 5;       ///< Transmit FIFO at its level.
inline constexpr std::uint32_t kUartIntRt = 1u << 6;       ///< Receive timeout (bytes waiting).
inline constexpr Address kUartMis = kUart0Base + 0x040;    ///< Masked interrupt status.
inline constexpr Address kUartIcr = kUart0Base + 0x044;    ///< Interrupt clear.
inline constexpr std::uint32_t kUart0Irq = 20;             ///< UART0_IRQ (datasheet 2.3.2).

/// Number of external interrupts of the RP2040 (0..25).
inline constexpr std::uint32_t kIrqCount = 26;

}  // namespace kestrel::m0plus::regs
