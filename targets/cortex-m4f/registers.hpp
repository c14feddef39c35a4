// SPDX-License-Identifier: Apache-2.0
// The few STM32F407 and Cortex-M4 registers this board touches, as constexpr
// addresses with the reference-manual name, offset and the bits used. No
// vendor HAL or CMSIS is available, so this file is the register map; each
// block cites its source: RM0090 (STM32F405/407 reference manual, rev 19)
// and the ARMv7-M Architecture Reference Manual (DDI 0403E) for the core.
// Access goes through reg(), a volatile 32-bit lvalue at an address.
#pragma once

#include <cstdint>

namespace kestrel::m4f::regs {

using Address = std::uintptr_t;

/// The memory-mapped 32-bit register at `address`.
inline volatile std::uint32_t& reg(Address address) {
  return *reinterpret_cast<volatile std::uint32_t*>(address);
}

// ------------------------------------------------------------- Core (SCS) --

inline constexpr Address kScbVtor = 0xE000ED08;   ///< Vector table offset (ARMv7-M B3.2.5).
inline constexpr Address kScbAircr = 0xE000ED0C;  ///< Application interrupt and reset control (B3.2.6).
inline constexpr std::uint32_t kAircrVectKey = 0x05FAu << 16;   ///< Write key of AIRCR.
inline constexpr std::uint32_t kAircrSysResetReq = 1u << 2;     ///< Request a system reset.
inline constexpr Address kScbCpacr = 0xE000ED88;  ///< Coprocessor access control (B3.2.20).
inline constexpr std::uint32_t kCpacrCp10Cp11Full = 0xFu << 20;  ///< CP10+CP11 (the FPU): full access.

inline constexpr Address kDhcsr = 0xE000EDF0;  ///< Debug halting control and status (C1.6.2).
inline constexpr std::uint32_t kDhcsrCDebugEn = 1u << 0;  ///< A debugger is attached.
inline constexpr Address kDemcr = 0xE000EDFC;  ///< Debug exception and monitor control (C1.6.5).
inline constexpr std::uint32_t kDemcrTrcEna = 1u << 24;   ///< Enable DWT and ITM.

inline constexpr Address kDwtCtrl = 0xE0001000;    ///< DWT control (C1.8.7).
inline constexpr std::uint32_t kDwtCtrlCycCntEna = 1u << 0;  ///< Run CYCCNT.
inline constexpr Address kDwtCyccnt = 0xE0001004;  ///< DWT cycle counter, 32 bits, wraps.
inline constexpr Address kDwtLar = 0xE0001FB0;     ///< CoreSight lock access (unlock key below).
inline constexpr std::uint32_t kDwtLarUnlock = 0xC5ACCE55u;  ///< Needed on some M7 parts, harmless on M4.

/// NVIC (B3.4): set-enable registers ISER0.. and byte-wide priority registers.
inline constexpr Address kNvicIser0 = 0xE000E100;
inline constexpr Address kNvicIspr0 = 0xE000E200;  ///< Set-pending registers ISPR0..
inline constexpr Address kNvicIpr0 = 0xE000E400;

// ------------------------------------------------------ STM32F407 (RM0090) --

/// RCC, base 0x4002 3800 (RM0090 section 7.3).
inline constexpr Address kRccBase = 0x40023800;
inline constexpr Address kRccCr = kRccBase + 0x00;       ///< Clock control.
inline constexpr std::uint32_t kRccCrHsiRdy = 1u << 1;
inline constexpr std::uint32_t kRccCrPllOn = 1u << 24;
inline constexpr std::uint32_t kRccCrPllRdy = 1u << 25;
inline constexpr Address kRccPllcfgr = kRccBase + 0x04;  ///< PLL configuration.
inline constexpr Address kRccCfgr = kRccBase + 0x08;     ///< Clock configuration (SW, prescalers).
inline constexpr std::uint32_t kRccCfgrSwMask = 0x3u;
inline constexpr std::uint32_t kRccCfgrSwHsi = 0x0u;
inline constexpr std::uint32_t kRccCfgrSwPll = 0x2u;
inline constexpr std::uint32_t kRccCfgrSwsMask = 0x3u << 2;
inline constexpr std::uint32_t kRccCfgrSwsPll = 0x2u << 2;
inline constexpr std::uint32_t kRccCfgrHpreMask = 0xFu << 4;    ///< AHB prescaler; 0 = /1.
inline constexpr std::uint32_t kRccCfgrPpre1Mask = 0x7u << 10;  ///< APB1 prescaler; 0 = /1.
inline constexpr std::uint32_t kRccCfgrPpre2Mask = 0x7u << 13;  ///< APB2 prescaler; 0 = /1.
inline constexpr std::uint32_t kRccCfgrPpre1Div4 = 0x5u << 10;  ///< APB1 = HCLK / 4.
inline constexpr std::uint32_t kRccCfgrPpre2Div2 = 0x4u << 13;  ///< APB2 = HCLK / 2.
inline constexpr Address kRccAhb1enr = kRccBase + 0x30;  ///< AHB1 clock enable.
inline constexpr std::uint32_t kRccAhb1enrGpioaEn = 1u << 0;
inline constexpr Address kRccApb1enr = kRccBase + 0x40;  ///< APB1 clock enable.
inline constexpr std::uint32_t kRccApb1enrUsart2En = 1u << 17;

/// Flash interface, base 0x4002 3C00 (RM0090 section 3.9).
inline constexpr Address kFlashAcr = 0x40023C00;  ///< Access control: latency and caches.
inline constexpr std::uint32_t kFlashAcrLatency5 = 5u;  ///< 5 wait states: 150-168 MHz at 2.7-3.6 V.
inline constexpr std::uint32_t kFlashAcrLatencyMask = 0x7u;
inline constexpr std::uint32_t kFlashAcrPrftEn = 1u << 8;
inline constexpr std::uint32_t kFlashAcrIcEn = 1u << 9;
inline constexpr std::uint32_t kFlashAcrDcEn = 1u << 10;

/// GPIOA, base 0x4002 0000 (RM0090 section 8.4).
inline constexpr Address kGpioaBase = 0x40020000;
inline constexpr Address kGpioaModer = kGpioaBase + 0x00;    ///< 2 bits per pin; 0b10 = alternate function.
inline constexpr Address kGpioaOspeedr = kGpioaBase + 0x08;  ///< 2 bits per pin; 0b10 = fast.
inline constexpr Address kGpioaPupdr = kGpioaBase + 0x0C;    ///< 2 bits per pin; 0b01 = pull-up.
inline constexpr Address kGpioaAfrl = kGpioaBase + 0x20;     ///< 4 bits per pin 0-7; AF7 = USART1-3.

/// USART2, base 0x4000 4400, on APB1 (RM0090 section 30.6). PA2 = TX, PA3 = RX.
inline constexpr Address kUsart2Base = 0x40004400;
inline constexpr Address kUsart2Sr = kUsart2Base + 0x00;   ///< Status.
inline constexpr Address kUsart2Dr = kUsart2Base + 0x04;   ///< Data (read: RX byte, write: TX byte).
inline constexpr Address kUsart2Brr = kUsart2Base + 0x08;  ///< Baud rate: f_APB1 / baud with OVER8 = 0.
inline constexpr Address kUsart2Cr1 = kUsart2Base + 0x0C;  ///< Control 1.
inline constexpr Address kUsart2Cr2 = kUsart2Base + 0x10;  ///< Control 2 (stop bits).
inline constexpr Address kUsart2Cr3 = kUsart2Base + 0x14;  ///< Control 3 (flow control, DMA).
inline constexpr std::uint32_t kUsartSrOre = 1u << 3;   ///< Overrun: a byte arrived before DR was read.
inline constexpr std::uint32_t kUsartSrNf = 1u << 2;    ///< Noise detected.
inline constexpr std::uint32_t kUsartSrFe = 1u << 1;    ///< Framing error.
inline constexpr std::uint32_t kUsartSrRxne = 1u << 5;  ///< DR holds a received byte.
inline constexpr std::uint32_t kUsartSrTxe = 1u << 7;   ///< DR can take the next byte to send.
inline constexpr std::uint32_t kUsartCr1Ue = 1u << 13;     ///< USART enable.
inline constexpr std::uint32_t kUsartCr1Txeie = 1u << 7;   ///< Interrupt on TXE.
inline constexpr std::uint32_t kUsartCr1Rxneie = 1u << 5;  ///< Interrupt on RXNE (and ORE).
inline constexpr std::uint32_t kUsartCr1Te = 1u << 3;      ///< Transmitter enable.
inline constexpr std::uint32_t kUsartCr1Re = 1u << 2;      ///< Receiver enable.
inline constexpr std::uint32_t kUsart2Irq = 38;  ///< USART2 global interrupt (RM0090 table 61).

/// Number of external interrupt vectors of the STM32F405/407 (RM0090 table 61: 0..81).
inline constexpr std::uint32_t kIrqCount = 82;

}  // namespace kestrel::m4f::regs
